// Recovery unit "contact back-up" (RobustParams::back_out, requires guide; stalled): pressed onto
// ∂F_k (within kContactClearance), the robot backs out first and follows a guide planned from
// where the back-up ends (the next rebuild), up to max_back_outs per action
// (ActionState::contact_outs). In discrete time the law of [7] can bring the centre onto ∂F_k,
// where LF(y) shrinks to a wedge and every goal beyond it projects onto y itself.
#include "executive/back_up.h"
#include "executive/recovery_units.h"
#include "geometry/distance.h"

namespace rearm::executive::units {

std::optional<Advance> contact_back_up(const Context& c, ActionState& a, const Pose& pose,
                                       Trigger& trigger, Tick tick) {
  if (!(a.back_up.contact_outs < c.p.robust.max_back_outs &&
        geometry::nearest_on_boundary(c.controller.mapped().freespace, trigger.center).distance <
            kContactClearance)) {
    return std::nullopt;
  }
  ++a.back_up.contact_outs;
  a.guide.path.clear();
  a.guide.pending = true;
  Advance b = begin_back_up(c, a, pose, tick.t, tick.dt, /*contact=*/true);
  if (b.kind != Advance::kStuck) return b;
  a.guide.pending = false;
  return std::nullopt;
}

}  // namespace rearm::executive::units
