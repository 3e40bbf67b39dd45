// The plan validator against hand geometry: a plan whose clearances are worked out by hand (a
// 6 × 4 m room with a wall from the floor, two objects) is valid, and each corruption of it —
// a transit through the wall, a transfer grazing the other object, a path that does not start
// where the robot is, a short approach, a goal region missed, a non-finite vertex, a placement
// overlapping the boundary, a wrong final arrangement — is reported by a message naming it.
// The sweep proof's edge is checked at hand-computed clearances on both sides of the sampling
// bound.
#include "baselines/validator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace rearm::baselines {
namespace {

using geometry::Point;
using geometry::Polygon;

constexpr double kPi = std::numbers::pi;

// The parameters the hand geometry below assumes (set explicitly, not taken from the defaults).
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

// The walled room of executor_test.cpp, as a problem built by hand: O1 from the floor (x 2.4..3.0,
// y 0..2.6); the robot (r = 0.2) at (1, 1) heading 0; M1 (ρ = 0.1) at (4, 1) with goal region l2
// (x 0.6..1.4, y 2.8..3.6), M2 (ρ = 0.1) at (5.2, 0.6) unconstrained; the robot's goal region l1
// (x 4.6..5.4, y 2.8..3.6).
RearrangementProblem problem() {
  RearrangementProblem p;
  p.name = "walled_room";
  p.workspace = rect(0, 0, 6, 4);
  p.obstacles = {rect(2.4, 0, 3.0, 2.6)};
  p.obstacle_names = {"O1"};
  p.robot_radius = 0.2;
  p.robot_start = Point(1, 1);
  p.robot_heading = 0;
  p.object_names = {"M1", "M2"};
  p.object_radii = {0.1, 0.1};
  p.start = {Point(4, 1), Point(5.2, 0.6)};
  p.goals = {Point(1, 3.2), std::nullopt};
  p.goal_regions = {rect(0.6, 2.8, 1.4, 3.6), std::nullopt};
  p.goal_region_names = {"l2", ""};
  p.robot_goal = Point(5, 3.2);
  p.robot_goal_region = rect(4.6, 2.8, 5.4, 3.6);
  p.robot_goal_name = "l1";
  return p;
}

// M1 to (to_x, 3.2), released at heading π (with params(): ℓ = 0.1025, the pair radius 0.3025,
// the standoff pose 0.33 and the grip pose 0.305 from the object's centre, the pair centre at
// the release 0.2025 right of it, the approach >= max(0.3, 3ℓ) = 0.3075 m; the heading turns
// from 0 to π/2 along the first 2.2 m of the transfer and to π along the last 2.595 m, within
// tan(π/4)·exp(−2.595/ℓ) ~ 1e-11 rad). Transit over O1
// (robot 0.3 above it) to M1's left; transfer up at x = 3.7975 and left at y = 3.2 (the pair
// disk 0.495 right of O1 and 0.2975 above it); back off to (to_x + 0.33, 3.2); final transit
// to (5, 3.2), inside l1.
Plan plan(double to_x = 1.0) {
  Plan p;
  ObjectMove m;
  m.object = 0;
  m.from = Point(4, 1);
  m.to = Point(to_x, 3.2);
  m.transit = {Point(1, 1), Point(1, 3.1), Point(3.67, 3.1), Point(3.67, 1)};
  m.grasp_heading = 0;
  m.transfer = {Point(3.7975, 1), Point(3.7975, 3.2), Point(to_x + 0.2025, 3.2)};
  m.release_heading = kPi;
  p.moves = {m};
  p.final_transit = {Point(to_x + 0.33, 3.2), Point(5, 3.2)};
  p.final_arrangement = {Point(to_x, 3.2), Point(5.2, 0.6)};
  return p;
}

// Does some message contain every one of the words?
bool reported(const std::vector<std::string>& msgs, const std::vector<std::string>& words) {
  for (const std::string& m : msgs) {
    bool all = true;
    for (const std::string& w : words) all = all && m.find(w) != std::string::npos;
    if (all) return true;
  }
  return false;
}

std::string dump(const std::vector<std::string>& msgs) {
  std::string s;
  for (const std::string& m : msgs) s += "  " + m + "\n";
  return s;
}

TEST(ValidatePlan, HandPlanIsValid) {
  const std::vector<std::string> msgs = validate_plan(problem(), plan(), params());
  EXPECT_TRUE(msgs.empty()) << dump(msgs);
}

TEST(ValidatePlan, TransitThroughAnObstacle) {
  Plan p = plan();
  p.moves[0].transit = {Point(1, 1), Point(3.67, 1)};  // straight through O1
  const auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"move 0 (M1)", "transit segment 0", "obstacle 'O1'", "clearance"}))
      << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);
}

