// The random scene generator of tests/support: determinism for a seed, the placement rule
// (checked with exact Booleans and with brute-force distances that share no code with the
// generator), boundary-touching walls, the benchmark scene of docs/reactive.md §7 and free
// points of the mapped space.
#include "support/reactive_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/dilation.h"
#include "reactive/diffeomorphism.h"
#include "reactive/mapped_space.h"
#include "support/geometry_oracle.h"

namespace {

using rearm::Rng;
using rearm::geometry::Disk;
using rearm::geometry::Point;
using rearm::geometry::Polygon;
using rearm::geometry::RegionSet;
namespace ts = rearm::test_support;
namespace g = rearm::geometry;

// Brute-force distance between the boundaries of two polygons (vertex to edge both ways).
double boundary_gap(const Polygon& a, const Polygon& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point& v : a.vertices) best = std::min(best, ts::boundary_distance(b, v));
  for (const Point& v : b.vertices) best = std::min(best, ts::boundary_distance(a, v));
  return best;
}

// The mapped-space obstacle of a familiar or unknown polygon (mitered, one simple region).
Polygon dilated(const Polygon& p, double r) {
  const RegionSet s = g::dilate_miter(p, r);
  EXPECT_EQ(s.size(), 1u);
  EXPECT_TRUE(s[0].holes.empty());
  return s[0].outer;
}

bool same(const Polygon& a, const Polygon& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.vertices[i] != b.vertices[i]) return false;
  }
  return true;
}

bool same(const ts::ReactiveScene& a, const ts::ReactiveScene& b) {
  if (!same(a.workspace, b.workspace) || a.familiar.size() != b.familiar.size() ||
      a.unknown.size() != b.unknown.size() || a.movable.size() != b.movable.size() ||
      a.goal != b.goal) {
    return false;
  }
  for (std::size_t i = 0; i < a.familiar.size(); ++i) {
    if (!same(a.familiar[i], b.familiar[i])) return false;
  }
  for (std::size_t i = 0; i < a.unknown.size(); ++i) {
    if (!same(a.unknown[i], b.unknown[i])) return false;
  }
  for (std::size_t i = 0; i < a.movable.size(); ++i) {
    if (a.movable[i].center != b.movable[i].center || a.movable[i].radius != b.movable[i].radius)
      return false;
  }
  return true;
}

// Checks the placement rule of reactive_scenes.h on a generated scene.
void expect_placement_rule(const ts::ReactiveScene& s, const ts::SceneOptions& o) {
  const double r = o.robot_radius;
  const double tol = 1e-9;
  const RegionSet W = g::to_set(s.workspace);
  // Every obstacle of the mapped space: dilated polygons, and disks kept apart.
  std::vector<Polygon> polys;
  for (const Polygon& p : s.familiar) polys.push_back(dilated(p, r));
  for (const Polygon& p : s.unknown) {
    EXPECT_TRUE(g::validated(p).is_convex());
    polys.push_back(dilated(p, r));
  }
  for (std::size_t i = 0; i < polys.size(); ++i) {
    for (std::size_t j = i + 1; j < polys.size(); ++j) {
      EXPECT_FALSE(g::intersects(g::to_set(polys[i]), g::to_set(polys[j]))) << i << " " << j;
      EXPECT_GE(boundary_gap(polys[i], polys[j]), o.margin - tol) << i << " " << j;
    }
    for (const Disk& d : s.movable) {
      EXPECT_FALSE(ts::ray_cast_inside(polys[i], d.center));
      EXPECT_GE(ts::boundary_distance(polys[i], d.center) - d.radius - r, o.margin - tol);
    }
  }
  for (std::size_t i = 0; i < s.movable.size(); ++i) {
    for (std::size_t j = i + 1; j < s.movable.size(); ++j) {
      const Disk& a = s.movable[i];
      const Disk& b = s.movable[j];
      EXPECT_GE((a.center - b.center).norm() - a.radius - b.radius - 2 * r, o.margin - tol);
    }
    EXPECT_TRUE(g::contains(s.workspace, s.movable[i].center));
    EXPECT_GE(ts::boundary_distance(s.workspace, s.movable[i].center) - s.movable[i].radius,
              2 * r + o.margin - tol);
  }
  // Inside the workspace, `margin` away from the workspace eroded by r (so r + margin from
  // its boundary), except the boundary-touching walls.
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const bool touching = i < static_cast<std::size_t>(o.boundary_touching);
    EXPECT_TRUE(
        g::subtract(
            g::to_set(i < s.familiar.size() ? s.familiar[i] : s.unknown[i - s.familiar.size()]), W)
            .empty())
        << i;
    if (!touching) {
      EXPECT_TRUE(g::subtract(g::to_set(polys[i]), W).empty()) << i;
      EXPECT_GE(boundary_gap(polys[i], s.workspace), r + o.margin - tol) << i;
    }
  }
  // The goal is free with its clearance.
  EXPECT_TRUE(ts::ray_cast_inside(s.workspace, s.goal));
  EXPECT_GE(ts::boundary_distance(s.workspace, s.goal), r + o.goal_clearance - tol);
  for (const Polygon& p : polys) {
    EXPECT_FALSE(ts::ray_cast_inside(p, s.goal));
  }
}

