// Boolean operations against independent truth: area identities (inclusion-exclusion),
// pointwise set membership decided by a double ray-casting oracle on the INPUT polygons
// (samples near an input edge skipped), and hand-computed cases. Seeded random star-shaped
// polygons (simple by construction) and rectangles.
#include "geometry/boolean.h"

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

// Relative tolerance of the area identities: results are exact sets rounded to doubles.
constexpr double kAreaRelTol = 1e-9;
// Hand-case areas are exact up to a few roundings.
constexpr double kTol = 1e-12;
// Samples closer than this to an input edge are skipped: the oracle works in doubles.
constexpr double kEdgeClearance = 1e-9;
constexpr int kSamplesPerCase = 250;

Polygon poly(std::vector<Point> v) { return Polygon{std::move(v)}; }
Polygon rect(double x0, double y0, double x1, double y1) {
  return poly({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}
Polygon square(double x0, double y0, double side) { return rect(x0, y0, x0 + side, y0 + side); }

bool near_any_edge(const std::vector<Polygon>& inputs, const Point& x) {
  for (const Polygon& p : inputs) {
    if (boundary_distance(p, x) < kEdgeClearance) return true;
  }
  return false;
}

Polygon random_rect(Rng& rng) {
  const double x = rng.uniform(-2, 1), y = rng.uniform(-2, 1);
  return rect(x, y, x + rng.uniform(0.1, 3), y + rng.uniform(0.1, 3));
}

// A random simple polygon near the origin: a star (3..24 vertices) or a rectangle.
Polygon random_shape(Rng& rng) {
  if (rng.bernoulli(0.4)) return random_rect(rng);
  const Point c(rng.uniform(-1, 1), rng.uniform(-1, 1));
  return random_star(rng, 3 + static_cast<int>(rng.index(22)), 0.3, 2.5, c, 0.0, 0.5);
}

// The orientation convention of Region: every boundary counter-clockwise.
void expect_counter_clockwise(const RegionSet& s) {
  for (const Region& r : s) {
    EXPECT_GT(r.outer.signed_area(), 0);
    for (const Polygon& h : r.holes) EXPECT_GT(h.signed_area(), 0);
  }
}

std::size_t total_holes(const RegionSet& s) {
  std::size_t n = 0;
  for (const Region& r : s) n += r.holes.size();
  return n;
}

TEST(BooleanTest, RandomPairsSatisfyAreaIdentitiesAndMembership) {
  Rng rng(0x9e0b001);
  int samples = 0;
  for (int trial = 0; trial < 120; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Polygon a = random_shape(rng);
    const Polygon b = random_shape(rng);
    const RegionSet sa = to_set(a), sb = to_set(b);
    const RegionSet u = unite(sa, sb), i = intersect(sa, sb), d = subtract(sa, sb);
    expect_counter_clockwise(u);
    expect_counter_clockwise(i);
    expect_counter_clockwise(d);
    const double area_a = a.area(), area_b = b.area();
    const double scale = area_a + area_b;
    EXPECT_NEAR(total_area(u) + total_area(i), area_a + area_b, kAreaRelTol * scale);
    EXPECT_NEAR(total_area(d), area_a - total_area(i), kAreaRelTol * scale);
    EXPECT_GE(total_area(i), 0);
    EXPECT_EQ(intersects(sa, sb), total_area(i) > 0);  // touching has probability zero
    const std::vector<Polygon> inputs{a, b};
    for (int k = 0; k < kSamplesPerCase; ++k) {
      const Point x(rng.uniform(-4.5, 4.5), rng.uniform(-4.5, 4.5));
      if (near_any_edge(inputs, x)) continue;
      const bool in_a = ray_cast_inside(a, x), in_b = ray_cast_inside(b, x);
      ASSERT_EQ(contains(u, x), in_a || in_b) << x.transpose();
      ASSERT_EQ(contains(i, x), in_a && in_b) << x.transpose();
      ASSERT_EQ(contains(d, x), in_a && !in_b) << x.transpose();
      ++samples;
    }
  }
  EXPECT_GT(samples, 120 * 200);
}

// Differences produce holes; the results are fed back as inputs (regions with holes).
TEST(BooleanTest, RandomHolesRoundTripThroughFurtherOperations) {
  Rng rng(0x501e5);
  int samples = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Point c(rng.uniform(-1, 1), rng.uniform(-1, 1));
    const Polygon outer =
        random_star(rng, 8 + static_cast<int>(rng.index(16)), 2.5, 3.5, c, 0.0, 0.5);
    const Polygon inner =
        random_star(rng, 3 + static_cast<int>(rng.index(10)), 0.5, 1.5, c, 0.0, 0.5);
    const Polygon other = random_shape(rng);
    const RegionSet ring = subtract(to_set(outer), to_set(inner));
    ASSERT_EQ(ring.size(), 1u);
    ASSERT_EQ(ring[0].holes.size(), 1u);
    EXPECT_NEAR(total_area(ring), outer.area() - inner.area(), kAreaRelTol * outer.area());
    const RegionSet u = unite(ring, to_set(other)), i = intersect(ring, to_set(other));
    const double scale = outer.area() + other.area();
    EXPECT_NEAR(total_area(u) + total_area(i), total_area(ring) + other.area(),
                kAreaRelTol * scale);
    expect_counter_clockwise(u);
    const std::vector<Polygon> inputs{outer, inner, other};
    for (int k = 0; k < kSamplesPerCase; ++k) {
      const Point x = c + Point(rng.uniform(-4, 4), rng.uniform(-4, 4));
      if (near_any_edge(inputs, x)) continue;
      const bool in_ring = ray_cast_inside(outer, x) && !ray_cast_inside(inner, x);
      const bool in_other = ray_cast_inside(other, x);
      ASSERT_EQ(contains(ring, x), in_ring) << x.transpose();
      ASSERT_EQ(contains(u, x), in_ring || in_other) << x.transpose();
      ASSERT_EQ(contains(i, x), in_ring && in_other) << x.transpose();
      ++samples;
    }
  }
  EXPECT_GT(samples, 40 * 200);
}

TEST(BooleanTest, RandomUniteAllMatchesMembership) {
  Rng rng(0xa11);
  for (int trial = 0; trial < 30; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Polygon> ps;
    const int n = 2 + static_cast<int>(rng.index(7));
    double sum = 0, largest = 0;
    for (int k = 0; k < n; ++k) {
      ps.push_back(random_shape(rng));
      sum += ps.back().area();
      largest = std::max(largest, ps.back().area());
    }
    const RegionSet u = unite_all(ps);
    expect_counter_clockwise(u);
    EXPECT_LE(total_area(u), sum * (1 + kAreaRelTol));
    EXPECT_GE(total_area(u), largest * (1 - kAreaRelTol));
    // Pairwise unite gives the same set.
    RegionSet folded = to_set(ps[0]);
    for (int k = 1; k < n; ++k) folded = unite(folded, to_set(ps[k]));
    EXPECT_NEAR(total_area(u), total_area(folded), kAreaRelTol * sum);
    for (int k = 0; k < kSamplesPerCase; ++k) {
      const Point x(rng.uniform(-4.5, 4.5), rng.uniform(-4.5, 4.5));
      if (near_any_edge(ps, x)) continue;
      bool in_any = false;
      for (const Polygon& p : ps) in_any = in_any || ray_cast_inside(p, x);
      ASSERT_EQ(contains(u, x), in_any) << x.transpose();
    }
  }
}

// Many small shapes scattered over a room with a pillar (a hole): most stand alone inside it
// (subtract adds them as holes and unite_all passes them through without the sweep), some
// cross the walls or the pillar, overlap or touch each other, or lie outside. Membership by the
// ray-casting oracle and the area identity area(a − ∪b) = area(a) − area(a ∩ ∪b) decide.
TEST(BooleanTest, ScatteredObstaclesInARoomMatchMembershipAndArea) {
  Rng rng(0x5ca77e4);
  const Polygon room = square(-5, -5, 10), pillar = square(0.5, 0.5, 1.5);
  const RegionSet a{Region{room, {pillar}}};
  std::size_t holes = 0;
  int samples = 0;
  for (int trial = 0; trial < 25; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Polygon> obstacles;
    const int n = 4 + static_cast<int>(rng.index(20));
    for (int k = 0; k < n; ++k) {
      const Point c(rng.uniform(-6, 6), rng.uniform(-6, 6));
      obstacles.push_back(
          rng.bernoulli(0.3)
              ? rect(c.x(), c.y(), c.x() + rng.uniform(0.2, 1.5), c.y() + rng.uniform(0.2, 1.5))
              : random_star(rng, 3 + static_cast<int>(rng.index(30)), 0.2, 0.9, c, 0.0, 0.5));
    }
    if (trial % 5 == 0) {  // two squares touching at a corner, alone otherwise
      obstacles.push_back(square(-4, 3, 0.5));
      obstacles.push_back(square(-3.5, 3.5, 0.5));
    }
    const RegionSet u = unite_all(obstacles);
    const RegionSet d = subtract(a, u);
    expect_counter_clockwise(u);
    expect_counter_clockwise(d);
    holes += total_holes(d);
    const double cut = total_area(intersect(a, u));
    EXPECT_NEAR(total_area(d), total_area(a) - cut, kAreaRelTol * total_area(a));
    for (const Region& r : d) {
      EXPECT_NO_THROW(validated(r.outer));
      for (const Polygon& h : r.holes) EXPECT_NO_THROW(validated(h));
    }
    std::vector<Polygon> inputs = obstacles;
    inputs.push_back(room);
    inputs.push_back(pillar);
    for (int k = 0; k < kSamplesPerCase; ++k) {
      const Point x(rng.uniform(-6.5, 6.5), rng.uniform(-6.5, 6.5));
      if (near_any_edge(inputs, x)) continue;
      bool in_any = false;
      for (const Polygon& p : obstacles) in_any = in_any || ray_cast_inside(p, x);
      const bool in_a = ray_cast_inside(room, x) && !ray_cast_inside(pillar, x);
      ASSERT_EQ(contains(u, x), in_any) << x.transpose();
      ASSERT_EQ(contains(d, x), in_a && !in_any) << x.transpose();
      ++samples;
    }
  }
  EXPECT_GT(holes, 100u);  // the pillar and the obstacles standing alone inside
  EXPECT_GT(samples, 25 * 200);
}

// An obstacle strictly inside becomes a hole; outside, it removes nothing; one inside a hole
// of a, or holding a region of a, or touching another obstacle goes through the sweep.
TEST(BooleanTest, SubtractPlacesObstaclesExactly) {
  const RegionSet ring = subtract(to_set(square(0, 0, 10)), to_set(square(4, 4, 2)));
  const RegionSet inner = subtract(ring, RegionSet{Region{square(1, 1, 1), {}}});
  ASSERT_EQ(inner.size(), 1u);
  EXPECT_EQ(inner[0].holes.size(), 2u);
  EXPECT_NEAR(total_area(inner), 100.0 - 4 - 1, kTol);
  const RegionSet outside = subtract(ring, to_set(square(20, 20, 1)));
  EXPECT_NEAR(total_area(outside), 96.0, kTol);
  const RegionSet in_hole = subtract(ring, to_set(square(4.5, 4.5, 1)));
  EXPECT_NEAR(total_area(in_hole), 96.0, kTol);
  EXPECT_EQ(in_hole[0].holes.size(), 1u);
  EXPECT_TRUE(subtract(to_set(square(1, 1, 1)), to_set(square(0, 0, 4))).empty());
  // One ulp from the wall: still strictly inside, a hole.
  const double ulp = std::nextafter(0.0, 1.0);
  const RegionSet near_wall = subtract(to_set(square(0, 0, 10)), to_set(square(ulp, 1, 1)));
  ASSERT_EQ(near_wall.size(), 1u);
  EXPECT_EQ(near_wall[0].holes.size(), 1u);
  // On the wall: the boundary changes (an L-shaped notch, no hole).
  const RegionSet on_wall = subtract(to_set(square(0, 0, 10)), to_set(square(0, 1, 1)));
  ASSERT_EQ(on_wall.size(), 1u);
  EXPECT_EQ(on_wall[0].holes.size(), 0u);
  EXPECT_NEAR(total_area(on_wall), 99.0, kTol);
  // Obstacles given as overlapping regions of b are united by the sweep.
  const RegionSet overlapping =
      subtract(to_set(square(0, 0, 10)),
               RegionSet{Region{square(1, 1, 2), {}}, Region{square(2, 2, 2), {}}});
  ASSERT_EQ(overlapping.size(), 1u);
  EXPECT_EQ(overlapping[0].holes.size(), 1u);
  EXPECT_NEAR(total_area(overlapping), 100.0 - 7, kTol);
}

TEST(BooleanTest, OverlappingSquares) {
  const RegionSet a = to_set(square(0, 0, 2)), b = to_set(square(1, 1, 2));
  const RegionSet u = unite(a, b);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].holes.size(), 0u);
  EXPECT_EQ(u[0].outer.size(), 8u);
  EXPECT_NEAR(total_area(u), 7.0, kTol);
  const RegionSet i = intersect(a, b);
  ASSERT_EQ(i.size(), 1u);
  EXPECT_NEAR(total_area(i), 1.0, kTol);
  EXPECT_TRUE(contains(i, Point(1.5, 1.5)));
  EXPECT_FALSE(contains(i, Point(0.5, 0.5)));
  const RegionSet d = subtract(a, b);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NEAR(total_area(d), 3.0, kTol);
  EXPECT_EQ(d[0].outer.size(), 6u);  // an L
  EXPECT_TRUE(intersects(a, b));
}

