// The sensor model (paper §II) against independent truth: the footprint's error bound; familiar
// visibility against the true polygon distance (ray casting + brute-force boundary distance);
// fragments against the obstacle's half-planes, the sensing radius and the exact area of
// obstacle ∩ disk (closed form, itself checked against a fine grid).
#include "perception/sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "perception_oracle.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"

namespace rearm::perception {
namespace {

using oracle::convex_excess;
using oracle::is_convex_ccw;
using oracle::polygon_disk_area;
using oracle::random_convex;
using oracle::true_distance;

// Geometric slack for rounding in the clip and in the oracle (m, m²).
constexpr double kEps = 1e-9;
// Queries this close to the decision boundary distance == R are skipped (the oracle rounds).
constexpr double kKnifeEdge = 1e-9;

Polygon square(double x0, double y0, double side) {
  return Polygon{{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}};
}

double circumradius(const Sensor& s) { return s.range() / std::cos(std::numbers::pi / s.sides()); }

TEST(SensorTest, DefaultFootprintHas32SidesWithinTolerance) {
  const Sensor s({.range = 2.0});
  EXPECT_EQ(s.sides(), 32);
  const Point x(1.5, -0.25);
  const Polygon f = s.footprint(x);
  ASSERT_EQ(f.size(), 32u);
  for (const Point& v : f.vertices) {
    EXPECT_LE((v - x).norm(), s.range() * (1 + kFootprintTolerance));
    EXPECT_GE((v - x).norm(), s.range());
  }
  // Every edge is tangent to the sensing circle: its midpoint is at distance R.
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Point m = 0.5 * (f.vertices[i] + f.vertices[(i + 1) % f.size()]);
    EXPECT_NEAR((m - x).norm(), s.range(), 1e-12);
  }
}

TEST(SensorTest, SideCountIsTheLeastMeetingTheTolerance) {
  for (const double tol : {1e-1, 2e-2, 5e-3, 1e-3, 1e-4, 1e-5}) {
    const Sensor s({.range = 1.0, .footprint_tolerance = tol});
    const int n = s.sides();
    EXPECT_LE(1 / std::cos(std::numbers::pi / n) - 1, tol) << tol;
    if (n > kMinFootprintSides) {
      EXPECT_GT(1 / std::cos(std::numbers::pi / (n - 1)) - 1, tol) << tol;
    }
  }
}

TEST(SensorTest, OracleAreaMatchesFineGrid) {
  // The closed-form oracle itself, against midpoint counting on a 1000 x 1000 grid.
  Rng rng(7);
  const Polygon p = random_convex(rng, 7, 1.5, 0.8, 0.3, Point(0.9, 0.2));
  const Point c(0, 0);
  const double r = 1.2;
  const int m = 1000;
  const double lo = -1.3;
  const double h = 2.6 / m;
  int hits = 0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const Point q(lo + (i + 0.5) * h, lo + (j + 0.5) * h);
      if ((q - c).norm() <= r && test_support::ray_cast_inside(p, q)) ++hits;
    }
  }
  const double grid = hits * h * h;
  // Boundary cells: (perimeter of disk + polygon) / h cells of area h², a loose bound.
  EXPECT_NEAR(polygon_disk_area(p, c, r), grid, 1e-2);
  EXPECT_NEAR(polygon_disk_area(square(-0.5, -0.5, 1), c, 10), 1.0, 1e-12);
  EXPECT_NEAR(polygon_disk_area(square(-5, -5, 10), c, 1), std::numbers::pi, 1e-12);
}

TEST(SensorTest, SeesHandCases) {
  const Sensor s({.range = 2.0});
  const Polygon sq = square(2, 0, 1);  // distance 2 from the origin
  EXPECT_TRUE(s.sees(sq, Point(0, 0.5)));
  EXPECT_TRUE(s.sees(sq, Point(0, 0)));  // closed disk: exactly R away
  EXPECT_FALSE(s.sees(sq, Point(-1e-9, 0)));
  EXPECT_FALSE(s.sees(sq, Point(-3, 0)));
  // Inside a large polygon, far from its boundary.
  EXPECT_TRUE(s.sees(square(-50, -50, 100), Point(0, 0)));
  // Inside the bounding box of a U but in its pocket, far from every wall.
  const Polygon u{
      {{-20, -20}, {20, -20}, {20, 20}, {19, 20}, {19, -19}, {-19, -19}, {-19, 20}, {-20, 20}}};
  EXPECT_FALSE(s.sees(u, Point(0, 5)));
  EXPECT_TRUE(s.sees(u, Point(0, -17.5)));
}

