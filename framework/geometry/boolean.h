// Exact polygon Boolean operations (CGAL Polygon_set_2 over the exact-constructions kernel;
// results rounded back to doubles and split into simple loops). The operations are
// regularized (two squares touching along an edge have an empty intersection), while
// intersects() counts touching. Every input boundary is validated (polygon.h) and bad input
// throws rearm::Error naming it; holes of an input region must lie inside its outer boundary
// and not overlap each other (not re-checked).
#pragma once

#include "geometry/polygon.h"

namespace rearm::geometry {

RegionSet to_set(const Polygon& p);
RegionSet unite(const RegionSet& a, const RegionSet& b);
RegionSet intersect(const RegionSet& a, const RegionSet& b);
RegionSet subtract(const RegionSet& a, const RegionSet& b);
// Union of many polygons (overlapping obstacles consolidated, holes kept).
RegionSet unite_all(const std::vector<Polygon>& polygons);
// Do the closed sets touch or overlap (exact)?
bool intersects(const RegionSet& a, const RegionSet& b);

// A closed boundary cycle rounded to doubles, cut into simple loops. Exact Boolean boundaries
// are only relatively simple (two squares touching at a corner give one cycle through that
// corner twice, which validated() rejects), and rounding can merge distinct vertices. Each loop
// keeps the cycle's orientation; consecutive duplicates and loops of fewer than 3 vertices (no
// area) are dropped.
std::vector<Polygon> simple_loops(const std::vector<Point>& cycle);

// A polygon as simple polygons: p itself when it is simple (polygon.h's check). Otherwise a
// boundary that touches itself away from its vertices (a vertex within `touch` of another edge,
// as rounding leaves a vertex that lies on an edge exactly) gets that vertex inserted into the
// edge, and the cycle, which then passes through it twice, is cut by simple_loops. The loops of
// counter-clockwise area above min_area that are simple are returned; the others (zero-area
// spikes, clockwise loops enclosed by the rest) are dropped.
std::vector<Polygon> simple_parts(const Polygon& p, double touch, double min_area);

}  // namespace rearm::geometry