TEST(BooleanTest, SubtractingAnInnerSquareLeavesAHole) {
  const RegionSet d = subtract(to_set(square(0, 0, 2)), to_set(square(0.5, 0.5, 1)));
  ASSERT_EQ(d.size(), 1u);
  ASSERT_EQ(d[0].holes.size(), 1u);
  EXPECT_NEAR(d[0].area(), 3.0, kTol);
  EXPECT_NEAR(d[0].outer.area(), 4.0, kTol);
  EXPECT_NEAR(d[0].holes[0].area(), 1.0, kTol);
  expect_counter_clockwise(d);
  EXPECT_FALSE(contains(d, Point(1, 1)));
  EXPECT_TRUE(contains(d, Point(0.25, 1)));
  EXPECT_TRUE(contains(d, Point(0.5, 1)));  // hole boundary
  // Filling the hole restores the square.
  const RegionSet filled = unite(d, to_set(square(0.5, 0.5, 1)));
  ASSERT_EQ(filled.size(), 1u);
  EXPECT_EQ(filled[0].holes.size(), 0u);
  EXPECT_NEAR(total_area(filled), 4.0, kTol);
  // A square inside the hole is disjoint from the ring.
  EXPECT_FALSE(intersects(d, to_set(square(0.75, 0.75, 0.5))));
  EXPECT_TRUE(intersects(d, to_set(square(0.5, 0.5, 0.5))));  // touches the hole boundary
}

