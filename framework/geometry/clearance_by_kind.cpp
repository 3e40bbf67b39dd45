#include "geometry/clearance_by_kind.h"

#include <algorithm>

#include "geometry/distance.h"

namespace rearm::geometry {

void ClearanceByKind::lower(const Polygon& workspace, const std::vector<Polygon>& obstacles,
                            std::size_t familiar_count, const std::vector<Disk>& objects,
                            const Point& center, double radius, std::optional<std::size_t> skip) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const double c = signed_distance(obstacles[i], center) - radius;
    double& kind = i < familiar_count ? familiar : unknown;
    kind = std::min(kind, c);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (skip && *skip == i) continue;
    const double gap = (objects[i].center - center).norm() - objects[i].radius - radius;
    this->objects = std::min(this->objects, gap);
  }
  boundary = std::min(boundary, -signed_distance(workspace, center) - radius);
}

}  // namespace rearm::geometry
