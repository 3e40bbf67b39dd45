// The robust variant's Fix-mode drop point (executive/targets.h, drop_point; docs/executive.md,
// "Fix mode's drop points") on hand-built rooms, checked against plain geometry: the point is
// clear of every goal region by the pair's reach, and a mover is never set down where its disk
// could meet the disk it lay on when Fix mode found the way closed. Each rule is shown to bind:
// the same search without it returns a point that breaks it.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "executive/context.h"
#include "executive/targets.h"
#include "geometry/distance.h"
#include "perception/semantic_map.h"
#include "perception/sensor.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

constexpr double kRho = 0.25;  // m, the carried object's radius

// An empty 8 m x 4 m room whose robot carries M at `held` (its pair centre), everything seen.
struct Room {
  explicit Room(const Point& held) : map(world(held), perception::Sensor({10.0})) {
    map.update(held);
    map.set_carried("M");
  }
  static perception::World world(const Point& held) {
    perception::World w;
    w.workspace = test_support::rect(0, 0, 8, 4);
    w.movable.push_back({"M", geometry::Disk{held, kRho}});
    return w;
  }
  Context context() {
    return Context{p,     regions,    map,    controller, cache,      dilations,
                   times, recoveries, checks, u,          keep_clear, ways};
  }
  // The drop point of a Fix-mode DISASSEMBLE of M with the pair's centre at `center`.
  std::optional<Point> drop(const Point& center) {
    ActionState a = make_action(ActionKind::kDisassemble, "M", "", true, 0, p.progress);
    const double radius = p.robot_radius + kRho + p.grasp.pair_margin;
    return drop_point(context(), a, geometry::Region{test_support::rect(0, 0, 8, 4), {}}, radius,
                      center, kRho);
  }
  ExecutiveParams p;
  std::vector<RegionOfInterest> regions;
  perception::SemanticMap map;
  reactive::ReactiveController controller{p.diffeo, p.nav};
  topology::TopologyCache cache;
  reactive::DilationCache dilations;
  ComputeTimes times;
  RecoveryCounts recoveries;
  int checks = 0;
  Twist u;
  std::vector<geometry::Disk> keep_clear;
  std::vector<Way> ways;
};

TEST(DropPoint, ClearOfEveryGoalRegionByThePairsReach) {
  const Point held(2.0, 2.0);
  Room room(held);
  const std::optional<Point> free = room.drop(held);
  ASSERT_TRUE(free.has_value());
  // A goal region over the point the empty room gave: the search must go elsewhere.
  room.regions.push_back({"l1", test_support::rect(free->x() - 0.6, free->y() - 0.6,
                                                   free->x() + 0.6, free->y() + 0.6)});
  const std::optional<Point> q = room.drop(held);
  ASSERT_TRUE(q.has_value());
  EXPECT_GT(geometry::distance(room.regions[0].polygon, *q), room.p.robot_radius + kRho);
}

TEST(DropPoint, AMoverIsNotSetDownWhereItLay) {
  const Point held(2.0, 2.0);
  Room room(held);
  const std::optional<Point> free = room.drop(held);
  ASSERT_TRUE(free.has_value());
  // The way Fix mode found closed with M lying at the point the empty room gave; its path runs
  // far from the room's middle, so only the rule about where M lay can reject a point.
  Way w;
  w.from = Point(0.5, 0.4);
  w.to = Point(7.5, 0.4);
  w.radius = room.p.robot_radius;
  w.movers = {geometry::Disk{*free, kRho}};
  w.mover_ids = {"M"};
  w.path = {w.from, w.to};
  room.ways.push_back(w);
  const std::optional<Point> q = room.drop(held);
  ASSERT_TRUE(q.has_value());
  const double reach = room.p.robot_radius + room.p.grasp.dock_gap + kRho;
  EXPECT_GE((*q - *free).norm(), reach + kRho) << "set down where it lay";
  // The rule concerns the mover only: a way whose movers are other objects leaves the point.
  room.ways[0].mover_ids = {"N"};
  const std::optional<Point> other = room.drop(held);
  ASSERT_TRUE(other.has_value());
  EXPECT_LT((*other - *free).norm(), reach + kRho);
}

}  // namespace
}  // namespace rearm::executive
