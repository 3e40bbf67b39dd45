// An action's plan (paper §IV–V, Appendix III): its target x* and the topology check's verdict
// (reachable, blocked by fixed obstacles: infeasible, blocked by objects: Fix mode), with the
// knowledge it was computed for, so that the action plans again when the map's topology
// knowledge changes.
#pragma once

#include <string>

#include "executive/action.h"
#include "executive/context.h"
#include "executive/recovery.h"
#include "executive/release_pose.h"
#include "geometry/polygon.h"
#include "topology/topology_check.h"

namespace rearm::executive {

// The map's topology knowledge (familiar obstacles, movable objects, the carried one) differs
// from what the action's plan was computed for.
bool knowledge_changed(const Context& c, const ActionState& a);
// x* and the verdict: kCommand when x* is reachable (the plan remembered), else kInfeasible,
// kBlocked (B_M) or kStuck; throws topology::CenterNotFree when the centre is not free. Where
// the movable objects alone leave no grasp side or release pose, the cause "closed by objects"
// asks the recovery policy first.
Advance plan(const Context& c, ActionState& a, const Pose& pose, Tick tick);
void remember_plan(const Context& c, ActionState& a);
// The topology check of the action's x* (Appendix III); a RELEASE the plan-among-fragments unit
// sent on checks with the visible unknown fragments as fixed obstacles.
topology::TopologyResult check_target(const Context& c, const ActionState& a, double radius,
                                      const Point& center, const Point& target);
// The release pose's parameters (release_pose.h) for the pair's dilation radius `radius`.
ReleasePoseParams pose_params(const Context& c, double radius);
// The exact freespace of the pair once `object` is gripped (the object carried, radius
// r + contact margin + ρ_i + pair_margin): F_list of Appendix III; with_fragments: the visible
// unknown fragments counted as fixed obstacles (blockers.h, fixed_with_fragments).
geometry::RegionSet pair_freespace(const Context& c, const std::string& object,
                                   bool with_fragments = false);

}  // namespace rearm::executive
