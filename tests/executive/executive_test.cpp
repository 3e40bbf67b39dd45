// The executive's contract beyond the paper's figures: bad input is rejected with its name
// before the first step; every task ends with a reason (a patrol after its action limit, the
// time budget, a gripper that does not close, an unknown obstacle over the target); the
// symbolic layer's alternatives are used after an infeasible action; gripper prerequisites
// are inserted; and a run is deterministic. Checked against the plant's ground truth.
#include "executive/executive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"
#include "executive/kinematic_plant.h"
#include "executive/task_runner.h"
#include "geometry/distance.h"
#include "ltl/parser.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using geometry::Polygon;
using test_support::rect;

std::string error_of(const TaskSpec& spec, const Pose& start) {
  try {
    KinematicPlant plant(spec.world, spec.executive.robot_radius, start);
    run_task(spec, plant);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TaskSpec open_room(const std::string& formula) {
  TaskSpec t;
  t.world.workspace = rect(0, 0, 10, 6);
  t.world.movable = {{"M1", geometry::Disk{Point(3, 3), 0.25}}};
  t.regions = {{"l1", rect(1, 1, 2, 2)}, {"l2", rect(8, 4, 9, 5)}, {"l3", rect(8, 1, 9, 2)}};
  t.formula = ltl::parse(formula);
  return t;
}

const Pose kStart{Point(5, 3), 0};

bool inside(const TaskSpec& t, const std::string& region, const Point& p) {
  for (const auto& r : t.regions) {
    if (r.id == region) return geometry::contains(r.polygon, p);
  }
  return false;
}

TEST(Executive, BadInputIsRejectedWithItsName) {
  EXPECT_NE(error_of(open_room("<>move(l9)"), kStart).find("l9"), std::string::npos);
  EXPECT_NE(error_of(open_room("<>grasp(M7)"), kStart).find("M7"), std::string::npos);
  // (A malformed formula never reaches run_task: TaskSpec carries the parsed tree.)
  TaskSpec t = open_room("<>move(l1)");
  t.regions.push_back({"l4", rect(9, 5, 11, 7)});
  EXPECT_NE(error_of(t, kStart).find("l4"), std::string::npos);
  t = open_room("<>move(l1)");
  t.executive.goal_tolerance = std::nan("");
  EXPECT_NE(error_of(t, kStart).find("goal_tolerance"), std::string::npos);
  t = open_room("<>move(l1)");
  t.sensor.range = -1;
  EXPECT_NE(error_of(t, kStart), "no error");
  // A plant with a different object list than the task's world.
  t = open_room("<>move(l1)");
  perception::World other = t.world;
  other.movable.clear();
  KinematicPlant plant(other, 0.2, kStart);
  EXPECT_THROW(run_task(t, plant), Error);
  TaskOptions o;
  o.dt = 0;
  KinematicPlant plant2(t.world, 0.2, kStart);
  EXPECT_THROW(run_task(t, plant2, o), Error);
}

TEST(Executive, PatrolEndsAfterItsActionLimit) {
  TaskSpec t = open_room("[]<>move(l1) && []<>move(l2)");
  t.executive.max_ltl_actions = 4;
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  ASSERT_EQ(r.actions.size(), 4u);
  // Each visited region alternates, and the robot was inside it when the action succeeded.
  for (std::size_t i = 0; i < r.actions.size(); ++i) {
    EXPECT_EQ(r.actions[i].outcome, ActionOutcome::kSucceeded);
    EXPECT_NE(r.actions[i].action, r.actions[(i + 1) % 4].action);
    const std::size_t step = static_cast<std::size_t>(std::lround(r.actions[i].t_end / 0.01));
    ASSERT_LT(step, r.path.size());
    const std::string region = r.actions[i].action.substr(5, 2);
    EXPECT_TRUE(inside(t, region, r.path[step].x)) << r.actions[i].action;
  }
  EXPECT_EQ(r.collisions, 0);
}

TEST(Executive, TimeBudgetEndsTheTask) {
  TaskSpec t = open_room("<>move(l1)");
  KinematicPlant plant(t.world, 0.2, kStart);
  TaskOptions o;
  o.max_time = 2;
  const TaskResult r = run_task(t, plant, o);
  EXPECT_EQ(r.status, TaskStatus::kTimeout);
  EXPECT_NE(r.reason.find("move(l1)"), std::string::npos) << r.reason;
  ASSERT_EQ(r.actions.size(), 1u);
  EXPECT_EQ(r.actions[0].outcome, ActionOutcome::kAbandoned);
  EXPECT_NEAR(r.sim_time, 2.0, 0.011);
}

// A plant whose gripper never closes.
class BrokenGripper final : public Plant {
 public:
  explicit BrokenGripper(KinematicPlant p) : p_(std::move(p)) {}
  Pose pose() const override { return p_.pose(); }
  Point object_center(std::size_t i) const override { return p_.object_center(i); }
  std::size_t object_count() const override { return p_.object_count(); }
  bool grip(std::size_t) override { return false; }
  void release() override { p_.release(); }
  std::optional<std::size_t> held() const override { return std::nullopt; }
  void step(const Twist& u, double dt) override { p_.step(u, dt); }
  double clearance() const override { return p_.clearance(); }
  int collisions() const override { return p_.collisions(); }

 private:
  KinematicPlant p_;
};

TEST(Executive, GripperFailureEndsStuck) {
  TaskSpec t = open_room("<>grasp(M1)");
  BrokenGripper plant(KinematicPlant(t.world, 0.2, kStart));
  const TaskResult r = run_task(t, plant);
  EXPECT_EQ(r.status, TaskStatus::kStuck);
  EXPECT_NE(r.reason.find("did not close on M1"), std::string::npos) << r.reason;
}

// Paper §III-A: an action the controller cannot complete is reported, and the mission
// controller's alternative runs. With the gripper broken, grasp(M1) ends stuck and the other
// disjunct, move(l2), completes the task; with no alternative the task ends stuck with every
// stuck action named.
TEST(Executive, AStuckActionIsReportedAndTheAlternativeRuns) {
  TaskSpec t = open_room("<>(grasp(M1) || move(l2))");
  BrokenGripper plant(KinematicPlant(t.world, 0.2, kStart));
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  ASSERT_EQ(r.actions.size(), 2u);
  EXPECT_EQ(r.actions[0].action, "grasp(M1)");
  EXPECT_EQ(r.actions[0].outcome, ActionOutcome::kStuck);
  EXPECT_EQ(r.actions[1].action, "move(l2)");
  EXPECT_EQ(r.actions[1].outcome, ActionOutcome::kSucceeded);
  EXPECT_TRUE(inside(t, "l2", plant.pose().x));

  TaskSpec both = open_room("<>grasp(M1) && <>grasp(M2)");
  both.world.movable.push_back({"M2", geometry::Disk{Point(3, 1.5), 0.25}});
  BrokenGripper plant2(KinematicPlant(both.world, 0.2, kStart));
  const TaskResult r2 = run_task(both, plant2);
  EXPECT_EQ(r2.status, TaskStatus::kStuck);
  EXPECT_NE(r2.reason.find("did not close on M"), std::string::npos) << r2.reason;
  EXPECT_NE(r2.reason.find("no alternative action"), std::string::npos) << r2.reason;
}

// Distance from p to the polygon's boundary, by its edges (the test's own geometry).
double edge_distance(const Polygon& poly, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.vertices.size(); i < n; ++i) {
    const Point& a = poly.vertices[i];
    const Point& b = poly.vertices[(i + 1) % n];
    const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * (b - a) - p).norm());
  }
  return best;
}

