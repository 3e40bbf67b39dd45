// The Box2D plan executor against independent truth: hand-written plans whose geometry is worked
// out by hand below (straight and L-shaped transits and transfers in a 6 × 4 m room, clearances
// checked on paper), executed in Box2D: completion without contact, the object's final centre
// against the plan's target and the goal region, path lengths against the polylines' lengths,
// the pair centre against the transfer polyline, and the failure modes (wrong dock heading,
// time budget, a plan that does not start where the robot is), interruption and resumption with
// held_at_start, and bit-identical repeated runs.
#include "baselines/executor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "baselines/validator.h"
#include "geometry/distance.h"
#include "scenario/scenario_io.h"
#include "sim/sim_config.h"

namespace rearm::baselines {
namespace {

using geometry::Point;
using geometry::Polygon;

constexpr double kPi = std::numbers::pi;
// The object lands within 1 cm of its target (docs: the pair's heading converges along the
// approach; in free space the placement is exact to well below a millimetre).
constexpr double kPlacementTol = 0.01;
// Path lengths within 1 % of the hand-computed polyline lengths.
constexpr double kLengthRelTol = 0.01;
// The pair centre stays within 1 mm of the transfer polyline (a few µm expected).
constexpr double kTrackTol = 1e-3;

// The hand geometry: r = 0.2, ρ = 0.1, standoff 0.03, grip_gap 0.005 (params()), so
// ℓ = ρ + gap/2 = 0.1025, the pair radius r + ρ + gap/2 = 0.3025, the robot centre at the
// standoff pose r + ρ + standoff = 0.33 from the object's centre, at the grip 0.305 from it, the
// pair centre at the grip 0.305 − 0.1025 = 0.2025 from it; the approach needs
// max(0.3, 3 · 0.1025) = 0.3075 m.
constexpr double kEll = 0.1025;
constexpr double kPairRadius = 0.3025;

BaselineParams params() {
  BaselineParams p;
  p.standoff = 0.03;
  p.grip_gap = 0.005;
  p.approach_min = 0.3;
  p.approach_factor = 3.0;
  return p;
}

Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

// A 6 × 4 m room, the robot at (1, 2) heading 0, M1 at (3, 2), goal regions l2 around (5, 2) and
// l3 around (3.8, 2.6); the task releases M1 in `region`.
scenario::Scenario open_room(const std::string& region = "l2") {
  scenario::Scenario s;
  s.name = "open_room";
  s.workspace = rect(0, 0, 6, 4);
  s.robot.radius = 0.2;
  s.robot.start = Point(1, 2);
  s.robot.heading = 0;
  s.objects = {{"M1", geometry::Disk{Point(3, 2), 0.1}}};
  s.regions = {{"l2", rect(4.6, 1.6, 5.4, 2.4)}, {"l3", rect(3.4, 2.2, 4.2, 3.0)}};
  s.task = "<>release(M1," + region + ")";
  scenario::validate(s);
  return s;
}

// Straight: transit (1, 2) → (2.67, 2), dock to (2.695, 2), transfer of the pair centre
// (2.7975, 2) → (4.7975, 2) (2 m, all approach), release at heading 0 with M1 at (5, 2), back off
// to (4.67, 2). The robot drives 1.67 + 0.025 + 2 + 0.025 = 3.72 m, M1 2 m. Clearances: the
// pair disk along y = 2 is 2 − 0.3025 from the walls.
Plan straight_plan() {
  Plan p;
  ObjectMove m;
  m.object = 0;
  m.from = Point(3, 2);
  m.to = Point(5, 2);
  m.transit = {Point(1, 2), Point(2.67, 2)};
  m.grasp_heading = 0;
  m.transfer = {Point(2.7975, 2), Point(4.7975, 2)};
  m.release_heading = 0;
  p.moves = {m};
  p.final_arrangement = {Point(5, 2)};
  return p;
}

// A wall O1 from the floor (x 2.4..3.0, y 0..2.6); the robot at (1, 1) heading 0; M1 at (4, 1),
// M2 at (5.2, 0.6) (never moved); l2 top left, l1 top right.
scenario::Scenario walled_room() {
  scenario::Scenario s;
  s.name = "walled_room";
  s.workspace = rect(0, 0, 6, 4);
  s.robot.radius = 0.2;
  s.robot.start = Point(1, 1);
  s.robot.heading = 0;
  s.objects = {{"M1", geometry::Disk{Point(4, 1), 0.1}},
               {"M2", geometry::Disk{Point(5.2, 0.6), 0.1}}};
  s.familiar = {{"O1", rect(2.4, 0, 3.0, 2.6)}};
  s.regions = {{"l1", rect(4.6, 2.8, 5.4, 3.6)}, {"l2", rect(0.6, 2.8, 1.4, 3.6)}};
  s.task = "<>(release(M1,l2) && <>move(l1))";
  scenario::validate(s);
  return s;
}

// Over the wall and down to M1's left: transit (1, 1) → (1, 3.1) → (3.67, 3.1) → (3.67, 1)
// (robot 0.3 above O1's top, 0.47 right of its face, 0.7 below the ceiling); grasp heading 0;
// transfer (3.7975, 1) → (3.7975, 3.2) → (1.2025, 3.2) (the pair disk 0.495 right of O1,
// 0.2975 above it, 0.4975 below the ceiling; the pair turns from heading 0 onto π/2, then π,
// and the last 2.595 m are the approach); release at heading π with M1 at (1, 3.2); back off to
// (1.33, 3.2); final transit to (5, 3.2) in l1.
Plan walled_plan() {
  Plan p;
  ObjectMove m;
  m.object = 0;
  m.from = Point(4, 1);
  m.to = Point(1, 3.2);
  m.transit = {Point(1, 1), Point(1, 3.1), Point(3.67, 3.1), Point(3.67, 1)};
  m.grasp_heading = 0;
  m.transfer = {Point(3.7975, 1), Point(3.7975, 3.2), Point(1.2025, 3.2)};
  m.release_heading = kPi;
  p.moves = {m};
  p.final_transit = {Point(1.33, 3.2), Point(5, 3.2)};
  p.final_arrangement = {Point(1, 3.2), Point(5.2, 0.6)};
  return p;
}

ExecutionOptions options_for(const scenario::Scenario& s) {
  ExecutionOptions o;
  o.dt = s.simulation.dt;
  o.time_budget = s.simulation.time_budget;
  return o;
}

double polyline_distance(const std::vector<Point>& path, const Point& x) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    best = std::min(best, (geometry::nearest_on_segment(path[k], path[k + 1], x) - x).norm());
  }
  return best;
}

