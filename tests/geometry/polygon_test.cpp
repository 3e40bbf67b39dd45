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

// Polygons whose turns all have one sign: convex and simple when the direction goes round once
// (regular and random ellipse polygons, either sense: kept or reversed), not simple when it goes
// round twice or more (star polygons {n/k}: every turn left, yet the edges cross).
TEST(PolygonTest, ValidatedOneSignedTurnsAreSimpleOnlyWhenWindingOnce) {
  const auto star = [](int n, int k, bool clockwise) {
    Polygon p;
    for (int i = 0; i < n; ++i) {
      const double a = (clockwise ? -2.0 : 2.0) * std::numbers::pi * k * i / n;
      p.vertices.emplace_back(std::cos(a), std::sin(a));
    }
    return p;
  };
  for (const bool cw : {false, true}) {
    expect_rejected(star(5, 2, cw), {"not simple"});
    expect_rejected(star(7, 2, cw), {"not simple"});
    expect_rejected(star(7, 3, cw), {"not simple"});
    expect_rejected(star(9, 4, cw), {"not simple"});
    for (const int n : {3, 4, 32}) {
      const Polygon p = star(n, 1, cw);
      Polygon ccw = p;
      if (cw) std::reverse(ccw.vertices.begin(), ccw.vertices.end());
      EXPECT_EQ(validated(p).vertices, ccw.vertices) << n << (cw ? " clockwise" : "");
    }
  }
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> angles;
    const int n = 3 + static_cast<int>(rng.uniform(0, 40));
    for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0, 2 * std::numbers::pi));
    std::sort(angles.begin(), angles.end());
    angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
    Polygon p = test_support::ellipse_polygon(angles, rng.uniform(0.1, 5), rng.uniform(1e-3, 5),
                                              rng.uniform(0, 3), Point(rng.uniform(-1e3, 1e3), 2));
    if (p.size() < 3 || p.signed_area() <= 0) continue;
    EXPECT_EQ(validated(p).vertices, p.vertices) << trial;
    Polygon cw = p;
    std::reverse(cw.vertices.begin(), cw.vertices.end());
    EXPECT_EQ(validated(cw).vertices, p.vertices) << trial;
  }
}

// Simplicity on small-integer vertices (touching, collinear overlaps and repeated vertices
// everywhere) against the definition evaluated in exact integer arithmetic here: no two
// non-consecutive edges meet, consecutive edges only at their shared vertex. Sizes on both
// sides of checked_polygon's switch from all pairs of edges to CGAL's sweep (64 vertices).
namespace exact_int {
using I = long long;
int orient(const Point& a, const Point& b, const Point& c) {
  const I v = (static_cast<I>(b.x()) - static_cast<I>(a.x())) *
                  (static_cast<I>(c.y()) - static_cast<I>(a.y())) -
              (static_cast<I>(b.y()) - static_cast<I>(a.y())) *
                  (static_cast<I>(c.x()) - static_cast<I>(a.x()));
  return (v > 0) - (v < 0);
}
bool on_segment(const Point& a, const Point& b, const Point& q) {
  return orient(a, b, q) == 0 && std::min(a.x(), b.x()) <= q.x() &&
         q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
         q.y() <= std::max(a.y(), b.y());
}
bool meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}
bool simple(const Polygon& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point &a = p.vertices[i], &b = p.vertices[(i + 1) % n];
      const Point &c = p.vertices[j], &d = p.vertices[(j + 1) % n];
      if (j == i + 1) {  // consecutive: b == c; d must not lie on [a, b], nor a on [c, d]
        if (on_segment(a, b, d) || on_segment(c, d, a)) return false;
      } else if (i == 0 && j == n - 1) {  // consecutive: d == a
        if (on_segment(a, b, c) || on_segment(c, d, b)) return false;
      } else if (meet(a, b, c, d)) {
        return false;
      }
    }
  }
  return true;
}
// Strictly inside a simple polygon, q on no edge: the crossings of the ray from q towards +x
// (edges with one end at or below q's height and the other above, q left of the edge).
bool inside(const Polygon& p, const Point& q) {
  bool in = false;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    Point a = p.vertices[i], b = p.vertices[(i + 1) % n];
    if ((a.y() <= q.y()) == (b.y() <= q.y())) continue;
    if (a.y() > b.y()) std::swap(a, b);
    in ^= orient(a, b, q) > 0;
  }
  return in;
}
}  // namespace exact_int

