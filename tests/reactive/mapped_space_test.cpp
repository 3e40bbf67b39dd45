// The mapped space built with a dilation cache is the one built without it, bit for bit.
#include "reactive/mapped_space.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "support/reactive_scenes.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

void expect_same(const Polygon& a, const Polygon& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
}

TEST(MappedSpace, DilationCacheGivesTheSameSpace) {
  DilationCache cache;
  const int scenes = static_cast<int>(test_support::scaled(20, 2));
  for (int i = 0; i < scenes; ++i) {
    Rng rng = Rng::derive(515, static_cast<std::uint64_t>(i));
    test_support::SceneOptions o;
    o.familiar = 4;
    o.unknown = 2;
    o.movable = 1;
    o.boundary_touching = i % 2;
    const test_support::ReactiveScene s = test_support::random_scene(rng, o);
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
      }
    }
  }
  EXPECT_GT(cache.size(), 0u);
  EXPECT_LE(cache.size(), kDilationCacheEntries);
}

}  // namespace
}  // namespace rearm::reactive
