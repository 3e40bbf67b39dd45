// Property test of the semantic map over seeded random worlds and robot paths (paper §II,
// docs/reactive.md §2). After every update the map is checked against independent truth:
// - familiar obstacles: localized iff their true distance (ray casting + brute-force boundary
//   distance) was within R at some position so far, knife edges excepted; never forgotten;
//   appended in order of localization;
// - unknown obstacles: at a version change every fragment lies in its obstacle and within
//   R·(1 + tol) of the robot, is convex, and its area lies between the exact areas of
//   obstacle ∩ disk(R) and obstacle ∩ disk(R / cos(π/n)); an obstacle with a visible part of
//   area above the sliver tolerance has a fragment; without a version change the stored
//   fragments are still within the fragment tolerance of the truth;
// - movable objects: a move bumps the version iff it goes beyond the tolerance from the position
//   reported at the last version change (a model of the contract kept by the test); the carried
//   object is never listed;
// - the version increments at most once per call, exactly when the call reports a change, and
//   standing still (exactly, or with sub-tolerance jitter) changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "perception/semantic_map.h"
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

constexpr double kEps = 1e-9;
constexpr double kHalf = 15;  // workspace half-width (m)

std::string Id(const char* prefix, std::size_t i) {
  std::string s = prefix;
  s += std::to_string(i);
  return s;
}

World RandomWorld(Rng& rng) {
  World w;
  w.workspace = Polygon{{{-kHalf, -kHalf}, {kHalf, -kHalf}, {kHalf, kHalf}, {-kHalf, kHalf}}};
  const std::size_t nf = 1 + rng.index(20);
  for (std::size_t i = 0; i < nf; ++i) {
    const Point c(rng.uniform(-12, 12), rng.uniform(-12, 12));
    const int n = 3 + static_cast<int>(rng.index(10));
    w.familiar.push_back({Id("F", i), test_support::random_star(rng, n, 0.3, 1.8, c)});
  }
  const std::size_t nu = rng.index(6);
  for (std::size_t i = 0; i < nu; ++i) {
    const Point c(rng.uniform(-12, 12), rng.uniform(-12, 12));
    const int n = 3 + static_cast<int>(rng.index(10));
    w.unknown.push_back({Id("U", i), random_convex(rng, n, rng.uniform(0.2, 2.5),
                                                   rng.uniform(0.2, 2.5), rng.uniform(0, 3.2), c)});
  }
  const std::size_t nm = rng.index(5);
  for (std::size_t i = 0; i < nm; ++i) {
    w.movable.push_back({Id("M", i), Disk{Point(rng.uniform(-12, 12), rng.uniform(-12, 12)),
                                          rng.uniform(0.1, 0.5)}});
  }
  return w;
}

// The test's own record of what must hold, kept from the truth alone.
struct Truth {
  std::vector<bool> surely_seen;    // true distance < R − eps at some position so far
  std::vector<bool> possibly_seen;  // true distance <= R + eps at some position so far
  std::vector<Point> reported;      // per object: centre at the last version change
  std::optional<std::size_t> carried;
};

class PerceptionProperty {
 public:
  PerceptionProperty(const World& w, const Sensor& s) : world_(w), map_(w, s) {
    truth_.surely_seen.assign(w.familiar.size(), false);
    truth_.possibly_seen.assign(w.familiar.size(), false);
    for (const MovableObject& m : w.movable) truth_.reported.push_back(m.disk.center);
    outer_ = s.range() / std::cos(std::numbers::pi / s.sides());
  }

  // One robot update plus every check; returns whether the map changed.
  bool Update(const Point& x, const std::string& where) {
    const auto before = map_.version();
    const std::vector<std::string> ids_before = map_.familiar_ids();
    const bool changed = map_.update(x);
    EXPECT_EQ(map_.version(), before + (changed ? 1 : 0)) << where;
    if (changed) OnBump();
    CheckFamiliar(x, ids_before, changed, where);
    CheckFragments(x, changed, where);
    CheckMovable(where);
    return changed;
  }

