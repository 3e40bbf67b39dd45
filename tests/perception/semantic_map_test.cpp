// The semantic map (paper §II, docs/reactive.md §2): familiar memory, visible fragments,
// movable objects and the version counter, on hand-built scenes whose truth is computed by hand
// (distances to axis-aligned boxes, fragments of a wall that translate with the robot).
#include "perception/semantic_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "perception_oracle.h"

namespace rearm::perception {
namespace {

using oracle::convex_excess;
using oracle::is_convex_ccw;

Polygon box(double x0, double y0, double x1, double y1) {
  return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

// Room 60 x 40 m; familiar obstacles "A" (an L whose nearest point to the negative x axis is
// (5, 0)), "B" (a unit box above A), "C" (far away); an unknown wall "W" along y in [1, 1.5] for
// x in [20, 30]; objects M1 and M2.
World scene() {
  World w;
  w.workspace = box(-20, -20, 40, 20);
  w.familiar.push_back({"A", Polygon{{{5, -1}, {7, -1}, {7, 1}, {6, 1}, {6, 0}, {5, 0}}}});
  w.familiar.push_back({"B", box(5, 1, 6, 2)});
  w.familiar.push_back({"C", box(-15, -15, -14, -14)});
  w.unknown.push_back({"W", box(20, 1, 30, 1.5)});
  w.movable.push_back({"M1", Disk{Point(0, 5), 0.3}});
  w.movable.push_back({"M2", Disk{Point(0, -5), 0.25}});
  return w;
}

constexpr double kR = 2.0;

TEST(SemanticMapTest, StartsEmptyWithMovableObjectsKnown) {
  const SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_EQ(map.version(), 0u);
  EXPECT_TRUE(map.familiar().empty());
  EXPECT_TRUE(map.unknown().empty());
  ASSERT_EQ(map.movable().size(), 2u);
  EXPECT_EQ(map.movable_ids(), (std::vector<std::string>{"M1", "M2"}));
  EXPECT_EQ(map.movable()[1].center, Point(0, -5));
  EXPECT_EQ(map.workspace().size(), 4u);
}

TEST(SemanticMapTest, FamiliarLocalizedExactlyAtDistanceRAndRemembered) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  // A's nearest point is (5, 0) for robots on the x axis left of it.
  EXPECT_FALSE(map.update(Point(2.999, 0)));  // distance 2.001
  EXPECT_EQ(map.version(), 0u);
  EXPECT_TRUE(map.update(Point(3.0, 0)));  // distance exactly R: closed disk
  EXPECT_EQ(map.version(), 1u);
  EXPECT_EQ(map.familiar_ids(), (std::vector<std::string>{"A"}));
  EXPECT_TRUE(map.is_localized("A"));
  EXPECT_FALSE(map.is_localized("B"));  // distance hypot(2, 1) > 2
  // Localized whole, not as a fragment.
  EXPECT_EQ(map.familiar()[0].vertices, map.ground_truth().familiar[0].polygon.vertices);
  // Memory: moving away keeps it, and changes nothing.
  EXPECT_FALSE(map.update(Point(-10, 0)));
  EXPECT_EQ(map.version(), 1u);
  EXPECT_EQ(map.familiar_ids(), (std::vector<std::string>{"A"}));
  // B then C, in order of localization.
  EXPECT_TRUE(map.update(Point(5.5, 3.5)));  // B at distance 1.5
  EXPECT_TRUE(map.update(Point(-12, -14.5)));
  EXPECT_EQ(map.familiar_ids(), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(map.version(), 3u);
}

TEST(SemanticMapTest, TwoObstaclesAtOnceBumpTheVersionOnce) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_TRUE(map.update(Point(5.5, 0.5)));  // between A and B: both in range
  EXPECT_EQ(map.version(), 1u);
  EXPECT_EQ(map.familiar_ids(), (std::vector<std::string>{"A", "B"}));  // world order on ties
}

TEST(SemanticMapTest, RobotInsideAFamiliarObstacleFarFromItsBoundarySeesIt) {
  World w = scene();
  w.familiar.push_back({"big", box(-19, 10, 19, 19)});
  SemanticMap map(w, Sensor({.range = 1.0}));
  EXPECT_TRUE(map.update(Point(0, 15)));
  EXPECT_EQ(map.familiar_ids(), (std::vector<std::string>{"big"}));
}

TEST(SemanticMapTest, FragmentOfAWallSeenAndForgotten) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_TRUE(map.update(Point(25, 0)));
  ASSERT_EQ(map.unknown().size(), 1u);
  EXPECT_EQ(map.unknown_ids(), (std::vector<std::string>{"W"}));
  const Polygon& f = map.unknown()[0];
  EXPECT_TRUE(is_convex_ccw(f));
  for (const Point& v : f.vertices) {
    EXPECT_LE(convex_excess(map.ground_truth().unknown[0].polygon, v), 1e-9);
    EXPECT_LE((v - Point(25, 0)).norm(), kR * (1 + kFootprintTolerance));
  }
  EXPECT_GT(f.area(), 0.5 * 2 * std::sqrt(kR * kR - 1.5 * 1.5));  // contains disk ∩ wall
  // Out of range: the fragment disappears (not remembered).
  EXPECT_TRUE(map.update(Point(25, -5)));
  EXPECT_TRUE(map.unknown().empty());
  EXPECT_EQ(map.version(), 2u);
  EXPECT_FALSE(map.update(Point(25, -6)));
}

// What has been seen of an unknown obstacle (the robust variant's memory): the hull of every
// fragment read, inside the true wall (convex), growing as the robot drives along it, kept after
// the wall is out of range, and never bumping the version by itself.
TEST(SemanticMapTest, SeenHullGrowsInsideTheObstacleAndIsKept) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  ASSERT_EQ(map.seen().size(), 1u);
  EXPECT_TRUE(map.seen()[0].vertices.empty());
  const Polygon& wall = map.ground_truth().unknown[0].polygon;
  double last_area = 0;
  for (double x = 21; x <= 29; x += 1) {
    map.update(Point(x, 0));
    const Polygon& h = map.seen()[0];
    ASSERT_GE(h.size(), 3u);
    EXPECT_TRUE(is_convex_ccw(h));
    for (const Point& v : h.vertices) EXPECT_LE(convex_excess(wall, v), 1e-9);
    // The visible fragment lies in the hull.
    for (const Point& v : map.unknown()[0].vertices) {
      EXPECT_LE(convex_excess(h, v), kSeenGrowth + 1e-9);
    }
    EXPECT_GT(h.area(), last_area);
    last_area = h.area();
  }
  // Every point of the wall was within R of a robot position (its far corners (20, 1.5) and
  // (30, 1.5) are 1.80 m from (21, 0) and (29, 0); the footprints overlap along it): the hull
  // is the whole wall.
  EXPECT_NEAR(last_area, wall.area(), 1e-9);
  const std::uint64_t v = map.version();
  EXPECT_TRUE(map.update(Point(25, -5)));  // the fragment disappears: the version bumps for that
  EXPECT_TRUE(map.unknown().empty());
  EXPECT_EQ(map.version(), v + 1);
  EXPECT_DOUBLE_EQ(map.seen()[0].area(), last_area);  // kept
}

