// A scenario (scenario/) as the executive's task (executive/task_runner.h): the ground-truth
// world, the regions, the parsed formula and π0 (experiment/scenario_task.h), the sensor and
// every controller parameter.
#pragma once

#include "executive/task_runner.h"
#include "experiment/scenario_task.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

// The task of a validated scenario: its formula and π0 parsed and checked once (parse_task).
// Perception's unknown-fragment change tolerance is the scenario's controller.fragment_tolerance;
// the executive's patrol limit is simulation.max_actions.
executive::TaskSpec task_spec(const scenario::Scenario& s);

// The reactive controller's parameters of a scenario: the diffeomorphism's (p, ε, μ1, μ2) and
// the navigation law's (gains, speed limits, sensor range R); the rest at their defaults.
reactive::DiffeoParams diffeo_params(const scenario::Scenario& s);
reactive::NavParams nav_params(const scenario::Scenario& s);

// The kinematic plant's start pose and world for a scenario.
executive::Pose start_pose(const scenario::Scenario& s);
perception::World world_of(const scenario::Scenario& s);

}  // namespace rearm::experiment
