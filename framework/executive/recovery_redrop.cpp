// Recovery unit "redrop" (RobustParams::redrop, requires guide and drop; stalled, DISASSEMBLE):
// the law and every guide failed to reach the drop point; it is rejected with its surroundings
// (targets.h, drop_point) and the action plans again with a fresh guide budget, up to
// kMaxRedrops per action.

#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> redrop(const Context& c, ActionState& a, const Pose& /*pose*/,
                              Trigger& /*trigger*/, Tick tick) {
  if (!a.target || a.drop.redrops >= kMaxRedrops) return std::nullopt;
  ++a.drop.redrops;
  ++c.recoveries.redrops;
  a.drop.rejected.push_back(*a.target);
  a.planned = false;
  a.target.reset();
  a.guide.restart();
  a.monitor.reset(tick.t);
  return restart();
}

}  // namespace rearm::executive::units
