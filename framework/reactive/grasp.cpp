// GRASP alignment and approach point (see grasp.h).
#include "reactive/grasp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace rearm::reactive {

double bearing_error(double psi, const Point& x, const Point& object_center) {
  if (!std::isfinite(psi) || !x.allFinite() || !object_center.allFinite()) {
    throw Error("bearing_error: heading, position and object centre must be finite");
  }
  const Point d = object_center - x;
  if (d.x() == 0 && d.y() == 0) {
    throw Error("bearing_error: the robot is at the object centre (bearing undefined)");
  }
  return wrap_angle(std::atan2(d.y(), d.x()) - psi);
}

Twist align_command(double psi, const Point& x, const Point& object_center, const NavParams& p,
                    double k_align) {
  validate(p);
  if (!std::isfinite(k_align) || !(k_align > 0)) {
    throw Error("align_command: k_align must be finite and positive");
  }
  const double err = bearing_error(psi, x, object_center);
  return Twist{0.0, std::clamp(k_align * err, -p.omega_max, p.omega_max)};
}

bool aligned(double psi, const Point& x, const Point& object_center, double tol) {
  return std::abs(bearing_error(psi, x, object_center)) <= tol;
}

std::optional<Point> grasp_approach_point(const geometry::Disk& object, double robot_radius,
                                          const Point& robot,
                                          const std::function<bool(const Point&)>& is_free,
                                          int samples, double standoff) {
  if (!object.center.allFinite() || !std::isfinite(object.radius) || !robot.allFinite() ||
      !std::isfinite(robot_radius) || !std::isfinite(standoff)) {
    throw Error("grasp_approach_point: inputs must be finite");
  }
  if (robot_radius < 0 || standoff < 0 || object.radius < 0) {
    throw Error("grasp_approach_point: radii and standoff must be non-negative");
  }
  const double radius = object.radius + robot_radius + standoff;
  if (!(radius > 0)) throw Error("grasp_approach_point: approach circle has zero radius");
  if (samples < 1) throw Error("grasp_approach_point: need at least one sample");
  if (!is_free) throw Error("grasp_approach_point: no freespace predicate given");

  std::optional<Point> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < samples; ++i) {
    const double a = 2 * std::numbers::pi * i / samples;
    const Point q = object.center + radius * Point(std::cos(a), std::sin(a));
    const double d = (q - robot).squaredNorm();
    if (d < best_d && is_free(q)) {
      best_d = d;
      best = q;
    }
  }
  return best;
}

}  // namespace rearm::reactive