std::vector<std::string> names(const ExecutionLog& log) {
  std::vector<std::string> out;
  for (const ExecutedAction& a : log.actions) out.push_back(a.action + ":" + a.outcome);
  return out;
}

TEST(PlanExecutor, StatusNames) {
  EXPECT_STREQ(to_string(ExecStatus::kCompleted), "completed");
  EXPECT_STREQ(to_string(ExecStatus::kFailed), "failed");
  EXPECT_STREQ(to_string(ExecStatus::kTimeout), "timeout");
  EXPECT_STREQ(to_string(ExecStatus::kInterrupted), "interrupted");
}

TEST(PlanExecutor, HandPlansAreValid) {
  const scenario::Scenario a = open_room(), b = walled_room();
  EXPECT_TRUE(validate_plan(problem_from_scenario(a), straight_plan(), params()).empty());
  EXPECT_TRUE(validate_plan(problem_from_scenario(b), walled_plan(), params()).empty());
}

TEST(PlanExecutor, StraightPlanPlacesTheObject) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  const ExecutionLog log = execute_plan(s, problem, straight_plan(), params(), options_for(s));
  ASSERT_EQ(log.status, ExecStatus::kCompleted) << log.reason;
  EXPECT_EQ(log.collisions, 0);
  EXPECT_NEAR((log.objects_end[0] - Point(5, 2)).norm(), 0, kPlacementTol);
  EXPECT_TRUE(geometry::contains(rect(4.6, 1.6, 5.4, 2.4), log.objects_end[0]));
  EXPECT_TRUE(log.goals_reached);
  EXPECT_TRUE(log.robot_goal_reached);  // no robot goal
  EXPECT_EQ(log.moves_done, 1u);
  EXPECT_NEAR(log.robot_path_length, 3.72, kLengthRelTol * 3.72);
  EXPECT_NEAR(log.object_path_length, 2.0, kLengthRelTol * 2.0);
  // The closest approach is the grip gap, 5 mm, to M1 before it is held.
  EXPECT_NEAR(log.min_clearance, 0.005, 1e-4);
  EXPECT_EQ(names(log),
            (std::vector<std::string>{"grasp(M1):succeeded", "release(M1,l2):succeeded"}));
  EXPECT_LE(log.actions[0].t_end, log.actions[1].t_start + 1e-12);
  // The recorded steps: the start plus one per step.
  EXPECT_EQ(log.robot.size(), static_cast<std::size_t>(log.steps) + 1);
  EXPECT_EQ(log.objects.size(), log.robot.size());
  EXPECT_NEAR(log.sim_time, static_cast<double>(log.steps) * s.simulation.dt, 1e-9);
  // Lower bound: 3.72 m at v_max = 0.4 m/s.
  EXPECT_GE(log.sim_time, 3.72 / 0.4);
  std::cout << "straight: placement error " << (log.objects_end[0] - Point(5, 2)).norm()
            << " m, robot path " << log.robot_path_length << " m (3.72), object path "
            << log.object_path_length << " m (2), sim time " << log.sim_time << " s\n";
}

