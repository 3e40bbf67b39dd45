// The mapped space built with a dilation cache is the one built without it, bit for bit; a
// movable object's model disk covers exactly what the freespace leaves out for it; components
// that merge a disk or an unknown obstacle are marked curved.
#include "reactive/mapped_space.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/rng.h"
#include "geometry/convex.h"
#include "support/reactive_scenes.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

void expect_same(const Polygon& a, const Polygon& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
}

// Random scene i of a family (test_support::random_scene) with one movable object.
test_support::ReactiveScene scene(Rng& rng, int familiar, int unknown, int touching,
                                  double margin) {
  test_support::SceneOptions o;
  o.familiar = familiar;
  o.unknown = unknown;
  o.movable = 1;
  o.boundary_touching = touching;
  o.margin = margin;
  return test_support::random_scene(rng, o);
}

TEST(MappedSpace, DilationCacheGivesTheSameSpace) {
  DilationCache cache;
  const int scenes = static_cast<int>(test_support::scaled(20, 2));
  for (int i = 0; i < scenes; ++i) {
    Rng rng = Rng::derive(515, static_cast<std::uint64_t>(i));
    const test_support::ReactiveScene s =
        scene(rng, 4, 2, i % 2, test_support::SceneOptions{}.margin);
    const SemanticInput in = test_support::to_semantic_input(s);
    for (const double r : {s.robot_radius, s.robot_radius + 0.25}) {
      const MappedSpace plain = build_mapped_space(in, r, s.goal);
      for (int twice = 0; twice < 2; ++twice) {  // the second time from the cache
        const MappedSpace cached = build_mapped_space(in, r, s.goal, cache);
        expect_same(plain.enclosing, cached.enclosing);
        expect_same(plain.freespace.outer, cached.freespace.outer);
        ASSERT_EQ(plain.freespace.holes.size(), cached.freespace.holes.size());
        ASSERT_EQ(plain.familiar.size(), cached.familiar.size());
        for (std::size_t k = 0; k < plain.familiar.size(); ++k) {
          expect_same(plain.familiar[k].polygon, cached.familiar[k].polygon);
          EXPECT_EQ(plain.familiar[k].lid.has_value(), cached.familiar[k].lid.has_value());
        }
        ASSERT_EQ(plain.unknown.size(), cached.unknown.size());
        for (std::size_t k = 0; k < plain.unknown.size(); ++k) {
          expect_same(plain.unknown[k], cached.unknown[k]);
        }
      }
    }
  }
  EXPECT_GT(cache.size(), 0u);
  EXPECT_LE(cache.size(), 3 * kDilationCacheEntries);  // miter, round, erosion
}

// The cycle of a polygon from its lexicographically smallest vertex (holes of the incremental
// path may start elsewhere than CGAL's).
std::vector<Point> from_smallest(const Polygon& p) {
  const auto less = [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  };
  const auto first = std::min_element(p.vertices.begin(), p.vertices.end(), less);
  std::vector<Point> out(first, p.vertices.end());
  out.insert(out.end(), p.vertices.begin(), first);
  return out;
}

// Equal mapped spaces: every component, convex obstacle and disk bit for bit, the holes of F_k
// as a set of cycles.
void expect_same_space(const MappedSpace& a, const MappedSpace& b) {
  expect_same(a.enclosing, b.enclosing);
  expect_same(a.freespace.outer, b.freespace.outer);
  auto cycles = [](const MappedSpace& m) {
    std::vector<std::vector<Point>> c;
    for (const Polygon& h : m.freespace.holes) c.push_back(from_smallest(h));
    std::sort(c.begin(), c.end(), [](const auto& l, const auto& r) {
      return std::lexicographical_compare(
          l.begin(), l.end(), r.begin(), r.end(), [](const Point& p, const Point& q) {
            return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
          });
    });
    return c;
  };
  EXPECT_EQ(cycles(a), cycles(b));
  ASSERT_EQ(a.familiar.size(), b.familiar.size());
  for (std::size_t k = 0; k < a.familiar.size(); ++k) {
    expect_same(a.familiar[k].polygon, b.familiar[k].polygon);
    EXPECT_EQ(a.familiar[k].lid, b.familiar[k].lid);
    EXPECT_EQ(a.familiar[k].curved, b.familiar[k].curved);
  }
  ASSERT_EQ(a.unknown.size(), b.unknown.size());
  for (std::size_t k = 0; k < a.unknown.size(); ++k) expect_same(a.unknown[k], b.unknown[k]);
  ASSERT_EQ(a.movable.size(), b.movable.size());
  for (std::size_t k = 0; k < a.movable.size(); ++k) {
    EXPECT_EQ(a.movable[k].center, b.movable[k].center);
    EXPECT_EQ(a.movable[k].radius, b.movable[k].radius);
  }
}

