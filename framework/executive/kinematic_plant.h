// The kinematic plant (no Box2D): the robot moves by exact zero-order-hold unicycle steps
// (reactive/kinematics.h), a gripped object moves rigidly with it, objects that are not held
// never move, and collisions are counted against the exact ground-truth geometry. The
// end-to-end tests run whole tasks on it; sim/ (Box2D) adds dynamics and contacts.
#pragma once

#include <vector>

#include "executive/plant.h"
#include "perception/world.h"

namespace rearm::executive {

// The gripper closes on an object whose boundary is within this distance (m) of the robot's
// boundary, with the object's centre within kGripCone (rad) of the heading.
inline constexpr double kGripReach = 0.01;
inline constexpr double kGripCone = 0.1;
// A collision starts when the clearance drops below −kPenetrationTolerance (m): exact contact
// (clearance 0 up to rounding) is not a collision, any overlap beyond rounding is.
inline constexpr double kPenetrationTolerance = 1e-9;

class KinematicPlant final : public Plant {
 public:
  // Validates the world (perception::validated) and the robot: finite radius > 0, finite
  // start pose. Throws rearm::Error.
  KinematicPlant(const perception::World& world, double robot_radius, const Pose& start);

  Pose pose() const override { return pose_; }
  Point object_center(std::size_t i) const override;
  std::size_t object_count() const override { return world_.movable.size(); }
  bool grip(std::size_t i) override;
  void release() override;
  std::optional<std::size_t> held() const override { return held_; }
  void step(const Twist& u, double dt) override;
  double clearance() const override { return clearance_; }
  int collisions() const override { return collisions_; }

  const perception::World& world() const { return world_; }

  // Ground-truth clearance of a disk to the workspace boundary, every familiar and unknown
  // obstacle and every object except `skip` (m; negative when overlapping). Exact geometry in
  // doubles: point-polygon distances and exact point location.
  double disk_clearance(const Point& center, double radius, std::optional<std::size_t> skip) const;

 private:
  double measure() const;

  perception::World world_;
  std::vector<geometry::Polygon> obstacles_;  // familiar and unknown, for the clearance
  std::vector<geometry::Disk> disks_;         // the objects' current disks, world order
  double radius_;
  Pose pose_;
  std::optional<std::size_t> held_;
  Point held_offset_ = Point::Zero();  // held object's centre in the robot frame
  double clearance_ = 0;
  bool in_contact_ = false;
  int collisions_ = 0;
};

}  // namespace rearm::executive
