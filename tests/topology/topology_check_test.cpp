// Hand-built scenes with known answers for the topology check (paper
// Appendix III and Fig. 3): one object blocking the only corridor, a chain of two touching
// objects in a door, a walled-in target, a target reachable around objects; the same for the
// robot–object pair (larger radius), and bad input.
#include "topology/topology_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::topology {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

constexpr double kRobot = 0.2;  // robot radius (m)

Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

const Polygon kRoom = rect(0, 0, 10, 10);

// Two rectangles across the room at y ∈ [4.8, 5.2] leaving a door x ∈ [lo, hi] (Fig. 3(a)).
std::vector<Polygon> wall_with_door(double lo, double hi) {
  return {rect(0, 4.8, lo, 5.2), rect(hi, 4.8, 10, 5.2)};
}

// A closed box of four walls (thickness 0.2) around [x0, x1] × [y0, y1].
std::vector<Polygon> closed_box(double x0, double y0, double x1, double y1) {
  return {rect(x0, y0, x1, y0 + 0.2), rect(x0, y1 - 0.2, x1, y1), rect(x0, y0, x0 + 0.2, y1),
          rect(x1 - 0.2, y0, x1, y1)};
}

// F_e ⊇ F: every vertex of F's outer boundary in the hull.
void expect_hull_contains_freespace(const TopologyResult& t) {
  ASSERT_GE(t.enclosing.size(), 3u);
  for (const Point& v : t.freespace.outer.vertices) {
    EXPECT_TRUE(geometry::convex_contains(t.enclosing, v, 1e-9)) << v.transpose();
  }
}

TEST(TopologyCheck, Fig3OneObjectBlocksTheOnlyCorridor) {
  // Door 1.6 m wide (1.2 m after dilation); the object (ρ = 0.5) fills it. A second object
  // lies elsewhere and must not be listed. Region 1 is around (5, 8).
  const std::vector<Disk> objects{{{5.0, 5.0}, 0.5}, {{8.0, 2.0}, 0.4}};
  const TopologyInput in =
      make_input(kRoom, wall_with_door(4.2, 5.8), objects, kRobot, {2, 2}, {5, 8});
  const TopologyResult t = check_topology(in);
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{0})) << t.reason;
  EXPECT_TRUE(geometry::contains(t.freespace, Point(2, 2)));
  EXPECT_FALSE(geometry::contains(t.freespace, Point(5, 8)));
  expect_hull_contains_freespace(t);
  EXPECT_NE(t.reason.find("1 movable object"), std::string::npos) << t.reason;

  // Once the object is gone (d), the task is reachable.
  const TopologyResult after = check_topology(
      make_input(kRoom, wall_with_door(4.2, 5.8), {objects[1]}, kRobot, {2, 2}, {5, 8}));
  EXPECT_EQ(after.verdict, Verdict::kReachable) << after.reason;
  EXPECT_TRUE(after.blocking.empty());
}

TEST(TopologyCheck, TargetInsideTheBlockingObject) {
  // x* inside the object: the goal vertex is the object's cluster.
  const std::vector<Disk> objects{{{5.0, 5.0}, 0.5}};
  const TopologyResult t = check_topology(
      make_input(kRoom, wall_with_door(4.2, 5.8), objects, kRobot, {2, 2}, {5.0, 5.1}));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{0}));
}