TEST(BooleanTest, DisjointSquares) {
  const RegionSet a = to_set(square(0, 0, 1)), b = to_set(square(3, 0, 1));
  const RegionSet u = unite(a, b);
  EXPECT_EQ(u.size(), 2u);
  EXPECT_NEAR(total_area(u), 2.0, kTol);
  EXPECT_TRUE(intersect(a, b).empty());
  EXPECT_NEAR(total_area(subtract(a, b)), 1.0, kTol);
  EXPECT_FALSE(intersects(a, b));
  // Containment without boundary contact, both ways.
  EXPECT_TRUE(intersects(to_set(square(0, 0, 4)), to_set(square(1, 1, 1))));
  EXPECT_TRUE(intersects(to_set(square(1, 1, 1)), to_set(square(0, 0, 4))));
}

TEST(BooleanTest, TouchingSquares) {
  const RegionSet a = to_set(square(0, 0, 1)), b = to_set(square(1, 0, 1));
  const RegionSet u = unite(a, b);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].holes.size(), 0u);
  EXPECT_NEAR(total_area(u), 2.0, kTol);
  EXPECT_TRUE(intersects(a, b));
  EXPECT_NEAR(total_area(intersect(a, b)), 0.0, kTol);  // regularized: the edge vanishes
  // Touching at one corner only; a gap of one ulp does not touch.
  EXPECT_TRUE(intersects(a, to_set(square(1, 1, 1))));
  EXPECT_FALSE(intersects(a, to_set(square(std::nextafter(1.0, 2.0), 1, 1))));
}

