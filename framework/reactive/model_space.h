// The model space of docs/reactive.md §3–4: a convex enclosing boundary with disks (the
// familiar obstacles deformed by h, and the movable objects) and convex polygons (the unknown
// obstacles, left as they are). The navigation law of Arslan & Koditschek runs here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::reactive {

struct ModelSpace {
  geometry::Polygon boundary;             // convex, counter-clockwise (F_e)
  std::vector<geometry::Disk> disks;      // model disks of familiar obstacles, movable objects
  std::vector<geometry::Polygon> convex;  // unknown convex obstacles (counter-clockwise)
};

// Why y is not strictly inside the model freespace (outside or on the boundary F_e, inside or on
// a disk or a convex obstacle), nullopt when it is. The checked mode's test of the law's model
// point (executive/task_runner.h), written apart from local_freespace, which asks the same
// before every command.
std::optional<std::string> outside_model_freespace(const ModelSpace& m, const geometry::Point& y);

}  // namespace rearm::reactive
