// The SimConfig of a scenario: SimWorld takes its step and iteration counts from the SimConfig it
// is given, not from the scenario, so a run that should honour the scenario's `simulation`
// section builds its config here.
#pragma once

#include "scenario/scenario.h"
#include "sim/sim_world.h"

namespace rearm::sim {

// `base` with dt, velocity_iterations and position_iterations taken from s.simulation; the
// other fields (damping, densities, gripper) stay as in `base`. No validation here: SimWorld
// rejects an invalid config.
SimConfig config_for(const scenario::Scenario& s, const SimConfig& base = {});

}  // namespace rearm::sim
