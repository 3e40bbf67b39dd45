// The model space of docs/reactive.md §3–4: a convex enclosing boundary with disks (the
// familiar obstacles deformed by h, and the movable objects) and convex polygons (the unknown
// obstacles, left as they are). The navigation law of Arslan & Koditschek runs here.
#pragma once

#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::reactive {

struct ModelSpace {
  geometry::Polygon boundary;             // convex, counter-clockwise (F_e)
  std::vector<geometry::Disk> disks;      // model disks of familiar obstacles, movable objects
  std::vector<geometry::Polygon> convex;  // unknown convex obstacles (counter-clockwise)
};

}  // namespace rearm::reactive