// CGAL's boundaries are only relatively simple (a vertex may repeat); results are cut into
// simple boundaries so that they are valid inputs again.
TEST(BooleanTest, PinchedResultsAreSplitIntoValidRegions) {
  const RegionSet corner = unite(to_set(square(0, 0, 1)), to_set(square(1, 1, 1)));
  ASSERT_EQ(corner.size(), 2u);
  EXPECT_NEAR(total_area(corner), 2.0, kTol);
  expect_counter_clockwise(corner);
  for (const Region& r : corner) EXPECT_NO_THROW(validated(r.outer));
  const RegionSet again = unite(corner, to_set(square(5, 5, 1)));
  EXPECT_EQ(again.size(), 3u);
  EXPECT_NEAR(total_area(again), 3.0, kTol);
  EXPECT_TRUE(contains(corner, Point(1, 1)));
  // Two holes touching at a corner.
  const RegionSet holes =
      subtract(to_set(square(0, 0, 4)), unite(to_set(square(1, 1, 1)), to_set(square(2, 2, 1))));
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_EQ(holes[0].holes.size(), 2u);
  EXPECT_NEAR(total_area(holes), 14.0, kTol);
  expect_counter_clockwise(holes);
  for (const Polygon& h : holes[0].holes) EXPECT_NO_THROW(validated(h));
  const RegionSet cut = subtract(holes, to_set(rect(0, 0, 4, 0.5)));
  EXPECT_NEAR(total_area(cut), 12.0, kTol);
  EXPECT_FALSE(contains(cut, Point(1.5, 1.5)));
  EXPECT_TRUE(contains(cut, Point(2, 2)));
}

