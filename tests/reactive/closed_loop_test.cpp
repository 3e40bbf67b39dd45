// Closed loop of the reactive controller in static scenes of [7]'s kind
// (docs/reactive.md §5): familiar non-convex obstacles localized whole within the sensor range,
// unknown convex ones seen as fragments, the map updated between steps and the controller
// rebuilt on change. Truth: clearance against the ground-truth geometry, the goal distance.
#include "reactive/closed_loop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/rng.h"
#include "geometry/distance.h"
#include "perception/semantic_map.h"
#include "perception/sensor.h"
#include "perception/world.h"
#include "support/reactive_scenes.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

using test_support::ReactiveScene;

constexpr double kSensingRange = 3.0;     // m: limited, smaller than the obstacles' spacing
constexpr double kCarriedRadius = 0.25;   // ρ_i of the carried object (m)
constexpr double kStartClearance = 0.05;  // m between a start and every obstacle
constexpr double kGoalTolerance = 0.05;   // m
// The map counts as changed when a fragment vertex moved by more than this (m): the parts of an
// unknown obstacle that come into view lie near the sensing range R = 3 m, so a map that lags
// by a few centimetres of travel misses nothing within reach, and the controller is rebuilt
// every ~5 cm instead of every step.
constexpr double kFragmentTolerance = 0.05;

// Scenes of [7]'s kind: >= 3 familiar non-convex obstacles, >= 2 unknown convex ones, one
// movable object, one familiar wall attached to the boundary (scene 0) or an L-shaped room.
ReactiveScene scene(int i) {
  Rng rng = Rng::derive(4242, static_cast<std::uint64_t>(i));
  test_support::SceneOptions o;
  o.familiar = 4;
  o.unknown = 2;
  o.round_unknown = true;  // [7]'s unknown obstacles satisfy the curvature condition
  o.movable = 1;
  o.margin = 0.8;
  o.sensor_range = kSensingRange;
  o.goal_clearance = 0.6;  // room for the robot–object pair (r + ρ_i) at the goal
  o.boundary_touching = i == 0 ? 1 : 0;
  o.workspace_shape =
      i == 0 ? test_support::WorkspaceShape::kSquare : test_support::WorkspaceShape::kLRoom;
  return test_support::random_scene(rng, o);
}

perception::World world_of(const ReactiveScene& s) {
  perception::World w;
  w.workspace = s.workspace;
  for (std::size_t k = 0; k < s.familiar.size(); ++k) {
    w.familiar.push_back({"P" + std::to_string(k), s.familiar[k]});
  }
  for (std::size_t k = 0; k < s.unknown.size(); ++k) {
    w.unknown.push_back({"C" + std::to_string(k), s.unknown[k]});
  }
  for (std::size_t k = 0; k < s.movable.size(); ++k) {
    w.movable.push_back({"M" + std::to_string(k), s.movable[k]});
  }
  return perception::validated(w);
}

// Clearance of a disk (centre x, radius r) from the true obstacles and the workspace boundary.
double disk_clearance(const ReactiveScene& s, const Point& x, double r) {
  double c = geometry::contains(s.workspace, x)
                 ? geometry::nearest_on_boundary(s.workspace, x).distance - r
                 : -1;
  for (const Polygon& p : s.familiar) c = std::min(c, geometry::distance(p, x) - r);
  for (const Polygon& p : s.unknown) c = std::min(c, geometry::distance(p, x) - r);
  for (const Disk& d : s.movable) c = std::min(c, (x - d.center).norm() - d.radius - r);
  return c;
}

struct Tally {
  int runs = 0;
  int reached = 0;
  double min_clearance = std::numeric_limits<double>::infinity();
  double max_time = 0;
  long steps = 0;
  long rebuilds = 0;
};

