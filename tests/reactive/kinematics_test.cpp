#include "reactive/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "core/rng.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

constexpr double kPi = std::numbers::pi;

// Independent truth: classical RK4 on ẋ = v cos ψ, ẏ = v sin ψ, ψ̇ = ω with n substeps.
Pose rk4(const Pose& p0, const Twist& u, double dt, int n) {
  const auto f = [&](const Eigen::Vector3d& s) {
    return Eigen::Vector3d(u.v * std::cos(s.z()), u.v * std::sin(s.z()), u.omega);
  };
  Eigen::Vector3d s(p0.x.x(), p0.x.y(), p0.psi);
  const double h = dt / n;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d k1 = f(s);
    const Eigen::Vector3d k2 = f(s + 0.5 * h * k1);
    const Eigen::Vector3d k3 = f(s + 0.5 * h * k2);
    const Eigen::Vector3d k4 = f(s + h * k3);
    s += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return Pose{Point(s.x(), s.y()), s.z()};
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * kPi)); }

TEST(UnicycleStep, MatchesRk4OfTheOde) {
  Rng rng(20240611);
  const std::size_t cases = test_support::scaled(200, 20);
  for (std::size_t c = 0; c < cases; ++c) {
    const Pose p0{Point(rng.uniform(-5, 5), rng.uniform(-5, 5)), rng.uniform(-kPi, kPi)};
    const Twist u{rng.uniform(-1, 1), rng.uniform(-3, 3)};
    const double dt = rng.uniform(0.001, 0.8);
    const Pose exact = unicycle_step(p0, u, dt);
    const Pose truth = rk4(p0, u, dt, 2000);
    EXPECT_NEAR((exact.x - truth.x).norm(), 0.0, 1e-10) << "case " << c;
    EXPECT_LT(angle_diff(exact.psi, truth.psi), 1e-10) << "case " << c;
    EXPECT_GT(exact.psi, -kPi);
    EXPECT_LE(exact.psi, kPi);
  }
}

TEST(UnicycleStep, StraightLineAtZeroTurnRate) {
  const Pose p0{Point(1, 2), 0.3};
  const Pose p = unicycle_step(p0, Twist{0.5, 0.0}, 2.0);
  EXPECT_NEAR(p.x.x(), 1 + 1.0 * std::cos(0.3), 1e-15);
  EXPECT_NEAR(p.x.y(), 2 + 1.0 * std::sin(0.3), 1e-15);
  EXPECT_DOUBLE_EQ(p.psi, 0.3);
}

TEST(UnicycleStep, ContinuousAsTurnRateVanishes) {
  const Pose p0{Point(-0.4, 0.7), 2.1};
  const double v = 0.8;
  const double dt = 0.5;
  const Pose straight = unicycle_step(p0, Twist{v, 0.0}, dt);
  // |step(ω) − step(0)| = O(v dt² ω): shrinks linearly, on both sides of zero.
  for (double w : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    for (double sign : {-1.0, 1.0}) {
      const Pose p = unicycle_step(p0, Twist{v, sign * w}, dt);
      EXPECT_LE((p.x - straight.x).norm(), v * dt * dt * w) << w;
    }
  }
  // Across the series/closed-form switch the step moves by a rounding error only, and the
  // closed form (v/ω)(sin(ψ+ωdt) − sin ψ, cos ψ − cos(ψ+ωdt)) agrees where it is accurate.
  const double w_switch = 2 * kSincSeriesThreshold / dt;
  const Pose below = unicycle_step(p0, Twist{v, w_switch * (1 - 1e-9)}, dt);
  const Pose above = unicycle_step(p0, Twist{v, w_switch * (1 + 1e-9)}, dt);
  EXPECT_LE((below.x - above.x).norm(), 1e-13);
  for (double w : {1e-3, 0.3, 2.0}) {
    const Pose p = unicycle_step(p0, Twist{v, w}, dt);
    const Point closed(v / w * (std::sin(p0.psi + w * dt) - std::sin(p0.psi)),
                       v / w * (std::cos(p0.psi) - std::cos(p0.psi + w * dt)));
    EXPECT_NEAR((p.x - p0.x - closed).norm(), 0.0, 1e-12) << w;
  }
}

TEST(UnicycleStep, TurnInPlace) {
  const Pose p0{Point(3, -1), 3.0};
  const Pose p = unicycle_step(p0, Twist{0.0, 1.0}, 0.5);
  EXPECT_EQ(p.x, p0.x);
  EXPECT_NEAR(p.psi, 3.5 - 2 * kPi, 1e-15);  // wrapped into (−π, π]
}

TEST(UnicycleStep, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(unicycle_step(Pose{Point(nan, 0), 0}, Twist{1, 0}, 0.1), Error);
  EXPECT_THROW(unicycle_step(Pose{Point(0, 0), inf}, Twist{1, 0}, 0.1), Error);
  EXPECT_THROW(unicycle_step(Pose{}, Twist{nan, 0}, 0.1), Error);
  EXPECT_THROW(unicycle_step(Pose{}, Twist{0, inf}, 0.1), Error);
  EXPECT_THROW(unicycle_step(Pose{}, Twist{1, 0}, -0.1), Error);
  EXPECT_THROW(unicycle_step(Pose{}, Twist{1, 0}, nan), Error);
  EXPECT_THROW(holonomic_step(Point(0, 0), Point(nan, 0), 0.1), Error);
  EXPECT_THROW(holonomic_step(Point(inf, 0), Point(0, 0), 0.1), Error);
  EXPECT_THROW(holonomic_step(Point(0, 0), Point(1, 0), -1.0), Error);
}

TEST(HolonomicStep, IsExactForConstantVelocity) {
  const Point x = holonomic_step(Point(1, 2), Point(-0.5, 0.25), 0.4);
  EXPECT_NEAR(x.x(), 0.8, 1e-15);
  EXPECT_NEAR(x.y(), 2.1, 1e-15);
  EXPECT_EQ(holonomic_step(Point(1, 2), Point(3, 4), 0.0), Point(1, 2));
}

TEST(Kinematics, DefaultStepIsTheReferenceMaxStep) { EXPECT_DOUBLE_EQ(kDefaultStep, 0.01); }

}  // namespace
}  // namespace rearm::reactive
