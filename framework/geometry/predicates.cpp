// The exact predicates of polygon.h: validated() and contains(). Inputs are doubles, which
// CGAL's exact-predicates-inexact-constructions kernel represents exactly, so every decision
// here (simplicity, orientation, point location) is exact; no construction is needed, which
// keeps this translation unit lighter than the exact-constructions kernel of
// cgal_internal.h.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/outcome.h"
#include "geometry/polygon.h"

namespace rearm::geometry {
namespace {

// Up to this many vertices the simplicity test checks all pairs of edges (box-filtered): below
// it that is faster than CGAL's sweep, whose set and sort dominate small polygons.
constexpr std::size_t kPairwiseSimplicityMax = 64;

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using EPoint = Epick::Point_2;

bool finite(const Point& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

[[noreturn]] void fail(const char* what, const std::string& defect) {
  throw Error(std::string(what) + ": " + defect);
}

Failure defect(const char* what, const std::string& text) {
  return Failure{std::string(what) + ": " + text};
}

std::string show(const Point& v) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << v.x() << ", " << v.y() << ')';
  return s.str();
}

std::vector<EPoint> to_epick(const Polygon& p) {
  std::vector<EPoint> out;
  out.reserve(p.size());
  for (const Point& v : p.vertices) out.emplace_back(v.x(), v.y());
  return out;
}

// Finiteness and size of a polygon handed to contains() (house style 5); simplicity is the
// caller's contract (the polygon as returned by validated()), not re-checked per query.
void demand_finite(const Polygon& p, const char* what) {
  if (p.size() < 3) fail(what, "needs at least 3 vertices, got " + std::to_string(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!finite(p.vertices[i])) {
      fail(what, "vertex " + std::to_string(i) + " is not finite " + show(p.vertices[i]));
    }
  }
}

// Does q lie in the box of [a, b] (on the closed segment when the three are collinear)?
bool within_box(const Point& a, const Point& b, const Point& q) {
  return std::min(a.x(), b.x()) <= q.x() && q.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= q.y() && q.y() <= std::max(a.y(), b.y());
}

// Exact location of x relative to p (orientation-independent): on an edge when collinear with
// it and inside its box; otherwise by the winding number, whose crossings are decided by the
// exact orientation of x against each edge that spans x's height (such an edge cannot be
// collinear with x without containing it). No allocation: this runs on every control tick.
CGAL::Bounded_side locate(const Polygon& p, const Point& x) {
  int winding = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    if (within_box(a, b, x) && orientation(a, b, x) == 0) {
      return CGAL::ON_BOUNDARY;
    }
    if (a.y() <= x.y()) {
      if (b.y() > x.y() && orientation(a, b, x) > 0) ++winding;
    } else if (b.y() <= x.y() && orientation(a, b, x) < 0) {
      --winding;
    }
  }
  return winding != 0 ? CGAL::ON_BOUNDED_SIDE : CGAL::ON_UNBOUNDED_SIDE;
}

void check_query(const Point& x) {
  if (!finite(x)) fail("contains", "query point is not finite " + show(x));
}

bool region_contains(const Region& r, const Point& x) {
  if (locate(r.outer, x) == CGAL::ON_UNBOUNDED_SIDE) return false;
  for (const Polygon& h : r.holes) {
    if (locate(h, x) == CGAL::ON_BOUNDED_SIDE) return false;
  }
  return true;
}

void demand_finite(const Region& r) {
  demand_finite(r.outer, "contains: region outer boundary");
  for (const Polygon& h : r.holes) demand_finite(h, "contains: region hole");
}

// The sign of every turn of p when all its turns are strict and of one sign and its edge
// direction goes round exactly once, else 0. Such a polygon is convex and simple (a closed
// polygon whose turns all have one sign and whose direction turns by 2π in all bounds a convex
// region), which is all checked_polygon's sweep would establish. Exact: the turns are exact
// predicates; the direction's half (angle in [0, π) or [π, 2π)) follows from the signs of the
// edge vector's coordinates, which a floating-point difference of doubles gets right. The
// direction turns monotonically by less than π a vertex, so it enters [0, π) from [π, 2π) once
// per full turn, whichever its sense.
int strictly_convex_orientation(const Polygon& p) {
  const auto upper = [](const Point& d) { return d.y() > 0 || (d.y() == 0 && d.x() > 0); };
  const std::size_t n = p.size();
  int sign = 0;
  int entries = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const Point& c = p.vertices[(i + 2) % n];
    const int turn = orientation(a, b, c);
    if (turn == 0 || (sign != 0 && turn != sign)) return 0;
    sign = turn;
    if (!upper(b - a) && upper(c - b)) ++entries;
  }
  return entries == 1 ? sign : 0;
}