  void MoveObject(std::size_t i, const Point& c, const std::string& where) {
    const auto before = map_.version();
    const bool expect = (!truth_.carried || *truth_.carried != i) &&
                        (c - truth_.reported[i]).norm() > map_.tolerances().object_move;
    world_.movable[i].disk.center = c;
    EXPECT_EQ(map_.move_object(world_.movable[i].id, c), expect) << where;
    EXPECT_EQ(map_.version(), before + (expect ? 1 : 0)) << where;
    if (expect) OnBump();
    CheckMovable(where);
  }

  void SetCarried(std::optional<std::size_t> i, const std::string& where) {
    const bool expect = i != truth_.carried;
    std::optional<std::string_view> id;
    if (i) id = world_.movable[*i].id;
    EXPECT_EQ(map_.set_carried(id), expect) << where;
    truth_.carried = i;
    if (expect) OnBump();
    CheckMovable(where);
  }

  const SemanticMap& map() const { return map_; }

 private:
  void OnBump() {
    for (std::size_t i = 0; i < world_.movable.size(); ++i) {
      truth_.reported[i] = world_.movable[i].disk.center;
    }
  }

  void CheckFamiliar(const Point& x, const std::vector<std::string>& ids_before, bool changed,
                     const std::string& where) {
    const double r = map_.sensor().range();
    for (std::size_t i = 0; i < world_.familiar.size(); ++i) {
      const double d = true_distance(world_.familiar[i].polygon, x);
      if (d < r - kEps) truth_.surely_seen[i] = true;
      if (d <= r + kEps) truth_.possibly_seen[i] = true;
      const bool localized = map_.is_localized(world_.familiar[i].id);
      if (truth_.surely_seen[i]) {
        EXPECT_TRUE(localized) << where << " " << world_.familiar[i].id;
      }
      if (localized) {
        EXPECT_TRUE(truth_.possibly_seen[i]) << where << " " << world_.familiar[i].id;
      }
    }
    // Memory: earlier localizations are a prefix; a new one is a change.
    const std::vector<std::string>& ids = map_.familiar_ids();
    ASSERT_GE(ids.size(), ids_before.size()) << where;
    EXPECT_TRUE(std::equal(ids_before.begin(), ids_before.end(), ids.begin())) << where;
    if (ids.size() > ids_before.size()) {
      EXPECT_TRUE(changed) << where;
    }
    std::vector<std::string> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << where;
    ASSERT_EQ(map_.familiar().size(), ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const auto it = std::find_if(world_.familiar.begin(), world_.familiar.end(),
                                   [&](const FamiliarObstacle& f) { return f.id == ids[k]; });
      ASSERT_NE(it, world_.familiar.end());
      EXPECT_NEAR(map_.familiar()[k].area(), it->polygon.area(), 1e-12) << where;
    }
  }

  void CheckFragments(const Point& x, bool changed, const std::string& where) {
    const Sensor& s = map_.sensor();
    const double slack = changed ? kEps : map_.tolerances().fragment + kEps;
    const double sliver = s.params().sliver_area;
    ASSERT_EQ(map_.unknown().size(), map_.unknown_ids().size());
    std::size_t k = 0;
    for (const UnknownObstacle& u : world_.unknown) {
      const double inner = polygon_disk_area(u.polygon, x, s.range());
      const double outer = polygon_disk_area(u.polygon, x, outer_);
      const bool listed = k < map_.unknown_ids().size() && map_.unknown_ids()[k] == u.id;
      if (!listed) {
        EXPECT_LT(inner, sliver + kEps) << where << " " << u.id << " missing";
        continue;
      }
      const Polygon& f = map_.unknown()[k++];
      EXPECT_TRUE(is_convex_ccw(f)) << where << " " << u.id;
      EXPECT_GE(outer, sliver - kEps) << where << " " << u.id << " listed but out of sight";
      for (const Point& v : f.vertices) {
        EXPECT_LE(convex_excess(u.polygon, v), slack) << where << " " << u.id;
        EXPECT_LE((v - x).norm(), s.range() * (1 + s.params().footprint_tolerance) + slack)
            << where << " " << u.id;
      }
      if (changed) {
        EXPECT_GE(f.area(), inner - kEps) << where << " " << u.id;
        EXPECT_LE(f.area(), outer + kEps) << where << " " << u.id;
      }
    }
    EXPECT_EQ(k, map_.unknown_ids().size()) << where << ": fragments out of world order";
  }

