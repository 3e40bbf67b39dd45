#include "executive/path_tracker.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rearm::executive {

using geometry::Point;

reactive::Twist track_command(const reactive::Pose& pose, double rho,
                              const geometry::Point& waypoint, const reactive::NavParams& p) {
  if (!pose.x.allFinite() || !std::isfinite(pose.psi) || !waypoint.allFinite() ||
      !std::isfinite(rho) || rho < 0) {
    throw Error("track_command: pose, waypoint and object radius must be finite, radius >= 0");
  }
  const Point heading(std::cos(pose.psi), std::sin(pose.psi));
  if (rho > 0) {
    // The pair centre as a fully actuated point (reactive.md §4): ẋ_c = T(ψ)[v, ω]ᵀ.
    const Point xc = pose.x + rho * heading;
    Point u = p.k_v * (waypoint - xc);
    if (u.norm() > p.v_max) u *= p.v_max / u.norm();
    const Point normal(-heading.y(), heading.x());
    const reactive::Twist raw{heading.dot(u), normal.dot(u) / rho};
    return reactive::limit_common(raw, p.v_max, p.omega_max);
  }
  const Point d = waypoint - pose.x;
  const double dist = d.norm();
  if (dist == 0) return {};
  const double e = reactive::wrap_angle(std::atan2(d.y(), d.x()) - pose.psi);
  const double omega = std::clamp(kTrackTurnGain * e, -p.omega_max, p.omega_max);
  if (std::abs(e) > kTrackTurn) return {0, omega};
  const double scale = (1 - std::abs(e) / kTrackTurn) * std::cos(e);
  return {std::min(p.v_max, p.k_v * dist) * scale, omega};
}

}  // namespace rearm::executive
