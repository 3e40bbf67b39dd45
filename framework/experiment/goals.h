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

// Whether every object that has a goal region ends with its centre inside it (exact point
// location; the boundary counts). `end` lists the objects' final centres in scenario order.
bool goals_reached(const scenario::Scenario& s, const std::vector<geometry::Point>& end);

}  // namespace rearm::experiment
