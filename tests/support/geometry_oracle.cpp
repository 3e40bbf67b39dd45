#include "support/geometry_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rearm::test_support {

using geometry::Point;
using geometry::Polygon;

Polygon random_star(Rng& rng, int n, double r_min, double r_max, const Point& c, double jitter_lo,
                    double jitter_hi) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * (k + rng.uniform(jitter_lo, jitter_hi)) / n;
    const double rho = rng.uniform(r_min, r_max);
    p.vertices.push_back(c + rho * Point(std::cos(a), std::sin(a)));
  }
  return p;
}

bool ray_cast_inside(const Polygon& p, const Point& x) {
  bool inside = false;
  for (std::size_t i = 0, n = p.size(), j = n - 1; i < n; j = i++) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

double segment_distance(const Point& a, const Point& b, const Point& x) {
  const Point d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - x).norm();
}

double boundary_distance(const Polygon& p, const Point& x) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    best = std::min(best, segment_distance(p.vertices[i], p.vertices[(i + 1) % n], x));
  }
  return best;
}

geometry::Polygon ellipse_polygon(const std::vector<double>& angles, double a, double b,
                                  double theta, const geometry::Point& c) {
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  geometry::Polygon p;
  for (const double t : angles) {
    const geometry::Point e(a * std::cos(t), b * std::sin(t));
    p.vertices.push_back(c + geometry::Point(ct * e.x() - st * e.y(), st * e.x() + ct * e.y()));
  }
  return p;
}

double raster_union_share(const std::vector<geometry::Polygon>& polygons, double W, double H,
                          double cell) {
  const int nx = static_cast<int>(std::ceil(W / cell)), ny = static_cast<int>(std::ceil(H / cell));
  std::vector<char> hit(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
  for (const geometry::Polygon& p : polygons) {
    double x0 = W, x1 = 0, y0 = H, y1 = 0;
    for (const geometry::Point& v : p.vertices) {
      x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
      y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
    }
    for (int iy = std::max(0, static_cast<int>(y0 / cell)); iy < ny && iy * cell <= y1; ++iy) {
      for (int ix = std::max(0, static_cast<int>(x0 / cell)); ix < nx && ix * cell <= x1; ++ix) {
        if (ray_cast_inside(p, geometry::Point((ix + 0.5) * cell, (iy + 0.5) * cell)))
          hit[static_cast<std::size_t>(iy * nx + ix)] = 1;
      }
    }
  }
  return static_cast<double>(std::count(hit.begin(), hit.end(), 1)) / (nx * ny);
}

}  // namespace rearm::test_support