TEST(SemanticMapTest, StandingStillNeverChangesTheMap) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  const Point x(25.3, 0.1);
  EXPECT_TRUE(map.update(x));
  const auto v = map.version();
  for (int k = 0; k < 1000; ++k) EXPECT_FALSE(map.update(x));
  // Jitter far below the tolerances (a simulator's rounding) changes nothing either.
  for (int k = 0; k < 1000; ++k) {
    const double e = 1e-7 * std::sin(k);
    EXPECT_FALSE(map.update(x + Point(e, -e)));
  }
  EXPECT_EQ(map.version(), v);
}

TEST(SemanticMapTest, FragmentToleranceAccumulatesMotion) {
  // Along the wall, far from its ends, every fragment vertex is a footprint vertex or a crossing
  // of the footprint with the line y = 1: each translates exactly with the robot.
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_TRUE(map.update(Point(23, 0)));
  const auto v0 = map.version();
  const double step = 0.4 * kFragmentTolerance;  // bump every third step: 0.4, 0.8, 1.2 > 1
  int bumps = 0;
  for (int k = 1; k <= 30; ++k) {
    const bool changed = map.update(Point(23 + k * step, 0));
    EXPECT_EQ(changed, k % 3 == 0) << k;
    bumps += changed;
  }
  EXPECT_EQ(bumps, 10);
  EXPECT_EQ(map.version(), v0 + 10);
  // Above the tolerance every step changes the map.
  for (int k = 1; k <= 10; ++k) {
    EXPECT_TRUE(map.update(Point(24 + k * 2 * kFragmentTolerance, 0)));
  }
}

