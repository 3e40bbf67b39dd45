// A rearrangement plan (plan.h) as JSON, the format of the constructive class's witnesses
// (constructive.h; a sweep writes one beside each such instance as
// instances/<name>.witness.json) and of `rearm witness`. Documented in docs/experiments.md,
// "Plan files":
//   {"format": "rearm-plan", "version": 1,
//    "moves": [{"object": "M1", "held_at_start": false, "from": [x, y], "to": [x, y],
//               "transit": [[x, y], ...], "grasp_heading": h,
//               "transfer": [[x, y], ...], "release_heading": h}, ...],
//    "final_transit": [[x, y], ...], "final_arrangement": [[x, y], ...]}
// Objects are named as in the scenario (scenario object order gives the indices); every number
// is written in its shortest form that reads back exactly, so a plan round-trips bit for bit.
#pragma once

#include <string>
#include <vector>

#include "baselines/plan.h"

namespace rearm::baselines {

inline constexpr int kPlanFormatVersion = 1;

// The plan as JSON text (one line, ending in a newline). object_names: the scenario's objects
// in order; every move's object index must be in range (rearm::Error otherwise).
std::string plan_to_json(const Plan& plan, const std::vector<std::string>& object_names);

// The inverse. Throws rearm::Error naming `source` and the offending field for malformed JSON,
// another format or version, an unknown object name, a missing or mistyped field, or a
// non-finite number (JSON has none; null where a number belongs is refused).
Plan plan_from_json(const std::string& text, const std::vector<std::string>& object_names,
                    const std::string& source);

}  // namespace rearm::baselines
