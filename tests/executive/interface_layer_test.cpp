// The interface layer's geometric choices against hand-computed answers: clearances, the grasp
// candidates next to a wall (the admissible directions follow from distances to the wall in
// closed form), the DISASSEMBLE target heuristic, the early-stop rule and region targets.
#include "executive/interface_layer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "core/error.h"
#include "geometry/dilation.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using geometry::Polygon;
using test_support::rect;
using test_support::sensed_map;

perception::World open_room() {
  perception::World w;
  w.workspace = rect(0, 0, 10, 10);
  w.familiar = {{"P1", rect(4, 4, 6, 6)}};
  w.movable = {{"M1", geometry::Disk{Point(0.6, 8.0), 0.25}},
               {"M2", geometry::Disk{Point(8.0, 2.0), 0.5}}};
  return w;
}

TEST(InterfaceLayer, KnownClearance) {
  const auto map = sensed_map(open_room(), Point(1, 1));
  EXPECT_NEAR(known_clearance(map, Point(2, 5)), 2.0, 1e-12);        // P1 and the west wall
  EXPECT_NEAR(known_clearance(map, Point(3.5, 5)), 0.5, 1e-12);      // P1
  EXPECT_NEAR(known_clearance(map, Point(5, 5.5)), -0.5, 1e-12);     // inside P1
  EXPECT_NEAR(known_clearance(map, Point(8, 3)), 0.5, 1e-12);        // M2's boundary
  EXPECT_NEAR(known_clearance(map, Point(8, 3), "M2"), 2.0, 1e-12);  // M2 excepted
  EXPECT_NEAR(known_clearance(map, Point(11, 5)), -1.0, 1e-12);      // outside the workspace
  EXPECT_THROW(known_clearance(map, Point(std::nan(""), 1)), Error);
}

TEST(InterfaceLayer, KnownClearanceSeesOnlyLocalizedObstacles) {
  // P1 is 3 m away and the sensor range is 1 m: not localized, not an obstacle yet.
  const auto map = sensed_map(open_room(), Point(1, 5), 1.0);
  EXPECT_NEAR(known_clearance(map, Point(3.5, 5)), 3.5, 1e-12);  // only the west wall
}

TEST(InterfaceLayer, GraspCandidatesNextToAWall) {
  // M1 (radius 0.25) 0.6 m from the west wall; robot r = 0.2; standoff 0.02; pair margin 5 mm.
  // Direction a admits the approach x = 0.6 + 0.47 cos a >= 0.2, the dock points
  // x = 0.6 + (0.45 + s) cos a >= 0.2 (s in [0.001, 0.02]) and the pair centre
  // x = 0.6 + 0.2 cos a >= 0.455 (the pair radius). The other walls and
  // objects are far. Pair radius 0.2 + 0.25 + 0.005 = 0.455 binds: cos a >= -0.725.
  const auto map = sensed_map(open_room(), Point(5, 8.5));
  GraspParams p;
  const Point robot(5, 8.5);
  const auto c = grasp_candidates(map, "M1", 0.2, robot, p);
  std::set<int> got;
  for (const GraspCandidate& g : c) {
    const Point u = (g.approach - Point(0.6, 8.0)) / 0.47;
    EXPECT_NEAR(u.norm(), 1, 1e-12);
    const double a = std::atan2(u.y(), u.x());
    got.insert(static_cast<int>(std::lround(a / (2 * std::numbers::pi) * 72 + 72)) % 72);
    EXPECT_NEAR((g.contact - Point(0.6, 8.0)).norm(), 0.451, 1e-12);
    EXPECT_NEAR((g.pair_center - Point(0.6, 8.0)).norm(), 0.2, 1e-12);
  }
  std::set<int> expected;
  for (int k = 0; k < 72; ++k) {
    if (std::cos(2 * std::numbers::pi * k / 72) >= -0.725) expected.insert(k);
  }
  EXPECT_EQ(got, expected);
  for (std::size_t i = 1; i < c.size(); ++i) EXPECT_LE(c[i - 1].distance, c[i].distance);
  EXPECT_NEAR(c.front().distance, (c.front().approach - robot).norm(), 1e-12);
  EXPECT_THROW(grasp_candidates(map, "M9", 0.2, robot, p), Error);
  p.dock_gap = p.standoff;
  EXPECT_THROW(grasp_candidates(map, "M1", 0.2, robot, p), Error);
}

