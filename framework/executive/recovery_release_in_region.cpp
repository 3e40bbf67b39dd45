// Recovery unit "release in region" (RobustParams::early_release; stalled, RELEASE): RELEASE(M, ℓ)
// holds once M lies in ℓ (paper §II-B), wherever in ℓ: a pair stopped short of the centroid with
// M goal_tolerance inside ℓ releases here.
#include "executive/recovery_units.h"
#include "geometry/distance.h"
#include "geometry/polygon.h"

namespace rearm::executive::units {

std::optional<Advance> release_in_region(const Context& c, ActionState& a, const Pose& /*pose*/,
                                         Trigger& trigger, Tick tick) {
  if (c.map.carried() != a.object) return std::nullopt;
  const geometry::Disk m = *c.map.object(a.object);
  const geometry::Polygon& goal = region(c, a.region).polygon;
  if (!(geometry::contains(goal, m.center) &&
        -geometry::signed_distance(goal, m.center) >= c.p.goal_tolerance)) {
    return std::nullopt;
  }
  ++c.recoveries.early_releases;
  a.note = "early release at " + point_text(m.center) + " inside " + a.region + " (" +
           trigger.reason + ")";
  a.phase = ActionPhase::kOpen;
  a.phase_start = tick.t;
  a.open_sent = false;
  return Advance{};  // stop for one tick, then open
}

}  // namespace rearm::executive::units
