// The local freespace LF(y) of Arslan & Koditschek (IJRR 2019) in the model space
// (docs/reactive.md §4): the convex cell of points at least as close to y as to any obstacle,
//   LF(y) = { q : (q − y)·u_i ≤ d_i / 2 for every obstacle i } ∩ F_e ∩ B(y, R/2),
// with d_i, u_i the distance and unit direction from y to obstacle i's nearest point. The cell
// is exact for the model disks and the convex unknown obstacles; the complement of the
// enclosing boundary F_e is an obstacle too (its half-plane), and LF is also clipped by F_e.
// The sensing limit B(y, R/2) is replaced by an inscribed regular polygon (a subset of the
// disk, so every guarantee of the exact cell still holds).
#pragma once

#include <string>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "reactive/model_space.h"

namespace rearm::reactive {

// Thrown when y is not strictly inside the model freespace: the robot touches an obstacle's
// dilation (an outcome the interface layer answers by backing up, executive.h), unlike
// malformed input.
class OutsideModelFreespace : public Error {
 public:
  explicit OutsideModelFreespace(const std::string& what) : Error(what) {}
};

// Sides of the regular polygon inscribed in B(y, R/2). At 32 sides it keeps cos(π/32) ≈ 99.5%
// of the radius.
inline constexpr int kSensingPolygonSides = 32;

// LF(y) as a convex counter-clockwise polygon containing y in its interior.
// Obstacles farther than R from y are skipped (their half-plane cannot cut B(y, R/2)).
// Throws rearm::Error when y or R is not finite, R <= 0, sides < 3, the boundary has fewer
// than 3 vertices, or y is not strictly inside the model freespace (inside or on an obstacle,
// outside or on the boundary).
geometry::Polygon local_freespace(const ModelSpace& m, const geometry::Point& y,
                                  double sensor_range, int sides = kSensingPolygonSides);

// The same, written into `out`, using `scratch` as the second clipping buffer: once both have
// grown to their working size, no allocation happens (the control path).
void local_freespace(const ModelSpace& m, const geometry::Point& y, double sensor_range,
                     geometry::Polygon& out, geometry::Polygon& scratch,
                     int sides = kSensingPolygonSides);

}  // namespace rearm::reactive
