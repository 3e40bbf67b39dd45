// TopologyCache (topology_check.h): a cached check_topology / make_input returns exactly, bit
// for bit, what the uncached call returns, over seeded random scenes, with one cache reused
// across scenes, radii (robot alone, carrying), moving objects and targets, and after it has
// dropped entries; errors are the same too.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/dilation.h"
#include "support/scale.h"
#include "topology/topology_check.h"
#include "topology/topology_scenes.h"

namespace rearm::topology {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;
using geometry::Region;
using geometry::RegionSet;

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same(const Polygon& a, const Polygon& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a.vertices[i].x(), b.vertices[i].x()) ||
        !same(a.vertices[i].y(), b.vertices[i].y())) {
      return false;
    }
  }
  return true;
}

bool same(const Region& a, const Region& b) {
  if (!same(a.outer, b.outer) || a.holes.size() != b.holes.size()) return false;
  for (std::size_t k = 0; k < a.holes.size(); ++k) {
    if (!same(a.holes[k], b.holes[k])) return false;
  }
  return true;
}

bool same(const RegionSet& a, const RegionSet& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a[i], b[i])) return false;
  }
  return true;
}

void expect_identical(const TopologyResult& a, const TopologyResult& b, const std::string& what) {
  EXPECT_EQ(a.verdict, b.verdict) << what;
  EXPECT_TRUE(same(a.freespace, b.freespace)) << what << ": freespace";
  EXPECT_TRUE(same(a.enclosing, b.enclosing)) << what << ": enclosing";
  EXPECT_TRUE(same(a.components, b.components)) << what << ": components";
  EXPECT_EQ(a.blocking, b.blocking) << what;
  EXPECT_EQ(a.reason, b.reason) << what;
}

void expect_identical(const TopologyInput& a, const TopologyInput& b, const std::string& what) {
  EXPECT_TRUE(same(a.bound, b.bound)) << what << ": bound";
  ASSERT_EQ(a.fixed.size(), b.fixed.size()) << what;
  for (std::size_t i = 0; i < a.fixed.size(); ++i) {
    EXPECT_TRUE(same(a.fixed[i], b.fixed[i])) << what << ": fixed " << i;
  }
  ASSERT_EQ(a.movable.size(), b.movable.size()) << what;
  for (std::size_t i = 0; i < a.movable.size(); ++i) {
    EXPECT_TRUE(same(a.movable[i], b.movable[i])) << what << ": movable " << i;
  }
  EXPECT_EQ(a.movable_ids, b.movable_ids) << what;
  EXPECT_TRUE(same(a.x.x(), b.x.x()) && same(a.x.y(), b.x.y())) << what;
  EXPECT_TRUE(same(a.target.x(), b.target.x()) && same(a.target.y(), b.target.y())) << what;
}

// The uncached call's result or error message.
struct Outcome {
  std::optional<TopologyResult> result;
  std::string error;
};

template <class F>
Outcome run(F f) {
  Outcome o;
  try {
    o.result = f();
  } catch (const Error& e) {
    o.error = e.what();
  }
  return o;
}

// Checks `in` with and without the cache; true when the check succeeded.
bool compare(const TopologyInput& in, TopologyCache& cache, const std::string& what) {
  const Outcome plain = run([&] { return check_topology(in); });
  const Outcome cached = run([&] { return check_topology(in, cache); });
  EXPECT_EQ(plain.error, cached.error) << what;
  EXPECT_EQ(plain.result.has_value(), cached.result.has_value()) << what;
  if (plain.result && cached.result) expect_identical(*plain.result, *cached.result, what);
  return plain.result.has_value();
}

struct Tally {
  std::size_t checks = 0, succeeded = 0, verdicts[3] = {0, 0, 0};
};

