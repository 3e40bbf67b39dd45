// What one convex polygon adds to another (geometry/convex_difference.h). Truth: points of
// B \ A sampled on a grid and located by ray casting (test_support::ray_cast_inside, no shared
// code with the function under test): the distance computed is never above a sampled point's
// (the deferral's and the semantic map's safety: nothing new is nearer than reported) and
// within the grid's reach of the nearest one (the boundary a fragment shares with its earlier
// self does not count as new).
#include "geometry/convex_difference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/rng.h"
#include "geometry/convex.h"
#include "support/geometry_oracle.h"
#include "support/task_scenes.h"

namespace rearm::geometry {
namespace {

using test_support::ray_cast_inside;

constexpr double kInf = std::numeric_limits<double>::infinity();

// What a sensor of range 3 m at x sees of a convex obstacle: the obstacle clipped by the
// circumscribed 32-gon (the footprint of perception/sensor.h, built here by hand).
Polygon seen_from(const Polygon& obstacle, const Point& x) {
  return intersect_convex(obstacle, regular_polygon(Disk{x, 3.0}, 32, true));
}

struct Sampled {
  double nearest = kInf;  // least distance from x to a sampled point of B \ A
  int count = 0;          // sampled points of B \ A
};

// Grid points (spacing h) of B's bounding box that lie in B and not in A.
Sampled sample_difference(const Polygon& a, const Polygon& b, const Point& x, double h) {
  double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
  for (const Point& v : b.vertices) {
    x0 = std::min(x0, v.x());
    y0 = std::min(y0, v.y());
    x1 = std::max(x1, v.x());
    y1 = std::max(y1, v.y());
  }
  Sampled s;
  for (double u = x0; u <= x1; u += h) {
    for (double v = y0; v <= y1; v += h) {
      const Point p(u, v);
      if (!ray_cast_inside(b, p) || (a.size() >= 3 && ray_cast_inside(a, p))) continue;
      ++s.count;
      s.nearest = std::min(s.nearest, (p - x).norm());
    }
  }
  return s;
}

// A wall seen from two robot positions 0.5 m apart along it: the fragments share the wall's
// long edges (each clipped on its own by its footprint), and the new part lies about R away.
TEST(ConvexDifference, FragmentsOfOneWallCountOnlyTheirNewPart) {
  const Polygon wall = test_support::rect(-10, 0.5, 10, 1.0);
  const Point then(0, 0), now(0.5, 0);
  const Polygon a = seen_from(wall, then);
  const Polygon b = seen_from(wall, now);
  ASSERT_GE(a.size(), 3U);
  ASSERT_GE(b.size(), 3U);
  const double d = convex_difference_distance(a, b, now);
  const Sampled s = sample_difference(a, b, now, 0.002);
  ASSERT_GT(s.count, 100);
  EXPECT_LE(d, s.nearest + 1e-9);
  EXPECT_GE(d, s.nearest - 0.01);
  // The new part lies outside the old footprint: at least R − 0.5 m from the robot, far beyond
  // the wall's near edge (0.5 m away).
  EXPECT_GT(d, 3.0 - 0.5 - 1e-6);
}

// Random overlapping convex polygons (ellipse polygons) and random points.
TEST(ConvexDifference, ConvexDifferenceMatchesSampling) {
  Rng rng(20261204);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    auto ellipse = [&](const Point& c) {
      const int n = static_cast<int>(rng.uniform_int(3, 9));
      std::vector<double> angles;
      for (int i = 0; i < n; ++i) angles.push_back(2 * std::numbers::pi * (i + 0.5) / n);
      return test_support::ellipse_polygon(angles, rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0),
                                           rng.uniform(0, std::numbers::pi), c);
    };
    Polygon a = ellipse(Point(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)));
    Polygon b = ellipse(Point(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)));
    const Point x(rng.uniform(-4, 4), rng.uniform(-4, 4));
    const Sampled s = sample_difference(a, b, x, 0.01);
    const double d = convex_difference_distance(a, b, x);
    if (s.count == 0) continue;  // B inside A, or a sliver the grid misses: no bound to check
    EXPECT_LE(d, s.nearest + 1e-9) << "trial " << trial;
    if (s.count > 200) {
      EXPECT_GE(d, s.nearest - 0.05) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(ConvexDifference, EmptyOldFragmentIsTheWholeNewOne) {
  const Polygon b = test_support::rect(2, -1, 3, 1);
  EXPECT_DOUBLE_EQ(convex_difference_distance(Polygon{}, b, Point(0, 0)), 2.0);
  EXPECT_EQ(convex_difference_distance(b, b, Point(0, 0)), kInf);
  EXPECT_EQ(convex_difference_distance(b, Polygon{}, Point(0, 0)), kInf);
  // B inside A: nothing new.
  EXPECT_EQ(convex_difference_distance(test_support::rect(0, -3, 5, 3), b, Point(-1, 0)), kInf);
}

}  // namespace
}  // namespace rearm::geometry
