// A wall from the floor leaves a 3 m gap below the ceiling; an unknown square fills its upper
// part, and a movable object M2 sits in the 1.1 m that remains, with 0.3 m on either side (a
// robot of radius 0.2 needs 0.4). The topology check, which models the familiar obstacles and
// the objects only (paper Appendix III), finds the goal beyond the wall reachable through the
// gap; the reactive controller, which sees the square, finds it cut off. The robust variant's
// RobustParams::fragments runs the check again with the square as a fixed obstacle, which names
// M2: Fix mode moves it and the robot passes. Without it the MOVE ends infeasible. Truth: the
// plants' exact contact tests, and the robot's final position located exactly in the region.
#include <gtest/gtest.h>

#include "experiment/run_scenario.h"
#include "geometry/polygon.h"
#include "scenario/scenario.h"
#include "support/scenario_runs.h"
#include "support/task_scenes.h"

namespace rearm::experiment {
namespace {

using geometry::Point;
using test_support::rect;

scenario::Scenario gap_scene(bool fragments) {
  scenario::Scenario s;
  s.name = fragments ? "gap_fragments" : "gap_no_fragments";
  s.workspace = rect(0, 0, 10, 10);
  s.robot.start = Point(2, 7.5);
  s.robot.heading = 0;
  s.regions.push_back({"l2", rect(7.5, 7, 8.5, 8)});
  s.objects.push_back({"M2", geometry::Disk{Point(5.15, 7.55), 0.25}});
  s.familiar.push_back({"W", rect(5, 0.01, 5.3, 7)});
  s.unknown.push_back({"U", rect(4.6, 8.1, 5.7, 9.99)});
  s.task = "<>move(l2)";
  s.controller.switches.set("fragments", fragments);
  s.simulation.time_budget = 600;
  return s;
}

class Fragments : public ::testing::TestWithParam<PlantKind> {};

TEST_P(Fragments, FixModeMovesTheObjectThatClosesTheGapWithTheUnknownObstacle) {
  const RunRecord r = test_support::expect_reaches_first_region(gap_scene(true), GetParam());
  EXPECT_GE(r.result.recoveries.fragment_fixes, 1);
  EXPECT_GE(r.result.fix_mode_entries, 1);
}

TEST_P(Fragments, WithoutItTheMoveIsInfeasible) {
  RunOptions o;
  o.plant = GetParam();
  const RunRecord r = run_scenario(gap_scene(false), o);
  EXPECT_EQ(r.result.status, executive::TaskStatus::kInfeasible) << r.result.reason;
  EXPECT_EQ(r.result.recoveries.fragment_fixes, 0);
  EXPECT_EQ(r.result.collisions, 0);
}

INSTANTIATE_TEST_SUITE_P(Plants, Fragments,
                         ::testing::Values(PlantKind::kKinematic, PlantKind::kBox2d),
                         test_support::plant_name);

}  // namespace
}  // namespace rearm::experiment
