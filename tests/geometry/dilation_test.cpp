#include "geometry/dilation.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/partition.h"
#include "support/geometry_oracle.h"

namespace rearm::geometry {
namespace {

using test_support::boundary_distance;
using test_support::random_star;
using test_support::ray_cast_inside;

// Sample points per case within distance r of the boundary, and uniform points around it.
constexpr int kNearSamples = 300;
constexpr int kFarSamples = 300;
// Relative slack for the distance bounds: the dilation is exact and then rounded to doubles.
constexpr double kRelSlack = 1e-9;

Polygon make(std::initializer_list<Point> pts) { return Polygon{std::vector<Point>(pts)}; }

// Convex: points of an ellipse at sorted jittered angles.
Polygon random_convex(Rng& rng, int n) {
  Polygon p;
  const double ax = rng.uniform(0.5, 2), ay = rng.uniform(0.5, 2);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + rng.uniform(0.05, 0.95)) / n;
    p.vertices.emplace_back(ax * std::cos(a), ay * std::sin(a));
  }
  return p;
}

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Distance from x to the closed polygon (0 inside), brute force.
double polygon_distance(const Polygon& p, const Point& x) {
  return ray_cast_inside(p, x) ? 0 : boundary_distance(p, x);
}

// Inside a set of disjoint regions with holes: even-odd over every ring.
bool inside_set(const RegionSet& s, const Point& x) {
  bool in = false;
  for (const Region& r : s) {
    in ^= ray_cast_inside(r.outer, x);
    for (const Polygon& h : r.holes) in ^= ray_cast_inside(h, x);
  }
  return in;
}

double perimeter(const Polygon& p) {
  double sum = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    sum += (p.vertices[(i + 1) % n] - p.vertices[i]).norm();
  }
  return sum;
}

// Turning (exterior) angles of a counter-clockwise polygon, in [0, π).
std::vector<double> turning_angles(const Polygon& p) {
  std::vector<double> out;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point e1 = p.vertices[i] - p.vertices[(i + n - 1) % n];
    const Point e2 = p.vertices[(i + 1) % n] - p.vertices[i];
    out.push_back(std::atan2(cross(e1, e2), e1.dot(e2)));
  }
  return out;
}

// Sides of the disk polygon per the dilation.h contract.
int disk_sides() {
  int n = 8;
  while (1 / std::cos(std::numbers::pi / n) - 1 > kMaxDilationError) n += 2;
  return n;
}

double round_bound(double r) { return r / std::cos(std::numbers::pi / disk_sides()); }

// Farthest reach of the mitered offset from p: over convex vertices of turning angle φ, the
// miter point r / cos(φ/2), or for a bevelled corner the bevel ends at distance kMiterLimit·r
// along the bisector and h / tan(φ/2) across it, h = r / cos(φ/2) − kMiterLimit·r (reflex
// vertices turn negatively and add no corner).
double miter_bound(const Polygon& p, double r) {
  double reach = r;
  for (double phi : turning_angles(p)) {
    if (phi <= 0) continue;
    const double tip = r / std::cos(phi / 2);
    const double h = tip - kMiterLimit * r;
    reach = std::max(reach, h <= 0 ? tip : std::hypot(kMiterLimit * r, h / std::tan(phi / 2)));
  }
  return reach;
}

// Area of the miter corner at a convex vertex of turning angle φ: the kite r² tan(φ/2), less
// the tip beyond the bevel line (a triangle of height h = r / cos(φ/2) − kMiterLimit·r and
// half-width h / tan(φ/2)) when the corner is bevelled.
double corner_area(double phi, double r) {
  const double h = r / std::cos(phi / 2) - kMiterLimit * r;
  return r * r * std::tan(phi / 2) - (h > 0 ? h * h / std::tan(phi / 2) : 0.0);
}

