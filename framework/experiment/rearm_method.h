// rearm itself as a method of the Monte Carlo runner (method.h): the paper's architecture run
// online in the Box2D world (run_scenario.h) — the robot discovers the obstacles with its
// sensor; nothing is planned offline. Its compute split is the executive's (mission controller,
// topology checks, diffeomorphism rebuilds, control); it has no planning time and no time limit
// but the scenario's simulated time budget.
#pragma once

#include <memory>
#include <vector>

#include "experiment/method.h"

namespace rearm::experiment {

// The method "rearm": the robust variant with every extension (executive::RobustParams).
std::unique_ptr<Method> make_rearm_method();

// rearm with the scenario's controller variant overridden, for ablations
// (experiments/sweeps/README.md, "Variants"): "rearm-paper" (the paper's choices, no
// extension), "rearm-no<switch>" for each switch of
// the switch registry (core/switches.h), e.g. "rearm-noguide", "rearm-noearlyrelease" (that
// extension off).
std::vector<std::unique_ptr<Method>> make_rearm_variants();

// Registers "rearm" and its variants.
void register_rearm_methods(MethodRegistry& r);

}  // namespace rearm::experiment