TEST(PlanExecutor, TurnsCornersAndEndsInTheRobotGoal) {
  const scenario::Scenario s = walled_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  const Plan plan = walled_plan();
  const ExecutionLog log = execute_plan(s, problem, plan, params(), options_for(s));
  ASSERT_EQ(log.status, ExecStatus::kCompleted) << log.reason;
  EXPECT_EQ(log.collisions, 0);
  EXPECT_GT(log.min_clearance, 0);
  EXPECT_NEAR((log.objects_end[0] - Point(1, 3.2)).norm(), 0, kPlacementTol);
  EXPECT_TRUE(geometry::contains(rect(0.6, 2.8, 1.4, 3.6), log.objects_end[0]));
  EXPECT_NEAR((log.objects_end[1] - Point(5.2, 0.6)).norm(), 0, 1e-6);  // M2 untouched
  EXPECT_TRUE(log.goals_reached);
  EXPECT_TRUE(log.robot_goal_reached);
  EXPECT_NEAR((log.robot.back().x - Point(5, 3.2)).norm(), 0, 1e-6);
  EXPECT_EQ(names(log), (std::vector<std::string>{"grasp(M1):succeeded", "release(M1,l2):succeeded",
                                                  "move(l1):succeeded"}));
  // Transit 2.1 + 2.67 + 2.1 = 6.87 m and the final transit 3.67 m are driven exactly; the
  // transfer swings the robot around the pair centre, so only a lower bound for the whole.
  EXPECT_GE(log.robot_path_length, 6.87 + 0.025 + 0.025 + 3.67);

  // The pair centre x + ℓ·h(ψ) on the transfer polyline while the object is carried (the
  // release action minus its last 0.1 s: the still step and the 0.025 m back-off).
  const ExecutedAction& release = log.actions[1];
  const double dt = s.simulation.dt;
  double worst = 0;
  int samples = 0;
  for (std::size_t k = 0; k < log.robot.size(); ++k) {
    const double t = static_cast<double>(k) * dt;
    if (t < release.t_start || t > release.t_end - 0.1) continue;
    const sim::Pose& p = log.robot[k];
    const Point pair = p.x + kEll * Point(std::cos(p.psi), std::sin(p.psi));
    worst = std::max(worst, polyline_distance(plan.moves[0].transfer, pair));
    ++samples;
  }
  EXPECT_GT(samples, 1000);
  EXPECT_LT(worst, kTrackTol);
  std::cout << "walled: placement error " << (log.objects_end[0] - Point(1, 3.2)).norm()
            << " m, worst pair-centre distance from the transfer polyline " << worst
            << " m, min clearance " << log.min_clearance << " m, sim time " << log.sim_time
            << " s, wall time " << log.wall_time << " s\n";
}