// DISASSEMBLE target in F = the room [0, 10] × [0, 6] for the pair carrying M1 (radius 0.455),
// with region l1 = [8, 9] × [2.5, 3.5], another object M2 at (2, 4) and the given unknown
// obstacles.
std::optional<Point> room_target(const std::vector<perception::UnknownObstacle>& unknown,
                                 double inset = kDisassembleInset) {
  perception::World w;
  w.workspace = rect(0, 0, 10, 6);
  w.unknown = unknown;
  w.movable = {{"M1", geometry::Disk{Point(5, 3), 0.25}},
               {"M2", geometry::Disk{Point(2, 4), 0.25}}};
  perception::SemanticMap map = sensed_map(w, Point(5, 2.5));
  map.set_carried(std::string("M1"));
  const std::vector<RegionOfInterest> regions = {{"l1", rect(8, 2.5, 9, 3.5)}};
  const geometry::Region f{rect(0, 0, 10, 6), {}};
  return disassemble_target(f, map, "M1", regions, 0.455, inset);
}

TEST(InterfaceLayer, DisassembleTargetMaximizesTheMinimumDistance) {
  // Inset midpoints: bottom (5, 0.01): to l1's corner (8, 2.5) sqrt(9 + 2.49²) = 3.899, to M2
  // sqrt(9 + 3.99²) - 0.25 = 4.742 → 3.899. Top (5, 5.99): l1 3.899, M2 sqrt(9 + 1.99²) - 0.25
  // = 3.350 → 3.350. West (0.01, 3): M2 2.227 - 0.25. East (9.99, 3): l1 0.99. The bottom wins.
  const auto t = room_target({});
  ASSERT_TRUE(t);
  EXPECT_NEAR((*t - Point(5, 0.01)).norm(), 0, 1e-12);
  // Without the inset the midpoint itself.
  const auto t0 = room_target({}, 0.0);
  ASSERT_TRUE(t0);
  EXPECT_NEAR((*t0 - Point(5, 0)).norm(), 0, 1e-12);
}

TEST(InterfaceLayer, DisassembleTargetAvoidsUnknownFragments) {
  // An unknown obstacle next to the bottom midpoint: the top one is next.
  const auto t = room_target({{"C1", rect(4.8, 0.2, 5.2, 0.4)}});
  ASSERT_TRUE(t);
  EXPECT_NEAR((*t - Point(5, 5.99)).norm(), 0, 1e-12);
}

TEST(InterfaceLayer, DisassembleTargetInsetsHoleEdgesAwayFromTheHole) {
  // F = a square ring: outer [0, 10]², hole [1, 9]². Regions cover strips along the four outer
  // edges (0.3 m wide in the south, 0.5 m elsewhere), so every outer midpoint scores 0. The
  // hole edges' midpoints, moved 0.01 m into F (away from the hole), score 0.49, except the
  // south one, (5, 0.99), which scores 0.69 and wins. A midpoint moved the wrong way would fall
  // in the hole, stay at (5, 1) and score 0.7.
  perception::World w;
  w.workspace = rect(0, 0, 10, 10);
  w.movable = {{"M1", geometry::Disk{Point(0.5, 5), 0.2}}};
  perception::SemanticMap map = sensed_map(w, Point(0.5, 4));
  map.set_carried(std::string("M1"));
  const geometry::Region f{rect(0, 0, 10, 10), {rect(1, 1, 9, 9)}};
  const std::vector<RegionOfInterest> strips = {{"s", rect(0, 0, 10, 0.3)},
                                                {"n", rect(0, 9.5, 10, 10)},
                                                {"w", rect(0, 0, 0.5, 10)},
                                                {"e", rect(9.5, 0, 10, 10)}};
  const auto t = disassemble_target(f, map, "M1", strips, 0.3);
  ASSERT_TRUE(t);
  EXPECT_NEAR((*t - Point(5, 0.99)).norm(), 0, 1e-12);
}

