// What the executive drives: a differential-drive robot with a gripper among movable objects
// (paper §II). A real plug point (docs/architecture.md, house style 2): the kinematic plant of
// this module (kinematic_plant.h) for tests without Box2D, the Box2D world of sim/ for the
// experiments. The plant is the ground truth; the executive sees it only through perception.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "reactive/kinematics.h"

namespace rearm::executive {

using geometry::Point;
using reactive::Pose;
using reactive::Twist;

inline constexpr std::size_t kMaxCollisionEvents = 100;

class Plant {
 public:
  virtual ~Plant() = default;

  virtual Pose pose() const = 0;
  // True current centre of movable object i (world order of perception::World::movable).
  virtual Point object_center(std::size_t i) const = 0;
  virtual std::size_t object_count() const = 0;

  // Closes the gripper on object i. Returns false (and holds nothing) when the object is not
  // within the gripper's reach in front of the robot.
  virtual bool grip(std::size_t i) = 0;
  virtual void release() = 0;
  virtual std::optional<std::size_t> held() const = 0;

  // Advances the plant by dt with (v, ω) held constant.
  virtual void step(const Twist& u, double dt) = 0;

  // Ground truth, independent of what the robot knows: the smallest clearance of the robot and
  // the held object to every obstacle, every other object and the workspace boundary (m;
  // negative when they overlap), and the number of collisions so far.
  virtual double clearance() const = 0;
  virtual int collisions() const = 0;
  // What touched what and when, one line per collision ("t = 12.34 s: robot touched object 2");
  // at most kMaxCollisionEvents are kept.
  virtual std::vector<std::string> collision_events() const { return {}; }
};

}  // namespace rearm::executive
