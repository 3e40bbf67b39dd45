// The robust variant's back-up (RobustParams::back_out, docs/executive.md "Recoveries"): a short
// motion of the robot (or the robot–object pair) out of a dilation it was pressed into, every
// step checked against everything known (motion_checks.h); with RobustParams::escape, the
// clearest straight line (robot alone) or the looked-ahead clearest move (pair). The back-up
// and contact back-up recovery units start it; navigation continues it while
// ActionState::backing.
#pragma once

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

// Starts a back-up and gives its first command (or the restart when it ends at once). A back-up
// out of a dilation counts against RobustParams::max_back_outs (ActionState::back_outs);
// `contact`: one off ∂F_k after the progress monitor fired (ActionState::contact_outs, counted
// by its unit). Both count in RecoveryCounts::back_outs.
Advance begin_back_up(const Context& c, ActionState& a, const Pose& pose, double t, double dt,
                      bool contact);
// The next command of the back-up in progress; at its end the action plans again (restart).
Advance back_out(const Context& c, ActionState& a, const Pose& pose, double t, double dt);

}  // namespace rearm::executive
