#include "geometry/partition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "support/geometry_oracle.h"

namespace rearm::geometry {
namespace {

using test_support::random_star;
using test_support::ray_cast_inside;

// Relative tolerance on the total area of the pieces (they share the input's vertices, so
// only the shoelace rounding differs).
constexpr double kAreaRelTol = 1e-9;
// Sample points per polygon for the disjointness/cover check.
constexpr int kSamples = 400;

Polygon make(std::initializer_list<Point> pts) { return Polygon{std::vector<Point>(pts)}; }

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Strictly inside a convex counter-clockwise polygon (by more than `slack` in cross product).
bool strictly_inside_convex(const Polygon& p, const Point& x, double slack) {
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    if (cross(b - a, x - a) <= slack) return false;
  }
  return true;
}

bool inside_convex_closed(const Polygon& p, const Point& x, double slack) {
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    if (cross(b - a, x - a) < -slack) return false;
  }
  return true;
}

int reflex_count(const Polygon& ccw) {
  int r = 0;
  for (std::size_t i = 0, n = ccw.size(); i < n; ++i) {
    const Point& a = ccw.vertices[(i + n - 1) % n];
    const Point& b = ccw.vertices[i];
    const Point& c = ccw.vertices[(i + 1) % n];
    if (cross(b - a, c - b) < 0) ++r;
  }
  return r;
}

