// Recovery unit "retarget" (RobustParams::drop; goal cut off, DISASSEMBLE): a newly seen unknown
// fragment took the drop point (the topology knowledge, which re-plans, is unchanged): another
// is chosen; after kMaxDropRetargets (ActionState::retargets), the paper's target
// (disassemble_target) and early stop serve, as near as the pair's freespace allows. Every
// target chosen after a rejection, drop point or the paper's, keeps kRejectedDropRadius (r +
// max ρ) from the rejected ones (measured: the paper's target, which the topology check picks
// without the fragments, was chosen again nine times in one tick, spending the budget on one
// point).
#include "executive/recovery_units.h"
#include "executive/targets.h"

namespace rearm::executive::units {

std::optional<Advance> retarget(const Context& c, ActionState& a, const Pose& /*pose*/,
                                Trigger& trigger, Tick /*tick*/) {
  if (!drop_points(c, a)) return std::nullopt;
  ++a.drop.retargets;
  a.drop.rejected.push_back(*a.target);
  a.planned = false;
  a.target.reset();
  Advance out = restart();
  out.reason = trigger.reason;
  return out;
}

}  // namespace rearm::executive::units
