#include "sim/sim_config.h"

namespace rearm::sim {

SimConfig config_for(const scenario::Scenario& s, const SimConfig& base) {
  SimConfig c = base;
  c.dt = s.simulation.dt;
  c.velocity_iterations = s.simulation.velocity_iterations;
  c.position_iterations = s.simulation.position_iterations;
  return c;
}

}  // namespace rearm::sim