TEST(BooleanTest, UniteAllChainOfThreeRectangles) {
  // Pairwise overlaps 0.5 (first, second) and 0.25 (second, third); first and third apart.
  const std::vector<Polygon> chain{rect(0, 0, 2, 1), rect(1, 0.5, 3, 1.5), rect(2.5, 0, 4.5, 1)};
  const RegionSet u = unite_all(chain);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].holes.size(), 0u);
  EXPECT_NEAR(total_area(u), 6.0 - 0.75, kTol);
  expect_counter_clockwise(u);
}

TEST(BooleanTest, UniteAllKeepsEnclosedHoles) {
  // Four bars forming a frame around [1,2]^2, given clockwise and counter-clockwise.
  Polygon left = rect(0, 0, 1, 3);
  std::reverse(left.vertices.begin(), left.vertices.end());
  const RegionSet u = unite_all({rect(0, 0, 3, 1), rect(2, 0, 3, 3), rect(0, 2, 3, 3), left});
  ASSERT_EQ(u.size(), 1u);
  ASSERT_EQ(u[0].holes.size(), 1u);
  EXPECT_NEAR(total_area(u), 8.0, kTol);
  EXPECT_NEAR(u[0].holes[0].area(), 1.0, kTol);
  expect_counter_clockwise(u);
  EXPECT_EQ(total_holes(unite_all({})), 0u);
  EXPECT_TRUE(unite_all({}).empty());
}

TEST(BooleanTest, InvalidInputsAreRejectedWithTheirPlace) {
  const Polygon bow_tie = poly({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  const RegionSet good = to_set(square(0, 0, 1));
  EXPECT_THROW(to_set(bow_tie), Error);
  try {
    unite(good, RegionSet{Region{bow_tie, {}}});
    ADD_FAILURE() << "unite accepted a bow-tie";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unite: second region 0"), std::string::npos) << e.what();
  }
  try {
    unite_all({square(0, 0, 1), poly({{0, 0}, {1, 0}})});
    ADD_FAILURE() << "unite_all accepted a two-vertex polygon";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unite_all: polygon 1"), std::string::npos) << e.what();
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(intersects(good, RegionSet{Region{square(0, 0, 1), {square(nan, 0, 0.5)}}}), Error);
  EXPECT_THROW(subtract(good, RegionSet{Region{square(0, 0, 1), {poly({})}}}), Error);
}

// simple_parts: a boundary that touches itself away from its vertices, against validated()'s
// exact check and the shoelace area of hand-built pieces.
TEST(BooleanTest, SimplePartsReturnsASimplePolygonAsItIs) {
  const Polygon square{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}};
  const std::vector<Polygon> parts = simple_parts(square, 1e-6, 1e-12);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].vertices, square.vertices);
}