TEST(ReactiveScenesTest, SameSeedSameScene) {
  ts::SceneOptions o;
  o.movable = 2;
  o.boundary_touching = 1;
  Rng a(7), b(7), c(8);
  const ts::ReactiveScene sa = ts::random_scene(a, o);
  const ts::ReactiveScene sb = ts::random_scene(b, o);
  const ts::ReactiveScene sc = ts::random_scene(c, o);
  EXPECT_TRUE(same(sa, sb));
  EXPECT_FALSE(same(sa, sc));
  EXPECT_TRUE(same(ts::benchmark_scene(10, 3), ts::benchmark_scene(10, 3)));
  EXPECT_FALSE(same(ts::benchmark_scene(10, 3), ts::benchmark_scene(10, 4)));
}

TEST(ReactiveScenesTest, ShapesAreValidNonConvexPolygonsOfTheirSize) {
  Rng rng(1);
  const double s = 2.0, w = 0.5;
  const double expected_area[] = {2 * s * w - w * w,              // L
                                  s * s - (s - 2 * w) * (s - w),  // U
                                  s * w + (s - w) * w,            // T
                                  6 * (s / 3) * (s / 3),          // staircase
                                  2 * s * w - w * w};             // cross
  int k = 0;
  for (const ts::Shape shape : ts::kNonConvexShapes) {
    const Point c(3, -1);
    const Polygon p = ts::make_shape(rng, shape, s, w, 0.7, c);
    const Polygon v = g::validated(p, ts::to_string(shape));
    EXPECT_GT(p.signed_area(), 0) << ts::to_string(shape);
    EXPECT_FALSE(v.is_convex()) << ts::to_string(shape);
    EXPECT_NEAR(p.area(), expected_area[k++], 1e-9) << ts::to_string(shape);
    for (const Point& x : p.vertices) EXPECT_LE((x - c).norm(), s / std::sqrt(2.0) + 1e-9);
  }
  for (int i = 0; i < 50; ++i) {
    const Polygon star = ts::make_shape(rng, ts::Shape::kStar, s, 0, 0, Point(1, 1));
    EXPECT_NO_THROW(g::validated(star));
    const Polygon convex = ts::random_convex(rng, Point(-2, 5), 0.8);
    EXPECT_TRUE(g::validated(convex).is_convex());
    for (const Point& x : convex.vertices) EXPECT_LE((x - Point(-2, 5)).norm(), 0.8 + 1e-12);
  }
}

