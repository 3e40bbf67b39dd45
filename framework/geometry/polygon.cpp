// Double-precision measures of polygons. The exact predicates (validated, contains) live in
// predicates.cpp with CGAL.
#include "geometry/polygon.h"

#include <cmath>

namespace rearm::geometry {
namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

double Polygon::signed_area() const {
  double twice = 0;
  for (std::size_t i = 0, n = vertices.size(); i < n; ++i) {
    twice += cross(vertices[i], vertices[(i + 1) % n]);
  }
  return twice / 2;
}

double Polygon::area() const { return std::abs(signed_area()); }

Point Polygon::centroid() const {
  const double a = signed_area();
  if (vertices.empty()) return Point::Zero();
  if (std::abs(a) <= 0) {
    Point m = Point::Zero();
    for (const Point& v : vertices) m += v;
    return m / static_cast<double>(vertices.size());
  }
  Point c = Point::Zero();
  for (std::size_t i = 0, n = vertices.size(); i < n; ++i) {
    const Point& p = vertices[i];
    const Point& q = vertices[(i + 1) % n];
    c += (p + q) * cross(p, q);
  }
  return c / (6 * a);
}

bool Polygon::is_convex() const {
  const std::size_t n = vertices.size();
  if (n < 3 || signed_area() <= 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = vertices[i];
    const Point& b = vertices[(i + 1) % n];
    const Point& c = vertices[(i + 2) % n];
    if (cross(b - a, c - b) < 0) return false;
  }
  return true;
}

double Region::area() const {
  double a = outer.area();
  for (const Polygon& h : holes) a -= h.area();
  return a;
}

double total_area(const RegionSet& s) {
  double a = 0;
  for (const Region& r : s) a += r.area();
  return a;
}

}  // namespace rearm::geometry
