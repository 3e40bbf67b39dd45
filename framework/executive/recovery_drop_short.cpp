// Recovery unit "drop short" (RobustParams::early_release; back-ups spent, and with
// RobustParams::drop goal cut off; DISASSEMBLE): a DISASSEMBLE still pressed against a dilation
// after every back-up, or whose drop points and the paper's target were all cut off, releases
// its object where it stands when the object is clear of every region there: DISASSEMBLE only
// has to move the object out of the way (paper §V-B), and an object left in the way is one
// that Fix mode can move again, where a wedged pair ends the task (measured: the pair pushed
// into a corner of F_k beside its drop point, four back-ups without a millimetre of motion).
#include "executive/interface_layer.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> drop_short(const Context& c, ActionState& a, const Pose& /*pose*/,
                                  Trigger& trigger, Tick tick) {
  if (c.map.carried() != a.object) return std::nullopt;
  const geometry::Disk m = *c.map.object(a.object);
  if (!clear_of_regions(m.center, m.radius, c.regions)) return std::nullopt;
  ++c.recoveries.early_releases;
  a.note = "released at " + point_text(m.center) + " short of the drop point (centre at " +
           point_text(trigger.center) + ")";
  a.phase = ActionPhase::kOpen;
  a.phase_start = tick.t;
  a.open_sent = false;
  return Advance{};  // stop for one tick, then open
}

}  // namespace rearm::executive::units
