// A scenario (scenario/) as the executive's task (executive/task_runner.h): the ground-truth
// world, the regions, the formula, the sensor and every controller parameter. Also the check
// the scenario module cannot make without the LTL parser: the task formula parses, stays in the
// mission controller's fragment and names only the scenario's objects and regions.
#pragma once

#include "executive/task_runner.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

// Throws scenario::ScenarioError(source, "task", reason) for a malformed formula, one outside
// the fragment (symbolic::check_mission_formula) or one naming an unknown object or region.
void check_task(const scenario::Scenario& s);

// The task of a validated scenario (check_task included). Perception's unknown-fragment change
// tolerance is the scenario's controller.fragment_tolerance; the executive's patrol limit is
// simulation.max_actions.
executive::TaskSpec task_spec(const scenario::Scenario& s);

// The reactive controller's parameters of a scenario: the diffeomorphism's (p, ε, μ1, μ2) and
// the navigation law's (gains, speed limits, sensor range R); the rest at their defaults.
reactive::DiffeoParams diffeo_params(const scenario::Scenario& s);
reactive::NavParams nav_params(const scenario::Scenario& s);

// The kinematic plant's start pose and world for a scenario.
executive::Pose start_pose(const scenario::Scenario& s);
perception::World world_of(const scenario::Scenario& s);

}  // namespace rearm::experiment