TEST(PolygonTest, ValidatedSimplicityMatchesTheDefinitionOnIntegerVertices) {
  Rng rng(11);
  int simple = 0, not_simple = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const bool large = trial % 4 == 0;
    const int n =
        large ? 60 + static_cast<int>(rng.uniform(0, 20)) : 4 + static_cast<int>(rng.uniform(0, 9));
    Polygon p;
    if (large) {  // a star around the centre of a 400 × 400 grid, sometimes two vertices swapped
      for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * (i + rng.uniform(0.1, 0.9)) / n;
        const double r = rng.uniform(50, 190);
        p.vertices.emplace_back(std::round(200 + r * std::cos(a)),
                                std::round(200 + r * std::sin(a)));
      }
      if (rng.uniform01() < 0.5) {
        const auto i = static_cast<std::size_t>(rng.uniform(0, n)),
                   j = static_cast<std::size_t>(rng.uniform(0, n));
        std::swap(p.vertices[i], p.vertices[j]);
      }
    } else {
      for (int i = 0; i < n; ++i)
        p.vertices.emplace_back(std::floor(rng.uniform(0, 7)), std::floor(rng.uniform(0, 7)));
    }
    bool repeated = false;
    for (std::size_t i = 0; i < p.size(); ++i)
      repeated |= p.vertices[i] == p.vertices[(i + 1) % p.size()];
    bool collinear = true;
    for (std::size_t i = 2; i < p.size(); ++i)
      collinear &= exact_int::orient(p.vertices[0], p.vertices[1], p.vertices[i]) == 0;
    if (repeated || collinear) continue;
    const Outcome<Polygon> checked = checked_polygon(p);
    const bool want = exact_int::simple(p);
    ASSERT_EQ(checked.ok(), want) << "trial " << trial << ", " << p.size() << " vertices"
                                  << (checked.ok() ? "" : ": " + checked.reason());
    (want ? simple : not_simple) += 1;
  }
  EXPECT_GT(simple, 500);
  EXPECT_GT(not_simple, 500);
}

TEST(PolygonTest, SideOfMatchesTheDefinitionOnIntegerVertices) {
  Rng rng(12);
  int counts[3] = {0, 0, 0};  // outside, boundary, inside
  for (int trial = 0; trial < 600; ++trial) {
    Polygon p;
    const int n = 4 + static_cast<int>(rng.uniform(0, 9));
    for (int i = 0; i < n; ++i)
      p.vertices.emplace_back(std::floor(rng.uniform(0, 7)), std::floor(rng.uniform(0, 7)));
    if (!checked_polygon(p).ok() || !exact_int::simple(p)) continue;
    for (int reversed = 0; reversed < 2; ++reversed) {
      if (reversed) std::reverse(p.vertices.begin(), p.vertices.end());
      for (double x = -1; x <= 7; x += 0.5) {
        for (double y = -1; y <= 7; y += 0.5) {
          const Point q(x, y);
          // Half-integer points: integers for the oracle after doubling every coordinate.
          Polygon p2 = p;
          for (Point& v : p2.vertices) v *= 2;
          bool edge = false;
          for (std::size_t i = 0; i < p2.size(); ++i)
            edge |= exact_int::on_segment(p2.vertices[i], p2.vertices[(i + 1) % p2.size()], 2 * q);
          const int want = edge ? 0 : exact_int::inside(p2, 2 * q) ? 1 : -1;
          ASSERT_EQ(side_of(p, q), want) << "trial " << trial << " at " << x << ", " << y;
          ++counts[want + 1];
        }
      }
    }
  }
  for (int c : counts) EXPECT_GT(c, 1000);
  EXPECT_THROW(side_of(unit_square(), Point(std::nan(""), 0)), Error);
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