TEST(BooleanTest, SimplePartsDropsASpikeAlongAnEdge) {
  // The triangle (2,0), (4,0), (4,2) and a zero-area spike from (2,0) back to (0,0) along the
  // bottom edge; the spike's tip lies on that edge exactly, then 1e-13 across it.
  for (const double off : {0.0, -1e-13}) {
    const Polygon p{{{0, 0}, {4, 0}, {4, 2}, {2, off}}};
    EXPECT_THROW(validated(p), Error);
    const std::vector<Polygon> parts = simple_parts(p, 1e-6, 1e-12);
    ASSERT_EQ(parts.size(), 1u) << off;
    EXPECT_NO_THROW(validated(parts[0]));
    EXPECT_NEAR(parts[0].signed_area(), 2.0, kTol);
    EXPECT_EQ(std::count(parts[0].vertices.begin(), parts[0].vertices.end(), Point(0, 0)), 0);
  }
}

// The pocket that ended a crowded trial (N = 8, footprint 0.05) with "convex_partition polygon:
// not simple": a dilated disk's arc and the hull edge (0.467, 1.142)-(2.281, 0.632), which the
// arc's vertex (1.3076, 0.9058) touches. One simple part remains, with the spike's tip gone and
// the pocket's area kept.
TEST(BooleanTest, SimplePartsMendsTheCrowdedPocket) {
  const Polygon pocket{
      {{1.2265862161651371, 1.115684254505924},   {1.2674706959096169, 0.98090618718608547},
       {1.3076386511656759, 0.90575722853135565}, {0.46724993615498484, 1.1420313067530627},
       {2.2810356794310884, 0.63208805438706284}, {2.3303955534596721, 0.65847145672446916},
       {2.4392684382488206, 0.74782112416725577}, {2.5286181056916073, 0.85669400895640457},
       {2.595010898176076, 0.98090618718608491},  {2.6358953779205563, 1.1156842545059238},
       {2.6497003772967478, 1.25584876537323},    {2.6358953779205563, 1.3960132762405359},
       {2.595010898176076, 1.5307913435603746},   {2.5286181056916073, 1.6550035217900554},
       {2.4392684382488206, 1.7638764065792041},  {2.3303955534596721, 1.8532260740219906},
       {2.2061833752299913, 1.9196188665064595},  {2.0714053079101529, 1.9605033462509396},
       {1.9312407970428467, 1.9743083456271311},  {1.7910762861755407, 1.9605033462509396},
       {1.6562982188557021, 1.9196188665064595},  {1.5320860406260213, 1.8532260740219908},
       {1.4232131558368726, 1.7638764065792041},  {1.3338634883940861, 1.6550035217900554},
       {1.2674706959096171, 1.5307913435603746},  {1.2265862161651371, 1.3960132762405362},
       {1.2127812167889456, 1.25584876537323}}};
  EXPECT_THROW(validated(pocket), Error);
  const std::vector<Polygon> parts = simple_parts(pocket, 1e-6, 1e-12);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_NO_THROW(validated(parts[0]));
  EXPECT_EQ(parts[0].size(), pocket.size() - 1);  // the spike's tip out
  const Point tip(0.46724993615498484, 1.1420313067530627);
  EXPECT_EQ(std::count(parts[0].vertices.begin(), parts[0].vertices.end(), tip), 0);
  EXPECT_NEAR(parts[0].signed_area(), pocket.signed_area(), 1e-9);
}

}  // namespace
}  // namespace rearm::geometry