TEST(TopologyCheck, ChainOfTwoTouchingObjectsInADoorNearestOnTop) {
  // Door x ∈ [3.8, 6.2] (free x ∈ [4.0, 6.0] after dilation); two objects whose dilations
  // overlap close it together; neither alone would.
  const std::vector<Disk> objects{{{4.5, 5.0}, 0.45}, {{5.6, 5.0}, 0.45}};
  const auto walls = wall_with_door(3.8, 6.2);
  {
    // Robot on the left, nearer object 0: it is on top (moved first).
    const TopologyResult t =
        check_topology(make_input(kRoom, walls, objects, kRobot, {1.5, 2}, {5, 8}));
    EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
    EXPECT_EQ(t.blocking, (std::vector<std::size_t>{1, 0})) << t.reason;
  }
  {
    // Robot on the right: object 1 on top.
    const TopologyResult t =
        check_topology(make_input(kRoom, walls, objects, kRobot, {8.5, 2}, {5, 8}));
    EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
    EXPECT_EQ(t.blocking, (std::vector<std::size_t>{0, 1})) << t.reason;
  }
  {
    // Either object alone leaves a passage.
    for (std::size_t keep = 0; keep < 2; ++keep) {
      const TopologyResult t =
          check_topology(make_input(kRoom, walls, {objects[keep]}, kRobot, {1.5, 2}, {5, 8}));
      EXPECT_EQ(t.verdict, Verdict::kReachable) << keep << ": " << t.reason;
    }
  }
}

TEST(TopologyCheck, TwoClustersInSeriesNearestClusterOnTop) {
  // Two walls, each with a door blocked by its own object: robot below, target above both.
  std::vector<Polygon> fixed = {rect(0, 2.8, 4.2, 3.2), rect(5.8, 2.8, 10, 3.2),
                                rect(0, 6.8, 4.2, 7.2), rect(5.8, 6.8, 10, 7.2)};
  const std::vector<Disk> objects{{{5.0, 7.0}, 0.5}, {{5.0, 3.0}, 0.5}, {{8, 5}, 0.4}};
  const TopologyResult t =
      check_topology(make_input(kRoom, fixed, objects, kRobot, {2, 1.5}, {5, 9}));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  // B_M: the far door's object at the bottom, the near door's on top.
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{0, 1})) << t.reason;
}

TEST(TopologyCheck, WalledInTargetIsBlockedByFixed) {
  std::vector<Polygon> fixed = closed_box(6.5, 6.5, 9.5, 9.5);
  // Objects around, one touching the box: still the fixed walls decide.
  const std::vector<Disk> objects{{{6.0, 8.0}, 0.3}, {{3, 3}, 0.5}};
  const TopologyResult t =
      check_topology(make_input(kRoom, fixed, objects, kRobot, {2, 2}, {8, 8}));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByFixed) << t.reason;
  EXPECT_TRUE(t.blocking.empty());
  EXPECT_NE(t.reason.find("separated"), std::string::npos) << t.reason;
  // A target inside a fixed obstacle is infeasible too.
  const TopologyResult inside =
      check_topology(make_input(kRoom, fixed, objects, kRobot, {2, 2}, {6.6, 8}));
  EXPECT_EQ(inside.verdict, Verdict::kBlockedByFixed) << inside.reason;
  EXPECT_NE(inside.reason.find("inside a fixed obstacle"), std::string::npos) << inside.reason;
}

TEST(TopologyCheck, ObjectOverlappingAThinWallDoesNotBridgeIt) {
  // Direct (already dilated) input: a closed box with 0.1 m walls and an object polygon
  // straddling its left wall (a localization error). (∪ F_list) ∪ (∪ movable) taken literally
  // would connect x to x* through the object; moving it cannot open the wall.
  TopologyInput in;
  in.bound = {geometry::Region{rect(0.2, 0.2, 9.8, 9.8), {}}};
  for (const Polygon& p : {rect(6, 6, 9.5, 6.1), rect(6, 9.4, 9.5, 9.5), rect(6, 6, 6.1, 9.5),
                           rect(9.4, 6, 9.5, 9.5)}) {
    in.fixed.push_back({geometry::Region{p, {}}});
  }
  in.movable = {rect(5.7, 7.7, 6.4, 8.3)};
  in.x = {2, 2};
  in.target = {8, 8};
  const TopologyResult t = check_topology(in);
  EXPECT_EQ(t.verdict, Verdict::kBlockedByFixed) << t.reason;
}

