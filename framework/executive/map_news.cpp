#include "executive/map_news.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "geometry/convex.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// m: two fragments of one obstacle share its edges, each clipped on its own, so a shared edge
// may be collinear only up to rounding. Parts of the new fragment's boundary this close outside
// the old one, and parts of the old one's boundary this close inside the new one, are that
// shared boundary, not the new part's (which they would put at their distance, however near
// the robot the obstacle's far side is); new parts thinner than this are not news.
constexpr double kSharedEdge = 1e-7;

double segment_distance(const Point& a, const Point& b, const Point& x) {
  return (geometry::nearest_on_segment(a, b, x) - x).norm();
}

// The parameter interval [t0, t1] of a + t (b − a), t in [0, 1], inside the convex polygon p
// shrunk by `inset` (m; geometry::line_interval); t0 > t1 when the segment misses it. With
// inset > 0 an edge that p shares with another fragment of the same obstacle (collinear up to
// rounding) stays out of p even where rounding puts it a hair inside.
std::pair<double, double> inside_interval(const Polygon& p, const Point& a, const Point& b,
                                          double inset = 0) {
  const std::optional<geometry::Interval> on = geometry::line_interval(p, a, b - a, inset);
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

double disk_distance(const Disk& d, const Point& x) {
  return std::max(0.0, (d.center - x).norm() - d.radius);
}

template <typename T>
const T* find_named(const std::vector<std::string>& ids, const std::vector<T>& items,
                    const std::string& id) {
  const auto it = std::find(ids.begin(), ids.end(), id);
  return it == ids.end() ? nullptr : &items[static_cast<std::size_t>(it - ids.begin())];
}

}  // namespace

MapSnapshot MapSnapshot::of(const perception::SemanticMap& map) {
  return MapSnapshot{map.familiar_ids(), map.unknown_ids(), map.unknown(), map.movable_ids(),
                     map.movable()};
}

// The boundary of B \ A consists of the parts of ∂B outside A's interior and the parts of
// ∂A inside B; x itself may lie in B \ A.
double convex_difference_distance(const Polygon& a, const Polygon& b, const Point& x) {
  if (b.size() < 3) return kInfinity;
  if (a.size() < 3) return geometry::distance(b, x);
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

double news_distance(const MapSnapshot& then, const perception::SemanticMap& now, const Point& x) {
  double d = kInfinity;
  for (std::size_t i = 0; i < now.familiar().size(); ++i) {
    const std::string& id = now.familiar_ids()[i];
    if (std::find(then.familiar_ids.begin(), then.familiar_ids.end(), id) ==
        then.familiar_ids.end()) {
      d = std::min(d, geometry::distance(now.familiar()[i], x));
    }
  }
  for (std::size_t j = 0; j < now.unknown().size(); ++j) {
    const Polygon& fragment = now.unknown()[j];
    const Polygon* old = find_named(then.unknown_ids, then.unknown, now.unknown_ids()[j]);
    if (old != nullptr && old->vertices == fragment.vertices) continue;
    const double du = convex_difference_distance(old != nullptr ? *old : Polygon{}, fragment, x);
    d = std::min(d, du);
  }
  for (std::size_t k = 0; k < now.movable().size(); ++k) {
    const Disk& disk = now.movable()[k];
    const Disk* old = find_named(then.movable_ids, then.movable, now.movable_ids()[k]);
    if (old != nullptr && old->center == disk.center && old->radius == disk.radius) continue;
    d = std::min(d, disk_distance(disk, x));
  }
  return d;
}

}  // namespace rearm::executive