TEST(PlanExecutor, ShortApproachLandsWhereTheLawPredicts) {
  // East 1 m at heading 0, then a quarter turn onto a 0.35 m approach north. Along it
  // φ = θ − ψ starts at π/2 and tan(φ/2) = exp(−0.35/ℓ) (the closed form of dφ/ds = −sin φ/ℓ):
  // the release heading is π/2 − φ (φ = 0.0658 rad), and M1 lands 0.2025·h(π/2 − φ) beyond the
  // pair centre's last vertex, 13 mm off the approach's axis.
  const scenario::Scenario s = open_room("l3");
  const RearrangementProblem problem = problem_from_scenario(s);
  const double phi = 2 * std::atan(std::exp(-0.35 / kEll));
  const double psi_end = kPi / 2 - phi;
  Plan plan = straight_plan();
  ObjectMove& m = plan.moves[0];
  m.transfer = {Point(2.7975, 2), Point(3.7975, 2), Point(3.7975, 2.35)};
  m.release_heading = psi_end;
  m.to = Point(3.7975, 2.35) + 0.2025 * Point(std::cos(psi_end), std::sin(psi_end));
  plan.final_arrangement = {m.to};
  EXPECT_TRUE(validate_plan(problem, plan, params()).empty());

  const ExecutionLog log = execute_plan(s, problem, plan, params(), options_for(s));
  ASSERT_EQ(log.status, ExecStatus::kCompleted) << log.reason;
  EXPECT_EQ(log.collisions, 0);
  const double error = (log.objects_end[0] - m.to).norm();
  EXPECT_LT(error, 1e-3);
  EXPECT_NEAR(std::remainder(log.robot.back().psi - psi_end, 2 * kPi), 0, 1e-3);
  EXPECT_TRUE(log.goals_reached);
  std::cout << "short approach: placement error " << error << " m (landing " << m.to.x() << ", "
            << m.to.y() << "), heading error "
            << std::remainder(log.robot.back().psi - psi_end, 2 * kPi) << " rad\n";
}

TEST(PlanExecutor, GripFailsWhenTheDockHeadingPointsAway) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  Plan plan = straight_plan();
  plan.moves[0].grasp_heading = kPi;  // turns its back on M1 at the standoff pose
  const ExecutionLog log = execute_plan(s, problem, plan, params(), options_for(s));
  EXPECT_EQ(log.status, ExecStatus::kFailed);
  EXPECT_NE(log.reason.find("grip of M1 failed"), std::string::npos) << log.reason;
  EXPECT_EQ(names(log), (std::vector<std::string>{"grasp(M1):failed"}));
  EXPECT_EQ(log.collisions, 0);
  EXPECT_FALSE(log.goals_reached);
  EXPECT_NEAR((log.objects_end[0] - Point(3, 2)).norm(), 0, 1e-6);
}

TEST(PlanExecutor, PlanThatDoesNotStartAtTheRobotFails) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  Plan plan = straight_plan();
  plan.moves[0].transit.front() = Point(1, 2.5);
  const ExecutionLog log = execute_plan(s, problem, plan, params(), options_for(s));
  EXPECT_EQ(log.status, ExecStatus::kFailed);
  EXPECT_NE(log.reason.find("transit starts at"), std::string::npos) << log.reason;
  EXPECT_EQ(log.steps, 0);
}

TEST(PlanExecutor, TinyTimeBudgetTimesOut) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  ExecutionOptions o = options_for(s);
  o.time_budget = 1.0;  // the transit alone takes 1.67 / 0.4 = 4.2 s
  const ExecutionLog log = execute_plan(s, problem, straight_plan(), params(), o);
  EXPECT_EQ(log.status, ExecStatus::kTimeout);
  EXPECT_EQ(log.steps, 100);
  EXPECT_NEAR(log.sim_time, 1.0, 1e-9);
  EXPECT_EQ(names(log), (std::vector<std::string>{"grasp(M1):timeout"}));
  EXPECT_NEAR((log.robot.back().x - Point(1.4, 2)).norm(), 0, 1e-6);  // 1 s at 0.4 m/s
}