// With a scan spacing s, the fragments are read again only once the robot is s from the last
// reading: along the wall in steps of 0.03 m with s = 0.1 m, readings at 0, 0.12, 0.24, ...
// (every fourth step), each fragment the one a fresh map reads at that point; familiar
// obstacles are still localized at the step they come into range.
TEST(SemanticMapTest, ScanSpacingReadsFragmentsEverySpacingOfTravel) {
  ChangeTolerances tol;
  tol.scan_spacing = 0.1;
  SemanticMap map(scene(), Sensor({.range = kR}), tol);
  const Point start(23, 0);
  EXPECT_TRUE(map.update(start));
  Point read = start;
  for (int k = 1; k <= 40; ++k) {
    const Point x = start + Point(0.03 * k, 0);
    const bool changed = map.update(x);
    EXPECT_EQ(changed, k % 4 == 0) << k;
    if (changed) read = x;
    SemanticMap fresh(scene(), Sensor({.range = kR}));
    fresh.update(read);
    ASSERT_EQ(map.unknown().size(), 1u);
    EXPECT_EQ(map.unknown()[0].vertices, fresh.unknown()[0].vertices) << k;
  }
  // Walking to the familiar obstacles: A comes into range at x = 3 (its nearest point (5, 0)),
  // between two readings, and is localized at once.
  SemanticMap walk(scene(), Sensor({.range = kR}), tol);
  walk.update(Point(2.95, 0));
  EXPECT_TRUE(walk.familiar().empty());
  EXPECT_TRUE(walk.update(Point(3.0, 0)));
  EXPECT_EQ(walk.familiar_ids(), (std::vector<std::string>{"A"}));
  // A spacing over a quarter of the sensing range is refused.
  tol.scan_spacing = kR / 4 + 1e-9;
  EXPECT_THROW(SemanticMap(scene(), Sensor({.range = kR}), tol), Error);
}