// Do the closed segments [a, b] and [c, d] meet? Exact (orientation predicates).
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

// CGAL::is_simple_2's definition by all pairs of edges, for small polygons (no sweep structure
// to build): no two non-consecutive edges meet, and consecutive edges meet only at their shared
// vertex (neither end folds back onto the other edge). Vertices are distinct from their
// successors (checked before).
bool simple_by_pairs(const Polygon& p) {
  const std::size_t n = p.size();
  const auto& v = p.vertices;
  std::array<std::array<double, 4>, kPairwiseSimplicityMax> box;  // x_min, x_max, y_min, y_max
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = v[i];
    const Point& b = v[(i + 1) % n];
    box[i] = {std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
              std::max(a.y(), b.y())};
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = v[i];
    const Point& b = v[(i + 1) % n];
    const Point& c = v[(i + 2) % n];
    if (orientation(a, b, c) == 0 && (within_box(a, b, c) || within_box(b, c, a))) return false;
    const auto& bi = box[i];
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the closing edge is consecutive with edge 0
      const auto& bj = box[j];
      if (bi[1] < bj[0] || bj[1] < bi[0] || bi[3] < bj[2] || bj[3] < bi[2]) continue;
      if (segments_meet(a, b, v[j], v[(j + 1) % n])) return false;
    }
  }
  return true;
}

}  // namespace

Outcome<Polygon> checked_polygon(const Polygon& p, const char* what) {
  const std::size_t n = p.size();
  if (n < 3) return defect(what, "needs at least 3 vertices, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(p.vertices[i])) {
      return defect(what, "vertex " + std::to_string(i) + " is not finite " + show(p.vertices[i]));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (p.vertices[i] == p.vertices[j]) {
      return defect(what, "zero-length edge: vertices " + std::to_string(i) + " and " +
                              std::to_string(j) + " coincide at " + show(p.vertices[i]));
    }
  }
  // Most polygons here are convex (dilated disks, fragments, pieces): linear, no sweep.
  if (const int turn = strictly_convex_orientation(p); turn != 0) {
    Polygon out = p;
    if (turn < 0) std::reverse(out.vertices.begin(), out.vertices.end());
    return out;
  }
  const std::vector<EPoint> pts = to_epick(p);
  // Zero area is checked before simplicity: a collinear polygon is also non-simple, and
  // "zero area" is the more precise report. Consecutive vertices are distinct here.
  bool collinear = true;
  for (std::size_t i = 2; i < n && collinear; ++i) {
    collinear = CGAL::collinear(pts[0], pts[1], pts[i]);
  }
  if (collinear)
    return defect(what, "zero area (all " + std::to_string(n) + " vertices collinear)");
  const bool simple = n <= kPairwiseSimplicityMax
                          ? simple_by_pairs(p)
                          : CGAL::is_simple_2(pts.begin(), pts.end(), Epick());
  if (!simple) {
    return defect(what, "not simple (edges cross or touch away from their shared vertices)");
  }
  Polygon out = p;
  // Simple and not collinear, so the orientation is strictly clockwise or counter-clockwise.
  if (CGAL::orientation_2(pts.begin(), pts.end(), Epick()) == CGAL::CLOCKWISE) {
    std::reverse(out.vertices.begin(), out.vertices.end());
  }
  return out;
}

Polygon validated(const Polygon& p, const char* what) {
  return checked_polygon(p, what).or_throw();
}

bool contains(const Polygon& p, const Point& x) {
  check_query(x);
  demand_finite(p, "contains: polygon");
  return locate(p, x) != CGAL::ON_UNBOUNDED_SIDE;
}

int side_of(const Polygon& p, const Point& x) {
  check_query(x);
  demand_finite(p, "side_of: polygon");
  switch (locate(p, x)) {
    case CGAL::ON_BOUNDED_SIDE:
      return 1;
    case CGAL::ON_BOUNDARY:
      return 0;
    case CGAL::ON_UNBOUNDED_SIDE:
      break;
  }
  return -1;
}

bool contains(const Region& r, const Point& x) {
  check_query(x);
  demand_finite(r);
  return region_contains(r, x);
}

bool contains(const RegionSet& s, const Point& x) {
  check_query(x);
  for (const Region& r : s) demand_finite(r);
  for (const Region& r : s) {
    if (region_contains(r, x)) return true;
  }
  return false;
}

int orientation(const Point& a, const Point& b, const Point& c) {
  return static_cast<int>(
      CGAL::orientation(EPoint(a.x(), a.y()), EPoint(b.x(), b.y()), EPoint(c.x(), c.y())));
}

}  // namespace rearm::geometry