// One scene: the robot alone and, when there are objects, carrying object 0; for each radius
// several moves of the objects, of x and of x*.
void scene_checks(std::uint64_t seed, TopologyCache& cache, Tally& tally) {
  Rng rng = Rng::derive(4242, seed);
  test_scenes::Scene s = test_scenes::random_scene(rng);
  for (int carrying = 0; carrying < (s.objects.empty() ? 1 : 2); ++carrying) {
    const double radius = carrying ? s.radius + s.objects.front().radius : s.radius;
    const std::optional<std::size_t> carried =
        carrying ? std::optional<std::size_t>(0) : std::nullopt;
    for (int move = 0; move < 3; ++move) {
      std::vector<Disk> objects = s.objects;
      for (Disk& d : objects) d.center += Point(rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4));
      for (int attempt = 0; attempt < 6; ++attempt) {
        const Point x(rng.uniform(0.3, 9.7), rng.uniform(0.3, 9.7));
        Point target(rng.uniform(0.3, 9.7), rng.uniform(0.3, 9.7));
        if (!objects.empty() && rng.bernoulli(0.3))
          target = objects[rng.index(objects.size())].center;
        if (carrying) objects.front().center = x;
        const std::string what = "seed " + std::to_string(seed) + ", carrying " +
                                 std::to_string(carrying) + ", move " + std::to_string(move) +
                                 ", attempt " + std::to_string(attempt);
        const TopologyInput in =
            make_input(s.workspace, s.familiar, objects, radius, x, target, carried);
        const TopologyInput in_cached =
            make_input(s.workspace, s.familiar, objects, radius, x, target, carried, cache);
        expect_identical(in, in_cached, what + ": make_input");
        ++tally.checks;
        if (compare(in, cache, what)) {
          ++tally.succeeded;
          ++tally.verdicts[static_cast<int>(check_topology(in, cache).verdict)];
          break;  // one valid x per move is enough
        }
      }
    }
  }
}

TEST(TopologyCache, CachedCallIsIdenticalToUncachedBitForBit) {
  const std::size_t scenes = test_support::scaled(120);
  TopologyCache cache;
  Tally tally;
  for (std::uint64_t seed = 1; seed <= scenes; ++seed) scene_checks(seed, cache, tally);
  EXPECT_LE(cache.freespaces(), kTopologyCacheFreespaces);
  EXPECT_LE(cache.dilations(), kTopologyCacheDilations);
  // The same scenes again with the cache left by all the others (entries evicted, rebuilt).
  for (std::uint64_t seed = 1; seed <= scenes / 4; ++seed) scene_checks(seed, cache, tally);
  std::printf(
      "topology cache: %zu checks compared, %zu succeeded (%zu reachable, %zu blocked by "
      "objects, %zu blocked by fixed), the others compared as errors\n",
      tally.checks, tally.succeeded, tally.verdicts[0], tally.verdicts[1], tally.verdicts[2]);
  EXPECT_GE(tally.succeeded, scenes);
  if (test_support::test_scale() >= 1) {
    for (std::size_t n : tally.verdicts) EXPECT_GE(n, 10u);
  }
}

TEST(TopologyCache, KeepsBoundMinusFixedAcrossObjectMoves) {
  const Polygon room = test_scenes::rect(0, 0, 10, 10);
  const std::vector<Polygon> walls = {test_scenes::rect(0, 4.8, 4.2, 5.2),
                                      test_scenes::rect(5.8, 4.8, 10, 5.2)};
  TopologyCache cache;
  for (int k = 0; k < 5; ++k) {
    const std::vector<Disk> objects{{{4.5 + 0.25 * k, 5.0}, 0.5}, {{8.0, 2.0}, 0.4}};
    const TopologyInput in =
        make_input(room, walls, objects, 0.2, {2, 2}, {5, 8}, std::nullopt, cache);
    compare(in, cache, "move " + std::to_string(k));
  }
  EXPECT_EQ(cache.freespaces(), 1u);  // one bound and fixed set
  EXPECT_EQ(cache.dilations(), 3u);   // the erosion and two walls
  // The pair (another radius): a second entry of each.
  const TopologyInput pair =
      make_input(room, walls, {{{2, 2}, 0.3}, {{8.0, 2.0}, 0.4}}, 0.5, {2, 2}, {5, 8}, 0, cache);
  compare(pair, cache, "pair");
  EXPECT_EQ(cache.freespaces(), 2u);
  EXPECT_EQ(cache.dilations(), 6u);
  cache.clear();
  EXPECT_EQ(cache.freespaces(), 0u);
  EXPECT_EQ(cache.dilations(), 0u);
  // More bound/fixed sets than entries: the oldest are dropped.
  for (std::size_t k = 0; k < kTopologyCacheFreespaces + 2; ++k) {
    const TopologyInput in = make_input(room, {test_scenes::rect(7, 7, 7.5 + 0.1 * k, 8)}, {}, 0.2,
                                        {2, 2}, {5, 8}, std::nullopt, cache);
    compare(in, cache, "set " + std::to_string(k));
  }
  EXPECT_EQ(cache.freespaces(), kTopologyCacheFreespaces);
}