// With the runs' fragment tolerance (0.1 m) and scan spacing (0.2 m), a random convex obstacle
// that the robot walks past: after every update, each point of the true obstacle's boundary
// within R/2 - s of the robot lies in the map's fragment (kFragmentNearFraction). Without that
// rule a corner the footprint cut off by less than the tolerance stayed cut off while the robot
// drove up to it. Truth: points sampled on the true polygon's edges, located against the
// fragment's edge lines (oracle::convex_excess).
TEST(SemanticMapTest, NothingNearTheRobotIsMissingFromItsFragment) {
  constexpr double kRange = 3.0, kSpacing = 0.2, kTol = 0.1;
  const double reach = kRange * kFragmentNearFraction - kSpacing;
  ChangeTolerances tol;
  tol.fragment = kTol;
  tol.scan_spacing = kSpacing;
  Rng rng(20261204);
  int checked = 0, worst_trial = -1;
  double worst = -1;
  for (int trial = 0; trial < 200; ++trial) {
    World w;
    w.workspace = box(-20, -20, 20, 20);
    const int n = static_cast<int>(rng.uniform_int(3, 8));
    w.unknown.push_back(
        {"C", oracle::random_convex(rng, n, rng.uniform(0.4, 2.0), rng.uniform(0.4, 2.0),
                                    rng.uniform(0, std::numbers::pi), Point(0, 0))});
    SemanticMap map(w, Sensor({.range = kRange}), tol);
    // A straight walk from 6 m away, passing the obstacle's centre at 0.5 to 2.5 m (or through it).
    const double heading = rng.uniform(0, 2 * std::numbers::pi);
    const Point dir(std::cos(heading), std::sin(heading));
    const Point side(-dir.y(), dir.x());
    const Point start = -6.0 * dir + rng.uniform(0.5, 2.5) * side;
    const Polygon& truth = w.unknown[0].polygon;
    for (int k = 0; k <= 1200; ++k) {
      const Point x = start + 0.01 * k * dir;
      map.update(x);
      for (std::size_t i = 0; i < truth.size(); ++i) {
        const Point& a = truth.vertices[i];
        const Point& b = truth.vertices[(i + 1) % truth.size()];
        for (int j = 0; j <= 20; ++j) {
          const Point p = a + (j / 20.0) * (b - a);
          if ((p - x).norm() > reach) continue;
          ASSERT_EQ(map.unknown().size(), 1u) << "trial " << trial << " step " << k;
          const double e = convex_excess(map.unknown()[0], p);
          if (e > worst) {
            worst = e;
            worst_trial = trial;
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_LE(worst, 1e-9) << "trial " << worst_trial;
}

TEST(SemanticMapTest, ObjectMovesBelowToleranceAccumulate) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_FALSE(map.move_object("M1", Point(0.0005, 5)));
  EXPECT_EQ(map.version(), 0u);
  EXPECT_EQ(map.movable()[0].center, Point(0, 5));        // as last reported
  EXPECT_EQ(map.object("M1")->center, Point(0.0005, 5));  // the truth
  EXPECT_FALSE(map.move_object("M1", Point(0.0009, 5)));
  EXPECT_TRUE(map.move_object("M1", Point(0.0011, 5)));
  EXPECT_EQ(map.version(), 1u);
  EXPECT_EQ(map.movable()[0].center, Point(0.0011, 5));
  EXPECT_TRUE(map.move_object("M2", Point(1, 1)));
  EXPECT_EQ(map.version(), 2u);
  EXPECT_EQ(map.movable()[1].center, Point(1, 1));
  EXPECT_FALSE(map.move_object("M2", Point(1, 1)));
}

TEST(SemanticMapTest, CarriedObjectIsNotAnObstacle) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_TRUE(map.set_carried("M1"));
  EXPECT_EQ(map.version(), 1u);
  EXPECT_EQ(map.movable_ids(), (std::vector<std::string>{"M2"}));
  EXPECT_EQ(*map.carried(), "M1");
  EXPECT_FALSE(map.set_carried("M1"));
  // Carrying it around changes nothing.
  for (int k = 1; k <= 50; ++k) EXPECT_FALSE(map.move_object("M1", Point(k * 0.1, 5)));
  EXPECT_EQ(map.version(), 1u);
  // Releasing it puts it back, where it is now.
  EXPECT_TRUE(map.set_carried(std::nullopt));
  EXPECT_EQ(map.movable_ids(), (std::vector<std::string>{"M1", "M2"}));
  EXPECT_EQ(map.movable()[0].center, Point(5, 5));
  EXPECT_FALSE(map.set_carried(std::nullopt));
  EXPECT_EQ(map.version(), 2u);
}

TEST(SemanticMapTest, AddAndRemoveObjects) {
  SemanticMap map(scene(), Sensor({.range = kR}));
  EXPECT_TRUE(map.add_object({"M3", Disk{Point(3, 3), 0.2}}));
  EXPECT_EQ(map.movable_ids(), (std::vector<std::string>{"M1", "M2", "M3"}));
  EXPECT_TRUE(map.set_carried("M2"));
  EXPECT_TRUE(map.remove_object("M2"));
  EXPECT_FALSE(map.carried().has_value());
  EXPECT_EQ(map.movable_ids(), (std::vector<std::string>{"M1", "M3"}));
  EXPECT_FALSE(map.object("M2").has_value());
  EXPECT_EQ(map.version(), 3u);
}

TEST(SemanticMapTest, AccessorsConvertToTheReactiveInput) {
  // The four accessors give what reactive::SemanticInput holds: workspace, familiar polygons,
  // unknown fragments and movable disks.
  SemanticMap map(scene(), Sensor({.range = kR}));
  map.update(Point(5.5, 0.5));
  const Polygon& ws = map.workspace();
  const std::vector<Polygon>& fam = map.familiar();
  const std::vector<Polygon>& unk = map.unknown();
  const std::vector<Disk>& mov = map.movable();
  EXPECT_EQ(ws.size(), 4u);
  EXPECT_EQ(fam.size(), 2u);
  EXPECT_EQ(unk.size(), 0u);
  EXPECT_EQ(mov.size(), 2u);
  EXPECT_EQ(map.familiar_ids().size(), fam.size());
  EXPECT_EQ(map.unknown_ids().size(), unk.size());
  EXPECT_EQ(map.movable_ids().size(), mov.size());
}

}  // namespace
}  // namespace rearm::perception
