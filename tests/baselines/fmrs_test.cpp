// fmRS and BiRRT(fmRS) (baselines/fmrs.h, mcr.h) against known answers built by hand:
// minimum-constraint-removal paths through two channels whose objects are placed so the answer
// is the channel with fewer of them (or none, or no path past hard disks); the topological
// order against a brute force over every permutation of random graphs; a chain solved in the
// only order its goals allow (the last object's goal is free, each other's is occupied by the
// next); a two-cycle on which fmRS reports the cycle and BiRRT(fmRS) needs at least one buffer
// move; a goal inside a fixed obstacle never reported solved; the same plan per seed, also in
// parallel threads. Every plan passes the independent validator (validator.h).
#include "baselines/fmrs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "baselines/birrt.h"
#include "core/rng.h"
#include "support/plan_checks.h"

namespace rearm::baselines {
namespace {

geometry::Polygon box(double x0, double y0, double x1, double y1) {
  return {{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

// A 6 x 4 m room; between x = 2 and 4 two channels, y in [0.8, 1.6] (A) and [2.4, 3.2] (B), the
// rest of that band walled. A robot disk (0.2 m) passes a channel only where no object
// (0.25 m, on the channel's axis) is: 0.4 m of channel width is left of 0.8.
DiskWorld channels() {
  return DiskWorld(box(0, 0, 6, 4), {box(2, 0, 4, 0.8), box(2, 1.6, 4, 2.4), box(2, 3.2, 4, 4)});
}

McrQuery crossing_query() {
  McrQuery q;
  q.radius = 0.2;
  q.margin = 0.01;
  q.sources = {Point(1, 2)};
  q.targets = {Point(5, 2)};
  return q;
}

TEST(Mcr, CrossesTheChannelWithFewerObjects) {
  const DiskWorld world = channels();
  const McrRoadmap roadmap(world, 0.1);
  McrQuery q = crossing_query();
  q.constraints = {{Point(3, 1.2), 0.25}, {Point(2.6, 2.8), 0.25}, {Point(3.4, 2.8), 0.25}};
  const McrPath p = roadmap.search(q);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.crossed.count(), 1u);
  EXPECT_TRUE(p.crossed.test(0));
  EXPECT_EQ(p.path.front(), q.sources[0]);
  EXPECT_EQ(p.path.back(), q.targets[0]);
  for (std::size_t k = 1; k < p.path.size(); ++k) {
    EXPECT_TRUE(world.segment_free(p.path[k - 1], p.path[k], q.radius, q.margin, {}));
  }
  // The other way round: two objects in A, one in B.
  q.constraints = {{Point(2.6, 1.2), 0.25}, {Point(3.4, 1.2), 0.25}, {Point(3, 2.8), 0.25}};
  const McrPath p2 = roadmap.search(q);
  ASSERT_TRUE(p2.found);
  EXPECT_EQ(p2.crossed.count(), 1u);
  EXPECT_TRUE(p2.crossed.test(2));
}

TEST(Mcr, AFreeChannelCostsNothingAndHardDisksCloseTheWay) {
  const DiskWorld world = channels();
  const McrRoadmap roadmap(world, 0.1);
  McrQuery q = crossing_query();
  q.constraints = {{Point(2.6, 2.8), 0.25}, {Point(3.4, 2.8), 0.25}};
  const McrPath free = roadmap.search(q);
  ASSERT_TRUE(free.found);
  EXPECT_EQ(free.crossed.count(), 0u);
  q.hard = {{Point(3, 1.2), 0.25}, {Point(3, 2.8), 0.25}};
  q.constraints.clear();
  EXPECT_FALSE(roadmap.search(q).found);
  q.hard.pop_back();  // channel B open again
  EXPECT_TRUE(roadmap.search(q).found);
  q.targets = {Point(3, 2)};  // inside the wall: no target
  EXPECT_FALSE(roadmap.search(q).found);
}

TEST(Mcr, RejectsAGridTooFineForTheWorkspace) {
  const DiskWorld world = channels();
  EXPECT_THROW(McrRoadmap(world, 1e-4), Error);
  EXPECT_THROW(McrRoadmap(world, 0.0), Error);
  EXPECT_THROW(McrRoadmap(world, std::numeric_limits<double>::quiet_NaN()), Error);
}

// True when some permutation puts every `before` entry first (by enumeration).
bool has_order(const std::vector<std::vector<std::size_t>>& before) {
  std::vector<std::size_t> perm(before.size());
  std::iota(perm.begin(), perm.end(), 0);
  do {
    std::vector<std::size_t> at(perm.size());
    for (std::size_t t = 0; t < perm.size(); ++t) at[perm[t]] = t;
    bool ok = true;
    for (std::size_t k = 0; k < before.size() && ok; ++k)
      for (const std::size_t m : before[k]) ok = ok && at[m] < at[k];
    if (ok) return true;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return false;
}

TEST(TopologicalOrder, MatchesBruteForceAndNamesARealCycle) {
  Rng rng(16);
  int cycles = 0;
  for (int g = 0; g < 300; ++g) {
    const std::size_t n = 1 + rng.index(6);
    std::vector<std::vector<std::size_t>> before(n);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t m = 0; m < n; ++m)
        if (m != k && rng.uniform01() < 0.2) before[k].push_back(m);
    const TopologicalOrder t = topological_order(before);
    ASSERT_EQ(t.cycle.empty(), has_order(before)) << "graph " << g;
    if (t.cycle.empty()) {
      ASSERT_EQ(t.order.size(), n);
      std::vector<std::size_t> at(n);
      for (std::size_t i = 0; i < n; ++i) at[t.order[i]] = i;
      for (std::size_t k = 0; k < n; ++k)
        for (const std::size_t m : before[k]) EXPECT_LT(at[m], at[k]) << "graph " << g;
    } else {
      ++cycles;
      for (std::size_t i = 0; i < t.cycle.size(); ++i) {
        const std::size_t a = t.cycle[i], b = t.cycle[(i + 1) % t.cycle.size()];
        EXPECT_NE(std::find(before[b].begin(), before[b].end(), a), before[b].end());
      }
    }
  }
  EXPECT_GT(cycles, 20);  // both branches were exercised
}

// An empty 8 x 6 m room; objects of radius 0.25 m; goals as 0.6 m squares.
RearrangementProblem room(const std::vector<Point>& starts, const std::vector<Point>& goals) {
  RearrangementProblem p;
  p.name = "hand-built";
  p.workspace = box(0, 0, 8, 6);
  p.robot_start = Point(1, 1);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    p.object_names.push_back("M" + std::to_string(i + 1));
    p.object_radii.push_back(0.25);
    p.start.push_back(starts[i]);
    p.goals.emplace_back(goals[i]);
    const Point& g = goals[i];
    p.goal_regions.emplace_back(box(g.x() - 0.3, g.y() - 0.3, g.x() + 0.3, g.y() + 0.3));
    p.goal_region_names.push_back("g" + std::to_string(i + 1));
  }
  return p;
}

PlannerOptions options(std::uint64_t seed, long queries = 4000) {
  PlannerOptions o;
  o.time_limit = 60;
  o.seed = seed;
  o.max_queries = queries;
  return o;
}

// M1's goal is M2's start and M2's goal M3's start; M3's goal is free: M3, M2, M1 is the only
// order that moves each object once.
TEST(Fmrs, SolvesAChainInTheOrderItsGoalsImply) {
  const auto p = room({Point(2, 3), Point(3.6, 3), Point(5.2, 3)},
                      {Point(3.6, 3), Point(5.2, 3), Point(6.8, 1.2)});
  const MovePlanner planner(p, {});
  const Fmrs f(planner, {});
  const FmrsDependencies d =
      f.dependencies(p.start, p.robot_start, {0, 1, 2}, p.goal_arrangement());
  EXPECT_TRUE(d.unreachable.empty());
  EXPECT_NE(std::find(d.before[0].begin(), d.before[0].end(), 1u), d.before[0].end());
  EXPECT_NE(std::find(d.before[1].begin(), d.before[1].end(), 2u), d.before[1].end());
  const PlanResult r = plan_fmrs(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  ASSERT_EQ(r.plan.moves.size(), 3u);
  EXPECT_EQ(r.plan.moves[0].object, 2u);
  EXPECT_EQ(r.plan.moves[1].object, 1u);
  EXPECT_EQ(r.plan.moves[2].object, 0u);
}

// M1 and M2 swap places: no order moves each once (each goal holds the other object), so a
// solution takes at least one move to a buffer: three moves or more.
TEST(Fmrs, ReportsATwoCycleThatBirrtFmrsSolvesWithABuffer) {
  const auto p = room({Point(3, 3), Point(5, 3)}, {Point(5, 3), Point(3, 3)});
  const PlanResult f = plan_fmrs(p, {}, options(1));
  EXPECT_EQ(f.status, PlanStatus::kUnsolved);
  EXPECT_NE(f.reason.find("dependency cycle"), std::string::npos) << f.reason;
  EXPECT_NE(f.reason.find("M1"), std::string::npos) << f.reason;
  EXPECT_NE(f.reason.find("M2"), std::string::npos) << f.reason;
  EXPECT_TRUE(f.plan.moves.empty());
  BirrtOptions b;
  b.extension = BirrtOptions::Extension::kFmrs;
  const PlanResult r = plan_birrt(p, {}, options(1), b);
  test_support::expect_valid_plan(p, r);
  EXPECT_GE(r.plan.moves.size(), 3u);
}

TEST(Fmrs, AGoalInsideAnObstacleIsNeverSolved) {
  auto p = room({Point(2, 3), Point(5, 3)}, {Point(4, 1.5), Point(6, 4.5)});
  p.obstacles = {box(3.6, 1.1, 4.4, 1.9)};
  p.obstacle_names = {"P1"};
  const PlanResult f = plan_fmrs(p, {}, options(1));
  EXPECT_EQ(f.status, PlanStatus::kInfeasible) << f.reason;
  EXPECT_NE(f.reason.find("M1"), std::string::npos) << f.reason;
  BirrtOptions b;
  b.extension = BirrtOptions::Extension::kFmrs;
  const PlanResult r = plan_birrt(p, {}, options(1, 60), b);
  EXPECT_NE(r.status, PlanStatus::kSolved);
  EXPECT_TRUE(r.plan.moves.empty());
}

TEST(Fmrs, BirrtFmrsGivesTheSamePlanPerSeedInParallelThreads) {
  const auto p = room({Point(2, 3), Point(3.6, 3), Point(5.2, 3)},
                      {Point(5.2, 3), Point(2, 3), Point(3.6, 3)});  // a three-cycle
  BirrtOptions b;
  b.extension = BirrtOptions::Extension::kFmrs;
  test_support::expect_valid_plan(p, plan_birrt(p, {}, options(7), b));
  test_support::expect_same_plan_in_threads([&] { return plan_birrt(p, {}, options(7), b); });
}

}  // namespace
}  // namespace rearm::baselines
