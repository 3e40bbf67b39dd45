// The saddle of [7]'s law behind a round obstacle: the robot starts on the line through the
// obstacle's centre and the goal, heading at the goal. The scene is mirror-symmetric about that
// line, so the paper's law keeps y on it (the nearest obstacle point, the projection of the goal
// and the heading all stay on the line, exactly in floating point on the kinematic plant) and
// comes to rest at the saddle in front of the obstacle. The robust variant's progress monitor
// finds the rest point and its guide (executive/guide_path.h) leads around. Truth: the
// robot's final position located exactly in the goal region, and the plant's exact clearance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "experiment/run_scenario.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "scenario/scenario.h"
#include "support/scenario_runs.h"
#include "support/task_scenes.h"

namespace rearm::experiment {
namespace {

using geometry::Point;
using geometry::Polygon;

using test_support::rect;

scenario::Scenario saddle_scene(const char* variant) {
  scenario::Scenario s;
  s.name = std::string("saddle_") + variant;
  s.workspace = rect(0, 0, 12, 10);
  s.robot.start = Point(2, 5);
  s.robot.heading = 0;
  s.regions.push_back({"l1", rect(9.5, 4.5, 10.5, 5.5)});
  // A 32-gon of radius 1.2 with a vertex on the line y = 5 on either side: symmetric about it.
  s.unknown.push_back({"C1", geometry::regular_polygon({Point(6, 5), 1.2}, 32, false)});
  s.task = "<>move(l1)";
  scenario::set_variant(s.controller, variant);
  s.simulation.time_budget = 400;
  return s;
}

TEST(Saddle, ThePaperVariantRestsAtTheSaddle) {
  RunOptions o;
  o.plant = PlantKind::kKinematic;
  const RunRecord r = run_scenario(saddle_scene("paper"), o);
  EXPECT_EQ(r.result.status, executive::TaskStatus::kStuck) << r.result.reason;
  EXPECT_EQ(r.result.collisions, 0);
}

TEST(Saddle, TheRobustVariantLeavesItAndReachesTheGoal) {
  const RunRecord r =
      test_support::expect_reaches_first_region(saddle_scene("robust"), PlantKind::kKinematic);
  EXPECT_GE(r.result.recoveries.guides, 1);
}

}  // namespace
}  // namespace rearm::experiment