// The early dock's grasp from where the robot stands, beside the same M1 (0.6 m from the west
// wall): docking along the line through the robot and M1's centre, the pair centre 0.2 m from
// M1 toward the robot must be 0.455 m from the wall, i.e. cos a >= -0.725 as above.
TEST(InterfaceLayer, GraspFromWhereTheRobotStands) {
  const auto map = sensed_map(open_room(), Point(5, 8.5));
  GraspParams p;
  const Point m(0.6, 8.0);
  for (const double a : {0.0, 1.0, 2.0, 2.4, 2.5, 3.0}) {
    const Point u(std::cos(a), std::sin(a));
    const Point robot = m + 0.5 * u;  // 0.05 m from contact
    const auto g = grasp_from(map, "M1", 0.2, robot, p);
    EXPECT_EQ(g.has_value(), std::cos(a) >= -0.725) << a;
    if (!g) continue;
    EXPECT_NEAR((g->contact - (m + 0.451 * u)).norm(), 0, 1e-12);
    EXPECT_NEAR((g->pair_center - (m + 0.2 * u)).norm(), 0, 1e-12);
    EXPECT_EQ(g->approach, robot);
  }
  // At contact already (within the dock gap): nothing to dock.
  EXPECT_FALSE(grasp_from(map, "M1", 0.2, m + Point(0.4505, 0), p).has_value());
  EXPECT_THROW(grasp_from(map, "M9", 0.2, m + Point(0.5, 0), p), Error);
}

// Robust RELEASE point: l = [6.2, 7.2] × [4.5, 5.5] lies 0.2 m east of P1 (x <= 6); with an
// inset of 0.3 m the candidates span x ∈ [6.5, 6.9], and the clearance of a point is x − 6
// (P1; the walls, M2 and the region's other sides are farther), below `enough` = 2 m: the
// chosen point is the easternmost grid column (x = 6.9 up to the grid step and rounding), on
// the row nearest the centroid. Where every candidate is clear enough the centroid itself
// wins; where F holds no candidate there is none.
TEST(InterfaceLayer, ReleasePointKeepsTheObjectClearestInsideTheRegion) {
  const auto map = sensed_map(open_room(), Point(1, 1));
  const geometry::Region room{rect(0, 0, 10, 10), {}};
  const RegionOfInterest beside{"l", rect(6.2, 4.5, 7.2, 5.5)};
  const double step = 0.05;
  const auto p = release_point(room, beside, map, "M1", 0.3, 2.0, step);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(p->x(), 6.9 + 1e-9);
  EXPECT_GE(p->x(), 6.9 - step - 1e-9);
  EXPECT_NEAR(p->y(), 5.0, step / 2 + 1e-9);

  const RegionOfInterest open{"o", rect(1, 1, 2, 2)};
  const auto c = release_point(room, open, map, "M1", 0.3, 0.5, step);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(*c, Point(1.5, 1.5));

  const geometry::Region corner{rect(0, 0, 3, 3), {}};
  EXPECT_FALSE(release_point(corner, beside, map, "M1", 0.3, 2.0, step).has_value());
  // A 10 km region at 5 cm would be 4·10¹⁰ points: the grid coarsens, the answer stays inside.
  const RegionOfInterest huge{"h", rect(-5000, -5000, 5000, 5000)};
  const geometry::Region everywhere{rect(-6000, -6000, 6000, 6000), {}};
  const auto far = release_point(everywhere, huge, map, "M1", 0.3, 2.0, step);
  ASSERT_TRUE(far.has_value());
  EXPECT_LE(far->cwiseAbs().maxCoeff(), 5000 - 0.3);
  EXPECT_THROW(release_point(room, beside, map, "M1", 0.3, 2.0, 0), Error);
  EXPECT_THROW(release_point(room, beside, map, "M1", std::nan(""), 2.0, step), Error);
}

