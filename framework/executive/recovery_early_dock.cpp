// Recovery unit "early dock" (RobustParams::early_dock; stalled, GRASP): stopped beside the object
// short of the chosen approach point, within kEarlyDockReach of the approach circle, and the
// grasp from here passes grasp_candidates' checks with its pair centre in the exact pair
// freespace: the grasp aligns and docks from where the robot stands.
#include "executive/interface_layer.h"
#include "executive/planning.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

namespace {

bool docks_from_here(const Context& c, const ActionState& a, const Pose& pose) {
  if (c.map.carried()) return false;
  const geometry::Disk m = *c.map.object(a.object);
  const double gap = (pose.x - m.center).norm() - m.radius - c.p.robot_radius;
  if (gap > c.p.grasp.standoff + kEarlyDockReach) return false;
  const std::optional<GraspCandidate> g =
      grasp_from(c.map, a.object, c.p.robot_radius, pose.x, c.p.grasp);
  return g && geometry::contains(pair_freespace(c, a.object), g->pair_center);
}

}  // namespace

std::optional<Advance> early_dock(const Context& c, ActionState& a, const Pose& pose,
                                  Trigger& /*trigger*/, Tick tick) {
  if (!docks_from_here(c, a, pose)) return std::nullopt;
  ++c.recoveries.early_docks;
  a.phase = ActionPhase::kAlign;
  a.phase_start = tick.t;
  return restart();
}

}  // namespace rearm::executive::units