TEST(TopologyCheck, TargetReachableAroundObjects) {
  const std::vector<Disk> objects{{{3, 3}, 0.5}, {{5, 5}, 0.6}, {{6.5, 3}, 0.4}, {{3, 7}, 0.5}};
  const std::vector<Polygon> fixed = {rect(7, 6, 8, 9)};
  const TopologyResult t =
      check_topology(make_input(kRoom, fixed, objects, kRobot, {1, 1}, {9, 9}));
  EXPECT_EQ(t.verdict, Verdict::kReachable) << t.reason;
  EXPECT_TRUE(t.blocking.empty());
  EXPECT_TRUE(geometry::contains(t.freespace, Point(9, 9)));
  EXPECT_TRUE(geometry::contains(t.enclosing, Point(9, 9)));
  expect_hull_contains_freespace(t);
  EXPECT_EQ(t.components.size(), 1u);
}

TEST(TopologyCheck, TargetInAPocketOfTheHullButNotInF) {
  // F is the room minus a closed box; x* inside the box lies in Conv(F) (= the eroded room)
  // but not in F: the literal "x* ∈ F_e" would wrongly pass, the check says fixed.
  const TopologyResult t =
      check_topology(make_input(kRoom, closed_box(4, 4, 6, 6), {}, kRobot, {1, 1}, {5, 5}));
  EXPECT_TRUE(geometry::contains(t.enclosing, Point(5, 5)));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByFixed) << t.reason;
}

// --- The robot–object pair: radius r + ρ_i, the carried object left out. ---

constexpr double kCarriedRadius = 0.4;
constexpr double kPair = kRobot + kCarriedRadius;

TEST(TopologyCheckPair, Fig3ForThePair) {
  // Carried object 0 sits at the pair centre (left out); object 1 blocks the 1.6 m door.
  const std::vector<Disk> objects{{{2, 2}, kCarriedRadius}, {{5.0, 5.0}, 0.3}, {{8, 2}, 0.3}};
  const TopologyInput in =
      make_input(kRoom, wall_with_door(4.2, 5.8), objects, kPair, {2, 2}, {5, 8}, 0);
  ASSERT_EQ(in.movable.size(), 2u);
  EXPECT_EQ(in.movable_ids, (std::vector<std::size_t>{1, 2}));
  const TopologyResult t = check_topology(in);
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{1})) << t.reason;
  // The robot alone (same objects, object 0 not carried but left where it is) also finds
  // object 1's dilation too small to block: free door x ∈ [4.4, 5.6] minus [4.5, 5.5].
  const std::vector<Disk> others{{{5.0, 5.0}, 0.3}, {{8, 2}, 0.3}};
  const TopologyResult alone =
      check_topology(make_input(kRoom, wall_with_door(4.2, 5.8), others, kRobot, {2, 2}, {5, 8}));
  EXPECT_EQ(alone.verdict, Verdict::kReachable) << alone.reason;
}

TEST(TopologyCheckPair, ChainForThePair) {
  const std::vector<Disk> objects{{{3.9, 5.0}, 0.3}, {{1, 1}, kCarriedRadius}, {{5.6, 5.0}, 0.3}};
  // Door x ∈ [3.2, 6.8]: pair-free x ∈ [3.8, 6.2]; object dilations (0.9 + slack) around 3.9
  // and 5.6 overlap each other and the walls' dilations.
  const TopologyResult t = check_topology(
      make_input(kRoom, wall_with_door(3.2, 6.8), objects, kPair, {1, 1}, {5, 8}, 1));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{2, 0})) << t.reason;
}

TEST(TopologyCheckPair, WalledInForThePair) {
  const std::vector<Disk> objects{{{2, 2}, kCarriedRadius}};
  const TopologyResult t = check_topology(
      make_input(kRoom, closed_box(6.5, 6.5, 9.5, 9.5), objects, kPair, {2, 2}, {8, 8}, 0));
  EXPECT_EQ(t.verdict, Verdict::kBlockedByFixed) << t.reason;
}

