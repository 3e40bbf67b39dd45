// Dilation of polygons by a disk of radius r (docs/reactive.md §2): the obstacles grown by
// the robot radius (or robot + object radius).
//  - round: Minkowski sum with a regular polygon circumscribed about the disk, so the
//    result contains the exact dilation (conservative for safety) and its boundary is
//    within r·(1/cos(π/n) − 1) of the exact one; n is chosen from kMaxDilationError.
//  - miter: the mitered offset of reactive.md §2 (familiar polygons): every edge pushed out
//    by r, consecutive offset lines meeting at convex vertices, corners longer than
//    kMiterLimit·r bevelled. Contains the exact dilation; every point is within
//    r / cos(φ/2) of the polygon (φ the largest convex turning angle), and within
//    sqrt(kMiterLimit² + 1)·r at bevelled corners.
#pragma once

#include <cmath>
#include <numbers>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::geometry {

// Largest distance allowed between the round dilation's boundary and the exact one,
// relative to r (0.5 %).
inline constexpr double kMaxDilationError = 5e-3;

// Longest miter corner, in units of r (>= 1 so the bevelled corner still contains the
// disk dilation); sharper corners are bevelled, as SVG's stroke-miterlimit does.
inline constexpr double kMiterLimit = 2.0;

// p is validated (polygon.h); r must be finite and > 0. Both throw rearm::Error otherwise.
// A strictly convex p (the unknown fragments) takes a linear-time merge of the two polygons'
// edges, decided exactly and rounded as the exact kernel rounds: the same polygon, vertex for
// vertex, as dilate_round_exact, which every other polygon takes.
RegionSet dilate_round(const Polygon& p, double r);
// The Minkowski sum of any simple polygon with the n-gon, built by CGAL's exact kernel.
RegionSet dilate_round_exact(const Polygon& p, double r);
// `limit`: the miter limit in units of r (finite, >= 1; kMiterLimit unless a caller asks for
// tighter corners: 1 bevels every convex corner on the disk dilation's tangent).
RegionSet dilate_miter(const Polygon& p, double r, double limit = kMiterLimit);

// Sides of the circumscribed regular polygon that stands for a disk (a dilated movable object,
// a corner of an eroded workspace) in exact Booleans: a superset of the disk whose boundary is
// within radius·(1/cos(π/32) − 1) ≈ 0.5 % of the circle.
inline constexpr int kDiskPolygonSides = 32;

// Obstacles that feed the freespace Booleans (reactive mapped space, topology check) are
// dilated by r + kContactSlack (m): dilations that touch in exact arithmetic can be 1e-15 m
// apart after rounding, which would leave a zero-width corridor of freespace between them; the
// slack consolidates them (and keeps the robot 1e-9 m further away).
inline constexpr double kContactSlack = 1e-9;

// A disk as its circumscribed kDiskPolygonSides-gon (radius finite and > 0, else rearm::Error).
Polygon disk_polygon(const Disk& d);
// The circumradius of disk_polygon for a disk of radius r: the disk that holds the polygon.
inline double disk_polygon_circumradius(double r) {
  return r / std::cos(std::numbers::pi / kDiskPolygonSides);
}

// The workspace eroded by r: W minus the union of thick segments (hulls of two circumscribed
// disk polygons) around its edges; a subset of the exact erosion (conservative). The
// workspace is validated (polygon.h); r must be finite and > 0. Both throw rearm::Error.
RegionSet erode(const Polygon& workspace, double r);

}  // namespace rearm::geometry
