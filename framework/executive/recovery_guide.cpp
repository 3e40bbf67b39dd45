// Recovery unit "guide" (RobustParams::guide; stalled): the law's goal becomes the next waypoint
// of a path in the known freespace F_k (guides.h), within the guide budget
// (GuideParams::max_recoveries, renewed by RobustParams::persist); when none helps, the
// trigger's reason says why.
#include <string>

#include "executive/guides.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> guide(const Context& c, ActionState& a, const Pose& /*pose*/,
                             Trigger& trigger, Tick tick) {
  std::string note;
  if (plan_guide(c, a, trigger.center, tick.t, note)) return restart();
  trigger.reason += note;
  return std::nullopt;
}

}  // namespace rearm::executive::units
