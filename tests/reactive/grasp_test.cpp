#include "reactive/grasp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "reactive/kinematics.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(WrapAngle, KnownCases) {
  EXPECT_EQ(wrap_angle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(wrap_angle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrap_angle(-kPi), kPi);  // the half-open range (−π, π]
  EXPECT_NEAR(wrap_angle(2 * kPi), 0.0, 1e-15);
  EXPECT_NEAR(wrap_angle(-2 * kPi), 0.0, 1e-15);
  EXPECT_NEAR(wrap_angle(3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(100 * kPi + 0.3), 0.3, 1e-12);
  EXPECT_NEAR(wrap_angle(-7 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(1.5 * kPi), -0.5 * kPi, 1e-15);
  EXPECT_THROW(wrap_angle(std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_THROW(wrap_angle(std::numeric_limits<double>::infinity()), Error);
}

TEST(WrapAngle, RangeAndEquivalenceOnRandomAngles) {
  Rng rng(7);
  for (std::size_t i = 0, n = test_support::scaled(10000, 100); i < n; ++i) {
    const double a = rng.uniform(-1000, 1000);
    const double w = wrap_angle(a);
    EXPECT_GT(w, -kPi);
    EXPECT_LE(w, kPi);
    EXPECT_NEAR(std::cos(w), std::cos(a), 1e-12);
    EXPECT_NEAR(std::sin(w), std::sin(a), 1e-12);
    EXPECT_NEAR(std::round((a - w) / (2 * kPi)) * 2 * kPi, a - w, 1e-9);
  }
}

TEST(Align, TurnsInPlaceAndConvergesFromRandomHeadings) {
  Rng rng(11);
  NavParams p;
  p.omega_max = 0.8;
  for (std::size_t c = 0, n = test_support::scaled(200, 20); c < n; ++c) {
    Pose pose{Point(rng.uniform(-3, 3), rng.uniform(-3, 3)), rng.uniform(-kPi, kPi)};
    const Point object(rng.uniform(-3, 3), rng.uniform(-3, 3));
    if ((object - pose.x).norm() < 0.1) continue;
    const Point start = pose.x;
    bool done = false;
    for (int step = 0; step < 5000 && !done; ++step) {
      const Twist u = align_command(pose.psi, pose.x, object, p);
      ASSERT_EQ(u.v, 0.0);
      ASSERT_LE(std::abs(u.omega), p.omega_max);
      ASSERT_TRUE(std::isfinite(u.omega));
      pose = unicycle_step(pose, u, kDefaultStep);
      done = aligned(pose.psi, pose.x, object);
    }
    EXPECT_TRUE(done) << "case " << c;
    EXPECT_EQ(pose.x, start);
    // Independent truth: the heading points at the object.
    const Point to = (object - pose.x).normalized();
    EXPECT_GT(to.dot(Point(std::cos(pose.psi), std::sin(pose.psi))), std::cos(kAlignTolerance));
  }
}

TEST(Align, TakesTheShortWayAcrossPi) {
  NavParams p;
  // Object straight "behind-left" at bearing 179°, heading −179°: the short turn is −2°.
  const double psi = -179.0 * kPi / 180;
  const Point object(std::cos(179.0 * kPi / 180), std::sin(179.0 * kPi / 180));
  const Twist u = align_command(psi, Point(0, 0), object, p, 1.0);
  EXPECT_LT(u.omega, 0.0);
  EXPECT_NEAR(u.omega, -2.0 * kPi / 180, 1e-12);
  EXPECT_FALSE(aligned(psi, Point(0, 0), object));
  EXPECT_TRUE(aligned(psi, Point(0, 0), object, 0.05));
}

TEST(Align, RejectsBadInput) {
  NavParams p;
  EXPECT_THROW(align_command(0, Point(1, 1), Point(1, 1), p), Error);
  EXPECT_THROW(align_command(0, Point(0, 0), Point(1, 1), p, 0.0), Error);
  EXPECT_THROW(align_command(std::numeric_limits<double>::quiet_NaN(), Point(0, 0), Point(1, 1), p),
               Error);
  p.omega_max = -1;
  EXPECT_THROW(align_command(0, Point(0, 0), Point(1, 1), p), Error);
}

TEST(GraspApproach, NearestFreePointOnTheCircle) {
  Rng rng(5);
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const geometry::Disk object{Point(rng.uniform(-2, 2), rng.uniform(-2, 2)),
                                rng.uniform(0.05, 0.5)};
    const double r = rng.uniform(0.1, 0.3);
    const Point robot(rng.uniform(-5, 5), rng.uniform(-5, 5));
    // Blockers: random disks; a point is free when outside all of them.
    std::vector<geometry::Disk> blockers;
    for (int k = 0; k < 3; ++k) {
      blockers.push_back(
          {object.center + Point(rng.uniform(-1, 1), rng.uniform(-1, 1)), rng.uniform(0.1, 0.8)});
    }
    const auto is_free = [&](const Point& q) {
      for (const auto& b : blockers) {
        if ((q - b.center).norm() <= b.radius) return false;
      }
      return true;
    };
    const int samples = 48;
    const std::optional<Point> q = grasp_approach_point(object, r, robot, is_free, samples);
    // Independent truth: the same candidates, enumerated here.
    const double radius = object.radius + r + kGraspStandoff;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < samples; ++i) {
      const double a = 2 * kPi * i / samples;
      const Point cand = object.center + radius * Point(std::cos(a), std::sin(a));
      if (is_free(cand)) best = std::min(best, (cand - robot).norm());
    }
    if (!std::isfinite(best)) {
      EXPECT_FALSE(q.has_value()) << "case " << c;
      continue;
    }
    ASSERT_TRUE(q.has_value()) << "case " << c;
    EXPECT_NEAR((*q - object.center).norm(), radius, 1e-12);
    EXPECT_TRUE(is_free(*q));
    EXPECT_NEAR((*q - robot).norm(), best, 1e-12);
  }
}

TEST(GraspApproach, NoneFreeGivesNullopt) {
  const geometry::Disk object{Point(0, 0), 0.3};
  const auto never = [](const Point&) { return false; };
  EXPECT_FALSE(grasp_approach_point(object, 0.2, Point(3, 0), never).has_value());
  const auto always = [](const Point&) { return true; };
  const auto q = grasp_approach_point(object, 0.2, Point(3, 0), always);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->x(), 0.5 + kGraspStandoff, 1e-12);  // the candidate facing the robot
  EXPECT_NEAR(q->y(), 0.0, 1e-12);
  EXPECT_THROW(grasp_approach_point(object, 0.2, Point(3, 0), always, 0), Error);
  EXPECT_THROW(grasp_approach_point(object, -0.2, Point(3, 0), always), Error);
  EXPECT_THROW(
      grasp_approach_point(object, 0.2, Point(std::numeric_limits<double>::quiet_NaN(), 0), always),
      Error);
  EXPECT_THROW(grasp_approach_point(object, 0.2, Point(3, 0), nullptr), Error);
}

}  // namespace
}  // namespace rearm::reactive
