#include "geometry/clearance_by_kind.h"

#include <algorithm>

#include "geometry/distance.h"

namespace rearm::geometry {

void ClearanceByKind::lower(const Polygon& workspace, const std::vector<Polygon>& obstacles,
                            std::size_t familiar_count, const std::vector<Disk>& objects,
                            const Point& center, double radius, std::optional<std::size_t> skip) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    double& kind = i < familiar_count ? familiar : unknown;
    // Outside the box the signed distance is at least the box's distance (inside it, it may be
    // negative: computed).
    const double outside = box_distance(obstacles[i], center);
    if (outside > 0 && outside - radius >= kind) continue;
    kind = std::min(kind, signed_distance(obstacles[i], center) - radius);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (skip && *skip == i) continue;
    const double gap = (objects[i].center - center).norm() - objects[i].radius - radius;
    this->objects = std::min(this->objects, gap);
  }
  boundary = std::min(boundary, -signed_distance(workspace, center) - radius);
}

}  // namespace rearm::geometry