TEST(ReactiveScenesTest, ObstaclesAreSeparatedAndInsideTheWorkspace) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    for (const auto shape : {ts::WorkspaceShape::kSquare, ts::WorkspaceShape::kLRoom}) {
      ts::SceneOptions o;
      o.workspace_shape = shape;
      o.familiar = 4;
      o.unknown = 3;
      o.movable = 2;
      o.margin = seed % 2 ? 2.0 : 0.8;
      o.shapes.push_back(ts::Shape::kStar);
      Rng rng(seed);
      const ts::ReactiveScene s = ts::random_scene(rng, o);
      ASSERT_EQ(s.familiar.size(), 4u);
      ASSERT_EQ(s.unknown.size(), 3u);
      ASSERT_EQ(s.movable.size(), 2u);
      expect_placement_rule(s, o);
    }
  }
}

TEST(ReactiveScenesTest, BoundaryTouchingWallsReallyTouch) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ts::SceneOptions o;
    o.workspace_shape = seed % 2 ? ts::WorkspaceShape::kSquare : ts::WorkspaceShape::kLRoom;
    o.familiar = 4;
    o.boundary_touching = 2;
    o.unknown = 2;
    Rng rng(100 + seed);
    const ts::ReactiveScene s = ts::random_scene(rng, o);
    expect_placement_rule(s, o);
    const RegionSet W = g::to_set(s.workspace);
    for (int i = 0; i < o.boundary_touching; ++i) {
      const Polygon& p = s.familiar[i];
      // Inside the workspace (exact), yet any dilation leaves it: it touches the boundary.
      EXPECT_TRUE(g::subtract(g::to_set(p), W).empty()) << i;
      EXPECT_FALSE(g::subtract(g::dilate_miter(p, 1e-3), W).empty()) << i;
      EXPECT_LT(boundary_gap(p, s.workspace), 1e-9) << i;
      // And stays away from the corners.
      for (const Point& v : s.workspace.vertices) {
        EXPECT_FALSE(ts::ray_cast_inside(p, v));
        EXPECT_GE(ts::boundary_distance(p, v), 2 * o.robot_radius + o.margin - 1e-9);
      }
    }
    for (std::size_t i = o.boundary_touching; i < s.familiar.size(); ++i) {
      EXPECT_GT(boundary_gap(s.familiar[i], s.workspace), 0.5) << i;
    }
  }
}

TEST(ReactiveScenesTest, BenchmarkSceneFitsTwentyObstacles) {
  for (const int K : {0, 1, 10, 20}) {
    const ts::ReactiveScene s = ts::benchmark_scene(K, 42);
    ASSERT_EQ(s.familiar.size(), static_cast<std::size_t>(K));
    EXPECT_TRUE(s.unknown.empty());
    EXPECT_DOUBLE_EQ(s.robot_radius, 0.2);
    EXPECT_NEAR(s.workspace.area(), 400.0, 1e-9);
    std::vector<Polygon> polys;
    for (const Polygon& p : s.familiar) {
      EXPECT_FALSE(g::validated(p).is_convex());
      polys.push_back(dilated(p, s.robot_radius));
      EXPECT_GE(boundary_gap(polys.back(), s.workspace), 1.0) << K;
      EXPECT_FALSE(ts::ray_cast_inside(polys.back(), s.goal));
    }
    for (std::size_t i = 0; i < polys.size(); ++i) {
      for (std::size_t j = i + 1; j < polys.size(); ++j) {
        EXPECT_GE(boundary_gap(polys[i], polys[j]), 0.5) << K << ": " << i << " " << j;
      }
    }
  }
  EXPECT_THROW(ts::benchmark_scene(21, 1), rearm::Error);
  EXPECT_THROW(ts::benchmark_scene(-1, 1), rearm::Error);
}

