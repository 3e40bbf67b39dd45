// The goal half of the one success rule (trial.h, is_success): "every object inside its goal
// region". An object's goal region is the region of the task's release(M, l) atoms when they all
// name one region; an object released in several regions (a patrol of objects) or never has no
// final region, and only the mission status judges it.
#pragma once

#include <optional>
#include <vector>

#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

// Per object of s.objects: the index into s.regions of its goal region, or nullopt. Throws
// scenario::ScenarioError(source, "task", reason) for a formula that does not parse.
std::vector<std::optional<std::size_t>> goal_regions(const scenario::Scenario& s);

// A reachability task (action atoms joined by && and <>, the nesting of formula (1) of the
// paper) as a rearrangement planner takes it: per object of s.objects the region of its
// release(M, l) atoms and that region's navigation target (executive::region_target), and the
// region of the move(l) atoms with its target. Throws scenario::ScenarioError(source, "task",
// reason) for any other operator, an unknown name, an object released in two regions or the
// robot sent to two.
struct ReachabilityGoals {
  std::vector<std::optional<std::size_t>> object_region;  // index into s.regions
  std::vector<std::optional<geometry::Point>> object_target;
  std::optional<std::size_t> robot_region;
  std::optional<geometry::Point> robot_target;
};
ReachabilityGoals reachability_goals(const scenario::Scenario& s);

// Whether every object that has a goal region ends with its centre inside it (exact point
// location; the boundary counts). `end` lists the objects' final centres in scenario order.
bool goals_reached(const scenario::Scenario& s, const std::vector<geometry::Point>& end);

}  // namespace rearm::experiment
