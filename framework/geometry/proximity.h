// Proximity of polygons in doubles, for accept-or-retry decisions (the random instance
// generator's clearance tests): a rejected candidate is simply redrawn, so the tests may be
// conservative where exactness would cost (crossing or collinear edges count as touching).
#pragma once

#include <utility>

#include "geometry/box.h"
#include "geometry/polygon.h"

namespace rearm::geometry {

// Distance between segments [a, b] and [c, d]; 0 when they may touch (collinear or crossing).
double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d);
// Whether two closed simple polygons are less than w apart (they overlap, one contains the
// other, or two edges come closer than w).
bool closer_than(const Polygon& p, const Polygon& q, double w);
// How deep the deepest vertex of p lies inside q, whose bounding box is qbox (0 when none does).
double vertex_depth(const Polygon& p, const Polygon& q, const Box& qbox);
// Crossing-number point-in-polygon in doubles (an estimate: no exact predicate).
bool inside_by_crossings(const Polygon& p, const Point& x);
// The nearest pair of boundary points (on p, on q) of two disjoint polygons.
std::pair<Point, Point> nearest_points(const Polygon& p, const Polygon& q);
// Distance from x to the closed axis-aligned square of side `side` centred at c.
double square_distance(const Point& c, double side, const Point& x);

}  // namespace rearm::geometry
