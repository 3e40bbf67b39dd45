// The GRASP action's reactive pieces (paper §V-B; docs/reactive.md §4 last bullet): the robot
// navigates to a free point on the boundary of the object dilated by the robot radius, then
// turns in place until its gripper (the front, heading ψ) faces the object's centre.
#pragma once

#include <functional>
#include <optional>

#include "geometry/convex.h"
#include "reactive/kinematics.h"
#include "reactive/navigation.h"

namespace rearm::reactive {

// The robot counts as facing the object when |wrap(bearing − ψ)| <= this (rad, ≈ 1.1°).
inline constexpr double kAlignTolerance = 0.02;
// Gain of the in-place turn (1/s): ω = k_align · wrap(bearing − ψ), saturated.
inline constexpr double kDefaultAlignGain = 1.0;
// The approach point lies this far (m) outside the dilated object boundary ρ_i + r, so the
// robot stops just short of contact before the gripper closes.
inline constexpr double kGraspStandoff = 0.02;
// Candidate approach points tried around the object.
inline constexpr int kDefaultApproachSamples = 72;

// Bearing from x to the object centre minus ψ, wrapped to (−π, π]. Throws rearm::Error on
// non-finite input or when x coincides with the centre (the bearing is undefined).
double bearing_error(double psi, const Point& x, const Point& object_center);

// Turn in place toward the object: v = 0, ω = k_align · bearing_error, |ω| <= omega_max.
// Throws as bearing_error, and on a non-positive or non-finite k_align.
Twist align_command(double psi, const Point& x, const Point& object_center, const NavParams& p,
                    double k_align = kDefaultAlignGain);

// |bearing_error| <= tol.
bool aligned(double psi, const Point& x, const Point& object_center, double tol = kAlignTolerance);

// The GRASP target: among `samples` points evenly spaced on the circle of radius
// object.radius + robot_radius + standoff around object.center, the one with is_free(q) (the
// caller's freespace test, e.g. in the mapped space) nearest to `robot`; nullopt when none is
// free. Throws rearm::Error on non-finite input, a non-positive total radius, negative
// robot_radius or standoff, or samples < 1.
std::optional<Point> grasp_approach_point(const geometry::Disk& object, double robot_radius,
                                          const Point& robot,
                                          const std::function<bool(const Point&)>& is_free,
                                          int samples = kDefaultApproachSamples,
                                          double standoff = kGraspStandoff);

}  // namespace rearm::reactive
