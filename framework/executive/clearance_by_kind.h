// The ground-truth clearance of the robot and of the object it holds, to each kind of thing in
// the world separately: familiar obstacles, unknown obstacles, the other movable objects and the
// workspace boundary (the plant's clearance is their minimum). The paper's scenes report them
// (metrics.json) to show how close to each kind the robot works.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "geometry/polygon.h"
#include "perception/world.h"

namespace rearm::executive {

struct ClearanceByKind {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  double familiar = kNone;  // m; +infinity when the world has none
  double unknown = kNone;
  double objects = kNone;
  double boundary = kNone;

  // Lowers each entry to the clearance (signed distance of the centre minus the radius,
  // negative when overlapping) of the disk at `center` with `radius` to that kind; `skip` is
  // an object left out (the held one, or the disk itself).
  void lower(const perception::World& world, const std::vector<geometry::Point>& object_centers,
             const geometry::Point& center, double radius, std::optional<std::size_t> skip);
};

}  // namespace rearm::executive
