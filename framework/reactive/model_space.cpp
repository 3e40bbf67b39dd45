#include "reactive/model_space.h"

#include "geometry/distance.h"

namespace rearm::reactive {

std::optional<std::string> outside_model_freespace(const ModelSpace& m, const geometry::Point& y) {
  if (!y.allFinite()) return "y is not finite";
  if (m.boundary.size() < 3 || !geometry::convex_contains(m.boundary, y) ||
      !(geometry::nearest_on_boundary(m.boundary, y).distance > 0)) {
    return "y is not strictly inside the model boundary";
  }
  for (std::size_t i = 0; i < m.disks.size(); ++i) {
    if (!((y - m.disks[i].center).norm() > m.disks[i].radius)) {
      return "y is inside or on model disk " + std::to_string(i);
    }
  }
  for (std::size_t i = 0; i < m.convex.size(); ++i) {
    const geometry::Polygon& c = m.convex[i];
    if (c.size() < 3) continue;
    if (geometry::convex_contains(c, y) || !(geometry::nearest_on_boundary(c, y).distance > 0)) {
      return "y is inside or on convex obstacle " + std::to_string(i);
    }
  }
  return std::nullopt;
}

}  // namespace rearm::reactive
