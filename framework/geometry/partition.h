// Convex decomposition (docs/reactive.md §3.1): CGAL's optimal convex partition (Greene's
// dynamic programming, minimal number of pieces) for polygons up to kOptimalPartitionLimit
// vertices, Hertel–Mehlhorn approximation (at most 4x optimal) above, and as the fallback
// when CGAL 5.5's optimal result fails its exact validity check (see partition.cpp; CGAL
// issue #4398: the "optimal" count can still exceed the optimum). Pieces of area below
// kSliverArea are dropped; every piece vertex is an input vertex (bit for bit), so shared
// edges between pieces are exact.
#pragma once

#include <vector>

#include "geometry/polygon.h"

namespace rearm::geometry {

inline constexpr std::size_t kOptimalPartitionLimit = 64;
inline constexpr double kSliverArea = 1e-9;

std::vector<Polygon> convex_partition(const Polygon& p);

}  // namespace rearm::geometry
