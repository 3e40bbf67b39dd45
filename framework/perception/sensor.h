// The sensor model of paper §II (docs/reactive.md §1): a disk of radius R around the robot, no
// occlusion. A familiar obstacle is seen (and localized whole) when it meets the closed sensor
// disk; an unknown convex obstacle is seen as its fragment inside the sensor footprint, the
// disk's circumscribed regular polygon.
#pragma once

#include <vector>

#include "geometry/polygon.h"

namespace rearm::perception {

using geometry::Point;
using geometry::Polygon;

// Default relative tolerance of the sensor footprint: the circumscribed regular polygon's
// boundary lies within R·tol outside the sensing circle (its vertices reach R/cos(π/n)). 5e-3
// gives n = 32 sides, the count the reactive layer uses for disks (kDiskPolygonSides).
inline constexpr double kFootprintTolerance = 5e-3;
// Fragments of smaller area (m²) are dropped: clipping a convex obstacle that only grazes the
// footprint leaves slivers that carry no freespace information and would make the
// diffeomorphism's convex pieces degenerate.
inline constexpr double kFragmentSliverArea = 1e-6;
// Consecutive fragment vertices closer than this (m) are merged; clipping creates such pairs
// where an obstacle vertex lies on (or within rounding of) a footprint edge.
inline constexpr double kFragmentMergeDistance = 1e-9;
// Bounds on the footprint's side count (the tolerance above picks a count in between).
inline constexpr int kMinFootprintSides = 8;
inline constexpr int kMaxFootprintSides = 4096;

struct SensorParams {
  double range = 0;  // R > 0 (m)
  double footprint_tolerance = kFootprintTolerance;
  double sliver_area = kFragmentSliverArea;
};

class Sensor {
 public:
  // Throws rearm::Error when the range is not finite and positive, the footprint tolerance is not
  // finite and positive (or needs more than kMaxFootprintSides sides), or the sliver area is
  // negative or not finite.
  explicit Sensor(const SensorParams& params);

  double range() const { return params_.range; }
  const SensorParams& params() const { return params_; }
  // Sides n of the footprint: the least n >= kMinFootprintSides with 1/cos(π/n) − 1 <= tol.
  int sides() const { return static_cast<int>(normals_.size()); }

  // The footprint at x: the regular n-gon circumscribed about the sensing circle, equal to
  // geometry::regular_polygon({x, R}, sides(), true). Every point of it is within
  // R/cos(π/n) <= R·(1 + footprint_tolerance) of x.
  Polygon footprint(const Point& x) const;

  // Does the closed polygon (valid, any orientation) meet the closed sensing disk, i.e. is its
  // distance to x at most R? When the boundary is out of range, point location (unambiguous
  // that far from every edge) decides the case of x inside the polygon. Allocation-free.
  // Throws rearm::Error when x is not finite.
  bool sees(const Polygon& p, const Point& x) const;

  // The visible fragment of a convex obstacle (counter-clockwise) from x: convex ∩ footprint(x),
  // with coincident and collinear vertices removed; empty when the intersection is empty or its
  // area is below sliver_area. The result is convex and counter-clockwise.
  Polygon fragment(const Polygon& convex, const Point& x) const;
  // The same, written into `out`, with `scratch` as working storage: no allocation once the two
  // buffers' capacities suffice (the semantic map's per-update path).
  void fragment(const Polygon& convex, const Point& x, std::vector<Point>& out,
                std::vector<Point>& scratch) const;

 private:
  SensorParams params_;
  std::vector<Point> normals_;  // unit outward normals of the footprint's edges
};

}  // namespace rearm::perception