void run_starts(const ReactiveScene& s, RobotModel model, double carried, Tally* t) {
  const perception::World world = world_of(s);
  const double r = s.robot_radius;
  NavParams nav;
  nav.sensor_range = kSensingRange;
  Rng rng = Rng::derive(77, static_cast<std::uint64_t>(model) * 10 + (carried > 0));
  const int starts = static_cast<int>(test_support::scaled(200, 4));
  for (int k = 0; k < starts; ++k) {
    // A start whose robot (and carried object) clears every true obstacle.
    Pose start;
    auto clearance = [&](const Pose& p) {
      double c = disk_clearance(s, p.x, r);
      if (carried > 0) {
        const Point object = p.x + (r + carried) * Point(std::cos(p.psi), std::sin(p.psi));
        c = std::min(c, disk_clearance(s, object, carried));
      }
      return c;
    };
    // The controlled disk (the robot, or the pair's circumscribed disk of radius r + ρ_i) must
    // clear every obstacle at the start.
    auto start_clearance = [&](const Pose& p) {
      return carried > 0 ? disk_clearance(s, pair_center(p.x, p.psi, carried), r + carried)
                         : disk_clearance(s, p.x, r);
    };
    do {
      start = Pose{Point(rng.uniform(0, 20), rng.uniform(0, 20)), rng.uniform(-M_PI, M_PI)};
    } while (start_clearance(start) < kStartClearance);
    perception::ChangeTolerances tol;
    tol.fragment = kFragmentTolerance;
    perception::SemanticMap map(world, perception::Sensor({kSensingRange}), tol);
    bool first = true;
    auto sense = [&](const Pose& p) -> std::optional<SemanticInput> {
      const bool changed = map.update(p.x);
      if (!changed && !first) return std::nullopt;
      first = false;
      return SemanticInput{map.workspace(), map.familiar(), map.unknown(), map.movable()};
    };
    ReactiveController controller(DiffeoParams{}, nav);
    ClosedLoopOptions o;
    o.model = model;
    o.radius = r;
    o.carried_radius = carried;
    o.goal_tolerance = kGoalTolerance;
    o.max_time = 600;
    o.record_path = false;
    const ClosedLoopResult res = run_closed_loop(controller, start, s.goal, sense, clearance, o);
    ++t->runs;
    t->steps += res.steps;
    t->rebuilds += res.rebuilds;
    t->min_clearance = std::min(t->min_clearance, res.min_clearance);
    t->max_time = std::max(t->max_time, res.time);
    if (res.status == ClosedLoopResult::Status::kReached) {
      ++t->reached;
    } else {
      ADD_FAILURE() << "start (" << start.x.transpose() << ", " << start.psi << ") status "
                    << static_cast<int>(res.status) << " " << res.message << " after " << res.time
                    << " s";
    }
    EXPECT_GT(res.min_clearance, 0) << "start " << start.x.transpose();
    EXPECT_LE(res.max_v, nav.v_max * (1 + 1e-12));
    EXPECT_LE(res.max_omega, nav.omega_max * (1 + 1e-12));
  }
}

void report(const char* what, const Tally& t) {
  std::printf(
      "%s: %d/%d reached, min clearance %.4f m, longest %.1f s, %.1f steps and %.1f "
      "rebuilds per run\n",
      what, t.reached, t.runs, t.min_clearance, t.max_time, static_cast<double>(t.steps) / t.runs,
      static_cast<double>(t.rebuilds) / t.runs);
}

class ClosedLoop : public ::testing::TestWithParam<int> {};

TEST_P(ClosedLoop, FullyActuatedReachesTheGoalWithoutCollision) {
  Tally t;
  run_starts(scene(GetParam()), RobotModel::kHolonomic, 0, &t);
  report("fully actuated", t);
  EXPECT_EQ(t.reached, t.runs);
}

TEST_P(ClosedLoop, DifferentialDriveReachesTheGoalWithoutCollision) {
  Tally t;
  run_starts(scene(GetParam()), RobotModel::kUnicycle, 0, &t);
  report("differential drive", t);
  EXPECT_EQ(t.reached, t.runs);
}

TEST_P(ClosedLoop, CarryingAnObjectReachesTheGoalWithoutCollision) {
  Tally t;
  run_starts(scene(GetParam()), RobotModel::kUnicycle, kCarriedRadius, &t);
  report("carrying", t);
  EXPECT_EQ(t.reached, t.runs);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ClosedLoop, ::testing::Values(0, 1));

}  // namespace
}  // namespace rearm::reactive
