// The robust variant's checks of a motion that is not the reactive law's (a back-up, a turn, a
// tracked step, a withdrawal; docs/executive.md, "Robust variant"): each keeps the robot and the
// object it carries clear of everything the semantic map knows.
#pragma once

#include <string>

#include "executive/context.h"
#include "geometry/convex.h"

namespace rearm::executive {

// The step from `pose` to `next` keeps the robot, and the object it carries (rigidly: its offset
// turns with the heading), clear of everything the map knows; within kStepClearance of it, a
// step may not come closer.
bool step_clear(const Context& c, const Pose& pose, const Pose& next);
// Carrying: the move keeps the pair centre in the last mapped freespace F_k, or, when it is
// outside already, takes it no deeper. Without an object: always.
bool centre_kept(const Context& c, const Pose& pose, const Pose& next);
// The robot at `robot` and the gripped object `m` (id `object`) moved to `object_at` keep clear
// of everything known (the robot by the plan radius, the object by the contact margin).
bool reverse_clear(const Context& c, const geometry::Disk& m, const std::string& object,
                   const Point& robot, const Point& object_at);
// The centre (robot, or pair) lies inside the mapped freespace F_k, kContactClearance from ∂F_k.
bool centre_inside(const Context& c, const ActionState& a, const Pose& pose);

}  // namespace rearm::executive
