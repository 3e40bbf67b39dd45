// The robust variant's recoveries (docs/executive.md, "Recoveries: causes, units and the policy
// table"): an action that meets a cause (the progress monitor fired, its centre left the
// freespace, the law has no command, x* was cut off, the guide's way was closed by memory, the
// back-ups were spent, the plan found no grasp side or release pose among the objects) asks the
// policy, which tries the units its table names for the cause and
// the action's kind, in order, each only when its switches are on. The first that applies gives
// the action's next step; when none does, the site that met the cause ends the action as the
// paper does.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

enum class Cause {
  kStalled,
  kCentreNotFree,
  kNoLaw,
  kGoalCutOff,
  kClosedByMemory,
  kBackUpsSpent,
  kClosedByObjects
};
inline constexpr std::size_t kCauseCount = 7;
// "stalled", "centre not free", "no law", "goal cut off", "closed by memory", "back-ups spent",
// "closed by objects".
const char* to_string(Cause cause);

struct Trigger {
  Cause cause = Cause::kStalled;
  std::string reason;  // why; a unit that tried and failed may add to it (the guide's note)
  double radius = 0;   // the law's dilation radius where the cause was met
  Point center = Point::Zero();      // the controlled centre (back-ups spent: the robot's position)
  bool model_point_outside = false;  // no law: h took the centre into a model obstacle
};

struct Tick {
  double t = 0;   // s
  double dt = 0;  // s
};

// The first next step of the policy's units for the trigger; nullopt when none applies.
std::optional<Advance> recover(const Context& c, ActionState& a, const Pose& pose, Trigger& trigger,
                               Tick tick);

}  // namespace rearm::executive
