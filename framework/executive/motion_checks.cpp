#include "executive/motion_checks.h"

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "executive/interface_layer.h"
#include "geometry/distance.h"
#include "reactive/grasp.h"

namespace rearm::executive {

// The step from `pose` to `next` keeps the robot, and the object it carries (rigidly: its offset
// turns with the heading), clear of everything the map knows.
bool step_clear(const Context& c, const Pose& pose, const Pose& next) {
  // Within kStepClearance of what is known, a step may not come closer: a back-up that slid
  // along an unknown obstacle at 0.1 mm, choosing a new move every few steps, touched it in
  // Box2D (measured).
  auto kept = [&](const Point& from, const Point& to, double radius) {
    const double after = known_clearance(c.map, to) - radius;
    return after >= kStepClearance || after >= known_clearance(c.map, from) - radius;
  };
  if (known_clearance(c.map, next.x) < c.p.robot_radius ||
      !kept(pose.x, next.x, c.p.robot_radius)) {
    return false;
  }
  if (const std::optional<std::string> carried = c.map.carried()) {
    const geometry::Disk m = *c.map.object(*carried);
    const Point moved = next.x + Eigen::Rotation2Dd(next.psi - pose.psi) * (m.center - pose.x);
    if (known_clearance(c.map, moved) < m.radius || !kept(m.center, moved, m.radius)) return false;
  }
  return true;
}

// Robust variant, carrying: does a checked move (a turn toward the goal, a back-up) keep the pair
// centre in the last mapped freespace F_k, or, when it is outside already, take it no deeper?
// The pair centre lies ahead of the axle, so a turn in place swings it: turns after a back-up
// took it 3 cm into a dilation (measured), where the law of [7] cannot run (its model point lies
// in a model obstacle) and four back-ups were spent in vain. Without an object: always.
bool centre_kept(const Context& c, const Pose& pose, const Pose& next) {
  const std::optional<std::string> carried = c.map.carried();
  if (!carried || c.controller.mapped().freespace.outer.size() < 3) return true;
  const double rho = object_radius(c, *carried);
  const geometry::Region& free = c.controller.mapped().freespace;
  auto depth = [&](const Pose& q) {
    const Point xc = reactive::pair_center(q.x, q.psi, rho);
    const double d = geometry::nearest_on_boundary(free, xc).distance;
    return geometry::contains(free, xc) ? -d : d;
  };
  const double after = depth(next);
  return after <= 0 || after <= depth(pose);
}

// The robot at `robot` and the gripped object `m` (id `object`) moved to `object_at` keep clear
// of everything known (the robot by the plan radius, the object by the contact margin).
bool reverse_clear(const Context& c, const geometry::Disk& m, const std::string& object,
                   const Point& robot, const Point& object_at) {
  return known_clearance(c.map, robot, object) >= plan_radius(c) &&
         known_clearance(c.map, object_at, object) >= m.radius + c.p.robust.contact_margin;
}

// Is the centre (robot, or pair) inside the mapped freespace F_k, kContactClearance from ∂F_k?
bool centre_inside(const Context& c, const ActionState& a, const Pose& pose) {
  const Point center = moving(c, a, pose).center;
  const geometry::Region& free = c.controller.mapped().freespace;
  return geometry::contains(free, center) &&
         geometry::nearest_on_boundary(free, center).distance >= kContactClearance;
}

}  // namespace rearm::executive
