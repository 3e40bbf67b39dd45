// Local freespace of the model-space navigation law (see local_freespace.h).
#include "reactive/local_freespace.h"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/distance.h"

namespace rearm::reactive {
namespace {

using geometry::HalfPlane;
using geometry::Point;
using geometry::Polygon;

// Sutherland–Hodgman clip of a convex polygon by h into `out` (reusing its capacity); the
// same construction as geometry::clip without the fresh allocation.
void clip_into(const Polygon& in, const HalfPlane& h, Polygon& out) {
  out.vertices.clear();
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = in.vertices[i];
    const Point& q = in.vertices[(i + 1) % n];
    const double fp = h.value(p);
    const double fq = h.value(q);
    if (fp <= 0) out.vertices.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      out.vertices.push_back(p + (fp / (fp - fq)) * (q - p));
    }
  }
}

// The bisector half-plane { q : (q − y)·u ≤ d/2 } of y and the obstacle point p at distance
// d = ‖p − y‖ > 0 in direction u = (p − y)/d.
HalfPlane bisector(const Point& y, const Point& p, double d) {
  const Point u = (p - y) / d;
  return HalfPlane{u, u.dot(y) + 0.5 * d};
}

// The vertices (cos a, sin a), a = 2πi/sides, of the unit sensing polygon, kept per thread for
// the last `sides` asked (one per controller in practice): the law asks for them every tick.
const std::vector<Point>& unit_polygon(int sides) {
  thread_local std::vector<Point> vertices;
  thread_local int cached_sides = 0;
  if (cached_sides != sides) {
    vertices.clear();
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * std::numbers::pi * i / sides;
      vertices.emplace_back(std::cos(a), std::sin(a));
    }
    cached_sides = sides;
  }
  return vertices;
}

[[noreturn]] void not_free(const std::string& what) {
  throw OutsideModelFreespace("local_freespace: the point y is not in the model freespace (" +
                              what + ")");
}

}  // namespace

void local_freespace(const ModelSpace& m, const Point& y, double sensor_range, Polygon& out,
                     Polygon& scratch, int sides) {
  if (!y.allFinite()) throw Error("local_freespace: point y is not finite");
  REARM_REQUIRE(std::isfinite(sensor_range) && sensor_range > 0,
                "local_freespace: sensing range must be finite and positive, got ", sensor_range);
  REARM_REQUIRE(sides >= 3, "local_freespace: the sensing polygon needs at least 3 sides, got ",
                sides);
  REARM_REQUIRE(m.boundary.size() >= 3, "local_freespace: model boundary has < 3 vertices (",
                m.boundary.size(), ")");

  // Start from the inscribed sensing polygon, written straight into `out`.
  out.vertices.clear();
  const double half_range = 0.5 * sensor_range;
  for (const Point& u : unit_polygon(sides)) out.vertices.emplace_back(y + half_range * u);
  const auto apply = [&](const HalfPlane& h) {
    clip_into(out, h, scratch);
    std::swap(out.vertices, scratch.vertices);
  };

  // Enclosing boundary: y strictly inside; its complement's nearest point gives a bisector,
  // and every edge of F_e clips LF.
  if (!geometry::convex_contains(m.boundary, y)) not_free("outside the model boundary");
  const geometry::Nearest wall = geometry::nearest_on_boundary(m.boundary, y);
  if (!(wall.distance > 0)) not_free("on the model boundary");
  if (wall.distance < sensor_range) apply(bisector(y, wall.point, wall.distance));
  for (std::size_t i = 0, n = m.boundary.size(); i < n; ++i) {
    apply(geometry::left_of(m.boundary.vertices[i], m.boundary.vertices[(i + 1) % n]));
  }

  for (std::size_t i = 0; i < m.disks.size(); ++i) {
    const geometry::Disk& disk = m.disks[i];
    const Point to_center = disk.center - y;
    const double dc = to_center.norm();
    const double d = dc - disk.radius;
    if (!(d > 0)) not_free("inside or on model disk " + std::to_string(i));
    if (d >= sensor_range) continue;
    // Nearest point of the disk: c + ρ·unit(y − c); the bisector depends only on u and d.
    apply(bisector(y, y + (d / dc) * to_center, d));
  }

  for (std::size_t i = 0; i < m.convex.size(); ++i) {
    const Polygon& obstacle = m.convex[i];
    if (obstacle.size() == 0) continue;
    if (obstacle.size() >= 3 && geometry::convex_contains(obstacle, y)) {
      not_free("inside convex obstacle " + std::to_string(i));
    }
    const geometry::Nearest near = geometry::nearest_on_boundary(obstacle, y);
    if (!(near.distance > 0)) not_free("on convex obstacle " + std::to_string(i));
    if (near.distance >= sensor_range) continue;
    apply(bisector(y, near.point, near.distance));
  }
}

Polygon local_freespace(const ModelSpace& m, const Point& y, double sensor_range, int sides) {
  Polygon out;
  Polygon scratch;
  if (sides >= 3) {
    out.vertices.reserve(static_cast<std::size_t>(sides) + 8);
    scratch.vertices.reserve(static_cast<std::size_t>(sides) + 8);
  }
  local_freespace(m, y, sensor_range, out, scratch, sides);
  return out;
}

}  // namespace rearm::reactive