TEST(InterfaceLayer, EarlyStopRule) {
  // r = 0.2, ρ = 0.25 for both objects: the pair centre must be 2(0.2 + 0.25) = 0.9 m from
  // every other object and obstacle, and its disk (0.45) must miss every region.
  perception::World w;
  w.workspace = rect(0, 0, 10, 6);
  w.familiar = {{"P1", rect(4.7, 0, 5.3, 2.5)}};
  w.movable = {{"M1", geometry::Disk{Point(2, 3), 0.25}},
               {"M2", geometry::Disk{Point(2, 1), 0.25}}};
  perception::SemanticMap map = sensed_map(w, Point(2, 2.5));
  map.set_carried(std::string("M1"));
  const std::vector<RegionOfInterest> regions = {{"l1", rect(8, 2.5, 9, 3.5)}};
  EXPECT_TRUE(disassembly_done(Point(3, 3.5), 0.45, 0.2, map, "M1", regions));
  // 0.8 m from M2's boundary (centre distance 1.05).
  EXPECT_FALSE(disassembly_done(Point(2.0, 2.05), 0.45, 0.2, map, "M1", regions));
  // 0.85 m from the wall P1 (x = 4.7) although far from objects.
  EXPECT_FALSE(disassembly_done(Point(3.85, 1.5), 0.45, 0.2, map, "M1", regions));
  // 0.85 m from the workspace's top.
  EXPECT_FALSE(disassembly_done(Point(3, 5.15), 0.45, 0.2, map, "M1", regions));
  // Pair disk reaching into l1 (0.4 m from it), though clear of everything else.
  EXPECT_FALSE(disassembly_done(Point(7.6, 3.0), 0.45, 0.2, map, "M1", regions));
  EXPECT_TRUE(disassembly_done(Point(7.0, 3.0), 0.45, 0.2, map, "M1", regions));
}

TEST(InterfaceLayer, RegionTargets) {
  const RegionOfInterest square{"l1", rect(1, 1, 3, 2)};
  EXPECT_NEAR((region_target(square) - Point(2, 1.5)).norm(), 0, 1e-12);
  // A thin L whose area centroid falls outside it.
  const RegionOfInterest ell{"l2", Polygon{{Point(0, 0), Point(4, 0), Point(4, 0.2),
                                            Point(0.2, 0.2), Point(0.2, 4), Point(0, 4)}}};
  ASSERT_FALSE(geometry::contains(ell.polygon, ell.polygon.centroid()));
  EXPECT_TRUE(geometry::contains(ell.polygon, region_target(ell)));
}

TEST(InterfaceLayer, RegionValidation) {
  const Polygon ws = rect(0, 0, 10, 10);
  EXPECT_NO_THROW(validated({{"l1", rect(1, 1, 2, 2)}}, ws));
  auto message = [&](const std::vector<RegionOfInterest>& r) {
    try {
      validated(r, ws);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{"l1", rect(9, 9, 11, 11)}}).find("outside the workspace"), std::string::npos);
  EXPECT_NE(message({{"l1", rect(1, 1, 2, 2)}, {"l1", rect(3, 3, 4, 4)}}).find("twice"),
            std::string::npos);
  EXPECT_NE(message({{"", rect(1, 1, 2, 2)}}).find("empty id"), std::string::npos);
  const Polygon bowtie{{Point(1, 1), Point(2, 2), Point(2, 1), Point(1, 2)}};
  EXPECT_NE(message({{"l3", bowtie}}).find("l3"), std::string::npos);
  const Polygon nan{{Point(1, 1), Point(std::nan(""), 2), Point(2, 1)}};
  EXPECT_NE(message({{"l4", nan}}).find("l4"), std::string::npos);
}

}  // namespace
}  // namespace rearm::executive
