// Distance from a point to what one convex polygon adds to another (B \ A). Two readings of a
// sensor fragment are convex polygons of one obstacle; this says how near the robot the part
// seen now and not then lies. Used by the semantic map (growth near the robot is always news,
// docs/reactive.md §2) and by the executive's deferred rebuilds (docs/executive.md).
#pragma once

#include "geometry/polygon.h"

namespace rearm::geometry {

// m: two fragments of one obstacle share its edges, each clipped on its own, so a shared edge
// may be collinear only up to rounding. Parts of B's boundary this close outside A, and parts
// of A's boundary this close inside B, are that shared boundary, not the new part's; new parts
// thinner than this do not count.
inline constexpr double kSharedEdge = 1e-7;

// Distance (m) from x to the closure of B \ A for convex counter-clockwise polygons A and B
// (A may be empty: the distance to B). +infinity when B adds nothing beyond kSharedEdge (or B
// is empty). Rounding makes the value uncertain by about 1e-12 m.
double convex_difference_distance(const Polygon& a, const Polygon& b, const Point& x);

}  // namespace rearm::geometry