// A robot walking through random scenes sees its unknown obstacles through a 3 m footprint;
// MappedSpaceBuilder, which updates the previous space in place when only lone fragments
// changed, gives at every step the space the whole construction gives (or the same
// NotInFreespace). Scenes with wide margins keep fragments lone (the in-place path), tight ones
// merge them into clusters and pockets (the whole construction); both must occur.
TEST(MappedSpace, IncrementalBuilderGivesTheWholeConstruction) {
  const int scenes = static_cast<int>(test_support::scaled(12, 2));
  int incremental = 0, whole = 0, not_free = 0;
  for (int i = 0; i < scenes; ++i) {
    Rng rng = Rng::derive(2026, static_cast<std::uint64_t>(i));
    const test_support::ReactiveScene s = scene(rng, 3, 5, 0, i % 2 == 0 ? 2.0 : 0.05);
    SemanticInput in = test_support::to_semantic_input(s);
    const std::vector<Polygon> whole_unknown = in.unknown;
    MappedSpaceBuilder builder;
    const double angle = rng.uniform(0, 2 * std::numbers::pi);
    const Point dir(std::cos(angle), std::sin(angle));
    for (int k = 0; k < 60; ++k) {
      const Point x = s.goal + 0.1 * k * dir;
      const Polygon footprint = geometry::regular_polygon({x, 3.0}, 32, true);
      in.unknown.clear();
      for (const Polygon& u : whole_unknown) {
        Polygon f = geometry::intersect_convex(u, footprint);
        if (f.size() >= 3 && f.area() > 1e-6) in.unknown.push_back(std::move(f));
      }
      const double r = s.robot_radius + (k >= 30 ? 0.25 : 0.0);
      SCOPED_TRACE(testing::Message() << "scene " << i << " step " << k);
      std::optional<MappedSpace> expected;
      try {
        expected = build_mapped_space(in, r, x);
      } catch (const NotInFreespace&) {
      }
      if (!expected) {
        EXPECT_THROW(builder.build(in, r, x), NotInFreespace);
        ++not_free;
        continue;
      }
      const int before = builder.incremental();
      const MappedSpace got = builder.build(in, r, x);
      (builder.incremental() > before ? incremental : whole)++;
      expect_same_space(*expected, got);
    }
  }
  // Both paths and the refusal taken (at every scale: REARM_TEST_SCALE shrinks the scene count).
  EXPECT_GE(incremental, scenes);
  EXPECT_GE(whole, scenes);
  EXPECT_GT(not_free, 0);
}

Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

// Hand-built: the model disk of a lone movable object contains the hole of the freespace (every
// hole vertex within its radius), is no larger (the farthest vertex lies on it), and a point
// just outside it in any direction is in the freespace. Before, the model disk had radius
// ρ + r, 2.2 mm short of the circumscribed hole polygon at its vertices.
TEST(MappedSpace, ModelDiskCoversExactlyTheHoleOfAMovableObject) {
  SemanticInput in;
  in.workspace = rect(0, 0, 10, 10);
  in.movable.push_back(Disk{Point(5, 5), 0.25});
  const double r = 0.2;
  const MappedSpace m = build_mapped_space(in, r, Point(1, 1));
  ASSERT_EQ(m.movable.size(), 1u);
  ASSERT_EQ(m.freespace.holes.size(), 1u);
  ASSERT_TRUE(m.familiar.empty());
  const Disk& d = m.movable[0];
  EXPECT_EQ(d.center, Point(5, 5));
  double farthest = 0;
  for (const Point& v : m.freespace.holes[0].vertices) {
    const double dist = (v - d.center).norm();
    EXPECT_LE(dist, d.radius + 1e-12);
    farthest = std::max(farthest, dist);
  }
  EXPECT_NEAR(farthest, d.radius, 1e-9);
  EXPECT_GT(d.radius, 0.25 + r);  // circumscribes the r + ρ disk
  for (int k = 0; k < 360; ++k) {
    const double a = 2 * std::numbers::pi * k / 360;
    const Point out = d.center + (d.radius + 1e-6) * Point(std::cos(a), std::sin(a));
    EXPECT_TRUE(in_freespace(m, out)) << "angle " << a;
  }
}

// Hand-built: a disk overlapping a familiar rectangle and a disk touching the wall merge into
// curved components (a hole and a pocket); a familiar rectangle alone and a familiar L against
// the wall (a pocket) are not curved.
TEST(MappedSpace, ComponentsThatMergeADiskOrAnUnknownObstacleAreCurved) {
  const double r = 0.2;
  auto one_component = [&](const SemanticInput& in) {
    const MappedSpace m = build_mapped_space(in, r, Point(1, 1));
    EXPECT_EQ(m.familiar.size(), 1u);
    return m.familiar.empty() ? FamiliarComponent{} : m.familiar.front();
  };
  SemanticInput base;
  base.workspace = rect(0, 0, 10, 10);
  {
    SemanticInput in = base;
    in.familiar.push_back(rect(4, 4, 6, 5));
    in.movable.push_back(Disk{Point(5, 5.5), 0.25});  // 0.5 from the rectangle: dilations overlap
    const FamiliarComponent c = one_component(in);
    EXPECT_TRUE(c.curved);
    EXPECT_FALSE(c.lid.has_value());
  }
  {
    SemanticInput in = base;
    in.unknown.push_back(rect(6.3, 4, 7, 5));  // 0.3 from the familiar rectangle
    in.familiar.push_back(rect(4, 4, 6, 5));
    EXPECT_TRUE(one_component(in).curved);
  }
  {
    SemanticInput in = base;
    in.movable.push_back(Disk{Point(9.5, 5), 0.25});  // 0.25 from the wall: a pocket
    const FamiliarComponent c = one_component(in);
    EXPECT_TRUE(c.curved);
    EXPECT_TRUE(c.lid.has_value());
  }
  {
    SemanticInput in = base;
    in.familiar.push_back(rect(4, 4, 6, 5));
    EXPECT_FALSE(one_component(in).curved);
  }
  {
    SemanticInput in = base;
    // An L whose foot touches the bottom wall: a pocket of familiar shapes only.
    in.familiar.push_back(
        Polygon{{Point(4, 0), Point(6, 0), Point(6, 1), Point(5, 1), Point(5, 3), Point(4, 3)}});
    const FamiliarComponent c = one_component(in);
    EXPECT_FALSE(c.curved);
    EXPECT_TRUE(c.lid.has_value());
  }
}

}  // namespace
}  // namespace rearm::reactive
