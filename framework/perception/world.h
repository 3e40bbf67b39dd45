// Ground truth of the environment (paper §II; docs/reactive.md §1): what exists, whether or not
// the robot has seen it. Perception reads it through the sensor model (sensor.h) and keeps what
// the robot knows in the semantic map (semantic_map.h).
#pragma once

#include <string>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::perception {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

// A familiar obstacle P_i: a recognizable simple polygon (possibly non-convex), localized whole
// as soon as any part of it enters the sensor disk (paper §II).
struct FamiliarObstacle {
  std::string id;
  Polygon polygon;
};

// An unknown obstacle C_i: convex (the paper's strong-convexity assumption, §II), seen only as
// the fragment inside the sensor disk.
struct UnknownObstacle {
  std::string id;
  Polygon polygon;
};

// A movable object M_i: a disk whose position is known at all times (paper §II).
struct MovableObject {
  std::string id;
  Disk disk;
};

struct World {
  Polygon workspace;  // W: closed simple polygon, possibly non-convex
  std::vector<FamiliarObstacle> familiar;
  std::vector<UnknownObstacle> unknown;
  std::vector<MovableObject> movable;
};

// Checks a world given by a caller and returns it with every polygon counter-clockwise.
// Throws rearm::Error naming the offending item (its id) on: an invalid polygon (fewer than 3
// vertices, a non-finite vertex, a zero-length edge, self-intersection, zero area), a non-convex
// unknown obstacle, a movable object with a non-finite centre or a radius that is not finite and
// positive, an empty id, or an id used twice (ids share one namespace across the three kinds,
// since the executive names obstacles and objects alike).
World validated(const World& w);

// Checks one movable object (finite centre, finite positive radius, non-empty id); throws
// rearm::Error naming it.
void validate_movable(const MovableObject& m);

}  // namespace rearm::perception
