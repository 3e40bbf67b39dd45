// Independent geometry for the geometry tests: random simple polygons and plain-double
// point-in-polygon and distance computations that share no code with framework/geometry.
#pragma once

#include <vector>

#include "core/rng.h"
#include "geometry/polygon.h"

namespace rearm::test_support {

// Star-shaped simple polygon around c: one vertex per equal angular sector at a jittered
// angle (fraction [jitter_lo, jitter_hi) of the sector), radius uniform in [r_min, r_max].
geometry::Polygon random_star(Rng& rng, int n, double r_min, double r_max,
                              const geometry::Point& c = geometry::Point::Zero(),
                              double jitter_lo = 0.05, double jitter_hi = 0.95);

// The points at the given angles on the ellipse with semi-axes (a, b), rotated by theta and
// centred at c: a convex counter-clockwise polygon when the angles are distinct, increasing
// and within one turn (built without convex_hull).
geometry::Polygon ellipse_polygon(const std::vector<double>& angles, double a, double b,
                                  double theta, const geometry::Point& c);

// Even-odd ray casting in doubles (its verdict is unreliable within ~1e-12 of an edge).
bool ray_cast_inside(const geometry::Polygon& p, const geometry::Point& x);

// Share of the cells of side `cell` of the [0, W] x [0, H] box whose centre lies in some polygon
// (ray casting): the density of the polygons' union, overlaps counted once, to about the
// boundary cells' share.
double raster_union_share(const std::vector<geometry::Polygon>& polygons, double W, double H,
                          double cell);

// Distance from x to the segment [a, b] and to the polygon's boundary, brute force.
double segment_distance(const geometry::Point& a, const geometry::Point& b,
                        const geometry::Point& x);
double boundary_distance(const geometry::Polygon& p, const geometry::Point& x);

}  // namespace rearm::test_support