// A U-shaped pocket opening upward with lips that narrow its mouth to 1 m; M1 sits in the
// mouth, the robot comes from above. Docked, the pair's centre (ρ ahead of the robot) is
// 0.51 m from the lips' corners: free for the pair's radius r + margin + ρ + pair margin =
// 0.465 m, but in the mouth, where the law of [7] drives the pair on into the pocket.
TaskSpec pocket_mouth(const std::string& formula) {
  TaskSpec t;
  t.world.workspace = rect(0, 0, 10, 8);
  t.world.familiar = {
      {"P1", Polygon{{Point(3, 1.8), Point(5, 1.8), Point(5, 4), Point(4.5, 4), Point(4.5, 3.8),
                      Point(4.8, 3.8), Point(4.8, 2), Point(3.2, 2), Point(3.2, 3.8),
                      Point(3.5, 3.8), Point(3.5, 4), Point(3, 4)}}}};
  t.world.movable = {{"M1", geometry::Disk{Point(4, 3.9), 0.25}}};
  t.regions = {{"l1", rect(7, 5.5, 8, 6.5)}};
  t.formula = ltl::parse(formula);
  return t;
}

const Pose kAbovePocket{Point(4, 6.5), -std::numbers::pi / 2};

// Robust variant: after the gripper closes, the robot reverses straight along its docking line
// until the pair's centre is withdraw_clearance clear of its dilated surroundings (checked here
// against the pocket's edges), then carries M1 out to l1. Off, the grasp ends where it docked.
TEST(Executive, AGraspInAPocketsMouthWithdrawsTheObjectStraightOut) {
  TaskSpec t = pocket_mouth("<>grasp(M1)");
  const RobustParams& rp = t.executive.robust;
  const double pair_radius =
      t.executive.robot_radius + rp.contact_margin + 0.25 + t.executive.grasp.pair_margin;
  const Polygon& pocket = t.world.familiar[0].polygon;
  auto pair_center = [](const Pose& q) {
    return Point(q.x + 0.25 * Point(std::cos(q.psi), std::sin(q.psi)));
  };

  KinematicPlant plant(t.world, 0.2, kAbovePocket);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  EXPECT_EQ(r.recoveries.withdrawals, 1);
  EXPECT_NE(r.actions[0].reason.find("withdrew"), std::string::npos) << r.actions[0].reason;
  const Pose end = plant.pose();
  EXPECT_GE(edge_distance(pocket, pair_center(end)), pair_radius + rp.withdraw_clearance - 1e-6);
  // Straight back, facing the object: the heading is unchanged and M1 is still ahead.
  EXPECT_NEAR(std::remainder(end.psi + std::numbers::pi / 2, 2 * std::numbers::pi), 0, 0.05);
  EXPECT_NEAR((plant.object_center(0) - end.x).norm(), 0.45, 0.01);

  TaskSpec off = t;
  off.executive.robust.withdraw = false;
  KinematicPlant plant_off(off.world, 0.2, kAbovePocket);
  const TaskResult r_off = run_task(off, plant_off);
  ASSERT_EQ(r_off.status, TaskStatus::kCompleted) << r_off.reason;
  EXPECT_EQ(r_off.recoveries.withdrawals, 0);
  EXPECT_LT(edge_distance(pocket, pair_center(plant_off.pose())),
            pair_radius + rp.withdraw_clearance);

  TaskSpec carry = pocket_mouth("<>(grasp(M1) && <>release(M1,l1))");
  KinematicPlant plant_carry(carry.world, 0.2, kAbovePocket);
  const TaskResult rc = run_task(carry, plant_carry);
  ASSERT_EQ(rc.status, TaskStatus::kCompleted) << rc.reason;
  EXPECT_TRUE(inside(carry, "l1", plant_carry.object_center(0)));
  EXPECT_EQ(rc.collisions, 0);

  // The sealed case: l2 lies inside the pocket behind M1, so Fix mode grasps M1 in the mouth
  // (withdrawing it) and drops it clear before M2 goes in.
  TaskSpec seal = pocket_mouth("<>(grasp(M2) && <>release(M2,l2))");
  seal.world.movable.push_back({"M2", geometry::Disk{Point(7, 3), 0.25}});
  seal.regions.push_back({"l2", rect(3.5, 2.3, 4.5, 3.3)});
  KinematicPlant plant_seal(seal.world, 0.2, kAbovePocket);
  const TaskResult rs = run_task(seal, plant_seal);
  ASSERT_EQ(rs.status, TaskStatus::kCompleted) << rs.reason;
  EXPECT_TRUE(inside(seal, "l2", plant_seal.object_center(1)));
  EXPECT_EQ(rs.recoveries.withdrawals, 1);
  EXPECT_EQ(rs.collisions, 0);
}

