// Recovery unit "fragment blockers" (RobustParams::fragments; goal cut off, MOVE, GRASP, RELEASE):
// the reactive controller finds x* cut off from the centre where the topology check, which
// models the familiar obstacles and the objects only (paper Appendix III), did not: visible
// unknown fragments close the way, with objects or without. The check runs again with the
// fragments as fixed obstacles (blockers.h); objects that close the way with them are moved by
// Fix mode (paper §IV). Once per action.
#include "executive/blockers.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> fragment_blockers(const Context& c, ActionState& a, const Pose& /*pose*/,
                                         Trigger& trigger, Tick /*tick*/) {
  if (a.once.fragments || !a.target) return std::nullopt;
  a.once.fragments = true;
  return closing_with_fragments(c, a, trigger.radius, trigger.center);
}

}  // namespace rearm::executive::units
