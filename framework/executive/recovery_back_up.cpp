// Recovery unit "back-up" (RobustParams::back_out; centre not free): the robot (or pair) backs
// out of the dilation it was pressed into (back_up.h), then the action plans again; after
// max_back_outs per action (ActionState::back_outs) the cause "back-ups spent" is met, and the
// action ends stuck when none of its units applies.
#include <string>

#include "executive/back_up.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> back_up(const Context& c, ActionState& a, const Pose& pose, Trigger& trigger,
                               Tick tick) {
  if (a.back_up.count >= c.p.robust.max_back_outs) {
    Trigger spent{Cause::kBackUpsSpent,
                  trigger.reason + " (after " + std::to_string(a.back_up.count) + " back-ups)",
                  trigger.radius, pose.x};
    if (std::optional<Advance> next = recover(c, a, pose, spent, tick)) return next;
    return stuck(spent.reason);
  }
  return begin_back_up(c, a, pose, tick.t, tick.dt, /*contact=*/false);
}

}  // namespace rearm::executive::units