TEST(Executive, ReleaseWithoutTheObjectGraspsItFirst) {
  TaskSpec t = open_room("<>release(M1,l2)");
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  ASSERT_EQ(r.actions.size(), 2u);
  EXPECT_EQ(r.actions[0].action, "grasp(M1)");
  EXPECT_TRUE(r.actions[0].fix);
  EXPECT_EQ(r.actions[1].action, "release(M1,l2)");
  EXPECT_FALSE(r.actions[1].fix);
  EXPECT_TRUE(inside(t, "l2", plant.object_center(0)));
  EXPECT_EQ(r.collisions, 0);
  EXPECT_EQ(r.fix_mode_entries, 0);  // a prerequisite, not a blocked target
}

TEST(Executive, InfeasibleReleaseFallsBackOnTheFormulasAlternative) {
  // l1 is walled in by a familiar obstacle; the formula also allows l3.
  TaskSpec t = open_room("<>(grasp(M1) && <>(release(M1,l2) || release(M1,l3)))");
  // A U-shaped wall around l2 closed by a lid.
  t.world.familiar = {
      {"P1", Polygon{{Point(7.5, 3.5), Point(9.5, 3.5), Point(9.5, 5.5), Point(9.3, 5.5),
                      Point(9.3, 3.7), Point(7.7, 3.7), Point(7.7, 5.5), Point(7.5, 5.5)}}},
      {"P2", rect(7.5, 5.5, 9.5, 5.7)}};
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  bool l2_infeasible = false;
  for (const ActionRecord& a : r.actions) {
    if (a.action == "release(M1,l2)") {
      EXPECT_EQ(a.outcome, ActionOutcome::kInfeasible);
      l2_infeasible = true;
    }
  }
  EXPECT_TRUE(l2_infeasible);
  EXPECT_EQ(r.actions.back().action, "release(M1,l3)");
  EXPECT_TRUE(inside(t, "l3", plant.object_center(0)));
  EXPECT_EQ(r.collisions, 0);
}

