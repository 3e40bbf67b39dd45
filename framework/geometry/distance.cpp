// Point-to-polygon distances in doubles (docs/architecture.md rule 5: doubles are for the
// control law; only the inside test is an exact predicate, contains()).
#include "geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace rearm::geometry {
namespace {

void check_finite(const Point& x, const char* what) {
  if (!std::isfinite(x.x()) || !std::isfinite(x.y())) {
    throw Error(std::string(what) + ": point is not finite");
  }
}

// Slack of the bounding-box skip of disk_clearance (m).
constexpr double kBoxSkipMargin = 1e-9;

}  // namespace

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

Point nearest_on_segment(const Point& a, const Point& b, const Point& x) {
  const Point d = b - a;
  const double len2 = d.squaredNorm();
  if (len2 <= 0) return a;  // degenerate segment: its only point
  const double t = (x - a).dot(d) / len2;
  if (t <= 0) return a;
  if (t >= 1) return b;
  return a + t * d;
}

Nearest nearest_on_boundary(const Polygon& p, const Point& x) {
  check_finite(x, "nearest_on_boundary");
  if (p.vertices.empty()) throw Error("nearest_on_boundary: polygon has no vertices");
  Nearest best{p.vertices.front(), std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point q = nearest_on_segment(p.vertices[i], p.vertices[(i + 1) % n], x);
    const double d = (q - x).norm();
    if (d < best.distance) best = Nearest{q, d};
  }
  return best;
}

Nearest nearest_on_boundary(const Region& r, const Point& x) {
  Nearest best = nearest_on_boundary(r.outer, x);
  for (const Polygon& h : r.holes) {
    const Nearest n = nearest_on_boundary(h, x);
    if (n.distance < best.distance) best = n;
  }
  return best;
}

double distance(const Polygon& p, const Point& x) {
  check_finite(x, "distance");
  if (contains(p, x)) return 0;
  return nearest_on_boundary(p, x).distance;
}

double signed_distance(const Polygon& p, const Point& x) {
  check_finite(x, "signed_distance");
  const double d = nearest_on_boundary(p, x).distance;
  return contains(p, x) ? -d : d;
}

// An obstacle whose bounding box lies farther from the centre than the clearance found so far
// (by kBoxSkipMargin, which covers the rounding of either distance) cannot lower it: the
// centre is then outside the obstacle, at least the box distance away. The result is the same
// double as without the skip.
double disk_clearance(const Polygon& workspace, const std::vector<Polygon>& obstacles,
                      const std::vector<Disk>& objects, const Point& center, double radius,
                      std::optional<std::size_t> skip) {
  double best = -signed_distance(workspace, center) - radius;
  for (const Polygon& o : obstacles) {
    if (!o.vertices.empty() && box_distance(o, center) - radius > best + kBoxSkipMargin) continue;
    best = std::min(best, signed_distance(o, center) - radius);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (skip && *skip == i) continue;
    best = std::min(best, (objects[i].center - center).norm() - objects[i].radius - radius);
  }
  return best;
}

}  // namespace rearm::geometry
