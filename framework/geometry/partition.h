// Convex decomposition (docs/reactive.md §3.1): CGAL's optimal convex partition (Greene's
// dynamic programming, minimal number of pieces) for polygons up to kOptimalPartitionLimit
// vertices, Hertel–Mehlhorn approximation (at most 4x optimal) above, and as the fallback
// when CGAL 5.5's optimal result fails its exact validity check (see partition.cpp; CGAL
// issue #4398: the "optimal" count can still exceed the optimum). Pieces of area below
// kSliverArea are dropped; every piece vertex is an input vertex (bit for bit), so shared
// edges between pieces are exact.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::geometry {

inline constexpr std::size_t kOptimalPartitionLimit = 64;
inline constexpr double kSliverArea = 1e-9;

std::vector<Polygon> convex_partition(const Polygon& p);

// Polygons PartitionCache remembers before it is emptied (as reactive::DecompositionCache).
inline constexpr std::size_t kPartitionCacheEntries = 256;

// convex_partition's results remembered by their polygon's exact vertices (the partition is a
// function of them alone, so a hit returns what the call would): the reactive controller's
// convex fallback partitions the same familiar components at every rebuild, and those
// partitions were a quarter of an N = 8 trial's controller time. Emptied when it holds
// kPartitionCacheEntries polygons. Not thread-safe (one per controller).
class PartitionCache {
 public:
  std::vector<Polygon> pieces(const Polygon& p);
  std::size_t size() const { return entries_.size(); }

 private:
  std::vector<std::pair<std::vector<Point>, std::vector<Polygon>>> entries_;
};

}  // namespace rearm::geometry
