#include "sim/clearance.h"

#include <algorithm>

#include "geometry/distance.h"

namespace rearm::sim {

double disk_clearance(const StaticScene& scene, const std::vector<geometry::Disk>& objects,
                      const geometry::Point& center, double radius,
                      std::optional<std::size_t> skip) {
  double best = -geometry::signed_distance(scene.workspace, center) - radius;
  for (const geometry::Polygon& o : scene.obstacles) {
    best = std::min(best, geometry::signed_distance(o, center) - radius);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (skip && *skip == i) continue;
    best = std::min(best, (objects[i].center - center).norm() - objects[i].radius - radius);
  }
  return best;
}

}  // namespace rearm::sim
