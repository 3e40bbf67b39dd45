// Convex-polygon and disk helpers in doubles for the control path (docs/reactive.md §3–4):
// half-plane clipping, convex intersection, Euclidean projection, ray and line queries,
// convex hulls and regular polygons. None of these makes a topological decision (those use
// the exact predicates of polygon.h / boolean.h); they build collars, local freespaces and
// sensor footprints, and never allocate beyond their result.
#pragma once

#include <optional>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::geometry {

// A closed disk (a movable object, a model-space obstacle, the sensor footprint).
struct Disk {
  Point center = Point::Zero();
  double radius = 0;
};

// A closed half-plane { q : normal·q <= offset }; normal need not be unit length.
struct HalfPlane {
  Point normal = Point::UnitX();
  double offset = 0;
  double value(const Point& q) const { return normal.dot(q) - offset; }  // <= 0 inside
};

// The half-plane bounded by the line through a and b that lies on the left of a→b
// (the inside of a counter-clockwise edge).
HalfPlane left_of(const Point& a, const Point& b);

// Sutherland–Hodgman: the part of a convex polygon (counter-clockwise) inside h. Vertices
// closer than 1e-12 m are merged; the result is empty (size 0) when it has no area (h misses
// or only touches the polygon).
Polygon clip(const Polygon& convex, const HalfPlane& h);

// Intersection of two convex polygons (counter-clockwise); empty when they do not overlap.
Polygon intersect_convex(const Polygon& a, const Polygon& b);

// Euclidean projection of q onto a closed convex polygon (counter-clockwise, non-empty).
Point project_onto_convex(const Polygon& convex, const Point& q);

// Does the closed convex polygon contain q (tolerance tol, in length units)?
bool convex_contains(const Polygon& convex, const Point& q, double tol = 0);

// For a point o inside a convex polygon and a direction d (non-zero): the largest t >= 0
// with o + t·d in the polygon, or nullopt when o is outside.
std::optional<double> ray_exit(const Polygon& convex, const Point& o, const Point& d);

// The interval [t_lo, t_hi] of t with o + t·d in the convex polygon (counter-clockwise) shrunk by
// `inset` (m; negative grows it), or nullopt when the line misses it.
struct Interval {
  double lo = 0;
  double hi = 0;
};
std::optional<Interval> line_interval(const Polygon& convex, const Point& o, const Point& d,
                                      double inset = 0);

// Convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
Polygon convex_hull(std::vector<Point> points);

// Regular n-gon around a disk: inscribed (vertices on the circle, a subset of the disk) or
// circumscribed (edges tangent to the circle, a superset). n >= 3.
Polygon regular_polygon(const Disk& d, int n, bool circumscribed);

// Drops vertices whose two edges are collinear within `tol` (the turning cross product
// relative to the edge lengths) and repeated vertices; keeps orientation.
Polygon remove_collinear(const Polygon& p, double tol = 1e-12);

// Do two convex polygons overlap with positive area (separating-axis test, tolerance tol)?
// Touching along an edge or at a vertex is not overlap.
bool convex_overlap(const Polygon& a, const Polygon& b, double tol = 1e-12);

// A separating half-plane for interior-disjoint convex polygons a and b: a lies inside it,
// b outside (touching allowed), chosen among the edge normals of both with the largest
// separation. nullopt when they overlap by more than tol.
std::optional<HalfPlane> separating_half_plane(const Polygon& a, const Polygon& b,
                                               double tol = 1e-12);

// Mitered outward offset of a convex polygon (counter-clockwise) by d > 0: every edge pushed
// out by d, consecutive offset lines meeting at the vertices; a corner whose miter is longer
// than miter_limit·d (>= 1) is bevelled by the line perpendicular to the corner's bisector at
// distance miter_limit·d from the vertex. The result is convex and contains the d-dilation.
Polygon offset_convex(const Polygon& convex, double d, double miter_limit = 2.0);

// Convex decomposition by reflex-vertex extensions: while a piece has a reflex vertex, it is
// cut along the continuation of one of that vertex's edges (the shorter of the two cuts) up to
// the first boundary point hit. Orthogonal shapes (L, U, T, staircase, cross) fall apart into
// rectangles, with no sharp angle a diagonal partition makes. A cut's end point is a new vertex
// shared bit for bit by both sides; pieces keep their 180° vertices. The polygon must be simple,
// counter-clockwise, without collinear vertices. A failure (a value: the caller tries another
// decomposition) when no cut splits a piece (the polygon is not simple enough) or past
// `max_pieces` pieces.
Outcome<std::vector<Polygon>> decompose_by_extensions(const Polygon& simple,
                                                      std::size_t max_pieces = 256);

// Ear-clipping triangulation of a simple counter-clockwise polygon without collinear
// vertices: n − 2 triangles whose vertices are the input vertices (bit for bit), so shared
// edges are exact. A failure when no ear is found (the polygon is not simple).
Outcome<std::vector<Polygon>> triangulate(const Polygon& simple);

}  // namespace rearm::geometry