TEST(ValidatePlan, TransferGrazingAnotherObject) {
  // A detour to (4.8, 0.6): the pair disk's centre 0.4 from M2's, 0.0025 less than the radii's
  // sum 0.3025 + 0.1.
  Plan p = plan();
  p.moves[0].transfer = {Point(3.7975, 1), Point(4.8, 0.6), Point(3.7975, 1.2), Point(3.7975, 3.2),
                         Point(1.2025, 3.2)};
  const auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"move 0 (M1)", "transfer segment 0", "object M2", "-0.0025"}))
      << dump(msgs);
  EXPECT_TRUE(reported(msgs, {"transfer segment 1", "object M2"})) << dump(msgs);
  EXPECT_EQ(msgs.size(), 2u) << dump(msgs);
  // 3 mm further away the sweep is proven clear.
  p.moves[0].transfer[1] = Point(4.797, 0.6);
  EXPECT_TRUE(validate_plan(problem(), p, params()).empty());
}

TEST(ValidatePlan, SweepProofNeedsHalfTheSampleSpacing) {
  // The final transit passes M2 at a hand-set clearance c: samples every <= 2 mm prove c >= 0
  // when c >= 1 mm everywhere; at 0.2 mm the samples cannot prove it; overlapping is reported
  // as a negative clearance.
  for (const double c : {0.0011, 0.0002, -0.001}) {
    Plan p = plan();
    const double y = 0.6 + 0.1 + 0.2 + c;  // M2's centre + ρ + r + c
    // Down at x = 4.5, right over M2 at height y (its closest approach, above M2's centre),
    // up at x = 5.6 (0.1 from M2, 0.2 from the wall) into l1.
    p.final_transit = {Point(1.33, 3.2), Point(4.5, 3.2), Point(4.5, y),
                       Point(5.6, y),    Point(5.6, 3.2), Point(5.0, 3.2)};
    const auto msgs = validate_plan(problem(), p, params());
    if (c > 0.001) {
      EXPECT_TRUE(msgs.empty()) << c << "\n" << dump(msgs);
    } else {
      EXPECT_TRUE(reported(msgs, {"the final transit segment 2", "object M2", "clearance"}))
          << c << "\n"
          << dump(msgs);
      EXPECT_EQ(reported(msgs, {"too close to prove"}), c >= 0) << dump(msgs);
    }
  }
}

TEST(ValidatePlan, DiscontinuousPaths) {
  Plan p = plan();
  p.moves[0].transit.front() = Point(1, 1.05);
  auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"move 0 (M1)", "transit does not start where the robot is"}))
      << dump(msgs);

  p = plan();
  p.moves[0].transit.back() = Point(3.66, 1);  // not the standoff pose
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"transit does not end at the standoff pose"})) << dump(msgs);

  p = plan();
  p.moves[0].transfer.front() = Point(3.79, 1);
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"transfer does not start at the pair centre"})) << dump(msgs);

  p = plan();
  p.final_transit.front() = Point(1.4, 3.2);
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"final transit does not start where the robot is"})) << dump(msgs);

  p = plan();
  p.moves[0].from = Point(4, 1.01);
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"from is not the object's position"})) << dump(msgs);
}

TEST(ValidatePlan, ApproachTooShort) {
  // The same path with a vertex 0.3 m before its end: the last segment is shorter than 0.3075 m.
  Plan p = plan();
  p.moves[0].transfer = {Point(3.7975, 1), Point(3.7975, 3.2), Point(1.5025, 3.2),
                         Point(1.2025, 3.2)};
  const auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"approach", "0.3 m long", "0.3075"})) << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);
}

