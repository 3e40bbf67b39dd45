// Instance difficulty (scenario/instance_difficulty.h, solvability.h's walled_in_objects) on
// scenes whose answers hold by construction: a swap (a two-cycle) beside a free goal, a chain
// (occupied goals, no cycle), an object in a corner behind three others (walled in; open once
// one of them is gone), and the generator's cyclic class, where every goal is the next object's
// start (every object on the one cycle).
#include "scenario/instance_difficulty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenario/random_instance.h"
#include "scenario/solvability.h"
#include "support/task_scenes.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using test_support::rect;

// A 6 x 6 m room, the robot at (4.5, 4.5), objects of radius 0.25 m.
Scenario room(const std::vector<Point>& starts) {
  Scenario s;
  s.name = "room";
  s.workspace = rect(0, 0, 6, 6);
  s.robot.start = Point(4.5, 4.5);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    s.objects.push_back(Object{"M" + std::to_string(i + 1), geometry::Disk{starts[i], 0.25}});
  }
  return s;
}

TEST(InstanceDifficulty, ASwapIsACycleAndAChainIsNot) {
  const Scenario s = room({Point(1, 1), Point(2.5, 1), Point(4, 1)});
  // M1 and M2 swap, M3 goes to a free spot.
  const InstanceDifficulty swap = instance_difficulty(s, {Point(2.5, 1), Point(1, 1), Point(4, 3)});
  EXPECT_EQ(swap.goal_cycle_objects, 2);
  EXPECT_EQ(swap.goals_occupied, 2);
  EXPECT_EQ(swap.walled_in, 0);
  // M1 onto M2, M2 onto M3 (a few cm off: overlap counts), M3 free.
  const InstanceDifficulty chain =
      instance_difficulty(s, {Point(2.5, 1.1), Point(3.9, 1), Point(4, 3)});
  EXPECT_EQ(chain.goal_cycle_objects, 0);
  EXPECT_EQ(chain.goals_occupied, 2);
  // Goals a full diameter away from every start: nothing occupied.
  const InstanceDifficulty apart =
      instance_difficulty(s, {Point(1, 1.5), Point(2.5, 1.5), Point(4, 3)});
  EXPECT_EQ(apart.goals_occupied, 0);
  EXPECT_THROW(instance_difficulty(s, {Point(0, 0), Point(1, 1), Point(2, 2), Point(3, 3)}), Error);
}

// M1 in the corner (0.4, 0.4); M2..M4 on an arc of radius 1.15 m about the corner at 15, 45 and
// 75 degrees. Neighbours on the arc are 0.595 m apart (a 0.095 m gap) and the end ones 0.048 m
// off the walls: far less than the robot's 0.4 m diameter, so no robot position next to M1 is
// reachable from the robot's start outside.
TEST(InstanceDifficulty, AnObjectBehindOthersIsWalledIn) {
  std::vector<Point> starts{Point(0.4, 0.4)};
  for (const double deg : {15.0, 45.0, 75.0}) {
    const double a = deg * std::numbers::pi / 180;
    starts.push_back(1.15 * Point(std::cos(a), std::sin(a)));
  }
  const Scenario s = room(starts);
  const std::vector<bool> w = walled_in_objects(s);
  EXPECT_EQ(w, (std::vector<bool>{true, false, false, false}));
  EXPECT_EQ(instance_difficulty(s, {}).walled_in, 1);
  Scenario open = s;
  open.objects.erase(open.objects.begin() + 2);  // the middle of the arc
  EXPECT_EQ(instance_difficulty(open, {}).walled_in, 0);
}

TEST(InstanceDifficulty, TheCyclicClassPutsEveryObjectOnTheCycle) {
  for (const int n : {2, 5, 8}) {
    InstanceSpec spec;
    spec.objects = n;
    spec.goal_class = GoalClass::kCyclic;
    spec.obstacle_density = 0.05;
    spec.seed = static_cast<std::uint64_t>(n);
    const GeneratedInstance g = generate_instance(spec);
    ASSERT_EQ(g.goals.size(), static_cast<std::size_t>(n));
    const InstanceDifficulty d = instance_difficulty(g.scenario, g.goals);
    EXPECT_EQ(d.goal_cycle_objects, n);
    EXPECT_EQ(d.goals_occupied, n);
  }
}

}  // namespace
}  // namespace rearm::scenario
