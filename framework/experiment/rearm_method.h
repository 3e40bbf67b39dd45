// rearm itself as a method of the Monte Carlo runner (method.h): the paper's architecture run
// online in the Box2D world (run_scenario.h) — the robot discovers the obstacles with its
// sensor; nothing is planned offline. Its compute split is the executive's (mission controller,
// topology checks, diffeomorphism rebuilds, control); it has no planning time and no time limit
// but the scenario's simulated time budget.
#pragma once

#include <memory>

#include "experiment/method.h"

namespace rearm::experiment {

// The method "rearm".
std::unique_ptr<Method> make_rearm_method();

}  // namespace rearm::experiment
