// The baselines' geometric core against independent truth: the exact capsule test against
// sampled distances, OMPL motion queries against sampled geometry::disk_clearance, the
// closed-form heading of the off-axis tracking law against a numerical integration of the
// unicycle, and the task → rearrangement problem translation against the scenario files.
#include "baselines/motion_query.h"

#include <gtest/gtest.h>

#include <cmath>

#include "baselines/problem.h"
#include "core/rng.h"
#include "geometry/distance.h"
#include "scenario/scenario_io.h"

namespace rearm::baselines {
namespace {

using geometry::Point;

geometry::Polygon box(double x0, double y0, double x1, double y1) {
  geometry::Polygon p;
  p.vertices = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  return p;
}

TEST(SegmentDistance, MatchesDenseSampling) {
  Rng rng(5);
  for (int t = 0; t < 2000; ++t) {
    Point a(rng.uniform(-1, 1), rng.uniform(-1, 1)), b(rng.uniform(-1, 1), rng.uniform(-1, 1));
    Point c(rng.uniform(-1, 1), rng.uniform(-1, 1)), d(rng.uniform(-1, 1), rng.uniform(-1, 1));
    double best = 1e9;
    constexpr int kSamples = 400;
    for (int i = 0; i <= kSamples; ++i) {
      const Point x = a + (b - a) * (double(i) / kSamples);
      best = std::min(best, (x - geometry::nearest_on_segment(c, d, x)).norm());
    }
    const double exact = segment_distance(a, b, c, d);
    EXPECT_LE(exact, best + 1e-12);
    // Sampling one segment at spacing |ab|/400 overestimates by at most half a spacing.
    EXPECT_GE(exact, best - 0.5 * (b - a).norm() / kSamples - 1e-12);
  }
}

// Two rooms joined by a door; a disk crossing must bend through it.
struct Rooms {
  geometry::Polygon workspace = box(0, 0, 10, 5);
  std::vector<geometry::Polygon> walls = {box(4.8, 0, 5.2, 2), box(4.8, 3, 5.2, 5)};
  DiskWorld world{workspace, walls};
};

TEST(MotionQuery, PathThroughADoorKeepsItsClearanceBySampling) {
  Rooms r;
  const std::vector<geometry::Disk> disks = {{{2, 2.5}, 0.3}};
  const double radius = 0.3, margin = 0.02;
  QueryContext ctx(30, 9);
  const QueryResult q =
      plan_motion(r.world, disks, std::nullopt, radius, margin, {1, 0.8}, {9, 0.8}, ctx);
  ASSERT_EQ(q.status, QueryStatus::kSolved);
  ASSERT_GE(q.path.size(), 3u);  // not the straight line: it crosses the wall
  EXPECT_EQ(q.path.front(), Point(1, 0.8));
  EXPECT_EQ(q.path.back(), Point(9, 0.8));
  for (std::size_t k = 0; k + 1 < q.path.size(); ++k) {
    constexpr int kSamples = 500;
    for (int i = 0; i <= kSamples; ++i) {
      const Point x = q.path[k] + (q.path[k + 1] - q.path[k]) * (double(i) / kSamples);
      EXPECT_GE(geometry::disk_clearance(r.workspace, r.walls, disks, x, radius), margin - 1e-9)
          << "segment " << k << " sample " << i;
    }
  }
  EXPECT_EQ(ctx.subqueries, 1);
  EXPECT_GT(ctx.nodes, 0);
}

TEST(MotionQuery, InvalidEndsAndDisconnectedGoalsAreValues) {
  Rooms r;
  QueryContext ctx(30, 1);
  EXPECT_EQ(plan_motion(r.world, {}, std::nullopt, 0.3, 0, {5, 1}, {9, 4}, ctx).status,
            QueryStatus::kStartInvalid);
  EXPECT_EQ(plan_motion(r.world, {}, std::nullopt, 0.3, 0, {1, 1}, {9.9, 4}, ctx).status,
            QueryStatus::kGoalInvalid);
  // The door is 1 m wide: a disk of radius 0.55 cannot pass; RRTConnect gives up at its cap.
  ctx.iterations_per_query = 3000;
  const QueryResult q = plan_motion(r.world, {}, std::nullopt, 0.55, 0, {1, 2.5}, {9, 2.5}, ctx);
  EXPECT_EQ(q.status, QueryStatus::kNoPath);
  EXPECT_TRUE(q.path.empty());
  // An object standing in the door closes it for a radius that would pass.
  const std::vector<geometry::Disk> plug = {{{5, 2.5}, 0.25}};
  EXPECT_EQ(plan_motion(r.world, plug, std::nullopt, 0.2, 0, {1, 2.5}, {9, 2.5}, ctx).status,
            QueryStatus::kNoPath);
  // ... unless it is the object being carried (skipped).
  EXPECT_EQ(plan_motion(r.world, plug, 0, 0.2, 0, {1, 2.5}, {9, 2.5}, ctx).status,
            QueryStatus::kSolved);
}

TEST(MotionQuery, SameSeedSamePathAnyOrder) {
  Rooms r;
  QueryContext a(30, 42), b(30, 42);
  const auto p1 = plan_motion(r.world, {}, std::nullopt, 0.3, 0.01, {1, 0.8}, {9, 0.8}, a);
  const auto p2 = plan_motion(r.world, {}, std::nullopt, 0.3, 0.01, {1, 0.8}, {9, 0.8}, b);
  ASSERT_EQ(p1.status, QueryStatus::kSolved);
  ASSERT_GE(p1.path.size(), 3u);  // sampled, not the straight line
  EXPECT_EQ(p1.path, p2.path);
  EXPECT_EQ(p1.nodes, p2.nodes);
  EXPECT_THROW(QueryContext(0, 1), Error);
  EXPECT_THROW(QueryContext(std::nan(""), 1), Error);
}

// The off-axis law tracks the pair centre exactly; the heading then obeys
// ψ' = (t̂ · h⊥(ψ)) / ℓ per unit of arc length. Integrated here by RK4 in small steps.
double integrate_heading(const std::vector<Point>& path, double psi, double ell) {
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Point d = path[k + 1] - path[k];
    const double len = d.norm();
    const Point t = d / len;
    auto f = [&](double p) { return (t.y() * std::cos(p) - t.x() * std::sin(p)) / ell; };
    const int n = 20000;
    const double h = len / n;
    for (int i = 0; i < n; ++i) {
      const double k1 = f(psi), k2 = f(psi + 0.5 * h * k1), k3 = f(psi + 0.5 * h * k2),
                   k4 = f(psi + h * k3);
      psi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  return psi;
}

TEST(TrackedHeading, ClosedFormMatchesIntegration) {
  Rng rng(3);
  for (int t = 0; t < 40; ++t) {
    std::vector<Point> path = {{0, 0}};
    const int n = 2 + static_cast<int>(rng.index(4));
    for (int k = 0; k < n; ++k)
      path.push_back(path.back() + Point(rng.uniform(-1, 1), rng.uniform(-1, 1)));
    const double psi0 = rng.uniform(-3, 3), ell = rng.uniform(0.1, 0.4);
    const double a = tracked_heading(path, psi0, ell), b = integrate_heading(path, psi0, ell);
    EXPECT_NEAR(wrap_angle(a - b), 0, 1e-7) << "trial " << t;
  }
  // Driving straight backwards keeps the heading (the unstable equilibrium φ = π).
  EXPECT_NEAR(tracked_heading({{0, 0}, {-2, 0}}, 0, 0.3), 0, 1e-12);
}

TEST(Problem, GoalsComeFromTheTasksReleases) {
  const auto s = scenario::load_scenario("experiments/scenarios/fig5.yaml");
  const auto p = problem_from_scenario(s);
  ASSERT_EQ(p.object_count(), 3u);
  EXPECT_EQ(p.goal_region_names, (std::vector<std::string>{"l2", "l3", "l1"}));
  // Region centroids (fig5.yaml: l2 = [5.4, 6.6] x [7.8, 9.0], ...).
  EXPECT_NEAR((*p.goals[0] - Point(6.0, 8.4)).norm(), 0, 1e-9);
  EXPECT_NEAR((*p.goals[1] - Point(2.0, 1.8)).norm(), 0, 1e-9);
  EXPECT_NEAR((*p.goals[2] - Point(10.0, 1.8)).norm(), 0, 1e-9);
  EXPECT_EQ(p.obstacles.size(), s.familiar.size() + s.unknown.size());
  EXPECT_FALSE(p.robot_goal);
  EXPECT_FALSE(p.goals_reached(p.start));
  EXPECT_TRUE(p.goals_reached(p.goal_arrangement()));
}

TEST(Problem, TasksBeyondRearrangementAreRejectedWithTheKeyNamed) {
  auto s = scenario::load_scenario("experiments/scenarios/fig5.yaml");
  auto expect_error = [&](const std::string& task, const std::string& words) {
    s.task = task;
    try {
      problem_from_scenario(s);
      ADD_FAILURE() << "accepted " << task;
    } catch (const scenario::ScenarioError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("task"), std::string::npos) << what;
      EXPECT_NE(what.find(words), std::string::npos) << what;
    }
  };
  expect_error("[]<>move(l1) && []<>move(l2)", "reachability");
  expect_error("<>release(M1,l2) && <>release(M1,l3)", "two regions");
  expect_error("<>move(l1) && <>move(l2)", "two regions");
  expect_error("<>release(M9,l2)", "M9");
  expect_error("<>(release(M1,l2) &&", "task");
  s.task = "<>(grasp(M1) && <>release(M1,l2)) && <>move(l3)";
  const auto p = problem_from_scenario(s);
  EXPECT_TRUE(p.goals[0] && !p.goals[1] && !p.goals[2]);
  EXPECT_EQ(p.robot_goal_name, "l3");
}

}  // namespace
}  // namespace rearm::baselines
