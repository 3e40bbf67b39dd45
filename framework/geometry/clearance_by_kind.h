// The ground-truth clearance of a disk (the robot, or the object it holds) to each kind of thing
// in the world separately: familiar obstacles, unknown obstacles, movable objects and the
// workspace boundary (their minimum is the plant's clearance). The paper's scenes report them
// (metrics.json) to show how close to each kind the robot works; rearm's closed loop
// (executive/task_runner.h) and the baselines' executor (baselines/executor.h) fill them.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::geometry {

struct ClearanceByKind {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  double familiar = kNone;  // m; +infinity while nothing of that kind was measured
  double unknown = kNone;
  double objects = kNone;
  double boundary = kNone;

  // Lowers each entry to the clearance (signed distance of the centre minus the radius,
  // negative when overlapping) of the disk (center, radius) to that kind. `obstacles` lists the
  // familiar obstacles first, then (from index `familiar_count`) the unknown ones; `skip` is
  // an object left out (the held one).
  void lower(const Polygon& workspace, const std::vector<Polygon>& obstacles,
             std::size_t familiar_count, const std::vector<Disk>& objects, const Point& center,
             double radius, std::optional<std::size_t> skip);
};

}  // namespace rearm::geometry
