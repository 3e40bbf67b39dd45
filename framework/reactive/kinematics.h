// Exact zero-order-hold steps of the robot's kinematic models (docs/reactive.md §1, §6): a
// differential-drive (unicycle) robot with inputs (v, ω) held constant over a step, and a
// fully actuated point. Also the angle wrapping shared by the navigation and grasp laws.
#pragma once

#include "geometry/polygon.h"

namespace rearm::reactive {

using geometry::Point;

// The fixed integration step of the closed loop (s): the reference implementation's ode45
// MaxStep (docs/reactive.md §6).
inline constexpr double kDefaultStep = 0.01;

// Below this |ω·dt|/2 the arc's chord factor sin(a)/a is evaluated by its Taylor series
// 1 − a²/6 + a⁴/120 (truncation error < a⁶/5040 ≈ 2e-28 here), so unicycle_step is smooth
// through ω = 0 and never divides by a tiny ω.
inline constexpr double kSincSeriesThreshold = 1e-4;

// A differential-drive command: forward speed v (m/s) and turn rate ω (rad/s).
struct Twist {
  double v = 0;
  double omega = 0;
};

// A planar pose: position x and heading ψ (rad).
struct Pose {
  Point x = Point::Zero();
  double psi = 0;
};

// The angle in (−π, π] equivalent to a modulo 2π. Throws rearm::Error when a is not finite.
double wrap_angle(double a);

// Exact solution of ẋ = v[cos ψ, sin ψ]ᵀ, ψ̇ = ω over dt with (v, ω) constant: an arc of
// radius v/ω (a straight segment when ω = 0). The returned heading is wrapped to (−π, π].
// Throws rearm::Error on non-finite inputs or dt < 0.
Pose unicycle_step(const Pose& pose, const Twist& u, double dt);

// Exact step of ẋ = velocity (constant over dt). Throws rearm::Error as unicycle_step.
Point holonomic_step(const Point& x, const Point& velocity, double dt);

}  // namespace rearm::reactive