TEST(TopologyCheckPair, ReachableAroundObjectsForThePair) {
  const std::vector<Disk> objects{{{1, 1}, kCarriedRadius}, {{4, 4}, 0.5}, {{6, 6}, 0.4}};
  const TopologyResult t =
      check_topology(make_input(kRoom, {rect(7, 1, 8, 4)}, objects, kPair, {1, 1}, {9, 9}, 0));
  EXPECT_EQ(t.verdict, Verdict::kReachable) << t.reason;
  EXPECT_TRUE(t.blocking.empty());
  EXPECT_TRUE(geometry::contains(t.enclosing, Point(9, 9)));
  expect_hull_contains_freespace(t);
}

TEST(TopologyCheckPair, GapTheRobotFitsThroughButThePairDoesNot) {
  // Door 1.0 m wide: robot-free width 0.6 m, pair-free width < 0.
  const auto walls = wall_with_door(4.5, 5.5);
  const std::vector<Disk> objects{{{2, 2}, kCarriedRadius}};
  const TopologyResult robot = check_topology(make_input(kRoom, walls, {}, kRobot, {2, 2}, {5, 8}));
  EXPECT_EQ(robot.verdict, Verdict::kReachable) << robot.reason;
  const TopologyResult pair =
      check_topology(make_input(kRoom, walls, objects, kPair, {2, 2}, {5, 8}, 0));
  EXPECT_EQ(pair.verdict, Verdict::kBlockedByFixed) << pair.reason;
  // Not carrying it, the object at x would put x inside its dilation.
  EXPECT_THROW(check_topology(make_input(kRoom, walls, objects, kRobot, {2, 2}, {5, 8})), Error);
}

// F_list alone (step 1), against one global exact overlay of the same dilations: the same
// sets (each difference empty), warm cache or not.
TEST(TopologyCheck, FreespaceComponentsAreTheGlobalOverlay) {
  const std::vector<Disk> objects{{{5.0, 5.0}, 0.5}, {{8.0, 2.0}, 0.4}, {{1.0, 8.0}, 0.3}};
  TopologyCache cache;
  for (const double radius : {kRobot, kPair}) {
    const TopologyInput in =
        make_input(kRoom, wall_with_door(4.2, 5.8), objects, radius, {2, 2}, {5, 8}, {}, cache);
    geometry::RegionSet obstacles = geometry::unite_all(in.movable);
    for (const geometry::RegionSet& f : in.fixed) obstacles = geometry::unite(obstacles, f);
    const geometry::RegionSet want = geometry::subtract(in.bound, obstacles);
    for (int pass = 0; pass < 2; ++pass) {
      const geometry::RegionSet got = freespace_components(in, cache);
      EXPECT_EQ(got.size(), want.size());
      EXPECT_TRUE(geometry::subtract(got, want).empty()) << radius;
      EXPECT_TRUE(geometry::subtract(want, got).empty()) << radius;
    }
  }
  // The object in the door splits the room: two components (above and below the wall).
  const TopologyInput robot =
      make_input(kRoom, wall_with_door(4.2, 5.8), objects, kRobot, {2, 2}, {5, 8});
  EXPECT_EQ(freespace_components(robot, cache).size(), 2u);
  TopologyInput empty = robot;
  empty.bound.clear();
  EXPECT_THROW(freespace_components(empty, cache), Error);
}

// --- Direct inputs and bad input. ---

TEST(TopologyCheckInput, DirectInputWithIdsAndNonConvexObject) {
  TopologyInput in;
  in.bound = {geometry::Region{rect(0, 0, 10, 10), {}}};
  in.fixed = {{geometry::Region{rect(0, 4, 4, 6), {}}}, {geometry::Region{rect(6, 4, 10, 6), {}}}};
  // An L-shaped (non-convex) object closing the door.
  in.movable = {Polygon{{{3.5, 3.5}, {6.5, 3.5}, {6.5, 5}, {5, 5}, {5, 6.5}, {3.5, 6.5}}}};
  in.movable_ids = {7};
  in.x = {1, 1};
  in.target = {5, 9};
  const TopologyResult t = check_topology(in);
  EXPECT_EQ(t.verdict, Verdict::kBlockedByObjects) << t.reason;
  EXPECT_EQ(t.blocking, (std::vector<std::size_t>{7}));
  EXPECT_EQ(t.components.size(), 2u);
}

