// The Box2D world of sim/ as the executive's plant (executive/plant.h): the adapter between the
// two modules, which may not include each other (docs/architecture.md).
#pragma once

#include "executive/plant.h"
#include "scenario/scenario.h"
#include "sim/sim_world.h"

namespace rearm::experiment {

class SimPlant final : public executive::Plant {
 public:
  SimPlant(const scenario::Scenario& s, const sim::SimConfig& config);

  executive::Pose pose() const override;
  executive::Point object_center(std::size_t i) const override { return world_.object_center(i); }
  std::size_t object_count() const override { return world_.object_count(); }
  bool grip(std::size_t i) override { return world_.grip(i); }
  void release() override { world_.release(); }
  std::optional<std::size_t> held() const override { return world_.held(); }
  // dt must be the world's fixed step (Box2D steps at one rate); throws rearm::Error otherwise.
  void step(const executive::Twist& u, double dt) override;
  double clearance() const override { return world_.clearance(); }
  int collisions() const override { return world_.collisions(); }
  std::vector<std::string> collision_events() const override { return world_.collision_events(); }

  const sim::SimWorld& world() const { return world_; }

 private:
  sim::SimWorld world_;
  double dt_;
};

}  // namespace rearm::experiment
