// The recovery units (docs/executive.md, "Recoveries: causes, units and the policy table"), one
// per file recovery_<unit>.cpp. Internal to the recovery policy: only recovery_policy.cpp and
// the units include this header (tests/executive/recovery_policy_test checks it), so a unit
// runs only as a step of the policy's table, after its switches were checked there.
//
// Each takes the shared resources, the action's state, the pose, the trigger (cause, reason,
// the centre and radius where it was met) and the time; it returns the action's next step, or
// nullopt when it does not apply (its budget spent, its condition not met). It owns its slice
// of ActionState and its budget, and counts itself in RecoveryCounts.
#pragma once

#include <optional>

#include "executive/action.h"
#include "executive/context.h"
#include "executive/recovery.h"

namespace rearm::executive::units {

using UnitFunction = std::optional<Advance>(const Context& c, ActionState& a, const Pose& pose,
                                            Trigger& trigger, Tick tick);

UnitFunction release_in_region;
UnitFunction early_dock;
UnitFunction contact_back_up;
UnitFunction guide;
UnitFunction redrop;
UnitFunction narrow;
UnitFunction back_up;
UnitFunction convex;
UnitFunction fragment_blockers;
UnitFunction memory_blockers;
UnitFunction retarget;
UnitFunction drop_short;
UnitFunction object_blockers;
UnitFunction plan_among_fragments;

}  // namespace rearm::executive::units