TEST(Executive, TargetUnderAnUnknownObstacleIsInfeasible) {
  // An unknown convex obstacle covers l2's centre: the topology check (familiar obstacles and
  // objects) passes it, the reactive mapped space does not; the action is infeasible and so is
  // the mission.
  TaskSpec t = open_room("<>move(l2)");
  t.world.unknown = {{"C1", rect(8.2, 4.2, 8.8, 4.8)}};
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  EXPECT_EQ(r.status, TaskStatus::kInfeasible) << r.reason;
  ASSERT_FALSE(r.actions.empty());
  EXPECT_NE(r.actions[0].reason.find("unknown obstacles"), std::string::npos)
      << r.actions[0].reason;
  EXPECT_EQ(r.collisions, 0);
}

// l4 is 3 m by 2.5 m; an unknown obstacle covers its centroid (the paper's RELEASE target,
// §IV), which the topology check (familiar obstacles and objects, Appendix III) passes.
TaskSpec release_beside_unknown(const Polygon& unknown) {
  TaskSpec t = open_room("<>(grasp(M1) && <>release(M1,l4))");
  t.regions.push_back({"l4", rect(6.5, 3, 9.5, 5.5)});
  t.world.unknown = {{"C1", unknown}};
  return t;
}

const ActionRecord* find_action(const TaskResult& r, const std::string& name) {
  for (const ActionRecord& a : r.actions) {
    if (a.action == name) return &a;
  }
  return nullptr;
}

// RELEASE(M1, l4) ended infeasible, naming the unknown obstacles.
void expect_release_infeasible(const TaskResult& r) {
  const ActionRecord* release = find_action(r, "release(M1,l4)");
  ASSERT_NE(release, nullptr);
  EXPECT_EQ(release->outcome, ActionOutcome::kInfeasible);
  EXPECT_NE(release->reason.find("unknown obstacles"), std::string::npos) << release->reason;
}

TEST(Executive, AReleaseWhoseCentroidAnUnknownObstacleTakesSetsTheObjectDownBesideIt) {
  // RELEASE(M1, l4) holds wherever in l4 the object lies (§II-B): the robust variant plans again
  // with the visible fragment as a fixed obstacle and sets M1 down in l4 beside it.
  const Polygon c1 = rect(7.6, 3.9, 8.4, 4.6);
  const TaskSpec t = release_beside_unknown(c1);
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  const Point m = plant.object_center(0);
  EXPECT_TRUE(inside(t, "l4", m)) << m.transpose();
  // Ground truth: the object's disk clear of the unknown obstacle it was set down beside.
  EXPECT_GE(geometry::signed_distance(c1, m), 0.25) << m.transpose();
  EXPECT_GE(r.recoveries.release_points, 1);
  EXPECT_EQ(r.collisions, 0);

  // Without the fragments switch (as in the paper) the same RELEASE is infeasible.
  TaskSpec off = t;
  off.executive.robust.fragments = false;
  KinematicPlant plant_off(off.world, 0.2, kStart);
  const TaskResult r_off = run_task(off, plant_off);
  EXPECT_EQ(r_off.status, TaskStatus::kInfeasible) << r_off.reason;
  expect_release_infeasible(r_off);
}

