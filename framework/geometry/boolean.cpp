// Boolean operations of boolean.h on CGAL::Polygon_set_2 over the exact-constructions kernel
// (cgal_internal.h). The operations are regularized (CGAL's convention): lower-dimensional
// pieces such as the shared edge of two touching squares vanish from an intersection, while
// intersects() answers for the closed sets. The only CGAL Boolean translation unit.
#include "geometry/boolean.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/cgal_internal.h"
#include "geometry/distance.h"
#include "geometry/meeting.h"

namespace rearm::geometry {
namespace {

using internal::CPolygon;
using internal::CPolygonWithHoles;
using internal::Kernel;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

// Caller's regions, each boundary validated (polygon.h) and oriented as Region documents.
// Contract (not re-checked): the holes of a region lie inside its outer boundary and are
// pairwise interior-disjoint; distinct regions may overlap (they are united).
RegionSet normalized(const RegionSet& s, const char* op, const char* operand) {
  RegionSet out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string name = std::string(op) + ": " + operand + " region " + std::to_string(i);
    Region r;
    r.outer = validated(s[i].outer, (name + " outer boundary").c_str());
    for (std::size_t k = 0; k < s[i].holes.size(); ++k) {
      r.holes.push_back(validated(s[i].holes[k], (name + " hole " + std::to_string(k)).c_str()));
    }
    out.push_back(std::move(r));
  }
  return out;
}

PolygonSet to_set_exact(const RegionSet& normal) {
  std::vector<CPolygonWithHoles> parts;
  parts.reserve(normal.size());
  for (const Region& r : normal) parts.push_back(internal::to_cgal(r));
  PolygonSet out;
  if (!parts.empty()) out.join(parts.begin(), parts.end());
  return out;
}

// A CGAL boundary cycle in doubles, cut into simple loops (simple_loops below).
std::vector<Polygon> cycle_loops(const CPolygon& cycle) {
  std::vector<Point> points;
  points.reserve(cycle.size());
  for (auto it = cycle.vertices_begin(); it != cycle.vertices_end(); ++it) {
    points.push_back(internal::from_cgal(*it));
  }
  return simple_loops(points);
}

RegionSet from_set_exact(const PolygonSet& s) {
  std::vector<CPolygonWithHoles> parts;
  s.polygons_with_holes(std::back_inserter(parts));
  RegionSet out;
  for (const CPolygonWithHoles& p : parts) {
    REARM_DEMAND(!p.is_unbounded(), "a bounded Boolean operation gave an unbounded region");
    std::vector<Polygon> loops = cycle_loops(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
      std::vector<Polygon> more = cycle_loops(*h);
      loops.insert(loops.end(), more.begin(), more.end());
    }
    const std::size_t first = out.size();
    std::vector<Polygon> holes;
    for (Polygon& loop : loops) {
      if (loop.signed_area() > 0) {
        out.push_back(Region{std::move(loop), {}});
      } else {
        std::reverse(loop.vertices.begin(), loop.vertices.end());
        holes.push_back(std::move(loop));
      }
    }
    // A component whose loops all have non-positive area in doubles is a sliver that rounding
    // collapsed (its exact area below the doubles' resolution, e.g. a triangle of 1e-16 m^2
    // left between two nearly collinear edges): it has no area to keep, nor have its holes.
    if (out.size() == first) continue;
    // Usually one outer loop. Otherwise a hole belongs to the smallest loop containing the
    // midpoint of one of its edges (loops of a relatively simple cycle share no edge).
    for (Polygon& h : holes) {
      std::size_t best = first;
      if (out.size() - first > 1) {
        const Point probe = (h.vertices[0] + h.vertices[1]) / 2;
        double best_area = std::numeric_limits<double>::infinity();
        for (std::size_t k = first; k < out.size(); ++k) {
          const double a = out[k].outer.area();
          if (a < best_area && contains(out[k].outer, probe)) {
            best = k;
            best_area = a;
          }
        }
      }
      REARM_DEMAND(best < out.size(), "a Boolean result has a hole but no outer boundary");
      out[best].holes.push_back(std::move(h));
    }
  }
  return out;
}

RegionSet sweep_difference(const RegionSet& normal_a, const RegionSet& normal_b) {
  PolygonSet s = to_set_exact(normal_a);
  s.difference(to_set_exact(normal_b));
  return from_set_exact(s);
}

// Every boundary loop of the regions, outer and holes.
std::vector<const Polygon*> loops_of(const RegionSet& s) {
  std::vector<const Polygon*> out;
  for (const Region& r : s) {
    out.push_back(&r.outer);
    for (const Polygon& h : r.holes) out.push_back(&h);
  }
  return out;
}

}  // namespace

RegionSet to_set(const Polygon& p) { return {Region{validated(p, "to_set: polygon"), {}}}; }

RegionSet unite(const RegionSet& a, const RegionSet& b) {
  PolygonSet s = to_set_exact(normalized(a, "unite", "first"));
  s.join(to_set_exact(normalized(b, "unite", "second")));
  return from_set_exact(s);
}

RegionSet intersect(const RegionSet& a, const RegionSet& b) {
  PolygonSet s = to_set_exact(normalized(a, "intersect", "first"));
  s.intersection(to_set_exact(normalized(b, "intersect", "second")));
  return from_set_exact(s);
}