TEST(ValidatePlan, ReleaseHeadingTheLawDoesNotReach) {
  // Up at x = 3.7975 to y = 3.6 (2.6 m: the heading turns from 0 onto π/2), left to x = 1.2025
  // (2.595 m: onto π), then a quarter turn onto the approach straight down (0.4 m, direction
  // −π/2; the pair disk 0.0975 below the ceiling). Along the approach φ = θ − ψ starts at π/2 and
  // tan(φ/2) = exp(−0.4/ℓ) (the closed form of dφ/ds = −sin φ/ℓ): the heading lags by
  // φ = 0.04033 rad and M1 lands 0.2025·sin φ = 8.2 mm off the approach's axis.
  const double ell = 0.1025;
  const double phi = 2 * std::atan(std::exp(-0.4 / ell));
  const double psi_end = -kPi / 2 - phi;
  const Point h(std::cos(psi_end), std::sin(psi_end));
  Plan p = plan();
  ObjectMove& m = p.moves[0];
  m.transfer = {Point(3.7975, 1), Point(3.7975, 3.6), Point(1.2025, 3.6), Point(1.2025, 3.2)};
  m.release_heading = psi_end;
  m.to = Point(1.2025, 3.2) + 0.2025 * h;
  p.final_arrangement[0] = m.to;
  p.final_transit = {m.to - 0.33 * h, Point(1.2025, 3.6), Point(5, 3.5)};
  auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(msgs.empty()) << dump(msgs);

  // The approach's direction as the release heading, the rest consistent with it: 0.04 rad off
  // what the law reaches.
  m.release_heading = -kPi / 2;
  m.to = Point(1.2025, 3.2 - 0.2025);
  p.final_arrangement[0] = m.to;
  p.final_transit.front() = Point(1.2025, 3.2 - 0.2025 + 0.33);
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"move 0 (M1)", "release heading",
                              "not the heading the off-axis law reaches", "0.0403"}))
      << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);
}

TEST(ValidatePlan, GoalNotReached) {
  // M1 left at (2.0, 3.2), outside l2: a consistent plan otherwise.
  const auto msgs = validate_plan(problem(), plan(2.0), params());
  EXPECT_TRUE(reported(msgs, {"M1", "outside its goal region 'l2'", "goal not reached"}))
      << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);

  Plan p = plan();
  p.final_transit.back() = Point(4.0, 3.2);  // short of l1
  const auto robot = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(robot, {"robot ends at", "outside its goal region 'l1'"})) << dump(robot);
}

TEST(ValidatePlan, NonFiniteNumbers) {
  Plan p = plan();
  p.moves[0].transfer[1].x() = std::numeric_limits<double>::quiet_NaN();
  auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"move 0: transfer vertex 1", "not finite"})) << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);

  p = plan();
  p.moves[0].grasp_heading = std::numeric_limits<double>::infinity();
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"grasp_heading", "not finite"})) << dump(msgs);

  p = plan();
  p.final_arrangement[1].y() = std::numeric_limits<double>::quiet_NaN();
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"final_arrangement", "not finite"})) << dump(msgs);
}

TEST(ValidatePlan, OverlappingPlacement) {
  // M1 released at x = 0.05, overlapping the left wall by 5 cm (the pair disk crosses it too).
  const auto msgs = validate_plan(problem(), plan(0.05), params());
  EXPECT_TRUE(reported(msgs, {"released at", "overlaps the workspace boundary", "-0.05"}))
      << dump(msgs);
  EXPECT_TRUE(reported(msgs, {"transfer segment 1", "workspace boundary"})) << dump(msgs);

  // Released onto M2's place: overlaps object M2.
  RearrangementProblem q = problem();
  q.start[1] = Point(1.15, 3.2);  // 0.15 from M1's target: overlap 0.05
  q.goal_regions[0].reset();      // keep the goal out of it
  const auto onto = validate_plan(q, plan(), params());
  EXPECT_TRUE(reported(onto, {"released at", "overlaps object M2"})) << dump(onto);
}

TEST(ValidatePlan, WrongFinalArrangementAndIndices) {
  Plan p = plan();
  p.final_arrangement[0] = Point(1, 3.3);
  auto msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"final_arrangement: M1"})) << dump(msgs);
  EXPECT_EQ(msgs.size(), 1u) << dump(msgs);

  p = plan();
  p.final_arrangement.pop_back();
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"final_arrangement has 1 objects"})) << dump(msgs);

  p = plan();
  p.moves[0].object = 7;
  msgs = validate_plan(problem(), p, params());
  EXPECT_TRUE(reported(msgs, {"object index 7 out of range"})) << dump(msgs);
}

TEST(ValidatePlan, HeldAtStart) {
  // The robot starts holding M1: at (3.695, 1) heading 0 (M1 0.305 ahead), the pair centre at
  // (3.7975, 1), the transit and the dock skipped.
  RearrangementProblem q = problem();
  q.robot_start = Point(3.695, 1);
  Plan p = plan();
  p.moves[0].held_at_start = true;
  p.moves[0].transit.clear();
  EXPECT_TRUE(validate_plan(q, p, params()).empty()) << dump(validate_plan(q, p, params()));

  q.robot_start = Point(3.6, 1);  // not gripping it
  const auto msgs = validate_plan(q, p, params());
  EXPECT_TRUE(reported(msgs, {"held_at_start", "not where the robot's start pose holds it"}))
      << dump(msgs);
}

}  // namespace
}  // namespace rearm::baselines