TEST(ReactiveScenesTest, RandomFreePointsAreFreeWithClearance) {
  ts::SceneOptions o;
  o.familiar = 3;
  o.boundary_touching = 1;
  o.unknown = 2;
  o.movable = 1;
  Rng rng(5);
  const ts::ReactiveScene s = ts::random_scene(rng, o);
  const auto m =
      rearm::reactive::build_mapped_space(ts::to_semantic_input(s), s.robot_radius, s.goal);
  const double clearance = 0.25;
  for (int i = 0; i < 100; ++i) {
    const Point x = ts::random_free_point(rng, m, clearance);
    EXPECT_TRUE(rearm::reactive::in_freespace(m, x));
    // Independent truth: the undilated obstacles are at least r + clearance away (the
    // mapped obstacles contain their exact dilation by r).
    for (const Polygon& p : s.familiar) {
      EXPECT_FALSE(ts::ray_cast_inside(p, x));
      EXPECT_GE(ts::boundary_distance(p, x), s.robot_radius + clearance - 1e-9);
    }
    for (const Polygon& p : s.unknown) {
      EXPECT_GE(ts::boundary_distance(p, x), s.robot_radius + clearance - 1e-9);
    }
    for (const Disk& d : s.movable) {
      EXPECT_GE((x - d.center).norm() - d.radius, s.robot_radius + clearance - 1e-9);
    }
    EXPECT_TRUE(ts::ray_cast_inside(s.workspace, x));
    EXPECT_GE(ts::boundary_distance(s.workspace, x), s.robot_radius + clearance - 1e-9);
  }
  EXPECT_THROW(ts::random_free_point(rng, m, 100.0), rearm::Error);
}

TEST(ReactiveScenesTest, BadOptionsAndCrowdedScenesThrow) {
  Rng rng(1);
  ts::SceneOptions o;
  o.robot_radius = -1;
  EXPECT_THROW(ts::random_scene(rng, o), rearm::Error);
  o = {};
  o.boundary_touching = o.familiar + 1;
  EXPECT_THROW(ts::random_scene(rng, o), rearm::Error);
  o = {};
  o.margin = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ts::random_scene(rng, o), rearm::Error);
  o = {};
  o.familiar = 40;
  o.margin = 3;
  o.max_attempts = 20;
  o.max_restarts = 2;
  EXPECT_THROW(ts::random_scene(rng, o), rearm::Error);
}

// The scenes are usable by the reactive layer: the mapped space has one component per
// familiar obstacle, a pocket (with a lid on ∂F_e) per boundary-touching wall, and the
// diffeomorphism builds with the default parameters.
TEST(ReactiveScenesTest, ScenesBuildMappedSpacesAndDiffeomorphisms) {
  for (const int K : {1, 10, 20}) {
    const ts::ReactiveScene s = ts::benchmark_scene(K, 7);
    const auto m =
        rearm::reactive::build_mapped_space(ts::to_semantic_input(s), s.robot_radius, s.goal);
    EXPECT_EQ(m.familiar.size(), static_cast<std::size_t>(K));
    const auto h = rearm::reactive::Diffeomorphism::build(m);
    EXPECT_GE(h.purges().size(), static_cast<std::size_t>(2 * K));
    // At most a triangulation's n − 2 pieces per component of n vertices.
    std::size_t bound = 0;
    for (const auto& c : m.familiar) bound += c.polygon.size() - 2;
    EXPECT_LE(h.purges().size(), bound);
  }
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    ts::SceneOptions o;
    o.familiar = 4;
    o.boundary_touching = 2;
    o.unknown = 2;
    o.movable = 1;
    Rng rng(200 + seed);
    const ts::ReactiveScene s = ts::random_scene(rng, o);
    const auto m =
        rearm::reactive::build_mapped_space(ts::to_semantic_input(s), s.robot_radius, s.goal);
    ASSERT_EQ(m.familiar.size(), 4u) << seed;
    int pockets = 0;
    for (const auto& c : m.familiar) pockets += c.lid.has_value();
    EXPECT_EQ(pockets, 2) << seed;
    EXPECT_EQ(m.unknown.size(), 2u);
    EXPECT_EQ(m.movable.size(), 1u);
    EXPECT_NO_THROW(rearm::reactive::Diffeomorphism::build(m)) << seed;
  }
}

}  // namespace
