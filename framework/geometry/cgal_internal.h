// INTERNAL to framework/geometry .cpp files: CGAL kernels and conversions. Never include it
// from a header (docs/architecture.md: CGAL stays inside few .cpp files).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::geometry::internal {

// Exact constructions: Booleans, Minkowski sums and partitions are decided exactly.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CPoint = Kernel::Point_2;
using CPolygon = CGAL::Polygon_2<Kernel>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

inline CPoint to_cgal(const Point& p) { return CPoint(p.x(), p.y()); }

// Does the exact point hold a pair of doubles (an input vertex: its intervals are points, so
// it is exact already and its doubles are those intervals)?
inline bool is_double(const CPoint& p) {
  const auto& a = p.approx();
  return a.x().inf() == a.x().sup() && a.y().inf() == a.y().sup();
}
// The doubles of a point for which is_double holds (read from its intervals, no exact number).
inline Point double_point(const CPoint& p) {
  return Point(p.approx().x().inf(), p.approx().y().inf());
}
inline Point from_cgal(const CPoint& p) {
  return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}

inline CPolygon to_cgal(const Polygon& p) {
  CPolygon out;
  for (const Point& v : p.vertices) out.push_back(to_cgal(v));
  return out;
}

// Counter-clockwise double polygon from a CGAL one (whatever its orientation).
inline Polygon from_cgal(const CPolygon& p) {
  Polygon out;
  out.vertices.reserve(p.size());
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) {
    out.vertices.push_back(from_cgal(*it));
  }
  if (p.orientation() == CGAL::CLOCKWISE) {
    std::reverse(out.vertices.begin(), out.vertices.end());
  }
  return out;
}

inline CPolygonWithHoles to_cgal(const Region& r) {
  CPolygon outer = to_cgal(r.outer);
  if (outer.orientation() == CGAL::CLOCKWISE) outer.reverse_orientation();
  CPolygonWithHoles out(outer);
  for (const Polygon& h : r.holes) {
    CPolygon hole = to_cgal(h);
    if (hole.orientation() == CGAL::COUNTERCLOCKWISE) hole.reverse_orientation();
    out.add_hole(hole);
  }
  return out;
}

inline Region from_cgal(const CPolygonWithHoles& p) {
  Region out;
  out.outer = from_cgal(p.outer_boundary());
  for (auto it = p.holes_begin(); it != p.holes_end(); ++it) out.holes.push_back(from_cgal(*it));
  return out;
}

// material − ∪cutters, exact, for one counter-clockwise polygon and cutters without holes
// (outer boundaries counter-clockwise) whose boundaries meet only in proper crossings of two
// edges (crossing_difference.cpp): outer boundaries counter-clockwise, holes clockwise, as
// CGAL's Booleans return them. Nullopt for any other input (a vertex on another boundary,
// collinear edges, three edges through a point): the caller runs CGAL's overlay instead.
std::optional<std::vector<CPolygonWithHoles>> crossing_difference(
    const CPolygon& material, const std::vector<CPolygonWithHoles>& cutters);

}  // namespace rearm::geometry::internal
