#include "geometry/convex_difference.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "geometry/convex.h"
#include "geometry/distance.h"

namespace rearm::geometry {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double segment_distance(const Point& a, const Point& b, const Point& x) {
  return (nearest_on_segment(a, b, x) - x).norm();
}

// The parameter interval [t0, t1] of a + t (b − a), t in [0, 1], inside the convex polygon p
// shrunk by `inset` (m; line_interval); t0 > t1 when the segment misses it. With inset > 0 an
// edge that p shares with another fragment of the same obstacle (collinear up to rounding)
// stays out of p even where rounding puts it a hair inside.
std::pair<double, double> inside_interval(const Polygon& p, const Point& a, const Point& b,
                                          double inset = 0) {
  const std::optional<Interval> on = line_interval(p, a, b - a, inset);
  if (!on) return {1, 0};
  return {std::max(0.0, on->lo), std::min(1.0, on->hi)};
}

bool inside(const Polygon& p, const Point& x) {
  const auto [t0, t1] = inside_interval(p, x, x);
  return t0 <= t1;
}

Point along(const Point& a, const Point& b, double t) { return a + t * (b - a); }

// Distance from x to the parts of [a, b] outside the convex polygon p grown by kSharedEdge.
double outside_distance(const Polygon& p, const Point& a, const Point& b, const Point& x) {
  const auto [t0, t1] = inside_interval(p, a, b, -kSharedEdge);
  if (t0 > t1) return segment_distance(a, b, x);
  double d = kInfinity;
  if (t0 > 0) d = std::min(d, segment_distance(a, along(a, b, t0), x));
  if (t1 < 1) d = std::min(d, segment_distance(along(a, b, t1), b, x));
  return d;
}

// Distance from x to the part of [a, b] in the interior of the convex polygon p (kSharedEdge
// inside its boundary).
double inside_distance(const Polygon& p, const Point& a, const Point& b, const Point& x) {
  const auto [t0, t1] = inside_interval(p, a, b, kSharedEdge);
  if (t0 > t1) return kInfinity;
  return segment_distance(along(a, b, t0), along(a, b, t1), x);
}

}  // namespace

// The boundary of B \ A consists of the parts of ∂B outside A's interior and the parts of
// ∂A inside B; x itself may lie in B \ A.
double convex_difference_distance(const Polygon& a, const Polygon& b, const Point& x) {
  if (b.size() < 3) return kInfinity;
  if (a.size() < 3) return distance(b, x);
  if (inside(b, x) && !inside(a, x)) return 0;
  double d = kInfinity;
  for (std::size_t i = 0, n = b.size(); i < n; ++i) {
    d = std::min(d, outside_distance(a, b.vertices[i], b.vertices[(i + 1) % n], x));
  }
  for (std::size_t i = 0, n = a.size(); i < n; ++i) {
    d = std::min(d, inside_distance(b, a.vertices[i], a.vertices[(i + 1) % n], x));
  }
  return d;
}

}  // namespace rearm::geometry
