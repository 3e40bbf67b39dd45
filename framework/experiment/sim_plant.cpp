#include "experiment/sim_plant.h"

#include <string>

#include "core/error.h"

namespace rearm::experiment {

SimPlant::SimPlant(const scenario::Scenario& s, const sim::SimConfig& config)
    : world_(s, config), dt_(config.dt) {}

executive::Pose SimPlant::pose() const {
  const sim::Pose p = world_.pose();
  return executive::Pose{p.x, p.psi};
}

void SimPlant::step(const executive::Twist& u, double dt) {
  REARM_REQUIRE(dt == dt_, "sim plant: the Box2D world steps at ", dt_, " s, asked ", dt);
  world_.step(u.v, u.omega);
}

}  // namespace rearm::experiment
