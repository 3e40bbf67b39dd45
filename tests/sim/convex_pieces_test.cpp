// The Box2D convex splitter against independent truth: shoelace areas, a cross-product
// convexity check and even-odd ray casting (tests/support/geometry_oracle.h) at random points —
// every point of the polygon lies in exactly one piece, every point outside in none.
#include "sim/convex_pieces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "support/geometry_oracle.h"

namespace rearm::sim {
namespace {

using geometry::Point;
using geometry::Polygon;

double shoelace(const Polygon& p) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& u = p.vertices[i];
    const Point& w = p.vertices[(i + 1) % n];
    a += u.x() * w.y() - w.x() * u.y();
  }
  return a / 2;
}

// Counter-clockwise with every turn strictly left (no reflex, no collinear vertex).
bool strictly_convex_ccw(const Polygon& p) {
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point a = p.vertices[(i + 1) % n] - p.vertices[i];
    const Point b = p.vertices[(i + 2) % n] - p.vertices[(i + 1) % n];
    if (a.x() * b.y() - a.y() * b.x() <= 0) return false;
  }
  return true;
}

double near_boundary(const Polygon& p, const Point& x) {
  return test_support::boundary_distance(p, x);
}

// The pieces tile the polygon: areas add up, each piece is convex with 3..8 vertices, and random
// points away from every edge lie in exactly one piece when inside the polygon, in none outside.
void expect_tiling(const Polygon& p, const std::vector<Polygon>& pieces, Rng& rng,
                   int samples = 400) {
  double sum = 0;
  for (const Polygon& q : pieces) {
    EXPECT_GE(q.size(), 3u);
    EXPECT_LE(q.size(), kMaxPieceVertices);
    EXPECT_TRUE(strictly_convex_ccw(q));
    sum += shoelace(q);
  }
  const double area = std::abs(shoelace(p));
  EXPECT_NEAR(sum, area, 1e-9 * std::max(1.0, area));

  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Point& v : p.vertices) {
    x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
    y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
  }
  for (int k = 0; k < samples; ++k) {
    const Point x(rng.uniform(x0, x1), rng.uniform(y0, y1));
    bool on_edge = near_boundary(p, x) < 1e-9;
    for (const Polygon& q : pieces) on_edge = on_edge || near_boundary(q, x) < 1e-9;
    if (on_edge) continue;
    int in = 0;
    for (const Polygon& q : pieces) in += test_support::ray_cast_inside(q, x) ? 1 : 0;
    EXPECT_EQ(in, test_support::ray_cast_inside(p, x) ? 1 : 0) << x.transpose();
  }
}

TEST(SplitConvex, FanPiecesOfAtMostEightVertices) {
  // A regular 20-gon: three pieces of 8 vertices (each cut keeps v0 and the piece's last vertex,
  // so the rest shrinks from 20 to 14 to 8).
  Polygon p;
  for (int k = 0; k < 20; ++k) {
    const double a = 2 * std::numbers::pi * k / 20;
    p.vertices.emplace_back(std::cos(a), std::sin(a));
  }
  const std::vector<Polygon> pieces = split_convex(p);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0].size(), 8u);
  EXPECT_EQ(pieces[1].size(), 8u);
  EXPECT_EQ(pieces[2].size(), 8u);
  Rng rng(1);
  expect_tiling(p, pieces, rng);
  // Exactly 8 vertices stay one piece; a triangle fan for max_vertices = 3.
  p.vertices.resize(8);
  EXPECT_EQ(split_convex(p).size(), 1u);
  EXPECT_EQ(split_convex(p, 3).size(), 6u);
}

TEST(SplitConvex, RejectsBadArguments) {
  const Polygon tri{{Point(0, 0), Point(1, 0), Point(0, 1)}};
  EXPECT_THROW(split_convex(tri, 2), Error);
  EXPECT_THROW(split_convex(Polygon{{Point(0, 0), Point(1, 0)}}), Error);
}

TEST(ConvexPieces, ConvexPolygonWithCollinearVerticesIsOnePiece) {
  // A square with a midpoint on every side (clockwise input): Set would drop the midpoints.
  const Polygon p{{Point(0, 0), Point(0, 1), Point(0, 2), Point(1, 2), Point(2, 2), Point(2, 1),
                   Point(2, 0), Point(1, 0)}};
  const std::vector<Polygon> pieces = convex_pieces(p);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].size(), 4u);
  EXPECT_DOUBLE_EQ(shoelace(pieces[0]), 4.0);
}

TEST(ConvexPieces, LAndUShapes) {
  Rng rng(2);
  const Polygon l{{Point(0, 0), Point(3, 0), Point(3, 1), Point(1, 1), Point(1, 3), Point(0, 3)}};
  const std::vector<Polygon> lp = convex_pieces(l);
  EXPECT_EQ(lp.size(), 2u);
  expect_tiling(l, lp, rng);
  const Polygon u{{Point(0, 0), Point(3, 0), Point(3, 2), Point(2, 2), Point(2, 1), Point(1, 1),
                   Point(1, 2), Point(0, 2)}};
  const std::vector<Polygon> up = convex_pieces(u);
  EXPECT_EQ(up.size(), 3u);
  expect_tiling(u, up, rng);
}

TEST(ConvexPieces, RandomStarsAreTiled) {
  Rng rng(20240611);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = static_cast<int>(rng.uniform_int(3, 40));
    const Polygon p = test_support::random_star(rng, n, 0.3, 2.0, Point(rng.uniform(-5, 5), 0));
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(n));
    expect_tiling(p, convex_pieces(p), rng, 100);
  }
}

TEST(ConvexPieces, LargeConvexPolygonsAreSplit) {
  Rng rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    // Star with small radial jitter and many vertices: convex or nearly so.
    const int n = static_cast<int>(rng.uniform_int(9, 64));
    const Polygon p = test_support::random_star(rng, n, 1.0, 1.0 + 1e-3, Point::Zero(), 0.45, 0.55);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_tiling(p, convex_pieces(p), rng, 100);
  }
}

TEST(ConvexPieces, RejectsInvalidPolygons) {
  const Polygon bowtie{{Point(0, 0), Point(1, 1), Point(1, 0), Point(0, 1)}};
  EXPECT_THROW(convex_pieces(bowtie, "bowtie"), Error);
  const Polygon nan{{Point(0, 0), Point(1, 0), Point(0, std::nan(""))}};
  EXPECT_THROW(convex_pieces(nan), Error);
}

}  // namespace
}  // namespace rearm::sim