TEST(PlanExecutor, ResumesHoldingAfterAnInterruptedTransfer) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  sim::SimWorld world(s, sim::config_for(s));
  PlanExecutor ex(world, problem, params(), options_for(s));
  ex.load(straight_plan());

  // Before the first step: transit, dock, transfer, back-off.
  std::vector<PlanExecutor::Sweep> rest = ex.remaining();
  ASSERT_EQ(rest.size(), 4u);
  EXPECT_EQ(rest[0].kind, PlanExecutor::SweepKind::kTransit);
  EXPECT_EQ(rest[1].kind, PlanExecutor::SweepKind::kDock);
  EXPECT_EQ(rest[2].kind, PlanExecutor::SweepKind::kTransfer);
  EXPECT_EQ(rest[3].kind, PlanExecutor::SweepKind::kBackOff);
  EXPECT_NEAR(rest[2].radius, kPairRadius, 1e-12);
  EXPECT_EQ(rest[2].held, std::optional<std::size_t>(0));

  while (!ex.held() && ex.tick()) {
  }
  ASSERT_EQ(ex.held(), std::optional<std::size_t>(0));
  for (int k = 0; k < 100; ++k) ASSERT_TRUE(ex.tick());  // 1 s into the transfer

  rest = ex.remaining();
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(rest[0].kind, PlanExecutor::SweepKind::kTransfer);
  EXPECT_EQ(rest[0].held, std::optional<std::size_t>(0));
  const sim::Pose pose = world.pose();
  const Point pair = pose.x + kEll * Point(std::cos(pose.psi), std::sin(pose.psi));
  EXPECT_NEAR((rest[0].path.front() - pair).norm(), 0, 1e-12);
  EXPECT_NEAR((rest[0].path.back() - Point(4.7975, 2)).norm(), 0, 1e-12);
  EXPECT_EQ(rest[1].kind, PlanExecutor::SweepKind::kBackOff);

  ex.interrupt();
  EXPECT_TRUE(ex.finished());
  EXPECT_FALSE(ex.tick());
  EXPECT_EQ(ex.log().status, ExecStatus::kInterrupted);
  EXPECT_EQ(ex.held(), std::optional<std::size_t>(0));  // still holding
  const long steps = ex.log().steps;
  EXPECT_EQ(world.time(), static_cast<double>(steps) * s.simulation.dt);

  Plan resume;
  ObjectMove m;
  m.object = 0;
  m.held_at_start = true;
  m.from = world.object_center(0);
  m.to = Point(5, 2);
  m.transfer = {pair, Point(4.7975, 2)};
  m.release_heading = 0;
  resume.moves = {m};
  resume.final_arrangement = {Point(5, 2)};
  ex.load(resume);
  while (ex.tick()) {
  }
  const ExecutionLog log = ex.finish();
  ASSERT_EQ(log.status, ExecStatus::kCompleted) << log.reason;
  EXPECT_EQ(log.collisions, 0);
  EXPECT_NEAR((log.objects_end[0] - Point(5, 2)).norm(), 0, kPlacementTol);
  EXPECT_TRUE(log.goals_reached);
  EXPECT_EQ(log.moves_done, 1u);
  EXPECT_EQ(names(log),
            (std::vector<std::string>{"grasp(M1):succeeded", "release(M1,l2):interrupted",
                                      "release(M1,l2):succeeded"}));
  // The interruption changes nothing on a straight line: the same lengths as without it.
  EXPECT_NEAR(log.robot_path_length, 3.72, kLengthRelTol * 3.72);
}

TEST(PlanExecutor, HeldAtStartWithoutHoldingFails) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  Plan plan = straight_plan();
  plan.moves[0].held_at_start = true;
  const ExecutionLog log = execute_plan(s, problem, plan, params(), options_for(s));
  EXPECT_EQ(log.status, ExecStatus::kFailed);
  EXPECT_NE(log.reason.find("holds nothing"), std::string::npos) << log.reason;
}

TEST(PlanExecutor, WrongStepIsRejected) {
  const scenario::Scenario s = open_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  sim::SimWorld world(s, sim::config_for(s));
  ExecutionOptions o = options_for(s);
  o.dt = 0.02;
  PlanExecutor ex(world, problem, params(), o);
  ex.load(straight_plan());
  EXPECT_THROW(ex.tick(), Error);
}

TEST(PlanExecutor, RepeatedRunsAreBitIdentical) {
  const scenario::Scenario s = walled_room();
  const RearrangementProblem problem = problem_from_scenario(s);
  const ExecutionLog a = execute_plan(s, problem, walled_plan(), params(), options_for(s));
  const ExecutionLog b = execute_plan(s, problem, walled_plan(), params(), options_for(s));
  ASSERT_EQ(a.status, ExecStatus::kCompleted);
  ASSERT_EQ(a.robot.size(), b.robot.size());
  for (std::size_t k = 0; k < a.robot.size(); ++k) {
    ASSERT_EQ(a.robot[k].x.x(), b.robot[k].x.x()) << k;
    ASSERT_EQ(a.robot[k].x.y(), b.robot[k].x.y()) << k;
    ASSERT_EQ(a.robot[k].psi, b.robot[k].psi) << k;
    ASSERT_EQ(a.objects[k], b.objects[k]) << k;
  }
  EXPECT_EQ(a.robot_path_length, b.robot_path_length);
  EXPECT_EQ(a.objects_end, b.objects_end);
}

}  // namespace
}  // namespace rearm::baselines
