// One Box2D world per run (docs/experiments.md, "Box2D world"): the static workspace boundary
// and obstacles, dynamic damped disk objects, a dynamic disk robot driven by (v, ω) every step,
// a weld-joint gripper, contact accounting and minimum clearance, at a fixed step with fixed
// iteration counts (same binary + same input = same result). Box2D stays inside this module's
// .cpp files.
//
// Facts checked on Debian 12's Box2D 2.4.1 (docs/experiments.md): the robot must be dynamic (a
// kinematic body makes no contacts with static bodies); b2PolygonShape::Set takes convex
// polygons of at most 8 vertices (non-convex obstacles are partitioned, large pieces split);
// chain shapes are one-sided (the workspace boundary is wound so the robot is inside); a
// collision is a BeginContact that IsTouching() between the robot (or the held object) and
// anything it is not holding.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::sim {

struct Pose {
  geometry::Point x = geometry::Point::Zero();
  double psi = 0;
};

struct SimConfig {
  double dt = 0.01;  // s
  int velocity_iterations = 8;
  int position_iterations = 3;
  double object_linear_damping = 5.0;   // 1/s: objects slide to rest on the floor
  double object_angular_damping = 5.0;  // 1/s
  double object_density = 1.0;          // kg/m²
  double robot_density = 10.0;          // kg/m²
  double grip_reach = 0.01;             // m between the robot's and the object's boundaries to grip
  double grip_cone = 0.1;               // rad between the heading and the bearing to the object
};

class SimWorld {
 public:
  // Builds the world from a validated scenario (scenario::validate): the robot at its start
  // pose, every object at its start, every familiar and unknown obstacle static. Throws
  // rearm::Error for an invalid configuration.
  SimWorld(const scenario::Scenario& s, const SimConfig& config = {});
  ~SimWorld();
  SimWorld(const SimWorld&) = delete;
  SimWorld& operator=(const SimWorld&) = delete;

  Pose pose() const;
  geometry::Point object_center(std::size_t i) const;  // scenario object order
  std::size_t object_count() const;

  // Creates the weld joint when object i is within grip_reach of the robot's boundary and
  // within grip_cone of its heading; false (nothing held) otherwise.
  bool grip(std::size_t i);
  void release();
  std::optional<std::size_t> held() const;

  // Sets the robot's velocity from (v, ω) (and the held object's to the rigid-body velocity
  // of the pair) and advances one fixed step.
  void step(double v, double omega);
  double time() const;

  // Contact accounting: collisions so far (touching BeginContacts between the robot or the held
  // object and anything else but each other), and the smallest ground-truth clearance seen
  // (exact geometry, as the kinematic plant measures it: negative when overlapping).
  int collisions() const;
  // One line per collision, "t = 12.34 s: robot touched object 2" (boundary, familiar k,
  // unknown k, object k; "held object k" for the carried one), the first 100 kept.
  std::vector<std::string> collision_events() const;
  double clearance() const;      // now
  double min_clearance() const;  // over every step so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rearm::sim
