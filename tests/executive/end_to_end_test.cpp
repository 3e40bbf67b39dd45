// Kinematic end-to-end tasks: whole LTL tasks run through the mission
// controller, the interface layer with its Fix mode, the topology check and the reactive
// controller on the kinematic plant (no Box2D). The checks are against the ground truth the
// plant keeps, not against the executive's own view: where the robot and the objects end up
// (exact point location in the regions), and the clearance and collision count of every step.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "executive/kinematic_plant.h"
#include "executive/task_runner.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using test_support::fig3_start;
using test_support::fig3_task;
using test_support::fig4_start;
using test_support::fig4_task;
using test_support::swap_start;
using test_support::swap_task;
using test_support::walled_in_start;
using test_support::walled_in_task;

std::vector<std::string> names(const TaskResult& r, bool with_fix_mark) {
  std::vector<std::string> out;
  for (const ActionRecord& a : r.actions) {
    if (a.outcome != ActionOutcome::kSucceeded) continue;
    out.push_back(with_fix_mark && a.fix ? a.action + "*" : a.action);
  }
  return out;
}

std::string describe(const TaskResult& r) {
  std::string s = std::string(to_string(r.status)) + " (" + r.reason + ") after " +
                  std::to_string(r.sim_time) + " s, " + std::to_string(r.collisions) +
                  " collisions, min clearance " + std::to_string(r.min_clearance) + " m, " +
                  std::to_string(r.rebuilds) + " rebuilds, " + std::to_string(r.topology_checks) +
                  " topology checks, " + std::to_string(r.wall_time) + " s wall (" +
                  std::to_string(r.controller_time) + " s in the executive)\n";
  for (const ActionRecord& a : r.actions) {
    s += "  " + a.action + (a.fix ? " [fix]" : "") + " " + to_string(a.outcome) + " at " +
         std::to_string(a.t_end) + " s: " + a.reason + "\n";
  }
  return s;
}

const geometry::Polygon& region(const TaskSpec& t, const std::string& id) {
  for (const auto& r : t.regions) {
    if (r.id == id) return r.polygon;
  }
  throw std::runtime_error("no region " + id);
}

// One task on the kinematic plant; the log is printed for the record.
struct TaskRun {
  TaskRun(TaskSpec s, const Pose& start)
      : spec(std::move(s)), plant(spec.world, spec.executive.robot_radius, start) {
    r = run_task(spec, plant);
    std::cout << describe(r);
  }
  TaskSpec spec;
  KinematicPlant plant;
  TaskResult r;
};

// Completed, without a collision or a negative ground-truth clearance on any step.
void expect_completed_safely(const TaskResult& r) {
  EXPECT_EQ(r.status, TaskStatus::kCompleted) << describe(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GE(r.min_clearance, 0);
}

TEST(EndToEnd, Fig3MoveThroughFixMode) {
  TaskRun run(fig3_task(), fig3_start());
  const TaskResult& r = run.r;
  const TaskSpec& spec = run.spec;
  const KinematicPlant& plant = run.plant;
  expect_completed_safely(r);
  EXPECT_GE(r.fix_mode_entries, 1);
  const std::vector<std::string> expected = {"grasp(M1)*", "disassemble(M1)*", "move(l1)"};
  EXPECT_EQ(names(r, true), expected) << describe(r);
  EXPECT_TRUE(geometry::contains(region(spec, "l1"), plant.pose().x));
  // The object left the passage between the two rectangles (x in [4.7, 5.3]).
  const Point m = plant.object_center(0);
  EXPECT_TRUE(m.x() < 4.7 - 0.25 || m.x() > 5.3 + 0.25) << m.transpose();
}

TEST(EndToEnd, Fig4Task) {
  TaskRun run(fig4_task(), fig4_start());
  const TaskResult& r = run.r;
  expect_completed_safely(r);
  EXPECT_GE(r.fix_mode_entries, 1);
  // The formula's order, with the Fix mode before move(l1).
  std::vector<std::string> ltl;
  for (const std::string& a : names(r, false)) {
    if (a.rfind("disassemble", 0) == 0) continue;
    ltl.push_back(a);
  }
  const std::vector<std::string> visible = {"grasp(M1)", "move(l1)", "move(l2)", "grasp(M1)",
                                            "release(M1,l3)"};
  EXPECT_EQ(ltl, visible) << describe(r);
  EXPECT_TRUE(geometry::contains(region(run.spec, "l3"), run.plant.object_center(0)));
}

TEST(EndToEnd, WalledInRegionIsInfeasible) {
  TaskRun run(walled_in_task(), walled_in_start());
  const TaskResult& r = run.r;
  ASSERT_EQ(r.status, TaskStatus::kInfeasible) << describe(r);
  EXPECT_NE(r.reason.find("move(l1)"), std::string::npos) << r.reason;
  EXPECT_EQ(r.collisions, 0);
  ASSERT_FALSE(r.actions.empty());
  EXPECT_EQ(r.actions.front().outcome, ActionOutcome::kInfeasible);
  EXPECT_NE(r.actions.front().reason.find("fixed obstacles"), std::string::npos);
}

TEST(EndToEnd, SwapDisassemblesTheCarriedObjectFirst) {
  TaskRun run(swap_task(), swap_start());
  const TaskResult& r = run.r;
  expect_completed_safely(r);
  // The release target l2 is occupied by M2: M1 (carried) is disassembled first, M2 moved away,
  // M1 grasped again, then the formula goes on.
  const std::vector<std::string> expected = {
      "grasp(M1)",  "disassemble(M1)*", "grasp(M2)*", "disassemble(M2)*",
      "grasp(M1)*", "release(M1,l2)",   "grasp(M2)",  "release(M2,l1)"};
  EXPECT_EQ(names(r, true), expected) << describe(r);
  EXPECT_TRUE(geometry::contains(region(run.spec, "l2"), run.plant.object_center(0)));
  EXPECT_TRUE(geometry::contains(region(run.spec, "l1"), run.plant.object_center(1)));
}

}  // namespace
}  // namespace rearm::executive
