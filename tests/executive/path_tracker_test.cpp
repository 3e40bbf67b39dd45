// The straight tracking of a guide (executive/path_tracker.h) against the unicycle's exact
// kinematics (reactive::unicycle_step, closed-form arcs): the robot alone turns in place until
// it faces the waypoint, then drives along the straight line to it (its distance from that line
// stays within 5 mm, a tenth of the guide's clearance); the carried pair's centre moves, by finite
// differences of the exact steps, toward the waypoint and within 5 mm of the straight line to it;
// both arrive; bad input is rejected.
#include "executive/path_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "reactive/kinematics.h"

namespace rearm::executive {
namespace {

using geometry::Point;
using reactive::Pose;
using reactive::Twist;

constexpr double kDt = 0.01;
// m: how far a tracked point may leave the straight line (the guide keeps 5 cm of clearance).
constexpr double kOffLine = 5e-3;

// Distance of p from the line through a and b.
double line_distance(const Point& p, const Point& a, const Point& b) {
  const Point d = (b - a).normalized();
  const Point q = p - a;
  return std::abs(d.x() * q.y() - d.y() * q.x());
}

TEST(PathTracker, TheRobotTurnsInPlaceThenDrivesAlongTheSegment) {
  const reactive::NavParams nav;
  Pose pose{Point(1, 1), std::numbers::pi};  // facing away from the waypoint
  const Point start = pose.x;
  const Point waypoint(3, 2);
  const double bearing = std::atan2(1.0, 2.0);
  int turning = 0;
  for (int k = 0; k < 3000 && (pose.x - waypoint).norm() > 1e-3; ++k) {
    const Twist u = track_command(pose, 0, waypoint, nav);
    ASSERT_LE(std::abs(u.v), nav.v_max + 1e-12);
    ASSERT_LE(std::abs(u.omega), nav.omega_max + 1e-12);
    if (std::abs(reactive::wrap_angle(bearing - pose.psi)) > kTrackTurn + 1e-9) {
      EXPECT_EQ(u.v, 0) << "it moves before facing the waypoint";
      ++turning;
    }
    pose = reactive::unicycle_step(pose, u, kDt);
    EXPECT_LT(line_distance(pose.x, start, waypoint), kOffLine);
  }
  EXPECT_GT(turning, 0);
  EXPECT_LT((pose.x - waypoint).norm(), 1e-3);
}

TEST(PathTracker, ThePairCentreMovesStraightToTheWaypoint) {
  const reactive::NavParams nav;
  const double rho = 0.25;
  Pose pose{Point(0, 0), 0.3};
  const Point waypoint(-1, 1.5);  // behind and to the left: the pair must turn as it goes
  auto centre = [&](const Pose& q) -> Point {
    return Point(q.x.x() + rho * std::cos(q.psi), q.x.y() + rho * std::sin(q.psi));
  };
  const Point start = centre(pose);
  for (int k = 0; k < 5000 && (centre(pose) - waypoint).norm() > 1e-3; ++k) {
    const Twist u = track_command(pose, rho, waypoint, nav);
    ASSERT_LE(std::abs(u.v), nav.v_max + 1e-12);
    ASSERT_LE(std::abs(u.omega), nav.omega_max + 1e-12);
    const Point before = centre(pose);
    pose = reactive::unicycle_step(pose, u, kDt);
    const Point moved = centre(pose) - before;
    // The centre's finite-difference velocity points at the waypoint (within the arc error).
    if (moved.norm() > 1e-9) {
      EXPECT_GT(moved.normalized().dot((waypoint - before).normalized()), 1 - 1e-3);
    }
    EXPECT_LT(line_distance(centre(pose), start, waypoint), kOffLine);
  }
  EXPECT_LT((centre(pose) - waypoint).norm(), 1e-3);
}

TEST(PathTracker, BadInputIsRejected) {
  const reactive::NavParams nav;
  const Pose ok{Point(0, 0), 0};
  EXPECT_THROW(track_command(ok, -0.1, Point(1, 0), nav), Error);
  EXPECT_THROW(track_command(ok, 0, Point(NAN, 0), nav), Error);
  EXPECT_THROW(track_command(Pose{Point(0, INFINITY), 0}, 0, Point(1, 0), nav), Error);
  EXPECT_THROW(track_command(Pose{Point(0, 0), NAN}, 0.2, Point(1, 0), nav), Error);
  const Twist at = track_command(ok, 0, Point(0, 0), nav);
  EXPECT_EQ(at.v, 0);
  EXPECT_EQ(at.omega, 0);
}

}  // namespace
}  // namespace rearm::executive