TEST(SensorTest, SeesExactlyWhenTrueDistanceIsWithinRange) {
  Rng rng(11);
  const std::size_t cases = test_support::scaled(3000);
  std::size_t seen = 0, unseen = 0;
  for (std::size_t k = 0; k < cases; ++k) {
    const int n = 3 + static_cast<int>(rng.index(14));
    const Polygon p = test_support::random_star(rng, n, 0.3, 2.0, Point(0, 0));
    const Sensor s({.range = rng.uniform(0.1, 3.0)});
    const Point x(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double d = true_distance(p, x);
    if (std::abs(d - s.range()) < kKnifeEdge) continue;
    const bool truth = d <= s.range();
    EXPECT_EQ(s.sees(p, x), truth) << "case " << k << " d=" << d << " R=" << s.range();
    (truth ? seen : unseen)++;
  }
  EXPECT_GT(seen, cases / 10);
  EXPECT_GT(unseen, cases / 10);
}

// Checks a fragment of `obstacle` seen from x by `s` against the exact truth.
void ExpectFragmentTruth(const Sensor& s, const Polygon& obstacle, const Point& x,
                         const Polygon& frag, const char* label) {
  const double inner = polygon_disk_area(obstacle, x, s.range());
  const double outer = polygon_disk_area(obstacle, x, circumradius(s));
  if (frag.size() == 0) {
    // Dropped: empty or a sliver (its area is at least that of obstacle ∩ disk).
    EXPECT_LT(inner, s.params().sliver_area + kEps) << label;
    return;
  }
  EXPECT_TRUE(is_convex_ccw(frag)) << label;
  for (const Point& v : frag.vertices) {
    EXPECT_LE(convex_excess(obstacle, v), kEps) << label;
    EXPECT_LE((v - x).norm(), s.range() * (1 + s.params().footprint_tolerance) + kEps) << label;
  }
  // obstacle ∩ disk(R) ⊂ fragment ⊂ obstacle ∩ disk(R / cos(π/n)).
  EXPECT_GE(frag.area(), inner - kEps) << label;
  EXPECT_LE(frag.area(), outer + kEps) << label;
  EXPECT_GE(frag.area(), s.params().sliver_area) << label;
}

TEST(SensorTest, FragmentsMatchExactIntersectionOnRandomCases) {
  Rng rng(23);
  const std::size_t cases = test_support::scaled(3000);
  std::size_t partial = 0, empty = 0;
  std::vector<Point> out, scratch;
  for (std::size_t k = 0; k < cases; ++k) {
    const int n = 3 + static_cast<int>(rng.index(12));
    const Polygon obstacle =
        random_convex(rng, n, rng.uniform(0.2, 3), rng.uniform(0.2, 3), rng.uniform(0, 3.2),
                      Point(rng.uniform(-1, 1), rng.uniform(-1, 1)));
    const Sensor s({.range = rng.uniform(0.2, 3.0),
                    .footprint_tolerance = rng.bernoulli(0.5) ? kFootprintTolerance : 1e-3});
    const Point x(rng.uniform(-4, 4), rng.uniform(-4, 4));
    const Polygon frag = s.fragment(obstacle, x);
    const std::string label = "case " + std::to_string(k);
    ExpectFragmentTruth(s, obstacle, x, frag, label.c_str());
    // The allocation-free overload gives the same polygon.
    s.fragment(obstacle, x, out, scratch);
    EXPECT_EQ(out, frag.vertices) << label;
    if (frag.size() == 0) {
      ++empty;
    } else if (frag.area() < obstacle.area() - kEps) {
      ++partial;
    }
  }
  EXPECT_GT(partial, cases / 10);
  EXPECT_GT(empty, cases / 10);
}

TEST(SensorTest, WholeObstacleInsideTheDiskIsItsOwnFragment) {
  const Sensor s({.range = 5.0});
  const Polygon tri{{{0, 0}, {1, 0}, {0.2, 0.7}}};
  const Polygon frag = s.fragment(tri, Point(0.3, 0.3));
  EXPECT_EQ(frag.vertices, tri.vertices);
}

TEST(SensorTest, DisjointAndGrazingObstaclesGiveNoFragment) {
  const Sensor s({.range = 1.0});
  EXPECT_EQ(s.fragment(square(3, 3, 1), Point(0, 0)).size(), 0u);
  // A square poking 1e-5 m into the footprint: a sliver of area ~1e-5 · 2e-3 < 1e-6.
  const double reach = 1 / std::cos(std::numbers::pi / s.sides());
  const Polygon thin{
      {{reach - 1e-5, -1e-3}, {reach + 1, -1e-3}, {reach + 1, 1e-3}, {reach - 1e-5, 1e-3}}};
  EXPECT_EQ(s.fragment(thin, Point(0, 0)).size(), 0u);
  // Deeper, the same square is seen.
  const Polygon deep{{{0.5, -0.1}, {reach + 1, -0.1}, {reach + 1, 0.1}, {0.5, 0.1}}};
  const Polygon frag = s.fragment(deep, Point(0, 0));
  ExpectFragmentTruth(s, deep, Point(0, 0), frag, "deep");
  EXPECT_GT(frag.size(), 0u);
}

TEST(SensorTest, ObstacleVertexOnTheFootprintEdgeLeavesNoDuplicate) {
  const Sensor s({.range = 1.0});
  // The footprint's edge facing +x at angle π/32 is tangent at (cos, sin)(π/32); put a vertex
  // of a triangle exactly on the sensing circle there.
  const double a = std::numbers::pi / s.sides();
  const Point t(std::cos(a), std::sin(a));
  const Polygon tri{{{0.2, 0}, t, {0.2, 0.5}}};
  const Polygon frag = s.fragment(tri, Point(0, 0));
  ASSERT_GE(frag.size(), 3u);
  for (std::size_t i = 0; i < frag.size(); ++i) {
    EXPECT_GT((frag.vertices[i] - frag.vertices[(i + 1) % frag.size()]).norm(),
              kFragmentMergeDistance);
  }
  EXPECT_TRUE(is_convex_ccw(frag));
}

TEST(SensorTest, RejectsNonFinitePosition) {
  const Sensor s({.range = 1.0});
  const Point bad(std::nan(""), 0);
  EXPECT_THROW(s.sees(square(0, 0, 1), bad), Error);
  EXPECT_THROW(s.fragment(square(0, 0, 1), bad), Error);
  EXPECT_THROW(s.footprint(bad), Error);
}

}  // namespace
}  // namespace rearm::perception
