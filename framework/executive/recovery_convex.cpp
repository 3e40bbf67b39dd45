// Recovery unit "convex" (RobustParams::convex_fallback; no law): Dh turned singular, or h took a
// centre that lies inside F_k, clear of ∂F_k, into a model obstacle (the purge of a cluster
// deforms space across a convex obstacle near it, the separation of [7] broken): the action's
// clusters become convex pieces, which keep h the identity there, and the law is rebuilt.
// Once per action (ActionState::convex_all).
#include "executive/motion_checks.h"
#include "executive/recovery_units.h"

namespace rearm::executive::units {

std::optional<Advance> convex(const Context& c, ActionState& a, const Pose& pose, Trigger& trigger,
                              Tick /*tick*/) {
  if (a.once.convex_all) return std::nullopt;
  if (trigger.model_point_outside && !centre_inside(c, a, pose)) return std::nullopt;
  a.once.convex_all = true;
  a.built = false;
  ++c.recoveries.singular;
  return restart();
}

}  // namespace rearm::executive::units
