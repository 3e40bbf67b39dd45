// The robust variant's guide paths (RobustParams::guide and its options track, face, widen,
// memory, persist; docs/executive.md, "Recoveries"): waypoints of a path in the known
// freespace F_k (guide_path.h) that the law of [7] follows as goals, or (track) that are
// followed straight, after the progress monitor fired.
#pragma once

#include <string>

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

// Plans a guide from `center` to x* in the current mapped space; false when the guide budget
// is spent or no path helps (`note` says which).
bool plan_guide(const Context& c, ActionState& a, const Point& center, double t, std::string& note);
// The guide in use planned again from `center` (empty when the raster finds no path).
void replan_guide(const Context& c, ActionState& a, const Point& center);

}  // namespace rearm::executive
