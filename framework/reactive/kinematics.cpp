// Zero-order-hold kinematic steps (see kinematics.h).
#include "reactive/kinematics.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace rearm::reactive {
namespace {

void check_step(const Point& x, double dt, const char* what) {
  if (!x.allFinite()) throw Error(std::string(what) + ": position is not finite");
  REARM_REQUIRE(std::isfinite(dt) && dt >= 0, what,
                ": step dt must be finite and non-negative, got ", dt);
}

// sin(a)/a, continuous at 0.
double sinc(double a) {
  if (std::abs(a) < kSincSeriesThreshold) {
    const double a2 = a * a;
    return 1 - a2 / 6 + a2 * a2 / 120;
  }
  return std::sin(a) / a;
}

}  // namespace

double wrap_angle(double a) {
  if (!std::isfinite(a)) throw Error("wrap_angle: angle is not finite");
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double r = std::remainder(a, kTwoPi);  // in [−π, π]
  if (r <= -std::numbers::pi) r += kTwoPi;
  return r;
}

Pose unicycle_step(const Pose& pose, const Twist& u, double dt) {
  check_step(pose.x, dt, "unicycle_step");
  if (!std::isfinite(pose.psi)) throw Error("unicycle_step: heading is not finite");
  if (!std::isfinite(u.v) || !std::isfinite(u.omega)) {
    throw Error("unicycle_step: command (v, omega) is not finite");
  }
  // Chord of the arc: length v·dt·sinc(θ/2) along the mean heading ψ + θ/2, θ = ω·dt.
  const double half = 0.5 * u.omega * dt;
  const double chord = u.v * dt * sinc(half);
  const double mid = pose.psi + half;
  Pose out;
  out.x = pose.x + chord * Point(std::cos(mid), std::sin(mid));
  out.psi = wrap_angle(pose.psi + u.omega * dt);
  return out;
}

Point holonomic_step(const Point& x, const Point& velocity, double dt) {
  check_step(x, dt, "holonomic_step");
  if (!velocity.allFinite()) throw Error("holonomic_step: velocity is not finite");
  return x + dt * velocity;
}

}  // namespace rearm::reactive
