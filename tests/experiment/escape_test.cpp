// A robot pressed into the apex of a familiar V (a right angle), its centre 5 mm closer to both
// walls than the planning radius r + contact margin, heading into the upper wall, with a
// released object across the V's opening. The back-up along the heading runs into the walls
// both ways; the robust variant's escape (RobustParams::escape) turns in place and leaves along
// the clearest straight line, after which the action plans again and the robot leaves the V
// past the object. Truth: the plants' exact contact tests and clearances, and the robot's
// final position located exactly in the goal region.
#include <gtest/gtest.h>

#include "experiment/run_scenario.h"
#include "geometry/polygon.h"
#include "scenario/scenario.h"
#include "support/scenario_runs.h"
#include "support/task_scenes.h"

namespace rearm::experiment {
namespace {

using geometry::Point;
using geometry::Polygon;
using test_support::rect;

// The V: two 0.3 m thick arms at right angles (inner apex at (4.126, 6.924)), each with a
// short lip at its end, opening toward +x; the object M1 lies 0.25 m from the robot's
// dilation, below the bisector.
scenario::Scenario apex_scene(bool escape) {
  scenario::Scenario s;
  s.name = escape ? "apex_escape" : "apex_no_escape";
  s.workspace = rect(0, 0, 10, 10);
  s.robot.start = Point(4.405, 6.842);
  s.robot.heading = 1.88;
  s.regions.push_back({"l2", rect(5.43, 0.85, 6.43, 1.85)});
  s.objects.push_back({"M1", geometry::Disk{Point(4.9366, 6.5896), 0.25}});
  s.familiar.push_back(
      {"P1",
       Polygon{{Point(3.855993, 7.007231), Point(4.705142, 5.404008), Point(6.308365, 6.253157),
                Point(6.141220, 6.568733), Point(5.964480, 6.475123), Point(6.038014, 6.336286),
                Point(4.788271, 5.674359), Point(4.126344, 6.924102), Point(5.376087, 7.586029),
                Point(5.449621, 7.447193), Point(5.626361, 7.540804), Point(5.459216, 7.856380)}}});
  s.task = "<>move(l2)";
  s.controller.switches.set("escape", escape);
  s.simulation.time_budget = 400;
  return s;
}

class Escape : public ::testing::TestWithParam<PlantKind> {};

TEST_P(Escape, TheRobotLeavesTheApexAlongTheClearestLine) {
  const RunRecord r = test_support::expect_reaches_first_region(apex_scene(true), GetParam());
  EXPECT_GE(r.result.recoveries.back_outs, 1);
}

TEST_P(Escape, WithoutItTheBackUpsAlongTheHeadingDoNotLeave) {
  RunOptions o;
  o.plant = GetParam();
  const RunRecord r = run_scenario(apex_scene(false), o);
  EXPECT_EQ(r.result.status, executive::TaskStatus::kStuck) << r.result.reason;
  EXPECT_NE(r.result.reason.find("back-ups"), std::string::npos) << r.result.reason;
  EXPECT_EQ(r.result.collisions, 0);
}

INSTANTIATE_TEST_SUITE_P(Plants, Escape,
                         ::testing::Values(PlantKind::kKinematic, PlantKind::kBox2d),
                         test_support::plant_name);

}  // namespace
}  // namespace rearm::experiment