// The properties shared by both joins: every point within r of p is inside, every point
// farther than `bound` is outside, and every boundary vertex lies at a distance in
// [r, bound] from p.
void check_dilation(const Polygon& p, double r, const RegionSet& d, double bound, Rng& rng) {
  ASSERT_FALSE(d.empty());
  for (const Region& region : d) {
    std::vector<const Polygon*> rings{&region.outer};
    for (const Polygon& h : region.holes) rings.push_back(&h);
    for (const Polygon* ring : rings) {
      for (const Point& v : ring->vertices) {
        const double dist = polygon_distance(p, v);
        EXPECT_GE(dist, r * (1 - kRelSlack)) << "vertex (" << v.x() << ", " << v.y() << ")";
        EXPECT_LE(dist, bound * (1 + kRelSlack)) << "vertex (" << v.x() << ", " << v.y() << ")";
      }
    }
  }
  for (int s = 0; s < kNearSamples; ++s) {
    const std::size_t i = rng.index(p.size());
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % p.size()];
    const double angle = rng.uniform(0, 2 * std::numbers::pi);
    const Point x = a + rng.uniform01() * (b - a) +
                    rng.uniform(0, r * (1 - kRelSlack)) * Point(std::cos(angle), std::sin(angle));
    EXPECT_TRUE(inside_set(d, x)) << "(" << x.x() << ", " << x.y() << ") within r is outside";
  }
  Point lo = p.vertices.front(), hi = lo;
  for (const Point& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Point margin = Point::Constant(1.5 * bound);
  lo -= margin;
  hi += margin;
  int within = 0, beyond = 0;
  for (int s = 0; s < kFarSamples; ++s) {
    const Point x(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
    const double dist = polygon_distance(p, x);
    if (dist <= r * (1 - kRelSlack)) {
      ++within;
      EXPECT_TRUE(inside_set(d, x)) << "(" << x.x() << ", " << x.y() << ") within r is outside";
    } else if (dist > bound * (1 + kRelSlack)) {
      ++beyond;
      EXPECT_FALSE(inside_set(d, x)) << "(" << x.x() << ", " << x.y() << ") beyond the bound";
    }
  }
  EXPECT_GT(within, 0);
  EXPECT_GT(beyond, 0);
}

const double kRadii[] = {0.02, 0.3, 1.5};

TEST(DilationTest, RoundOnRandomPolygons) {
  Rng rng(20261123);
  const int n = disk_sides();
  for (int trial = 0; trial < 12; ++trial) {
    const bool convex = trial % 3 == 0;
    const Polygon p = convex ? random_convex(rng, static_cast<int>(rng.uniform_int(3, 12)))
                             : random_star(rng, static_cast<int>(rng.uniform_int(4, 16)), 0.3, 2.0);
    for (double r : kRadii) {
      SCOPED_TRACE(testing::Message() << "trial " << trial << " r " << r);
      const RegionSet d = dilate_round(p, r);
      check_dilation(p, r, d, round_bound(r), rng);
      const double area = total_area(d);
      const double base = p.area() + perimeter(p) * r;
      if (convex) {
        // Steiner: the exact disk dilation has area A + P r + π r²; the n-gon sum lies
        // between it and A + P r / cos(π/n) + n r² tan(π/n) (mixed area with the n-gon).
        EXPECT_GE(area, (base + std::numbers::pi * r * r) * (1 - 1e-12));
        EXPECT_LE(area, (p.area() + perimeter(p) * round_bound(r) +
                         n * r * r * std::tan(std::numbers::pi / n)) *
                            (1 + 1e-12));
      } else {
        EXPECT_GT(area, p.area());
      }
    }
  }
}

// The convex fast path (an exact edge merge) gives CGAL's exact Minkowski sum vertex for
// vertex, up to where the cycle starts: on ellipse polygons, thin slivers a millimetre wide,
// rectangles (edges parallel to none or some of the n-gon's) and far-off coordinates.
TEST(DilationTest, ConvexRoundEqualsTheExactSum) {
  Rng rng(20261202);
  auto same_cycle = [](const Polygon& a, const Polygon& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t s = 0; s < a.size(); ++s) {
      bool all = true;
      for (std::size_t i = 0; i < a.size() && all; ++i) {
        all = a.vertices[i] == b.vertices[(i + s) % b.size()];
      }
      if (all) return true;
    }
    return false;
  };
  for (int trial = 0; trial < 400; ++trial) {
    Polygon p = random_convex(rng, static_cast<int>(rng.uniform_int(3, 14)));
    const Point shift(rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3));
    const double squash = trial % 4 == 1 ? 1e-3 : 1;
    for (Point& v : p.vertices) v = Point(v.x() * squash, v.y()) + shift;
    if (trial % 4 == 2) {
      const double w = rng.uniform(0.1, 3), h = rng.uniform(0.1, 3);
      p = make({shift, shift + Point(w, 0), shift + Point(w, h), shift + Point(0, h)});
    }
    const double r = rng.uniform(0.01, 2);
    SCOPED_TRACE(testing::Message() << "trial " << trial << " r " << r);
    const RegionSet fast = dilate_round(p, r);
    const RegionSet exact = dilate_round_exact(p, r);
    ASSERT_EQ(fast.size(), 1u);
    ASSERT_EQ(exact.size(), 1u);
    EXPECT_TRUE(fast.front().holes.empty());
    EXPECT_TRUE(same_cycle(fast.front().outer, exact.front().outer));
  }
}

