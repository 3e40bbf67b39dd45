// The phases of an action after navigation (paper §V-B; docs/executive.md, "Actions"): GRASP
// aligns, docks, grips and (RobustParams::withdraw) withdraws; RELEASE and DISASSEMBLE stop,
// open the gripper and back off. Each advances the action by one tick.
#pragma once

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

// GRASP: turn in place until the gripper faces the object.
Advance align(const Context& c, ActionState& a, const Pose& pose, double t);
// GRASP: drive straight in to dock_gap from contact, then close the gripper (Advance::gripper).
Advance dock(const Context& c, ActionState& a, const Pose& pose, double t, double dt);
// GRASP: the tick after the close command, the map must report the object carried.
Advance grip(const Context& c, ActionState& a, const Pose& pose, double t);
// GRASP, robust variant: reverse straight along the docking line (grip chose how far).
Advance withdraw(const Context& c, ActionState& a, const Pose& pose, double t, double dt);
// RELEASE, DISASSEMBLE: open the gripper once the robot stood still for a tick (Context::last_u).
Advance open(const Context& c, ActionState& a, double t);
// RELEASE, DISASSEMBLE: back off straight until clear of the released object's dilation.
Advance back_off(const Context& c, ActionState& a, const Pose& pose, double t, double dt);

// The phase after navigation by one tick (align … back off, by ActionState::phase).
Advance advance(const Context& c, ActionState& a, const Pose& pose, double t, double dt);

}  // namespace rearm::executive
