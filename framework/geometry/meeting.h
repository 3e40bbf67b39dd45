// INTERNAL to framework/geometry: exact closed-set meeting tests on validated polygons, used by
// boolean.cpp to keep the exact Boolean sweep for the obstacles that need it. Most obstacles of
// a mapped space (§2 of the reactive controller's construction) stand alone, away from each
// other and from the workspace boundary: their union is themselves, and subtracting them from
// the workspace only adds them as holes. Deciding that is a matter of predicates (segment
// intersection, point location), which are exact on doubles; no construction is made, so the
// result is the same set the sweep computes.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::geometry::internal {

// Does an edge of a meet an edge of b (closed segments)? Exact; bounding boxes filter the pairs.
bool boundaries_meet(const Polygon& a, const Polygon& b);

// The polygons grouped by the transitive closure of "the closed polygons meet" (their
// boundaries meet or one contains the other): each cluster lists its
// members' indices in increasing order, clusters ordered by their first member.
std::vector<std::vector<std::size_t>> meeting_clusters(const std::vector<Polygon>& polygons);

// Where a region of b stands relative to the regions of a in a subtraction a \ b.
enum class Place {
  kNeedsSweep,  // touches a boundary of a or another region of b, or has holes
  kOutside,     // disjoint from every region of a: it removes nothing
  kInside,      // strictly inside a region of a, away from its holes and from the rest of b
};
// One Place per region of b. The boundaries are the callers' validated ones (boolean.cpp).
std::vector<Place> place_in(const RegionSet& a, const RegionSet& b);

}  // namespace rearm::geometry::internal
