// The OMPL rearrangement baselines as methods of the Monte Carlo runner
// (experiment/method.h): "mrs" (B1), "birrt" (B2) and "replan" (B2 replanning on discovery),
// each planning under the trial's time limit and executing its plan in Box2D (run_baseline.h).
#pragma once

#include "experiment/method.h"

namespace rearm::baselines {

// Adds mrs, birrt and replan to the registry.
void register_methods(experiment::MethodRegistry& registry);

}  // namespace rearm::baselines