// The obstacles of b that stand alone strictly inside a (meeting.h) become holes of the region
// that holds them without entering the sweep; those outside a remove nothing. Only the rest
// is swept. The set is the one the sweep of all of b gives (the decisions are exact).
RegionSet subtract(const RegionSet& a, const RegionSet& b) {
  const RegionSet na = normalized(a, "subtract", "first");
  const RegionSet nb = normalized(b, "subtract", "second");
  const std::vector<internal::Place> place = internal::place_in(na, nb);
  RegionSet swept;
  for (std::size_t i = 0; i < nb.size(); ++i) {
    if (place[i] == internal::Place::kNeedsSweep) swept.push_back(nb[i]);
  }
  // Regions of a may overlap: the sweep unites them.
  RegionSet out = swept.empty() && na.size() <= 1 ? na : sweep_difference(na, swept);
  for (std::size_t i = 0; i < nb.size(); ++i) {
    if (place[i] != internal::Place::kInside) continue;
    const Point& probe = nb[i].outer.vertices.front();
    auto holder = std::find_if(out.begin(), out.end(), [&](const Region& r) {
      return contains(r.outer, probe) &&
             std::none_of(r.holes.begin(), r.holes.end(),
                          [&](const Polygon& h) { return contains(h, probe); });
    });
    if (holder == out.end()) return sweep_difference(na, nb);  // rounding moved a boundary
    holder->holes.push_back(nb[i].outer);
  }
  return out;
}

// Clusters of meeting polygons are swept one by one; a polygon that meets no other is its own
// union.
RegionSet unite_all(const std::vector<Polygon>& polygons) {
  std::vector<Polygon> valid;
  valid.reserve(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const std::string name = "unite_all: polygon " + std::to_string(i);
    valid.push_back(validated(polygons[i], name.c_str()));
  }
  RegionSet out;
  for (const std::vector<std::size_t>& cluster : internal::meeting_clusters(valid)) {
    if (cluster.size() == 1) {
      out.push_back(Region{valid[cluster.front()], {}});
      continue;
    }
    std::vector<CPolygon> parts;
    parts.reserve(cluster.size());
    for (std::size_t i : cluster) parts.push_back(internal::to_cgal(valid[i]));
    PolygonSet s;
    s.join(parts.begin(), parts.end());  // aggregated (divide and conquer)
    RegionSet united = from_set_exact(s);
    out.insert(out.end(), std::make_move_iterator(united.begin()),
               std::make_move_iterator(united.end()));
  }
  return out;
}

// Closed sets meet iff two boundary segments meet (exact predicate, meeting.h), or, with
// disjoint boundaries, a region of one set lies wholly inside the other, which one outer vertex
// of that region decides.
bool intersects(const RegionSet& a, const RegionSet& b) {
  const RegionSet na = normalized(a, "intersects", "first");
  const RegionSet nb = normalized(b, "intersects", "second");
  for (const Polygon* x : loops_of(na)) {
    for (const Polygon* y : loops_of(nb)) {
      if (internal::boundaries_meet(*x, *y)) return true;
    }
  }
  for (const Region& r : na) {
    if (contains(nb, r.outer.vertices.front())) return true;
  }
  for (const Region& r : nb) {
    if (contains(na, r.outer.vertices.front())) return true;
  }
  return false;
}

std::vector<Polygon> simple_loops(const std::vector<Point>& cycle) {
  std::vector<Point> path;
  std::vector<Polygon> loops;
  auto emit = [&loops](std::vector<Point> v) {
    if (v.size() >= 3) loops.push_back(Polygon{std::move(v)});
  };
  for (const Point& v : cycle) {
    if (!path.empty() && path.back() == v) continue;
    const auto seen = std::find(path.begin(), path.end(), v);
    if (seen != path.end()) {
      emit(std::vector<Point>(seen, path.end()));
      path.erase(seen + 1, path.end());
    } else {
      path.push_back(v);
    }
  }
  while (path.size() > 1 && path.back() == path.front()) path.pop_back();
  emit(std::move(path));
  return loops;
}

namespace {

// The vertices of p other than a and b within `touch` of the edge ab, in order along it.
std::vector<Point> touching(const Polygon& p, std::size_t a, std::size_t b, double touch) {
  const Point& pa = p.vertices[a];
  const Point& pb = p.vertices[b];
  std::vector<std::pair<double, Point>> on;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Point& v = p.vertices[k];
    if (k == a || k == b || (nearest_on_segment(pa, pb, v) - v).norm() >= touch) continue;
    on.emplace_back((v - pa).dot(pb - pa), v);
  }
  std::sort(on.begin(), on.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Point> out;
  for (const auto& [along, v] : on) out.push_back(v);
  return out;
}

}  // namespace

std::vector<Polygon> simple_parts(const Polygon& p, double touch, double min_area) {
  if (checked_polygon(p)) return {p};
  std::vector<Point> cycle;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    cycle.push_back(p.vertices[i]);
    for (const Point& v : touching(p, i, (i + 1) % n, touch)) cycle.push_back(v);
  }
  std::vector<Polygon> out;
  for (Polygon& loop : simple_loops(cycle)) {
    if (loop.signed_area() > min_area && checked_polygon(loop)) out.push_back(std::move(loop));
  }
  return out;
}

}  // namespace rearm::geometry