TEST(DilationTest, MiterOnRandomPolygons) {
  Rng rng(20261124);
  for (int trial = 0; trial < 12; ++trial) {
    const bool convex = trial % 3 == 0;
    const Polygon p = convex ? random_convex(rng, static_cast<int>(rng.uniform_int(3, 12)))
                             : random_star(rng, static_cast<int>(rng.uniform_int(4, 16)), 0.3, 2.0);
    for (double r : kRadii) {
      SCOPED_TRACE(testing::Message() << "trial " << trial << " r " << r);
      const RegionSet d = dilate_miter(p, r);
      check_dilation(p, r, d, miter_bound(p, r), rng);
      // Every convex corner bevelled on the disk's tangent (limit 1): still a superset of the
      // exact dilation, inside the default one.
      const RegionSet tight = dilate_miter(p, r, 1.0);
      check_dilation(p, r, tight, miter_bound(p, r), rng);
      EXPECT_LE(total_area(tight), total_area(d) * (1 + kRelSlack));
      const double area = total_area(d);
      if (convex) {
        // Mitered offset of a convex polygon: A + P r + Σ corner areas (bevelled ones cut).
        double corners = 0;
        for (double phi : turning_angles(p)) corners += corner_area(phi, r);
        EXPECT_NEAR(area, p.area() + perimeter(p) * r + corners, 1e-9 * area);
      } else {
        EXPECT_GT(area, p.area());
      }
    }
  }
}

// For convex input the result is the single mitered polygon: its vertices are the
// intersections of consecutive offset lines (solved here as 2x2 linear systems), or, where
// that point is farther than limit·r from the vertex, the two points of the offset lines at
// distance limit·r along the corner's bisector; for the default limit and for 1 (every corner
// bevelled on the tangent of the disk dilation).
TEST(DilationTest, MiterOfConvexPolygonIsOffsetLineIntersection) {
  for (const double limit : {kMiterLimit, 1.0}) {
    SCOPED_TRACE(limit);
    Rng rng(5);
    for (int trial = 0; trial < 10; ++trial) {
      const Polygon p = random_convex(rng, static_cast<int>(rng.uniform_int(3, 10)));
      const double r = rng.uniform(0.05, 1.0);
      const RegionSet d = dilate_miter(p, r, limit);
      ASSERT_EQ(d.size(), 1u);
      EXPECT_TRUE(d[0].holes.empty());
      const std::size_t n = p.size();
      std::size_t expected_vertices = 0;
      auto has_vertex = [&](const Point& x) {
        double best = std::numeric_limits<double>::infinity();
        for (const Point& w : d[0].outer.vertices) best = std::min(best, (w - x).norm());
        return best < 1e-9;
      };
      for (std::size_t i = 0; i < n; ++i) {
        const Point& prev = p.vertices[(i + n - 1) % n];
        const Point& v = p.vertices[i];
        const Point& next = p.vertices[(i + 1) % n];
        Eigen::Matrix2d normals;
        const Point d1 = (v - prev).normalized(), d2 = (next - v).normalized();
        const Point n1(d1.y(), -d1.x()), n2(d2.y(), -d2.x());
        normals.row(0) = n1.transpose();
        normals.row(1) = n2.transpose();
        // Offset lines: n_k · x = n_k · v + r.
        const Point rhs(n1.dot(v) + r, n2.dot(v) + r);
        const Point miter = normals.partialPivLu().solve(rhs);
        if ((miter - v).norm() <= limit * r) {
          EXPECT_TRUE(has_vertex(miter)) << "corner " << i;
          ++expected_vertices;
          continue;
        }
        // Bevel: each offset line meets the line b · x = b · v + limit·r.
        const Point b = (n1 + n2).normalized();
        for (const Point& nk : {n1, n2}) {
          Eigen::Matrix2d m;
          m.row(0) = nk.transpose();
          m.row(1) = b.transpose();
          const Point q = m.partialPivLu().solve(Point(nk.dot(v) + r, b.dot(v) + limit * r));
          EXPECT_TRUE(has_vertex(q)) << "bevel of corner " << i;
        }
        expected_vertices += 2;
      }
      // The union keeps the strips' ends as collinear boundary points: count true corners.
      const auto& w = d[0].outer.vertices;
      std::size_t corners = 0;
      for (std::size_t k = 0; k < w.size(); ++k) {
        const Point e1 = w[k] - w[(k + w.size() - 1) % w.size()];
        const Point e2 = w[(k + 1) % w.size()] - w[k];
        if (std::abs(cross(e1, e2)) > 1e-9 * e1.norm() * e2.norm()) ++corners;
      }
      EXPECT_EQ(corners, expected_vertices);
    }
  }
}

