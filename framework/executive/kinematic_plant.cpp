#include "executive/kinematic_plant.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

Point rotate(const Point& p, double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  return Point(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

}  // namespace

KinematicPlant::KinematicPlant(const perception::World& world, double robot_radius,
                               const Pose& start)
    : world_(perception::validated(world)), radius_(robot_radius), pose_(start) {
  REARM_REQUIRE(std::isfinite(robot_radius) && robot_radius > 0,
                "kinematic plant: robot radius must be finite and > 0, got ", robot_radius);
  if (!start.x.allFinite() || !std::isfinite(start.psi)) {
    throw Error("kinematic plant: the start pose is not finite");
  }
  for (const auto& f : world_.familiar) obstacles_.push_back(f.polygon);
  for (const auto& u : world_.unknown) obstacles_.push_back(u.polygon);
  for (const auto& m : world_.movable) disks_.push_back(m.disk);
  clearance_ = measure();
  in_contact_ = clearance_ < -kPenetrationTolerance;
}

Point KinematicPlant::object_center(std::size_t i) const {
  if (i >= world_.movable.size()) {
    throw Error("kinematic plant: object index " + std::to_string(i) + " out of range");
  }
  return world_.movable[i].disk.center;
}

bool KinematicPlant::grip(std::size_t i) {
  if (i >= world_.movable.size()) {
    throw Error("kinematic plant: object index " + std::to_string(i) + " out of range");
  }
  if (held_) return false;
  const geometry::Disk& d = world_.movable[i].disk;
  const Point rel = d.center - pose_.x;
  const double gap = rel.norm() - radius_ - d.radius;
  if (gap > kGripReach) return false;
  const double bearing =
      std::remainder(std::atan2(rel.y(), rel.x()) - pose_.psi, 2 * std::acos(-1.0));
  if (std::abs(bearing) > kGripCone) return false;
  held_ = i;
  held_offset_ = rotate(rel, -pose_.psi);
  return true;
}

void KinematicPlant::release() { held_.reset(); }

void KinematicPlant::step(const Twist& u, double dt) {
  pose_ = reactive::unicycle_step(pose_, u, dt);
  if (held_) {
    const Point c = pose_.x + rotate(held_offset_, pose_.psi);
    world_.movable[*held_].disk.center = c;
    disks_[*held_].center = c;
  }
  clearance_ = measure();
  const bool contact = clearance_ < -kPenetrationTolerance;
  if (contact && !in_contact_) ++collisions_;
  in_contact_ = contact;
}

double KinematicPlant::disk_clearance(const Point& c, double r,
                                      std::optional<std::size_t> skip) const {
  return geometry::disk_clearance(world_.workspace, obstacles_, disks_, c, r, skip);
}

double KinematicPlant::measure() const {
  double c = disk_clearance(pose_.x, radius_, held_);
  if (held_) {
    const geometry::Disk& d = world_.movable[*held_].disk;
    c = std::min(c, disk_clearance(d.center, d.radius, held_));
  }
  return c;
}

}  // namespace rearm::executive
