// Polygon measures against hand-computed values; validated() against each defect it must
// name; contains() against hand cases, exact boundary decisions, and an independent
// ray-casting oracle on seeded random star-shaped polygons.
#include "geometry/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "support/geometry_oracle.h"

namespace rearm::geometry {
namespace {

using test_support::boundary_distance;
using test_support::random_star;
using test_support::ray_cast_inside;

// Measures of hand-built shapes are exact up to a few roundings.
constexpr double kTol = 1e-12;
// Oracle samples closer than this to an edge are skipped: the double ray cast is unreliable
// there, while contains() is exact.
constexpr double kEdgeClearance = 1e-9;

Polygon poly(std::vector<Point> v) { return Polygon{std::move(v)}; }

Polygon unit_square() { return poly({{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }
Polygon l_shape() { return poly({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}); }
Polygon triangle() { return poly({{0, 0}, {4, 0}, {0, 3}}); }
Polygon square(double x0, double y0, double side) {
  return poly({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}});
}

// Expects validated() to throw a rearm::Error whose message has every listed fragment, and
// checked_polygon() to report the same defect as a value.
void expect_rejected(const Polygon& p, const std::vector<std::string>& fragments) {
  const Outcome<Polygon> checked = checked_polygon(p, "probe");
  ASSERT_FALSE(checked.ok());
  for (const std::string& f : fragments) {
    EXPECT_NE(checked.reason().find(f), std::string::npos) << checked.reason();
  }
  try {
    validated(p, "probe");
    ADD_FAILURE() << "validated() accepted an invalid polygon";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("probe"), std::string::npos) << msg;
    for (const std::string& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << msg;
  }
}

TEST(PolygonTest, UnitSquareMeasures) {
  const Polygon s = unit_square();
  EXPECT_NEAR(s.signed_area(), 1.0, kTol);
  EXPECT_NEAR(s.area(), 1.0, kTol);
  EXPECT_NEAR(s.centroid().x(), 0.5, kTol);
  EXPECT_NEAR(s.centroid().y(), 0.5, kTol);
  EXPECT_TRUE(s.is_convex());
}

TEST(PolygonTest, LShapeMeasures) {
  // Two rectangles: [0,2]x[0,1] (area 2, centroid (1, 1/2)) and [0,1]x[1,2] (area 1,
  // centroid (1/2, 3/2)); combined centroid (5/6, 5/6).
  const Polygon l = l_shape();
  EXPECT_NEAR(l.area(), 3.0, kTol);
  EXPECT_NEAR(l.centroid().x(), 5.0 / 6.0, kTol);
  EXPECT_NEAR(l.centroid().y(), 5.0 / 6.0, kTol);
  EXPECT_FALSE(l.is_convex());
}

TEST(PolygonTest, TriangleMeasures) {
  const Polygon t = triangle();
  EXPECT_NEAR(t.area(), 6.0, kTol);
  EXPECT_NEAR(t.centroid().x(), 4.0 / 3.0, kTol);
  EXPECT_NEAR(t.centroid().y(), 1.0, kTol);
  EXPECT_TRUE(t.is_convex());
}

TEST(PolygonTest, ConvexityRespectsOrientationAndAllowsCollinearVertices) {
  Polygon cw = unit_square();
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  EXPECT_NEAR(cw.signed_area(), -1.0, kTol);
  EXPECT_NEAR(cw.area(), 1.0, kTol);
  EXPECT_FALSE(cw.is_convex());
  EXPECT_TRUE(poly({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}).is_convex());
}

TEST(PolygonTest, RegionAreaSubtractsHoles) {
  const Region r{square(0, 0, 4), {square(1, 1, 1), square(2.5, 2.5, 1)}};
  EXPECT_NEAR(r.area(), 14.0, kTol);
  EXPECT_NEAR(total_area({r, Region{square(10, 10, 2), {}}}), 18.0, kTol);
}

TEST(PolygonTest, ValidatedKeepsCounterClockwiseAndReversesClockwise) {
  const Polygon l = l_shape();
  EXPECT_EQ(validated(l).vertices, l.vertices);
  Polygon cw = l;
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  const Polygon fixed = validated(cw);
  EXPECT_GT(fixed.signed_area(), 0);
  EXPECT_EQ(fixed.vertices, l.vertices);
  // Collinear (but not repeated) vertices are allowed.
  EXPECT_NO_THROW(validated(poly({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}})));
}

TEST(PolygonTest, ValidatedRejectsTooFewVertices) {
  expect_rejected(poly({}), {"at least 3", "got 0"});
  expect_rejected(poly({{0, 0}, {1, 0}}), {"at least 3", "got 2"});
}

TEST(PolygonTest, ValidatedRejectsNonFiniteVerticesByIndex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expect_rejected(poly({{0, 0}, {1, 0}, {nan, 1}, {0, 1}}), {"vertex 2", "not finite"});
  expect_rejected(poly({{0, 0}, {1, inf}, {1, 1}}), {"vertex 1", "not finite"});
  expect_rejected(poly({{0, 0}, {1, 0}, {1, 1}, {-inf, 1}}), {"vertex 3", "not finite"});
}

TEST(PolygonTest, ValidatedRejectsZeroLengthEdges) {
  expect_rejected(poly({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}), {"zero-length", "1 and 2"});
  // The closing edge counts too.
  expect_rejected(poly({{0, 0}, {1, 0}, {1, 1}, {0, 0}}), {"zero-length", "3 and 0"});
}

TEST(PolygonTest, ValidatedRejectsSelfIntersection) {
  expect_rejected(poly({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), {"not simple"});  // bow-tie
  // A vertex touching a non-adjacent edge.
  expect_rejected(poly({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}), {"not simple"});
}

TEST(PolygonTest, ValidatedRejectsZeroArea) {
  expect_rejected(poly({{0, 0}, {1, 1}, {2, 2}}), {"zero area"});
  expect_rejected(poly({{0, 0}, {1, 0}, {3, 0}, {2, 0}}), {"zero area"});
}

TEST(PolygonTest, ContainsCountsBoundaryAsInside) {
  const Polygon s = unit_square();
  for (const Point& v : s.vertices) EXPECT_TRUE(contains(s, v));
  EXPECT_TRUE(contains(s, Point(0.5, 0)));
  EXPECT_TRUE(contains(s, Point(1, 0.25)));
  EXPECT_TRUE(contains(s, Point(0.5, 0.5)));
  EXPECT_FALSE(contains(s, Point(1.5, 0.5)));
  EXPECT_FALSE(contains(s, Point(-1e-300, 0.5)));
  // Orientation does not matter.
  Polygon cw = s;
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  EXPECT_TRUE(contains(cw, Point(0.5, 0.5)));
  EXPECT_TRUE(contains(cw, Point(0, 0.5)));
}

TEST(PolygonTest, ContainsIsExactOnSlantedEdges) {
  const Polygon t = poly({{0, 0}, {1, 0}, {0, 1}});
  EXPECT_TRUE(contains(t, Point(0.5, 0.5)));  // on the hypotenuse x + y = 1
  EXPECT_FALSE(contains(t, Point(0.5, std::nextafter(0.5, 1.0))));
  EXPECT_TRUE(contains(t, Point(0.5, std::nextafter(0.5, 0.0))));
}

TEST(PolygonTest, ContainsRespectsHoles) {
  const Region r{square(0, 0, 4), {square(1, 1, 2)}};
  EXPECT_TRUE(contains(r, Point(0.5, 0.5)));
  EXPECT_FALSE(contains(r, Point(2, 2)));  // strictly inside the hole
  EXPECT_TRUE(contains(r, Point(1, 2)));   // on the hole boundary
  EXPECT_TRUE(contains(r, Point(3, 3)));   // hole corner
  EXPECT_TRUE(contains(r, Point(4, 4)));   // outer corner
  EXPECT_FALSE(contains(r, Point(5, 2)));
  const RegionSet set{r, Region{square(1.5, 1.5, 1), {}}};  // an island inside the hole
  EXPECT_TRUE(contains(set, Point(2, 2)));
  EXPECT_FALSE(contains(set, Point(1.25, 1.25)));
  EXPECT_TRUE(contains(set, Point(0.5, 3.5)));
  EXPECT_FALSE(contains(RegionSet{}, Point(0, 0)));
}

TEST(PolygonTest, ContainsRejectsNonFiniteInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(contains(unit_square(), Point(nan, 0)), Error);
  EXPECT_THROW(contains(poly({{0, 0}, {1, nan}, {0, 1}}), Point(0, 0)), Error);
  EXPECT_THROW(contains(Region{unit_square(), {poly({{0, 0}, {1, 1}})}}, Point(0, 0)), Error);
}

TEST(PolygonTest, ContainsMatchesRayCastingOnRandomStars) {
  Rng rng(20261123);
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Point c(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const int n = 3 + static_cast<int>(rng.index(30));
    const Polygon p = validated(random_star(rng, n, 0.2, 3.0, c, 0.0, 0.5));
    EXPECT_GT(p.area(), 0);
    for (int k = 0; k < 200; ++k) {
      const Point x = c + Point(rng.uniform(-3.5, 3.5), rng.uniform(-3.5, 3.5));
      if (boundary_distance(p, x) < kEdgeClearance) continue;
      ASSERT_EQ(contains(p, x), ray_cast_inside(p, x)) << "trial " << trial;
      ++checked;
    }
    for (const Point& v : p.vertices) EXPECT_TRUE(contains(p, v));
  }
  EXPECT_GT(checked, 19000);
}

}  // namespace
}  // namespace rearm::geometry
