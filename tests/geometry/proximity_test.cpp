// The generator's proximity tests (geometry/proximity.h) against independent truth: distances
// between segments and polygons from dense sampling of both boundaries, point-in-polygon from
// the exact predicate (geometry::contains), and hand-computed configurations.
#include "geometry/proximity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/rng.h"

namespace rearm::geometry {
namespace {

Polygon square(double x, double y, double side) {
  return Polygon{{Point(x, y), Point(x + side, y), Point(x + side, y + side), Point(x, y + side)}};
}

// Least distance between points sampled densely along two segments (an upper bound within
// the sampling step of the true distance).
double sampled_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  constexpr int kSamples = 400;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSamples; ++i) {
    const Point p = a + (b - a) * (static_cast<double>(i) / kSamples);
    for (int j = 0; j <= kSamples; ++j) {
      const Point q = c + (d - c) * (static_cast<double>(j) / kSamples);
      best = std::min(best, (p - q).norm());
    }
  }
  return best;
}

TEST(Proximity, SegmentDistanceMatchesSampling) {
  Rng rng(20261205);
  int crossing = 0;
  for (int k = 0; k < 60; ++k) {
    const Point a(rng.uniform(0, 4), rng.uniform(0, 4)), b(rng.uniform(0, 4), rng.uniform(0, 4));
    const Point c(rng.uniform(0, 4), rng.uniform(0, 4)), d(rng.uniform(0, 4), rng.uniform(0, 4));
    const double got = segment_distance(a, b, c, d);
    const double sampled = sampled_distance(a, b, c, d);
    // The sampling step bounds the error: at most half a step's length on each segment.
    const double step = ((b - a).norm() + (d - c).norm()) / 400;
    EXPECT_LE(got, sampled + 1e-12) << k;
    EXPECT_GE(got, sampled - step) << k;
    crossing += got == 0;
  }
  EXPECT_GT(crossing, 0);  // the random draws include crossing pairs
  EXPECT_DOUBLE_EQ(segment_distance(Point(0, 0), Point(2, 0), Point(0, 1), Point(2, 1)), 1);
  // Collinear segments count as touching even 1 m apart: conservative, as documented (the
  // generator redraws a rejected candidate).
  EXPECT_EQ(segment_distance(Point(0, 0), Point(2, 0), Point(3, 0), Point(4, 0)), 0);
}

TEST(Proximity, CloserThanByGapOverlapAndNesting) {
  const Polygon p = square(0, 0, 1);
  const Polygon q = square(1.5, 0.25, 1);  // 0.5 m to the right
  EXPECT_TRUE(closer_than(p, q, 0.6));
  EXPECT_FALSE(closer_than(p, q, 0.4));
  EXPECT_TRUE(closer_than(p, square(0.5, 0.5, 1), 0.01));   // overlapping
  EXPECT_TRUE(closer_than(square(0, 0, 4), p, 0.01));       // p inside
  EXPECT_TRUE(closer_than(p, square(0.25, 0.25, 0.5), 0));  // inside p, any w
  // A diagonal gap: corner (1, 1) to corner (1.3, 1.4) is 0.5 m.
  const Polygon r = square(1.3, 1.4, 1);
  EXPECT_TRUE(closer_than(p, r, 0.5 + 1e-9));
  EXPECT_FALSE(closer_than(p, r, 0.5 - 1e-9));
}

TEST(Proximity, VertexDepthIsTheDeepestVertexInside) {
  const Polygon q = square(0, 0, 2);
  const Box qbox = box_of(q);
  EXPECT_DOUBLE_EQ(vertex_depth(square(1.7, 1.6, 1), q, qbox), 0.3);  // (1.7,1.6): 0.3 to x = 2
  EXPECT_DOUBLE_EQ(vertex_depth(square(3, 3, 1), q, qbox), 0);
}

TEST(Proximity, CrossingsAgreeWithTheExactPredicateOffTheBoundary) {
  const Polygon l{{Point(0, 0), Point(3, 0), Point(3, 1), Point(1, 1), Point(1, 3), Point(0, 3)}};
  Rng rng(7);
  for (int k = 0; k < 2000; ++k) {
    const Point x(rng.uniform(-0.5, 3.5), rng.uniform(-0.5, 3.5));
    EXPECT_EQ(inside_by_crossings(l, x), contains(l, x)) << x.transpose();
  }
}

TEST(Proximity, NearestPointsAndSquareDistance) {
  const auto [a, b] = nearest_points(square(0, 0, 1), square(2, 0.5, 1));
  EXPECT_DOUBLE_EQ((a - b).norm(), 1);
  EXPECT_DOUBLE_EQ(a.x(), 1);
  EXPECT_DOUBLE_EQ(b.x(), 2);
  EXPECT_DOUBLE_EQ(square_distance(Point(0, 0), 2, Point(4, 5)), std::hypot(3, 4));
  EXPECT_DOUBLE_EQ(square_distance(Point(0, 0), 2, Point(0.5, -0.5)), 0);
}

}  // namespace
}  // namespace rearm::geometry
