// A scenario's task parsed and checked once (paper §II and Appendix I-B): the LTL formula φ
// over move(l), grasp(M), release(M,l) as a tree, and the initial predicate π0 as an action.
// task_spec() hands both to the executive, which no longer reads text.
#pragma once

#include <optional>

#include "ltl/formula.h"
#include "scenario/scenario.h"
#include "symbolic/action.h"

namespace rearm::experiment {

struct ScenarioTask {
  ltl::Formula formula;                     // φ, in the mission controller's fragment
  std::optional<symbolic::Action> initial;  // π0; none: the empty symbol
};

// Parses the scenario's task and initial predicate once and checks them against the scene.
// Throws scenario::ScenarioError(source, "task", reason) for a malformed formula, one outside
// the fragment (symbolic::check_mission_formula) or one naming an unknown object or region;
// ScenarioError(source, "initial_predicate", reason) for a π0 that names unknown things or does
// not hold at the start (the robot in its region, the object in its region, the gripper open).
ScenarioTask parse_task(const scenario::Scenario& s);

// parse_task for its checks alone.
void check_task(const scenario::Scenario& s);

}  // namespace rearm::experiment
