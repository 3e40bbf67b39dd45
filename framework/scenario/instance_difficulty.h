// How hard an instance is for rearrangement, measured on the instance as generated (the sweep
// rows' difficulty columns, experiments/sweeps/README.md). The dependency graph of goals on
// starts: object i depends on object j when i's goal disk (radius ρ_i at its goal point)
// overlaps j's start disk, so j must leave before i can arrive (Gao et al., ICRA 2022; TRLB).
// An object on a cycle of that graph cannot be placed by any order that moves each object once
// (a non-monotone instance, as the paper's Fig. 5). Walled-in objects: solvability.h's
// walled_in_objects.
#pragma once

#include <vector>

#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::scenario {

struct InstanceDifficulty {
  int goal_cycle_objects = 0;  // objects on a cycle of the dependency graph
  int goals_occupied = 0;      // objects whose goal disk overlaps another object's start disk
  int walled_in = 0;           // objects the robot cannot reach with every object in place
};

// goals[k]: objects[k]'s goal point (k < goals.size(); the objects after have no goal). Throws
// rearm::Error when goals outnumber the objects or there are more than 64 objects.
InstanceDifficulty instance_difficulty(const Scenario& s,
                                       const std::vector<geometry::Point>& goals);

}  // namespace rearm::scenario
