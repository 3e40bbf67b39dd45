// Dilation by a disk (docs/reactive.md §2).
//  - dilate_round: exact Minkowski sum (CGAL, exact kernel) with the regular n-gon whose
//    edges touch the circle of radius r (vertices at r / cos(π/n)). The n-gon contains the
//    disk, so the result contains the exact dilation; its boundary lies within
//    r·(1/cos(π/n) − 1) <= kMaxDilationError·r of the exact boundary. (The n-gon's and the
//    result's vertices are doubles: "contains" holds up to their rounding, ~1e-16·r.)
//  - dilate_miter: the mitered offset of the whole polygon, built exactly (unite_all) as the
//    union of the polygon, each edge's outward strip of width r, and at each convex vertex
//    the miter corner bounded by the two offset lines; a corner whose miter point lies
//    farther than limit·r (kMiterLimit by default) from the vertex is bevelled by the line
//    perpendicular to the corner's bisector at distance kMiterLimit·r. Reflex vertices need no
//    corner: the two strips overlap there. The result contains the exact disk dilation (strips
//    cover the edges, corners the vertex sectors, and the bevel line is at distance >= r); its
//    points are within r / cos(φ/2) of the polygon at unbevelled corners (φ the turning angle) and
//    within sqrt(kMiterLimit² + 1)·r at bevelled ones (the bevel's ends).
#include "geometry/dilation.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/minkowski_sum_2.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/cgal_internal.h"

namespace rearm::geometry {
namespace {

// The smallest number of sides for the circumscribed polygon.
constexpr int kMinDiskSides = 8;

void check_radius(double r, const char* what) {
  REARM_REQUIRE(std::isfinite(r) && r > 0, what, ": radius must be finite and > 0, got ", r);
}

// Smallest even n >= kMinDiskSides with 1/cos(π/n) − 1 <= kMaxDilationError (the relative
// distance between the circumscribed n-gon's vertices and the circle).
int disk_sides() {
  int n = kMinDiskSides;
  while (1 / std::cos(std::numbers::pi / n) - 1 > kMaxDilationError) n += 2;
  return n;
}

std::vector<Point> disk_vertices(double r) {
  const int n = disk_sides();
  const double radius = r / std::cos(std::numbers::pi / n);
  std::vector<Point> disk;
  disk.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    disk.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  return disk;
}

internal::CPolygon circumscribed_disk(double r) {
  internal::CPolygon disk;
  for (const Point& v : disk_vertices(r)) disk.push_back(internal::to_cgal(v));
  return disk;
}

// Exact sign of the cross product of the edge vectors b - a and d - c (four double points):
// a floating-point filter, exact rationals when the filter cannot decide.
int cross_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  const double vx = d.x() - c.x(), vy = d.y() - c.y();
  const double l = ux * vy, m = uy * vx;
  // Each difference and product is within a relative 2^-53 of its exact value; 8 units of the
  // larger term bound the error of l - m with room to spare.
  const double bound = 8 * std::numeric_limits<double>::epsilon() * (std::abs(l) + std::abs(m));
  if (l - m > bound) return 1;
  if (m - l > bound) return -1;
  using Q = CGAL::Exact_rational;
  const Q ex = Q(b.x()) - Q(a.x()), ey = Q(b.y()) - Q(a.y());
  const Q fx = Q(d.x()) - Q(c.x()), fy = Q(d.y()) - Q(c.y());
  return CGAL::sign(ex * fy - ey * fx);
}

// Every turn of the closed polygon strictly to the left (exact): no collinear vertex.
bool strictly_convex(const Polygon& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const Point& c = p.vertices[(i + 2) % n];
    if (cross_sign(a, b, b, c) <= 0) return false;
  }
  return true;
}

// a + b as CGAL's exact kernel rounds a sum to a double: the midpoint of the tightest
// interval around the exact value (CGAL::to_double of a lazy number), which is not always the
// nearest double. Keeps the fast Minkowski sum below bit-identical to the exact one.
double lazy_rounded_sum(double a, double b) {
  const double s = a + b;
  const double t = s - a;
  const double e = (a - (s - t)) + (b - t);  // a + b = s + e exactly (two-sum)
  if (e == 0) return s;
  const double other = std::nextafter(s, e > 0 ? std::numeric_limits<double>::infinity()
                                               : -std::numeric_limits<double>::infinity());
  return (s + other) * 0.5;
}

// Index of the lowest vertex (smallest y, then smallest x).
std::size_t lowest(const std::vector<Point>& v) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (v[i].y() < v[best].y() || (v[i].y() == v[best].y() && v[i].x() < v[best].x())) best = i;
  }
  return best;
}