// The partition properties every result must have, checked against the input polygon p
// (counter-clockwise): convex CCW pieces made of input vertices, areas summing to p's
// area, and every sample point of p in exactly one piece.
void check_partition(const Polygon& p, const std::vector<Polygon>& pieces, Rng& rng) {
  ASSERT_FALSE(pieces.empty());
  double total = 0;
  for (const Polygon& q : pieces) {
    EXPECT_TRUE(q.is_convex());
    EXPECT_GT(q.signed_area(), 0);
    total += q.area();
    for (const Point& v : q.vertices) {
      EXPECT_TRUE(std::find(p.vertices.begin(), p.vertices.end(), v) != p.vertices.end())
          << "piece vertex (" << v.x() << ", " << v.y() << ") is not an input vertex";
    }
  }
  EXPECT_NEAR(total, p.area(), kAreaRelTol * p.area());

  Point lo = p.vertices.front(), hi = lo;
  for (const Point& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double slack = 1e-12 * (hi - lo).squaredNorm();
  int sampled = 0;
  while (sampled < kSamples) {
    const Point x(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
    if (!ray_cast_inside(p, x)) continue;
    ++sampled;
    int strict = 0, closed = 0;
    for (const Polygon& q : pieces) {
      strict += strictly_inside_convex(q, x, slack);
      closed += inside_convex_closed(q, x, slack);
    }
    // Interiors are disjoint; a point on a shared edge (within slack) may touch two.
    EXPECT_LE(strict, 1) << "point in two piece interiors";
    EXPECT_GE(closed, 1) << "point of the polygon in no piece";
    if (strict == 1) {
      EXPECT_LE(closed, 2);
    }
  }
}

TEST(PartitionTest, KnownOptimalCounts) {
  Rng rng(11);
  const Polygon square = make({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const Polygon hexagon = make({{2, 0}, {1, 1.7}, {-1, 1.7}, {-2, 0}, {-1, -1.7}, {1, -1.7}});
  const Polygon l_shape = make({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  const Polygon u_shape = make({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  const Polygon plus = make({{1, 0},
                             {2, 0},
                             {2, 1},
                             {3, 1},
                             {3, 2},
                             {2, 2},
                             {2, 3},
                             {1, 3},
                             {1, 2},
                             {0, 2},
                             {0, 1},
                             {1, 1}});
  struct Case {
    const char* name;
    const Polygon* polygon;
    std::size_t pieces;
  };
  for (const Case& c : {Case{"square", &square, 1}, Case{"hexagon", &hexagon, 1},
                        Case{"L", &l_shape, 2}, Case{"U", &u_shape, 3}, Case{"plus", &plus, 3}}) {
    SCOPED_TRACE(c.name);
    const std::vector<Polygon> pieces = convex_partition(*c.polygon);
    EXPECT_EQ(pieces.size(), c.pieces);
    check_partition(*c.polygon, pieces, rng);
  }
}

TEST(PartitionTest, ClockwiseInputGivesCounterClockwisePieces) {
  Rng rng(12);
  const Polygon l_ccw = make({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  Polygon l_cw = l_ccw;
  std::reverse(l_cw.vertices.begin(), l_cw.vertices.end());
  const std::vector<Polygon> pieces = convex_partition(l_cw);
  EXPECT_EQ(pieces.size(), 2u);
  check_partition(l_ccw, pieces, rng);
}

TEST(PartitionTest, RandomStarPolygonsOptimalBranch) {
  Rng rng(20261123);
  for (int trial = 0; trial < 25; ++trial) {
    const int n = static_cast<int>(rng.uniform_int(3, 24));
    const Polygon p = random_star(rng, n, 0.2, 2.0);
    SCOPED_TRACE(trial);
    const std::vector<Polygon> pieces = convex_partition(p);
    check_partition(p, pieces, rng);
    // Any diagonal partition needs >= ceil(reflex/2) diagonals (one diagonal resolves at
    // most two reflex vertices); the optimum is no worse than Hertel–Mehlhorn's 2·reflex + 1.
    const int reflex = reflex_count(p);
    const int count = static_cast<int>(pieces.size());
    EXPECT_GE(count, (reflex + 1) / 2 + 1);
    EXPECT_LE(count, 2 * reflex + 1);
    if (reflex == 0) {
      EXPECT_EQ(count, 1);
    }
  }
}

TEST(PartitionTest, OptimalBranchAtLimit) {
  Rng rng(7);
  const Polygon p = random_star(rng, static_cast<int>(kOptimalPartitionLimit), 0.5, 2.0);
  const std::vector<Polygon> pieces = convex_partition(p);
  check_partition(p, pieces, rng);
  const int reflex = reflex_count(p);
  EXPECT_GE(static_cast<int>(pieces.size()), (reflex + 1) / 2 + 1);
  EXPECT_LE(static_cast<int>(pieces.size()), 2 * reflex + 1);
}

TEST(PartitionTest, ApproxBranchAboveLimit) {
  Rng rng(8);
  for (int trial = 0; trial < 3; ++trial) {
    const Polygon p =
        random_star(rng, static_cast<int>(kOptimalPartitionLimit) + 36 + 50 * trial, 0.5, 2.0);
    ASSERT_GT(p.size(), kOptimalPartitionLimit);
    const std::vector<Polygon> pieces = convex_partition(p);
    check_partition(p, pieces, rng);
    // Hertel–Mehlhorn keeps only diagonals essential at a reflex endpoint: at most two per
    // reflex vertex, hence at most 2·reflex + 1 pieces.
    const int reflex = reflex_count(p);
    EXPECT_GE(static_cast<int>(pieces.size()), (reflex + 1) / 2 + 1);
    EXPECT_LE(static_cast<int>(pieces.size()), 2 * reflex + 1);
  }
}

// CGAL issue #9322 (fixed upstream after 5.5): for this hourglass octagon,
// optimal_convex_partition_2 returned a non-simple piece when the input started at (4,4),
// (6,6) or (0,6). Every rotation, in both orientations, must give 3 convex pieces.
TEST(PartitionTest, CgalIssue9322EveryStartVertex) {
  Rng rng(13);
  const Polygon octagon = make({{4, 4}, {6, 6}, {0, 6}, {2, 4}, {2, 2}, {0, 0}, {6, 0}, {4, 2}});
  for (bool reverse : {false, true}) {
    for (std::size_t start = 0; start < octagon.size(); ++start) {
      SCOPED_TRACE(testing::Message() << "reverse " << reverse << " start " << start);
      Polygon p = octagon;
      if (reverse) std::reverse(p.vertices.begin(), p.vertices.end());
      std::rotate(p.vertices.begin(), p.vertices.begin() + start, p.vertices.end());
      const std::vector<Polygon> pieces = convex_partition(p);
      EXPECT_EQ(pieces.size(), 3u);
      Polygon ccw = p;
      if (ccw.signed_area() < 0) std::reverse(ccw.vertices.begin(), ccw.vertices.end());
      check_partition(ccw, pieces, rng);
    }
  }
}

// Collinear vertices (axis-aligned shapes with midpoints on edges) are the ordinary case.
TEST(PartitionTest, CollinearVertices) {
  Rng rng(14);
  const Polygon square = make({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}});
  const Polygon l_shape =
      make({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {1, 3}, {0, 3}, {0, 1.5}});
  const Polygon t_shape =
      make({{0, 2}, {1, 2}, {1, 0}, {2, 0}, {2, 2}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}});
  struct Case {
    const char* name;
    const Polygon* polygon;
    std::size_t pieces;
  };
  for (const Case& c :
       {Case{"square", &square, 1}, Case{"L", &l_shape, 2}, Case{"T", &t_shape, 2}}) {
    SCOPED_TRACE(c.name);
    for (std::size_t start = 0; start < c.polygon->size(); ++start) {
      Polygon p = *c.polygon;
      std::rotate(p.vertices.begin(), p.vertices.begin() + start, p.vertices.end());
      const std::vector<Polygon> pieces = convex_partition(p);
      EXPECT_EQ(pieces.size(), c.pieces) << "start " << start;
      check_partition(p, pieces, rng);
    }
  }
}

TEST(PartitionTest, InvalidPolygonThrows) {
  const Polygon bowtie = make({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  EXPECT_THROW(convex_partition(bowtie), Error);
  EXPECT_THROW(convex_partition(make({{0, 0}, {1, 0}})), Error);
}

}  // namespace
}  // namespace rearm::geometry
