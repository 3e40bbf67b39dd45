// Point-to-polygon distance and nearest point (doubles; the control law's inputs).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::geometry {

struct Nearest {
  Point point;      // nearest point on the boundary
  double distance;  // Euclidean distance to it (>= 0)
};

// Nearest point of the polygon's boundary to x.
Nearest nearest_on_boundary(const Polygon& p, const Point& x);
// Nearest point of the region's boundary (outer ring and holes) to x.
Nearest nearest_on_boundary(const Region& r, const Point& x);
// Distance from x to the closed polygon: 0 inside, else the boundary distance.
double distance(const Polygon& p, const Point& x);
// Signed distance from x to the polygon's boundary: negative inside (the boundary counts as
// inside, at distance 0). Clearance of a point to an obstacle, or to a workspace from within
// (negated).
double signed_distance(const Polygon& p, const Point& x);
// Ground-truth clearance (m) of the disk (center, radius) in a scene: to the workspace boundary
// (from inside), every obstacle polygon and every object disk but `skip` — the smallest of
// (signed distance of the centre) − radius, negative when overlapping. The kinematic plant and
// the Box2D world measure collisions and minimum clearance with it.
double disk_clearance(const Polygon& workspace, const std::vector<Polygon>& obstacles,
                      const std::vector<Disk>& objects, const Point& center, double radius,
                      std::optional<std::size_t> skip = std::nullopt);
// Euclidean distance from x to the polygon's axis-aligned bounding box (0 inside it): a lower
// bound of its distance to the polygon, without a square root per edge.
double box_distance(const Polygon& p, const Point& x);
// Nearest point of a segment [a, b] to x.
Point nearest_on_segment(const Point& a, const Point& b, const Point& x);

}  // namespace rearm::geometry
