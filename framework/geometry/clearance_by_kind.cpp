#include "geometry/clearance_by_kind.h"

#include <algorithm>
#include <cmath>

#include "geometry/distance.h"

namespace rearm::geometry {
namespace {

// Distance from x to the polygon's bounding box (0 inside it): a lower bound of the distance to
// the polygon, found without a square root per edge; the exact distance is computed only when
// this bound could lower an entry (most obstacles are far from the robot).
double box_distance(const Polygon& p, const Point& x) {
  double x0 = p.vertices.front().x(), x1 = x0, y0 = p.vertices.front().y(), y1 = y0;
  for (const Point& v : p.vertices) {
    x0 = std::min(x0, v.x());
    x1 = std::max(x1, v.x());
    y0 = std::min(y0, v.y());
    y1 = std::max(y1, v.y());
  }
  const double dx = std::max({x0 - x.x(), 0.0, x.x() - x1});
  const double dy = std::max({y0 - x.y(), 0.0, x.y() - y1});
  return std::hypot(dx, dy);
}

}  // namespace

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
