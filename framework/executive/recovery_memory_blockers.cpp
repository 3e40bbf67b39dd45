// Recovery unit "memory blockers" (RobustParams::fragments, requires memory; closed by memory,
// MOVE, GRASP, RELEASE): the last guide found a way only through what has been seen of the
// unknown obstacles, so objects may close every way together with them: fragment blockers'
// check, once per action, beside (not instead of) that unit's own once (sharing it left a
// RELEASE infeasible after the Fix mode this one started: measured). Not for DISASSEMBLE, whose
// drop point has alternatives: Fix mode for it drops the carried object by another
// DISASSEMBLE, which met the same hulls and nested Fix mode to its limit (measured).
#include "executive/blockers.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> memory_blockers(const Context& c, ActionState& a, const Pose& /*pose*/,
                                       Trigger& trigger, Tick /*tick*/) {
  if (a.once.memory || !a.target) return std::nullopt;
  a.once.memory = true;
  return closing_with_fragments(c, a, trigger.radius, trigger.center);
}

}  // namespace rearm::executive::units