TEST(Executive, AReleaseIntoARegionAnUnknownObstacleCoversIsInfeasible) {
  // The obstacle covers all of l4 but a strip narrower than the object: no point of l4 is left,
  // and only then is the RELEASE infeasible.
  const TaskSpec t = release_beside_unknown(rect(6.4, 2.9, 9.6, 5.3));
  KinematicPlant plant(t.world, 0.2, kStart);
  const TaskResult r = run_task(t, plant);
  EXPECT_EQ(r.status, TaskStatus::kInfeasible) << r.reason;
  expect_release_infeasible(r);
  EXPECT_EQ(r.collisions, 0);
}

// A wall across the room with a 2.8 m door that three objects, 0.8 m apart, close together
// (0.3 m between them, 0.35 m beside them: the robot is 0.4 m wide; their dilations overlap,
// one cluster: Appendix III's B_M). Each can be gripped where it lies, and any one of them moved
// leaves a gap of at least 0.95 m: by construction, one object is enough.
TaskSpec door_closed_by_three() {
  TaskSpec t;
  t.world.workspace = rect(0, 0, 10, 6);
  t.world.familiar = {{"W1", rect(4.9, 0.05, 5.1, 1.6)}, {"W2", rect(4.9, 4.4, 5.1, 5.95)}};
  t.world.movable = {{"M1", geometry::Disk{Point(5, 2.2), 0.25}},
                     {"M2", geometry::Disk{Point(5, 3.0), 0.25}},
                     {"M3", geometry::Disk{Point(5, 3.8), 0.25}}};
  t.regions = {{"l1", rect(7.5, 2.5, 8.5, 3.5)}};
  t.formula = ltl::parse("<>move(l1)");
  return t;
}

int fix_mode_grasps(const TaskResult& r) {
  return static_cast<int>(std::count_if(r.actions.begin(), r.actions.end(), [](const auto& a) {
    return a.fix && a.action.rfind("grasp(", 0) == 0 && a.outcome == ActionOutcome::kSucceeded;
  }));
}

TEST(Executive, FixModeMovesAMinimalSubsetOfABlockingCluster) {
  const Pose start{Point(2, 3), 0};
  TaskSpec t = door_closed_by_three();
  KinematicPlant plant(t.world, 0.2, start);
  const TaskResult r = run_task(t, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  EXPECT_TRUE(inside(t, "l1", plant.pose().x));
  EXPECT_EQ(fix_mode_grasps(r), 1);
  EXPECT_EQ(r.collisions, 0);

  // Without object_blockers, B_M is the whole cluster, as in the paper.
  t.executive.robust.object_blockers = false;
  KinematicPlant plant_all(t.world, 0.2, start);
  const TaskResult all = run_task(t, plant_all);
  ASSERT_EQ(all.status, TaskStatus::kCompleted) << all.reason;
  EXPECT_EQ(fix_mode_grasps(all), 3);
  EXPECT_EQ(all.collisions, 0);
}

TEST(Executive, RunsAreDeterministic) {
  const TaskSpec t = test_support::fig3_task();
  KinematicPlant a(t.world, 0.2, test_support::fig3_start());
  KinematicPlant b(t.world, 0.2, test_support::fig3_start());
  const TaskResult ra = run_task(t, a);
  const TaskResult rb = run_task(t, b);
  ASSERT_EQ(ra.path.size(), rb.path.size());
  for (std::size_t i = 0; i < ra.path.size(); ++i) {
    ASSERT_EQ(ra.path[i].x, rb.path[i].x) << i;
    ASSERT_EQ(ra.path[i].psi, rb.path[i].psi) << i;
  }
  ASSERT_EQ(ra.actions.size(), rb.actions.size());
  for (std::size_t i = 0; i < ra.actions.size(); ++i) {
    EXPECT_EQ(ra.actions[i].action, rb.actions[i].action);
    EXPECT_EQ(ra.actions[i].t_end, rb.actions[i].t_end);
  }
}

}  // namespace
}  // namespace rearm::executive
