// Exact meeting tests of meeting.h. Inputs are doubles, which CGAL's
// exact-predicates-inexact-constructions kernel represents exactly: the segment test is an
// exact predicate and the point location is polygon.h's exact contains().
#include "geometry/meeting.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <numeric>

#include "geometry/box.h"

namespace rearm::geometry::internal {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

Epick::Segment_2 segment(const Point& p, const Point& q) {
  return Epick::Segment_2(Epick::Point_2(p.x(), p.y()), Epick::Point_2(q.x(), q.y()));
}

// Does an edge of a meet an edge of b (closed segments, exact)?
bool boundaries_meet(const Polygon& a, const Polygon& b, const Box& box_b) {
  const std::size_t na = a.size(), nb = b.size();
  for (std::size_t i = 0; i < na; ++i) {
    const Point& p = a.vertices[i];
    const Point& q = a.vertices[(i + 1) % na];
    const Box ea = box_of(p, q);
    if (!overlaps(ea, box_b)) continue;
    const Epick::Segment_2 sa = segment(p, q);
    for (std::size_t j = 0; j < nb; ++j) {
      const Point& r = b.vertices[j];
      const Point& s = b.vertices[(j + 1) % nb];
      if (overlaps(ea, box_of(r, s)) && CGAL::do_intersect(sa, segment(r, s))) return true;
    }
  }
  return false;
}

// Closed simple polygons meet iff their boundaries meet or, with disjoint boundaries, one
// contains a vertex of the other.
bool meet(const Polygon& a, const Box& box_a, const Polygon& b, const Box& box_b) {
  if (!overlaps(box_a, box_b)) return false;
  if (boundaries_meet(a, b, box_b)) return true;
  return contains(a, b.vertices.front()) || contains(b, a.vertices.front());
}

std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Place of one region r of b, given the regions of a (with their outer boxes), when no
// other region of b meets it.
Place place_alone(const Region& r, const Box& box, const RegionSet& a,
                  const std::vector<Box>& boxes_a) {
  bool inside = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Polygon& outer = a[k].outer;
    if (!overlaps(box, boxes_a[k])) continue;
    if (boundaries_meet(r.outer, outer, boxes_a[k])) return Place::kNeedsSweep;
    if (contains(r.outer, outer.vertices.front())) return Place::kNeedsSweep;  // a inside r
    if (!contains(outer, r.outer.vertices.front())) continue;
    for (const Polygon& h : a[k].holes) {
      if (meet(r.outer, box, h, box_of(h))) return Place::kNeedsSweep;
    }
    inside = true;
  }
  return inside ? Place::kInside : Place::kOutside;
}

}  // namespace

bool boundaries_meet(const Polygon& a, const Polygon& b) {
  return boundaries_meet(a, b, box_of(b));
}

std::vector<std::vector<std::size_t>> meeting_clusters(const std::vector<Polygon>& polygons) {
  const std::size_t n = polygons.size();
  std::vector<Box> boxes;
  boxes.reserve(n);
  for (const Polygon& p : polygons) boxes.push_back(box_of(p));
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (root(parent, i) == root(parent, j)) continue;
      if (meet(polygons[i], boxes[i], polygons[j], boxes[j])) {
        parent[std::max(root(parent, i), root(parent, j))] =
            std::min(root(parent, i), root(parent, j));
      }
    }
  }
  std::vector<std::vector<std::size_t>> clusters;
  std::vector<std::size_t> slot(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root(parent, i);
    if (slot[r] == n) {
      slot[r] = clusters.size();
      clusters.emplace_back();
    }
    clusters[slot[r]].push_back(i);
  }
  return clusters;
}

std::vector<Place> place_in(const RegionSet& a, const RegionSet& b) {
  std::vector<Box> boxes_a, boxes_b;
  for (const Region& r : a) boxes_a.push_back(box_of(r.outer));
  for (const Region& r : b) boxes_b.push_back(box_of(r.outer));
  std::vector<Place> out(b.size(), Place::kOutside);
  std::vector<bool> crowded(b.size(), false);
  for (std::size_t i = 0; i < b.size(); ++i) {
    for (std::size_t j = i + 1; j < b.size(); ++j) {
      if (meet(b[i].outer, boxes_b[i], b[j].outer, boxes_b[j])) crowded[i] = crowded[j] = true;
    }
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    out[i] = crowded[i] || !b[i].holes.empty() ? Place::kNeedsSweep
                                               : place_alone(b[i], boxes_b[i], a, boxes_a);
  }
  return out;
}

}  // namespace rearm::geometry::internal
