// Convex decomposition with CGAL's partition package (docs/reactive.md §3.1). Both algorithms
// only insert diagonals between input vertices, so every piece vertex is an input vertex, bit
// for bit: adjacent pieces share vertices exactly, which the tree construction of §3.2 relies
// on. They construct no point (the visibility graph, the triangulation and the validity check
// decide by orientation and ordering predicates), so the exact-predicates kernel over the
// input doubles decides exactly what the exact-constructions kernel decided, without its lazy
// number handles (the partition was 14% of an N = 8 trial's controller time with them).
//
// CGAL 5.5's optimal_convex_partition_2 depends on the start vertex: it can return
// non-simple, non-convex pieces when vertex 0 is unsuitable (CGAL issue #9322, fixed
// upstream by PR #9349 by starting at the lexicographically smallest vertex, which is always
// convex) and more pieces than optimal (issue #4398, open). We start at the lex-smallest
// vertex as the fix does, and, since CGAL's own postcondition is compiled out under NDEBUG,
// check the result exactly with convex_partition_is_valid_2; an invalid result falls back
// to approx_convex_partition_2 (Hertel–Mehlhorn, at most 4x optimal).
#include "geometry/partition.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <iterator>
#include <list>
#include <utility>

namespace rearm::geometry {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<Epick>;
using TraitsPolygon = Traits::Polygon_2;

}  // namespace

std::vector<Polygon> convex_partition(const Polygon& p) {
  Polygon ccw = validated(p, "convex_partition polygon");
  const auto lex_less = [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  };
  std::rotate(ccw.vertices.begin(),
              std::min_element(ccw.vertices.begin(), ccw.vertices.end(), lex_less),
              ccw.vertices.end());
  TraitsPolygon input;
  for (const Point& v : ccw.vertices) input.push_back(Epick::Point_2(v.x(), v.y()));

  std::list<TraitsPolygon> pieces;
  const Traits traits;
  if (ccw.size() <= kOptimalPartitionLimit) {
    CGAL::optimal_convex_partition_2(input.vertices_begin(), input.vertices_end(),
                                     std::back_inserter(pieces), traits);
    if (!CGAL::convex_partition_is_valid_2(input.vertices_begin(), input.vertices_end(),
                                           pieces.begin(), pieces.end(), traits)) {
      pieces.clear();
    }
  }
  if (pieces.empty()) {
    CGAL::approx_convex_partition_2(input.vertices_begin(), input.vertices_end(),
                                    std::back_inserter(pieces), traits);
  }

  std::vector<Polygon> out;
  out.reserve(pieces.size());
  for (const TraitsPolygon& piece : pieces) {
    Polygon q;
    q.vertices.reserve(piece.size());
    for (auto it = piece.vertices_begin(); it != piece.vertices_end(); ++it) {
      q.vertices.emplace_back(it->x(), it->y());
    }
    if (q.signed_area() < 0) std::reverse(q.vertices.begin(), q.vertices.end());
    if (q.area() < kSliverArea) continue;
    out.push_back(std::move(q));
  }
  return out;
}

std::vector<Polygon> PartitionCache::pieces(const Polygon& p) {
  for (const auto& [vertices, parts] : entries_) {
    if (vertices == p.vertices) return parts;
  }
  std::vector<Polygon> parts = convex_partition(p);
  if (entries_.size() >= kPartitionCacheEntries) entries_.clear();
  entries_.emplace_back(p.vertices, parts);
  return parts;
}

}  // namespace rearm::geometry