// Minkowski sum of two strictly convex counter-clockwise polygons: their edges merged by
// direction from the lowest vertices (parallel edges joined), decided exactly; each vertex
// p_i + q_j rounded as the exact kernel rounds it. The same polygon as CGAL's exact sum.
Polygon convex_sum(const Polygon& p, const std::vector<Point>& q) {
  const std::vector<Point>& a = p.vertices;
  const std::size_t n = a.size(), m = q.size();
  std::size_t i = lowest(a), j = lowest(q), di = 0, dj = 0;
  Polygon out;
  out.vertices.reserve(n + m);
  while (di < n || dj < m) {
    const Point& pa = a[i % n];
    const Point& pq = q[j % m];
    out.vertices.emplace_back(lazy_rounded_sum(pa.x(), pq.x()), lazy_rounded_sum(pa.y(), pq.y()));
    const int turn = di == n   ? -1
                     : dj == m ? 1
                               : cross_sign(pa, a[(i + 1) % n], pq, q[(j + 1) % m]);
    if (turn >= 0) ++i, ++di;
    if (turn <= 0) ++j, ++dj;
  }
  return out;
}

}  // namespace

RegionSet dilate_round(const Polygon& p, double r) {
  check_radius(r, "dilate_round");
  const Polygon ccw = validated(p, "dilate_round polygon");
  if (strictly_convex(ccw)) return RegionSet{Region{convex_sum(ccw, disk_vertices(r)), {}}};
  return dilate_round_exact(ccw, r);
}

RegionSet dilate_round_exact(const Polygon& p, double r) {
  check_radius(r, "dilate_round_exact");
  const Polygon ccw = validated(p, "dilate_round_exact polygon");
  const internal::CPolygonWithHoles sum =
      CGAL::minkowski_sum_2(internal::to_cgal(ccw), circumscribed_disk(r));
  return RegionSet{internal::from_cgal(sum)};
}

RegionSet dilate_miter(const Polygon& p, double r, double limit_factor) {
  check_radius(r, "dilate_miter");
  REARM_REQUIRE(std::isfinite(limit_factor) && limit_factor >= 1,
                "dilate_miter: the miter limit must be finite and >= 1, got ", limit_factor);
  const Polygon q = validated(p, "dilate_miter polygon");  // counter-clockwise
  const std::size_t n = q.size();
  auto cross = [](const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); };
  std::vector<Point> dir(n), normal(n);  // edge i: q[i] -> q[i+1], outward normal on the right
  for (std::size_t i = 0; i < n; ++i) {
    dir[i] = (q.vertices[(i + 1) % n] - q.vertices[i]).normalized();
    normal[i] = Point(dir[i].y(), -dir[i].x());
  }
  std::vector<Polygon> parts{q};
  for (std::size_t i = 0; i < n; ++i) {  // edge strips
    const Point& a = q.vertices[i];
    const Point& b = q.vertices[(i + 1) % n];
    parts.push_back(Polygon{{a, a + r * normal[i], b + r * normal[i], b}});
  }
  const double limit = limit_factor * r;
  for (std::size_t i = 0; i < n; ++i) {  // convex corners
    const std::size_t in = (i + n - 1) % n;
    if (!(cross(dir[in], dir[i]) > 0)) continue;  // reflex or collinear: strips suffice
    const Point& v = q.vertices[i];
    const Point& n1 = normal[in];
    const Point& n2 = normal[i];
    const Point miter = v + r * (n1 + n2) / (1 + n1.dot(n2));  // at distance r from both lines
    if ((miter - v).norm() <= limit) {
      parts.push_back(Polygon{{v, v + r * n1, miter, v + r * n2}});
      continue;
    }
    // Bevel: cut the corner by {x : (x - v)·b = limit}, b the outward bisector.
    const Point b = (n1 + n2).normalized();
    const Point p1 = v + r * n1 + dir[in] * ((limit - r * n1.dot(b)) / dir[in].dot(b));
    const Point p2 = v + r * n2 - dir[i] * ((limit - r * n2.dot(b)) / -dir[i].dot(b));
    parts.push_back(Polygon{{v, v + r * n1, p1, p2, v + r * n2}});
  }
  return unite_all(parts);
}

Polygon disk_polygon(const Disk& d) { return regular_polygon(d, kDiskPolygonSides, true); }

RegionSet erode(const Polygon& workspace, double r) {
  REARM_REQUIRE(std::isfinite(r) && r > 0, "erode: distance must be finite and > 0, got ", r);
  const Polygon w = validated(workspace, "workspace");
  std::vector<Polygon> walls;
  for (std::size_t i = 0, n = w.size(); i < n; ++i) {
    std::vector<Point> pts = disk_polygon(Disk{w.vertices[i], r}).vertices;
    const Polygon b = disk_polygon(Disk{w.vertices[(i + 1) % n], r});
    pts.insert(pts.end(), b.vertices.begin(), b.vertices.end());
    walls.push_back(convex_hull(std::move(pts)));
  }
  return subtract(to_set(w), unite_all(walls));
}

}  // namespace rearm::geometry