// Two familiar triangles span a 4 × 2 m room, apexes 0.2 m apart at (1.9, 1) and (2.1, 1),
// their turning angle 2·atan(1/0.9) ≈ 96°. Dilated by R = 0.08 the round dilation leaves a
// 0.2 − 2R = 0.04 m pinch between the wedges above and below them; the default miter reaches
// R / cos(48°) ≈ 0.12 m from each apex and closes it; bevelled on the disk's tangent (limit 1)
// each apex reaches R and the pinch stays open, as the round dilation says.
TEST(TopologyCache, TheMiterLimitDecidesAPinchBetweenTwoCorners) {
  const Polygon room = test_scenes::rect(0, 0, 4, 2);
  const std::vector<Polygon> fixed = {Polygon{{Point(1, 0), Point(1.9, 1), Point(1, 2)}},
                                      Polygon{{Point(3, 0), Point(3, 2), Point(2.1, 1)}}};
  const double radius = 0.08;
  const Point above(2, 1.6), below(2, 0.4);
  TopologyCache mitered;
  EXPECT_EQ(check_topology(make_input(room, fixed, {}, radius, above, below, std::nullopt, mitered),
                           mitered)
                .verdict,
            Verdict::kBlockedByFixed);
  TopologyCache bevelled;
  bevelled.set_miter_limit(1.0);
  EXPECT_EQ(check_topology(
                make_input(room, fixed, {}, radius, above, below, std::nullopt, bevelled), bevelled)
                .verdict,
            Verdict::kReachable);
  // A new limit empties the cache (no dilation of the old limit is reused); bad limits throw.
  EXPECT_GT(bevelled.dilations(), 0u);
  bevelled.set_miter_limit(geometry::kMiterLimit);
  EXPECT_EQ(bevelled.dilations(), 0u);
  EXPECT_EQ(check_topology(
                make_input(room, fixed, {}, radius, above, below, std::nullopt, bevelled), bevelled)
                .verdict,
            Verdict::kBlockedByFixed);
  EXPECT_THROW(bevelled.set_miter_limit(0.5), Error);
  EXPECT_THROW(bevelled.set_miter_limit(std::nan("")), Error);
}

TEST(TopologyCache, SameErrorsWithAWarmCache) {
  const Polygon room = test_scenes::rect(0, 0, 10, 10);
  TopologyCache cache;
  const TopologyInput good = make_input(room, {test_scenes::rect(1, 1, 2, 2)}, {{{5, 5}, 0.5}}, 0.2,
                                        {8, 8}, {1, 8}, std::nullopt, cache);
  ASSERT_TRUE(compare(good, cache, "good"));
  TopologyInput in = good;
  in.x = {5, 5.1};  // inside the object's dilation
  EXPECT_FALSE(compare(in, cache, "x in an object"));
  in = good;
  in.movable.push_back(Polygon{{{3, 3}, {4, 4}, {4, 3}, {3, 4}}});  // a bow tie
  in.movable_ids.push_back(7);
  EXPECT_FALSE(compare(in, cache, "bow tie"));
  in = good;
  in.fixed.push_back({Region{Polygon{{{3, 3}, {4, 4}, {4, 3}, {3, 4}}}, {}}});
  EXPECT_FALSE(compare(in, cache, "bow tie fixed"));
  in = good;
  in.movable_ids = {1, 2};
  EXPECT_FALSE(compare(in, cache, "ids"));
  // make_input's errors, cached and not.
  for (int k = 0; k < 2; ++k) {
    EXPECT_THROW(make_input(room, {Polygon{{{3, 3}, {4, 4}, {4, 3}, {3, 4}}}}, {}, 0.2, {1, 1},
                            {8, 8}, std::nullopt, cache),
                 Error);
    EXPECT_THROW(make_input(room, {}, {{{3, 3}, 0.5}}, 0.2, {1, 1}, {8, 8}, 1, cache), Error);
    EXPECT_THROW(make_input(room, {}, {}, -1, {1, 1}, {8, 8}, std::nullopt, cache), Error);
  }
  // A moved-from cache still works.
  TopologyCache moved = std::move(cache);
  EXPECT_TRUE(compare(good, moved, "moved"));
  EXPECT_TRUE(compare(good, cache, "moved from"));  // NOLINT(bugprone-use-after-move)
}

}  // namespace
}  // namespace rearm::topology
