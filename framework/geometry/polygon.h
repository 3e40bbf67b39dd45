// Planar geometry value types (docs/architecture.md: geometry/ holds points, polygons,
// Boolean operations, dilation, convex decomposition and distances). Doubles here; the
// topological decisions (Booleans, partition) are made exactly inside the .cpp files with
// CGAL's exact kernel, which never appears in a header.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/outcome.h"

namespace rearm::geometry {

using Point = Eigen::Vector2d;

// A simple polygon: vertices in counter-clockwise order, no repeated closing vertex.
struct Polygon {
  std::vector<Point> vertices;

  std::size_t size() const { return vertices.size(); }
  // Shoelace area: positive when counter-clockwise.
  double signed_area() const;
  double area() const;
  Point centroid() const;  // area centroid (vertex mean for a degenerate polygon)
  bool is_convex() const;  // counter-clockwise, no reflex vertex (collinear allowed)
};

// A region: an outer boundary (counter-clockwise) with holes (each counter-clockwise too;
// they are subtracted).
struct Region {
  Polygon outer;
  std::vector<Polygon> holes;
  double area() const;
};

// Interior-disjoint regions (e.g. the result of a Boolean operation); regions may touch at
// single points.
using RegionSet = std::vector<Region>;

// Checks a polygon given by a caller: at least 3 finite vertices, no zero-length edge,
// simple (no self-intersection, exact predicates), non-zero area. Returns it in
// counter-clockwise order. Throws rearm::Error naming `what` and the defect.
Polygon validated(const Polygon& p, const char* what = "polygon");
// The same check as a value, for a search that rejects candidate polygons (a random instance's
// obstacles): the polygon in counter-clockwise order, or the defect naming `what`.
Outcome<Polygon> checked_polygon(const Polygon& p, const char* what = "polygon");

// Point in polygon / region (boundary counts as inside), exact predicates. The polygon is
// assumed valid (validated()); a non-finite point or vertex throws rearm::Error.
bool contains(const Polygon& p, const Point& x);
bool contains(const Region& r, const Point& x);
bool contains(const RegionSet& s, const Point& x);
// Where x lies relative to the polygon, exact: +1 in its interior, 0 on its boundary, −1
// outside (either orientation; the polygon assumed valid). Non-finite input throws as above.
int side_of(const Polygon& p, const Point& x);

double total_area(const RegionSet& s);

// The turn a → b → c, exact (predicates on the doubles): +1 left (counter-clockwise), −1
// right, 0 collinear. Points must be finite (not checked).
int orientation(const Point& a, const Point& b, const Point& c);

}  // namespace rearm::geometry
