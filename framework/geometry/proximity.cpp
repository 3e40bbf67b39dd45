#include "geometry/proximity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/distance.h"

namespace rearm::geometry {
namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

// Distance between segments [a, b] and [c, d]; 0 when they may touch (collinear or crossing:
// conservative, a rejected candidate is simply redrawn).
double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double abc = cross(b - a, c - a), abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c), cdb = cross(d - c, b - c);
  if (abc * abd <= 0 && cda * cdb <= 0) return 0;
  return std::min(
      {(nearest_on_segment(c, d, a) - a).norm(), (nearest_on_segment(c, d, b) - b).norm(),
       (nearest_on_segment(a, b, c) - c).norm(), (nearest_on_segment(a, b, d) - d).norm()});
}

// Whether two closed simple polygons are less than w apart (they overlap, one contains the
// other, or two edges come closer than w). Edge pairs whose bounding boxes are >= w apart are
// skipped (the box gap bounds the segments' distance from below).
bool closer_than(const Polygon& p, const Polygon& q, double w) {
  if (contains(q, p.vertices.front()) || contains(p, q.vertices.front())) {
    return true;
  }
  const Box qbox = box_of(q);
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const Box ebox = box_of(a, b);
    if (gap(ebox, qbox) >= w) continue;
    for (std::size_t j = 0, m = q.size(); j < m; ++j) {
      const Point& c = q.vertices[j];
      const Point& d = q.vertices[(j + 1) % m];
      if (gap(ebox, box_of(c, d)) >= w) continue;
      if (segment_distance(a, b, c, d) < w) return true;
    }
  }
  return false;
}

// How deep the deepest vertex of p lies inside q (0 when none does).
double vertex_depth(const Polygon& p, const Polygon& q, const Box& qbox) {
  double depth = 0;
  for (const Point& v : p.vertices) {
    if (gap(qbox, v) > 0) continue;
    depth = std::max(depth, -signed_distance(q, v));
  }
  return depth;
}

// Crossing-number point-in-polygon in doubles (the coverage grid's estimate only).
bool inside_by_crossings(const Polygon& p, const Point& x) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

// The nearest pair of boundary points (on p, on q) of two disjoint polygons, by the four
// endpoint-to-segment distances of every edge pair (exact for non-crossing edges).
std::pair<Point, Point> nearest_points(const Polygon& p, const Polygon& q) {
  std::pair<Point, Point> best{p.vertices.front(), q.vertices.front()};
  double d = std::numeric_limits<double>::infinity();
  auto consider = [&](const Point& a, const Point& b) {
    const double e = (a - b).norm();
    if (e < d) d = e, best = {a, b};
  };
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    for (std::size_t j = 0, m = q.size(); j < m; ++j) {
      const Point& c = q.vertices[j];
      const Point& e = q.vertices[(j + 1) % m];
      consider(a, nearest_on_segment(c, e, a));
      consider(nearest_on_segment(a, b, c), c);
    }
  }
  return best;
}

// Distance from x to the closed axis-aligned square of side `side` centred at c.
double square_distance(const Point& c, double side, const Point& x) {
  const double dx = std::max(std::abs(x.x() - c.x()) - side / 2, 0.0);
  const double dy = std::max(std::abs(x.y() - c.y()) - side / 2, 0.0);
  return std::hypot(dx, dy);
}

}  // namespace rearm::geometry
