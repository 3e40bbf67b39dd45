// The `buffer` baseline (TRLB-style, baselines/buffer.h) against known answers: its running-buffer
// order against a brute force over every permutation of random dependency graphs and against a
// long cycle (one buffer, the optimum, also beyond the exact limit); a monotone instance solved
// with no buffer; a two-cycle and Fig. 5's
// three-cycle each solved with exactly one buffer; Fig. 3's passage cleared of a goal-less
// object; a goal inside a fixed obstacle reported
// infeasible, never solved; a buffer spot in a goal region that fills only after it is vacated
// (TRLB's allocation; the strict rule finds none); the same plan for the same seed, also in
// parallel threads. Every plan passes the independent validator (validator.h).
#include "baselines/buffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "baselines/buffer_order.h"
#include "core/rng.h"
#include "geometry/distance.h"
#include "scenario/scenario_io.h"
#include "support/plan_checks.h"

namespace rearm::baselines {
namespace {

// The least maximum of running buffers over every order, by enumeration: the objects parked
// at a step are those blocking an arrived object or the arriving one, not yet arrived.
int brute_force(const DependencyGraph& g) {
  std::vector<std::size_t> order(g.goal_count);
  std::iota(order.begin(), order.end(), 0);
  int best = 1 << 20;
  do {
    std::vector<bool> arrived(g.object_count, false), parked(g.object_count, false);
    int worst = 0;
    for (const std::size_t i : order) {
      for (const std::size_t j : g.blockers[i]) {
        if (!arrived[j]) parked[j] = true;
      }
      int now = 0;
      for (std::size_t k = 0; k < g.object_count; ++k) now += parked[k] && !arrived[k];
      worst = std::max(worst, now);
      arrived[i] = true;
      parked[i] = false;
    }
    best = std::min(best, worst);
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

DependencyGraph random_graph(Rng& rng, std::size_t goals, std::size_t extra) {
  DependencyGraph g;
  g.goal_count = goals;
  g.object_count = goals + extra;
  g.blockers.resize(goals);
  for (std::size_t i = 0; i < goals; ++i) {
    for (std::size_t j = 0; j < g.object_count; ++j) {
      if (j != i && rng.uniform01() < 0.3) g.blockers[i].push_back(j);
    }
  }
  return g;
}

TEST(BufferOrder, ExactOrderMatchesBruteForce) {
  Rng rng(44);
  for (int k = 0; k < 200; ++k) {
    const DependencyGraph g = random_graph(rng, 1 + rng.index(7), rng.index(3));
    const BufferOrder order(g);
    ASSERT_TRUE(order.exact());
    EXPECT_EQ(order.running_buffers(), brute_force(g)) << "graph " << k;
    // Following the first candidate at every step realises the optimum.
    ObjectSet s = 0;
    int worst = 0;
    while (std::popcount(s) < static_cast<int>(g.goal_count)) {
      const std::size_t i = order.candidates(s).front();
      worst = std::max(worst, peak(g, s, i));
      s |= ObjectSet{1} << i;
    }
    EXPECT_EQ(worst, order.running_buffers()) << "graph " << k;
  }
}

// A cycle of n objects, each goal on the next one's start, needs exactly one buffer.
TEST(BufferOrder, ACycleNeedsOneBufferAtAnySize) {
  for (const std::size_t n : {2u, 5u, 16u, 24u}) {
    DependencyGraph g;
    g.goal_count = g.object_count = n;
    g.blockers.resize(n);
    for (std::size_t i = 0; i < n; ++i) g.blockers[i] = {(i + 1) % n};
    const BufferOrder order(g);
    EXPECT_EQ(order.exact(), n <= kExactOrderLimit);
    EXPECT_EQ(order.running_buffers(), 1) << n;
  }
  DependencyGraph chain;  // monotone: 0 on 1's start, 1 on 2's: no buffer
  chain.goal_count = chain.object_count = 3;
  chain.blockers = {{1}, {2}, {}};
  EXPECT_EQ(BufferOrder(chain).running_buffers(), 0);
  EXPECT_EQ(BufferOrder(chain).candidates(0).front(), 2u);
}

scenario::Scenario load(const std::string& name) {
  return scenario::load_scenario("experiments/scenarios/" + name + ".yaml");
}

PlannerOptions options(std::uint64_t seed) {
  PlannerOptions o;
  o.time_limit = 60;
  o.seed = seed;
  o.max_queries = 4000;
  return o;
}

// Moves that end elsewhere than the object's goal point region: the buffer moves.
int buffer_moves(const RearrangementProblem& p, const Plan& plan) {
  int n = 0;
  for (const ObjectMove& m : plan.moves) {
    n += !(p.goal_regions[m.object] && geometry::contains(*p.goal_regions[m.object], m.to));
  }
  return n;
}

TEST(Buffer, SolvesTheMonotoneInstanceWithoutBuffers) {
  const auto p = problem_from_scenario(load("monotone"));
  const PlanResult r = plan_buffer(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  EXPECT_EQ(r.plan.moves.size(), 3u);
  EXPECT_EQ(buffer_moves(p, r.plan), 0);
}

TEST(Buffer, ATwoCycleTakesExactlyOneBuffer) {
  scenario::Scenario s = load("fig5");
  s.task = "<>release(M1,l2) && <>release(M2,l1)";  // M1 onto M2's start and back
  const auto p = problem_from_scenario(s);
  const PlanResult r = plan_buffer(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  EXPECT_EQ(buffer_moves(p, r.plan), 1);
  EXPECT_EQ(r.plan.moves.size(), 3u);  // one to a buffer, two to their goals
}

// TRLB's allocation (BufferOptions::lifetime_spots): a swap of M1 and M2 in a 9 x 3 m room whose
// floor three goal regions tile (lB | lA | lC, M3 already inside lC). One of the two must wait in
// a buffer while the other arrives. Every point of the floor lies in some goal region, so a rule
// that keeps spots clear of every goal region finds none (buffer-strict: unsolved); a spot needs
// to keep clear only of the goal filled while it is used (lA, when M2 waits for M1) and of the
// objects, so lC or M2's own lB serve.
TEST(Buffer, ASpotKeepsClearOnlyOfTheGoalsFilledWhileItIsUsed) {
  const scenario::Scenario s = scenario::parse_scenario(R"yaml(
name: tiled
workspace: [[0, 0], [9, 0], [9, 3], [0, 3]]
robot: {radius: 0.2, start: [6.5, 0.6], heading: 0}
regions:
  - {name: lB, polygon: [[0, 0], [2.75, 0], [2.75, 3], [0, 3]]}
  - {name: lA, polygon: [[2.75, 0], [5, 0], [5, 3], [2.75, 3]]}
  - {name: lC, polygon: [[5, 0], [9, 0], [9, 3], [5, 3]]}
objects:
  - {name: M1, center: [1.5, 1.5], radius: 0.25}
  - {name: M2, center: [3.9, 1.5], radius: 0.25}
  - {name: M3, center: [7.5, 2.2], radius: 0.25}
task: "<>release(M1,lA) && <>release(M2,lB) && <>release(M3,lC)"
)yaml");
  const auto p = problem_from_scenario(s);
  BufferOptions strict;
  strict.lifetime_spots = false;
  const PlanResult no = plan_buffer(p, {}, options(1), strict);
  EXPECT_NE(no.status, PlanStatus::kSolved);
  EXPECT_NE(no.reason.find("no buffer spot"), std::string::npos) << no.reason;
  const PlanResult r = plan_buffer(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  ASSERT_EQ(buffer_moves(p, r.plan), 1);
  const ObjectMove& parked = r.plan.moves.front();
  EXPECT_EQ(parked.object, 1u);  // M2 (M1's goal point is under it) waits
  EXPECT_FALSE(geometry::contains(*p.goal_regions[0], parked.to)) << parked.to.transpose();
  EXPECT_GE(geometry::signed_distance(*p.goal_regions[0], parked.to), 0.25);  // ρ clear of lA
}

TEST(Buffer, Fig5ThreeCycleTakesExactlyOneBuffer) {
  const auto p = problem_from_scenario(load("fig5"));
  const PlanResult r = plan_buffer(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  EXPECT_EQ(buffer_moves(p, r.plan), 1);
  EXPECT_EQ(r.plan.moves.size(), 4u);
}

// Fig. 3: the robot's own way to l1 runs through the only passage, where M1 (no goal) sits: the
// dependency graph is empty, so only clearing the way solves it, with M1 parked off the way.
TEST(Buffer, ClearsAWayBlockedByAnObjectWithoutGoal) {
  const auto p = problem_from_scenario(load("fig3"));
  const PlanResult r = plan_buffer(p, {}, options(1));
  test_support::expect_valid_plan(p, r);
  ASSERT_EQ(r.plan.moves.size(), 1u);
  // M1 leaves the passage (the walls at x = 4.7 .. 5.3 leave y in [2.5, 3.5] free).
  const Point m1 = r.plan.final_arrangement[0];
  EXPECT_FALSE(m1.x() > 4.7 - 0.45 && m1.x() < 5.3 + 0.45 && std::abs(m1.y() - 3) < 0.5 + 0.45)
      << m1.transpose();
  ASSERT_FALSE(r.plan.final_transit.empty());
  EXPECT_TRUE(geometry::contains(*p.robot_goal_region, r.plan.final_transit.back()));
}

TEST(Buffer, AGoalInsideAnObstacleIsInfeasibleNeverSolved) {
  auto p = problem_from_scenario(load("monotone"));
  p.goals[0] = Point(1.3, 6.0);  // inside the familiar L (P1: x in [1.0, 1.6] at y = 6)
  const PlanResult r = plan_buffer(p, {}, options(1));
  EXPECT_EQ(r.status, PlanStatus::kInfeasible) << r.reason;
  EXPECT_NE(r.reason.find("M1"), std::string::npos) << r.reason;
  EXPECT_TRUE(r.plan.moves.empty());
}

TEST(Buffer, SameSeedSamePlanInParallelThreads) {
  const auto p = problem_from_scenario(load("fig5"));
  test_support::expect_same_plan_in_threads([&] { return plan_buffer(p, {}, options(7)); });
}

}  // namespace
}  // namespace rearm::baselines
