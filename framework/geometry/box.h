// Axis-aligned boxes of double coordinates, for cheap rejection before exact tests. Closed: boxes
// that touch overlap, and the distances are exact lower bounds of the distances between what the
// boxes contain.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/polygon.h"

namespace rearm::geometry {

struct Box {
  Point lo, hi;
};

// The smallest box holding the segment [p, q].
inline Box box_of(const Point& p, const Point& q) { return Box{p.cwiseMin(q), p.cwiseMax(q)}; }

// The smallest box holding every vertex of p (p has at least one vertex).
inline Box box_of(const Polygon& p) {
  Box b{p.vertices.front(), p.vertices.front()};
  for (const Point& v : p.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

inline bool overlaps(const Box& a, const Box& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y();
}

// Lower bound on the distance between anything in a and anything in b (0 when they overlap).
inline double gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, a.lo.x() - b.hi.x(), b.lo.x() - a.hi.x()});
  const double dy = std::max({0.0, a.lo.y() - b.hi.y(), b.lo.y() - a.hi.y()});
  return std::hypot(dx, dy);
}

inline double gap(const Box& a, const Point& x) { return gap(a, Box{x, x}); }

// Is some point of the box within distance r of x?
inline bool within(const Box& b, const Point& x, double r) {
  const Point d = (b.lo - x).cwiseMax(x - b.hi).cwiseMax(Point::Zero());
  return d.squaredNorm() <= r * r;
}

}  // namespace rearm::geometry