TEST(TopologyCheckInput, XInsideAnObstacleThrows) {
  const std::vector<Disk> objects{{{3, 3}, 0.5}};
  EXPECT_THROW(
      check_topology(make_input(kRoom, {rect(1, 1, 2, 2)}, {}, kRobot, {1.5, 1.5}, {8, 8})), Error);
  EXPECT_THROW(check_topology(make_input(kRoom, {}, objects, kRobot, {3.1, 3}, {8, 8})), Error);
  // Outside the eroded workspace.
  EXPECT_THROW(check_topology(make_input(kRoom, {}, {}, kRobot, {0.1, 5}, {8, 8})), Error);
  try {
    check_topology(make_input(kRoom, {}, objects, kRobot, {3.1, 3}, {8, 8}));
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not in the freespace"), std::string::npos) << e.what();
  }
}

TEST(TopologyCheckInput, NonFiniteNumbersThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(make_input(kRoom, {}, {}, kRobot, {nan, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {}, kRobot, {1, 1}, {8, inf}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {}, nan, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {}, -0.2, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {{{nan, 3}, 0.5}}, kRobot, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {{{3, 3}, inf}}, kRobot, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {{{3, 3}, 0}}, kRobot, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {rect(1, 1, nan, 2)}, {}, kRobot, {1, 1}, {8, 8}), Error);

  TopologyInput in = make_input(kRoom, {}, {}, kRobot, {1, 1}, {8, 8});
  in.x = {1, nan};
  EXPECT_THROW(check_topology(in), Error);
  in.x = {1, 1};
  in.target = {inf, 1};
  EXPECT_THROW(check_topology(in), Error);
  in.target = {8, 8};
  in.movable = {rect(3, 3, 4, nan)};
  EXPECT_THROW(check_topology(in), Error);
}

TEST(TopologyCheckInput, InvalidPolygonsAndShapesThrow) {
  const Polygon bowtie{{{3, 3}, {4, 4}, {4, 3}, {3, 4}}};
  const Polygon flat{{{3, 3}, {4, 3}, {5, 3}}};
  EXPECT_THROW(make_input(kRoom, {bowtie}, {}, kRobot, {1, 1}, {8, 8}), Error);
  EXPECT_THROW(make_input(bowtie, {}, {}, kRobot, {3.1, 3.5}, {8, 8}), Error);
  EXPECT_THROW(make_input(kRoom, {}, {{{3, 3}, 0.5}}, kRobot, {1, 1}, {8, 8}, 1), Error);

  const TopologyInput good = make_input(kRoom, {}, {}, kRobot, {1, 1}, {8, 8});
  TopologyInput in = good;
  in.movable = {bowtie};
  EXPECT_THROW(check_topology(in), Error);
  in = good;
  in.movable = {flat};
  EXPECT_THROW(check_topology(in), Error);
  in = good;
  in.fixed = {{geometry::Region{bowtie, {}}}};
  EXPECT_THROW(check_topology(in), Error);
  in = good;
  in.bound = {geometry::Region{Polygon{{{0, 0}, {1, 0}}}, {}}};
  EXPECT_THROW(check_topology(in), Error);
  in = good;
  in.bound.clear();
  EXPECT_THROW(check_topology(in), Error);
  in = good;
  in.movable = {rect(3, 3, 4, 4)};
  in.movable_ids = {0, 1};
  EXPECT_THROW(check_topology(in), Error);
}

TEST(TopologyCheckInput, VerdictNames) {
  EXPECT_STREQ(to_string(Verdict::kReachable), "reachable");
  EXPECT_STREQ(to_string(Verdict::kBlockedByObjects), "blocked by movable objects");
  EXPECT_STREQ(to_string(Verdict::kBlockedByFixed), "blocked by fixed obstacles");
}

}  // namespace
}  // namespace rearm::topology
