#include "executive/clearance_by_kind.h"

#include <algorithm>

#include "geometry/distance.h"

namespace rearm::executive {

void ClearanceByKind::lower(const perception::World& world,
                            const std::vector<geometry::Point>& object_centers,
                            const geometry::Point& center, double radius,
                            std::optional<std::size_t> skip) {
  for (const auto& f : world.familiar) {
    familiar = std::min(familiar, geometry::signed_distance(f.polygon, center) - radius);
  }
  for (const auto& u : world.unknown) {
    unknown = std::min(unknown, geometry::signed_distance(u.polygon, center) - radius);
  }
  for (std::size_t i = 0; i < world.movable.size(); ++i) {
    if (skip && *skip == i) continue;
    const double gap = (object_centers[i] - center).norm() - world.movable[i].disk.radius - radius;
    objects = std::min(objects, gap);
  }
  boundary = std::min(boundary, -geometry::signed_distance(world.workspace, center) - radius);
}

}  // namespace rearm::executive
