// The navigation phase of an action (paper §IV–V; docs/executive.md, "Actions"): plan x* when
// the topology knowledge changed, rebuild the diffeomorphism of [7] when the map did (at once in
// the paper variant, once the news comes near with RobustParams::defer), follow the guide's
// waypoints, stop at x* (or DISASSEMBLE's early stop), and otherwise give the reactive law's
// command. Where it meets a cause of docs/executive.md's recovery table (stalled, centre not
// free, no law, goal cut off, closed by memory) it asks the recovery policy (recovery.h).
#pragma once

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

Advance navigate(const Context& c, ActionState& a, const Pose& pose, double t, double dt);

}  // namespace rearm::executive