  void CheckMovable(const std::string& where) {
    std::vector<std::string> ids;
    std::vector<Point> centres;
    for (std::size_t i = 0; i < world_.movable.size(); ++i) {
      if (truth_.carried && *truth_.carried == i) continue;
      ids.push_back(world_.movable[i].id);
      centres.push_back(truth_.reported[i]);
    }
    ASSERT_EQ(map_.movable_ids(), ids) << where;
    for (std::size_t k = 0; k < centres.size(); ++k) {
      EXPECT_EQ(map_.movable()[k].center, centres[k]) << where;
    }
  }

  World world_;
  SemanticMap map_;
  Truth truth_;
  double outer_ = 0;
};

TEST(PerceptionPropertyTest, RandomWorldsAndPaths) {
  const std::size_t worlds = test_support::scaled(200, 3);
  const int steps = 200;
  std::size_t localized = 0, fragments_seen = 0, bumps = 0, still = 0;
  for (std::size_t w = 0; w < worlds; ++w) {
    Rng rng = Rng::derive(2021, w);
    const World world = RandomWorld(rng);
    const Sensor sensor({.range = rng.uniform(1, 4)});
    PerceptionProperty p(world, sensor);
    Point x(rng.uniform(-12, 12), rng.uniform(-12, 12));
    double heading = rng.uniform(-3.2, 3.2);
    for (int t = 0; t < steps; ++t) {
      const std::string where = "world " + std::to_string(w) + " step " + std::to_string(t);
      bumps += p.Update(x, where);
      fragments_seen += p.map().unknown().size();
      if (rng.bernoulli(0.2)) {
        // Standing still: exactly, then with jitter far below every tolerance.
        const auto v = p.map().version();
        EXPECT_FALSE(p.Update(x, where + " still"));
        EXPECT_FALSE(p.Update(x + Point(1e-9, -1e-9), where + " jitter"));
        EXPECT_EQ(p.map().version(), v) << where;
        ++still;
      }
      if (!world.movable.empty() && rng.bernoulli(0.3)) {
        const std::size_t i = rng.index(world.movable.size());
        const Point c = p.map().object(world.movable[i].id)->center;
        const double step = rng.bernoulli(0.5) ? rng.uniform(0, 1.5e-3) : rng.uniform(0, 0.5);
        const double a = rng.uniform(-3.2, 3.2);
        p.MoveObject(i, c + step * Point(std::cos(a), std::sin(a)), where + " move");
      }
      if (!world.movable.empty() && rng.bernoulli(0.05)) {
        std::optional<std::size_t> carried;
        if (rng.bernoulli(0.6)) carried = rng.index(world.movable.size());
        p.SetCarried(carried, where + " carry");
      }
      heading += rng.uniform(-0.5, 0.5);
      const double len = rng.bernoulli(0.1) ? rng.uniform(0, 2e-3) : rng.uniform(0, 0.4);
      x += len * Point(std::cos(heading), std::sin(heading));
      x = x.cwiseMax(Point(-14, -14)).cwiseMin(Point(14, 14));
    }
    localized += p.map().familiar().size();
  }
  // The random scenes exercise every branch.
  EXPECT_GT(localized, worlds);
  EXPECT_GT(fragments_seen, worlds);
  EXPECT_GT(bumps, worlds * 5);
  EXPECT_GT(still, worlds);
}

}  // namespace
}  // namespace rearm::perception
