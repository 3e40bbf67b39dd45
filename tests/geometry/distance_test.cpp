#include "geometry/distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "core/rng.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"

namespace rearm::geometry {
namespace {

using test_support::random_star;
using test_support::ray_cast_inside;

// Boundary samples per edge for the brute-force truth.
constexpr int kSamplesPerEdge = 4000;

Polygon unit_square() { return Polygon{{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}}; }

// Minimum distance from x to points sampled densely along the boundary, and the spacing.
double sampled_boundary_distance(const Polygon& p, const Point& x, double* spacing) {
  double best = std::numeric_limits<double>::infinity();
  *spacing = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    *spacing = std::max(*spacing, (b - a).norm() / kSamplesPerEdge);
    for (int k = 0; k <= kSamplesPerEdge; ++k) {
      const double t = static_cast<double>(k) / kSamplesPerEdge;
      best = std::min(best, (a + t * (b - a) - x).norm());
    }
  }
  return best;
}

TEST(DistanceTest, SegmentHandCases) {
  const Point a(0, 0), b(2, 0);
  EXPECT_TRUE(nearest_on_segment(a, b, Point(1, 3)).isApprox(Point(1, 0)));
  EXPECT_TRUE(nearest_on_segment(a, b, Point(-1, 1)).isApprox(a));
  EXPECT_TRUE(nearest_on_segment(a, b, Point(5, -1)).isApprox(b));
  EXPECT_TRUE(nearest_on_segment(a, a, Point(5, -1)).isApprox(a));  // degenerate segment
}

TEST(DistanceTest, SquareHandCases) {
  const Polygon sq = unit_square();
  EXPECT_EQ(distance(sq, Point(0.5, 0.5)), 0);
  EXPECT_EQ(distance(sq, Point(0.1, 0.9)), 0);
  EXPECT_EQ(distance(sq, Point(1, 0.5)), 0);  // on the boundary
  EXPECT_EQ(distance(sq, Point(0, 0)), 0);
  // Outside a corner: Euclidean distance to the corner.
  EXPECT_NEAR(distance(sq, Point(2, 3)), std::hypot(1.0, 2.0), 1e-15);
  EXPECT_NEAR(distance(sq, Point(-0.3, -0.4)), 0.5, 1e-15);
  // Outside an edge: perpendicular distance.
  EXPECT_NEAR(distance(sq, Point(0.25, 1.75)), 0.75, 1e-15);
  EXPECT_NEAR(distance(sq, Point(-2, 0.6)), 2, 1e-15);
  const Nearest n = nearest_on_boundary(sq, Point(0.3, 0.2));  // inside: nearest edge y = 0
  EXPECT_TRUE(n.point.isApprox(Point(0.3, 0)));
  EXPECT_NEAR(n.distance, 0.2, 1e-15);
  const Nearest c = nearest_on_boundary(sq, Point(1.5, 1.5));
  EXPECT_TRUE(c.point.isApprox(Point(1, 1)));
}

TEST(DistanceTest, SignedDistanceHandCases) {
  const Polygon sq = unit_square();
  EXPECT_NEAR(signed_distance(sq, Point(0.3, 0.2)), -0.2, 1e-15);  // inside: minus the depth
  EXPECT_NEAR(signed_distance(sq, Point(0.5, 0.5)), -0.5, 1e-15);
  EXPECT_EQ(signed_distance(sq, Point(1, 0.5)), 0);  // on the boundary
  EXPECT_NEAR(signed_distance(sq, Point(2, 3)), std::hypot(1.0, 2.0), 1e-15);
  EXPECT_NEAR(signed_distance(sq, Point(-2, 0.6)), 2, 1e-15);
}

// A region's boundary is its outer ring and its holes: hand-computed nearest points.
TEST(DistanceTest, RegionBoundaryIncludesTheHoles) {
  const Region r{Polygon{{Point(0, 0), Point(10, 0), Point(10, 10), Point(0, 10)}},
                 {Polygon{{Point(4, 4), Point(6, 4), Point(6, 6), Point(4, 6)}}}};
  const Nearest near_hole = nearest_on_boundary(r, Point(3, 5));  // 1 m from the hole, 3 m out
  EXPECT_DOUBLE_EQ(near_hole.distance, 1);
  EXPECT_EQ(near_hole.point, Point(4, 5));
  const Nearest near_outer = nearest_on_boundary(r, Point(0.5, 5));
  EXPECT_DOUBLE_EQ(near_outer.distance, 0.5);
  EXPECT_EQ(near_outer.point, Point(0, 5));
}

TEST(DistanceTest, NonFinitePointThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(signed_distance(unit_square(), Point(nan, 0)), Error);
  EXPECT_THROW(distance(unit_square(), Point(nan, 0)), Error);
  EXPECT_THROW(nearest_on_boundary(unit_square(), Point(0, INFINITY)), Error);
}

TEST(DistanceTest, RandomPolygonsAgainstDenseSampling) {
  Rng rng(20261123);
  int inside = 0, outside = 0;
  // 20 polygons x 40 points at scale 1 (REARM_TEST_SCALE shrinks the sanitizer run).
  const auto trials = static_cast<int>(test_support::scaled(20));
  for (int trial = 0; trial < trials; ++trial) {
    const Polygon p = random_star(rng, static_cast<int>(rng.uniform_int(3, 14)), 0.3, 2.0);
    for (int s = 0; s < 40; ++s) {
      const Point x(rng.uniform(-3, 3), rng.uniform(-3, 3));
      double spacing = 0;
      const double sampled = sampled_boundary_distance(p, x, &spacing);
      const Nearest n = nearest_on_boundary(p, x);
      // The exact minimum is below every sample and within half a spacing of the best one.
      EXPECT_LE(n.distance, sampled + 1e-12);
      EXPECT_GE(n.distance, sampled - spacing / 2 - 1e-12);
      EXPECT_NEAR((n.point - x).norm(), n.distance, 1e-12);
      double spacing_at_point = 0;
      EXPECT_LT(sampled_boundary_distance(p, n.point, &spacing_at_point), spacing_at_point);
      const double d = distance(p, x);
      if (ray_cast_inside(p, x)) {
        ++inside;
        EXPECT_EQ(d, 0);
      } else {
        ++outside;
        EXPECT_EQ(d, n.distance);
      }
    }
  }
  EXPECT_GT(inside, static_cast<int>(test_support::scaled(50)) - 1);  // both sides covered
  EXPECT_GT(outside, static_cast<int>(test_support::scaled(50)) - 1);
}

}  // namespace
}  // namespace rearm::geometry
