// Recovery unit "plan among fragments" (RobustParams::fragments; goal cut off, GRASP, RELEASE):
// the reactive controller finds x* cut off where the topology check, which models the familiar
// obstacles and the objects only (paper Appendix III), did not, and no object closes the way
// together with the visible unknown fragments (the fragment-blockers unit came first). x* is
// the interface layer's choice, not the task's: a grasp side of M (§IV) and a release point in
// ℓ (RELEASE(M, ℓ) holds wherever in ℓ the object lies, §II-B). The action plans again with the
// fragments as fixed obstacles (planning.cpp), so that the side, release point or pose is one
// they leave open; only a target that they and the familiar obstacles cut off ends the action
// infeasible. Fragments grow as the robot looks: at most kMaxFragmentRetargets per action.
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> plan_among_fragments(const Context& c, ActionState& a, const Pose& /*pose*/,
                                            Trigger& trigger, Tick /*tick*/) {
  if (a.fragment_plan.retargets >= kMaxFragmentRetargets) return std::nullopt;
  if (a.kind == ActionKind::kRelease && c.map.carried() != a.object) return std::nullopt;
  ++a.fragment_plan.retargets;
  a.fragment_plan.on = true;
  a.planned = false;
  a.target.reset();
  a.pose.reset();
  a.pose_stretch = false;
  Advance out = restart();
  out.reason = trigger.reason;
  return out;
}

}  // namespace rearm::executive::units
