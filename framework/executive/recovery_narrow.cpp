// Recovery unit "narrow" (RobustParams::narrow, requires guide; stalled): the law and every guide
// failed, yet the topology check finds x* reachable. With every movable object grown by
// kNarrowSlacks in turn (the fixed obstacles as they are), the first check that separates x* by
// objects names the objects that narrow the passage below what the law of [7] gets through:
// Fix mode moves them (paper §IV), then the action plans again. Once per action.
#include "core/text.h"
#include "executive/blockers.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> narrow(const Context& c, ActionState& a, const Pose& pose,
                              Trigger& /*trigger*/, Tick /*tick*/) {
  if (a.once.narrow || !a.target) return std::nullopt;
  a.once.narrow = true;
  const auto [rho, radius, center] = moving(c, a, pose);
  const std::optional<Narrowing> n =
      grown_blockers(c, c.map.familiar(), true, radius, center, *a.target);
  if (!n) return std::nullopt;
  std::optional<Advance> out =
      fix_mode_for(c, a, n->blocking,
                   "objects narrow the passage to x* below what the law got through (grown by " +
                       rearm::fixed(n->slack, 3) + " m): " + n->reason);
  if (out) ++c.recoveries.narrows;
  return out;
}

}  // namespace rearm::executive::units
