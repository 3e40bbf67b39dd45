// Independent truth for the perception tests, sharing no code with framework/perception: the
// exact area of a polygon ∩ disk (closed form, edge by edge), the true distance from a point to
// a polygon (ray casting + brute-force boundary distance of tests/support), convexity and
// half-plane membership in plain doubles, and random convex polygons.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/rng.h"
#include "geometry/polygon.h"
#include "support/geometry_oracle.h"

namespace rearm::perception::oracle {

using geometry::Point;
using geometry::Polygon;

inline double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Signed area of (triangle 0, a, b) ∩ disk(0, r): the segment split at its circle crossings;
// each piece contributes a triangle when inside the circle, a circular sector when outside.
inline double triangle_disk_area(const Point& a, const Point& b, double r) {
  const Point d = b - a;
  const double qa = d.squaredNorm();
  std::vector<double> ts{0.0};
  if (qa > 0) {
    const double qb = 2 * a.dot(d);
    const double qc = a.squaredNorm() - r * r;
    const double disc = qb * qb - 4 * qa * qc;
    if (disc > 0) {
      const double s = std::sqrt(disc);
      for (const double t : {(-qb - s) / (2 * qa), (-qb + s) / (2 * qa)}) {
        if (t > 0 && t < 1) ts.push_back(t);
      }
    }
  }
  ts.push_back(1.0);
  double area = 0;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const Point p = a + ts[k] * d;
    const Point q = a + ts[k + 1] * d;
    if ((0.5 * (p + q)).norm() <= r) {
      area += cross(p, q) / 2;
    } else {
      area += r * r / 2 * std::atan2(cross(p, q), p.dot(q));
    }
  }
  return area;
}

// Exact area of (simple polygon, counter-clockwise) ∩ disk(c, r).
inline double polygon_disk_area(const Polygon& p, const Point& c, double r) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    a += triangle_disk_area(p.vertices[i] - c, p.vertices[(i + 1) % n] - c, r);
  }
  return a;
}

// True distance from x to the closed polygon.
inline double true_distance(const Polygon& p, const Point& x) {
  if (test_support::ray_cast_inside(p, x)) return 0;
  return test_support::boundary_distance(p, x);
}

// Largest distance by which x lies outside one of the edge lines of a convex CCW polygon
// (<= 0 inside).
inline double convex_excess(const Polygon& convex, const Point& x) {
  double worst = -1e300;
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    const Point& a = convex.vertices[i];
    const Point& b = convex.vertices[(i + 1) % n];
    worst = std::max(worst, -cross(b - a, x - a) / (b - a).norm());
  }
  return worst;
}

// Is the polygon convex and counter-clockwise (positive area, no right turn beyond rounding)?
inline bool is_convex_ccw(const Polygon& p, double eps = 1e-12) {
  const std::size_t n = p.size();
  if (n < 3) return false;
  double twice = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const Point& c = p.vertices[(i + 2) % n];
    twice += cross(a, b);
    if (cross(b - a, c - b) < -eps * (b - a).norm() * (c - b).norm()) return false;
  }
  return twice > 0;
}

// Random convex polygon: n points at sorted random angles on an ellipse with semi-axes
// (a, b), rotated by theta and centred at c; counter-clockwise.
inline Polygon random_convex(Rng& rng, int n, double a, double b, double theta, const Point& c) {
  std::vector<double> angles;
  for (int k = 0; k < n; ++k) {
    angles.push_back(2 * std::numbers::pi * (k + rng.uniform(0.1, 0.9)) / n);
  }
  return test_support::ellipse_polygon(angles, a, b, theta, c);
}

}  // namespace rearm::perception::oracle