TEST(DilationTest, NonConvexShapes) {
  Rng rng(6);
  const Polygon l_shape = make({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  const Polygon u_shape = make({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  for (const Polygon* p : {&l_shape, &u_shape}) {
    for (double r : {0.1, 0.4, 2.0}) {
      SCOPED_TRACE(testing::Message() << "r " << r);
      check_dilation(*p, r, dilate_round(*p, r), round_bound(r), rng);
      check_dilation(*p, r, dilate_miter(*p, r), miter_bound(*p, r), rng);
    }
  }
}

// A square room (cavity [1,3]²) whose door (width 0.4) closes at r = 0.3: both dilations
// have exactly one hole, around the room's center.
TEST(DilationTest, ClosedDoorLeavesHole) {
  Rng rng(7);
  const Polygon room = make({{0, 0},
                             {4, 0},
                             {4, 1.8},
                             {3, 1.8},
                             {3, 1},
                             {1, 1},
                             {1, 3},
                             {3, 3},
                             {3, 2.2},
                             {4, 2.2},
                             {4, 4},
                             {0, 4}});
  const double r = 0.3;
  for (bool round : {true, false}) {
    SCOPED_TRACE(round ? "round" : "miter");
    const RegionSet d = round ? dilate_round(room, r) : dilate_miter(room, r);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].holes.size(), 1u);
    EXPECT_FALSE(inside_set(d, Point(2, 2)));
    EXPECT_TRUE(inside_set(d, Point(3.5, 2)));  // the closed door
    check_dilation(room, r, d, round ? round_bound(r) : miter_bound(room, r), rng);
  }
}

TEST(DilationTest, ClockwiseInputSameResult) {
  Polygon p = make({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  const double round_ccw = total_area(dilate_round(p, 0.5));
  const double miter_ccw = total_area(dilate_miter(p, 0.5));
  std::reverse(p.vertices.begin(), p.vertices.end());
  EXPECT_NEAR(total_area(dilate_round(p, 0.5)), round_ccw, 1e-12 * round_ccw);
  EXPECT_NEAR(total_area(dilate_miter(p, 0.5)), miter_ccw, 1e-12 * miter_ccw);
}

TEST(DilationTest, BadRadiusThrows) {
  const Polygon sq = make({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  for (double r : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()}) {
    SCOPED_TRACE(r);
    EXPECT_THROW(dilate_round(sq, r), Error);
    EXPECT_THROW(dilate_miter(sq, r), Error);
  }
  const Polygon bowtie = make({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  EXPECT_THROW(dilate_round(bowtie, 1), Error);
  EXPECT_THROW(dilate_miter(bowtie, 1), Error);
  for (double limit : {0.99, 0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(dilate_miter(sq, 1, limit), Error) << limit;
  }
}

}  // namespace
}  // namespace rearm::geometry
