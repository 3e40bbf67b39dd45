// Ground-truth clearance of a disk in the simulated world (docs/experiments.md: "also log
// minimum clearance"): exact geometry in doubles, measured exactly as the kinematic plant
// measures it (executive::KinematicPlant::disk_clearance), independent of Box2D's contact
// skin and float positions of the shapes.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::sim {

// The static scene: the workspace and every familiar and unknown obstacle, each validated
// (geometry::validated).
struct StaticScene {
  geometry::Polygon workspace;
  std::vector<geometry::Polygon> obstacles;
};

// Clearance (m) of the disk (center, radius) to the workspace boundary (from inside), every
// obstacle and every object but `skip`: the smallest of (signed distance of the centre) − radius,
// negative when overlapping.
double disk_clearance(const StaticScene& scene, const std::vector<geometry::Disk>& objects,
                      const geometry::Point& center, double radius,
                      std::optional<std::size_t> skip);

}  // namespace rearm::sim
