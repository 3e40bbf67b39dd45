// One Monte Carlo trial (docs in experiments/sweeps/README.md): its settings, its outcome, and
// the one success rule every method is judged by. A trial is one method on one generated
// instance; its record becomes one row of the sweep's CSV (trial_columns.h).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "executive/executive.h"
#include "scenario/instance_difficulty.h"
#include "scenario/random_instance.h"

namespace rearm::experiment {

// How a trial ended, one enum for every method:
//  - completed: the method says it reached its goal (rearm: the mission controller accepted;
//    a baseline: a valid plan executed in Box2D with every goal reached);
//  - infeasible: proven impossible for the method (rearm: the mission controller exhausted its
//    alternatives; mRS: a non-monotone instance);
//  - stuck: rearm's progress monitors ended an action (no progress, a revisited configuration);
//  - timeout: the time budget ran out (rearm: simulated time; a baseline: planning time);
//  - unsolved: a baseline's search ended without a plan inside its budget;
//  - invalid_plan: the independent validator rejected a baseline's plan;
//  - failed: a baseline's plan did not execute in Box2D;
//  - error: the trial threw (bad input, a bug); the message is the row's reason.
enum class TrialStatus {
  kCompleted,
  kInfeasible,
  kStuck,
  kTimeout,
  kUnsolved,
  kInvalidPlan,
  kFailed,
  kError,
  // A baseline cut by the wall-clock safety net with CPU budget left (baselines/motion_query.h):
  // the machine was loaded; not a result of the method.
  kTimeoutWall
};
inline constexpr int kTrialStatusCount = 9;
const char* to_string(TrialStatus s);
// Throws rearm::Error for any other text.
TrialStatus trial_status_from_string(std::string_view text);

// Where a method's compute time went (s of wall time). rearm: the mission controller, the
// topology checks (Appendix III), the diffeomorphism rebuilds ([7]) and the rest of the control
// loop; the baselines spend all of theirs in planning (planning_s).
struct ComputeSplit {
  double mission_s = 0;
  double topology_s = 0;
  double rebuild_s = 0;
  double control_s = 0;
  double planning_s = 0;
  double total() const { return mission_s + topology_s + rebuild_s + control_s + planning_s; }
};

// What a method reports for one trial.
struct TrialOutcome {
  TrialStatus status = TrialStatus::kError;
  std::string reason;
  bool goals_reached = false;  // every object with a goal ends inside its region (exact)
  // A method that plans offline (the baselines): its compute is compute.planning_s, and the
  // online split (mission, topology, rebuild, control) does not apply.
  bool plans_offline = false;
  ComputeSplit compute;
  // Compute before the first act (s of wall time; NaN when the method never acted): rearm's
  // mission set-up and control steps up to its first non-zero command, a baseline's planning
  // until its first plan was complete and valid.
  double first_action_s = std::numeric_limits<double>::quiet_NaN();
  // A baseline's planning in wall time (compute.planning_s is the planning thread's CPU time,
  // what its budget counts); NaN for rearm.
  double planning_wall_s = std::numeric_limits<double>::quiet_NaN();
  double wall_time_s = 0;  // the whole trial (planning, validation, simulation)
  double cpu_time_s = 0;   // the trial thread's CPU time (the runner measures it)
  double sim_time_s = 0;   // simulated seconds in Box2D
  double robot_path_m = 0;
  double object_path_m = 0;  // summed over the objects
  int actions = 0;           // rearm: executed actions, Fix mode's included; baselines: 2 per move
  int fix_mode_entries = 0;
  int replans = 0;
  executive::RecoveryCounts recoveries;  // rearm's robust variant (0 for the baselines)
  int collisions = 0;
  double min_clearance_m = 0;
  long queries = 0;     // motion queries, straight-line checks included (baselines)
  long subqueries = 0;  // motion queries that needed OMPL's sampling (baselines)
  long nodes = 0;       // search nodes (baselines)
};

// The one success rule (docs: "completed in Box2D, every object inside its goal region,
// 0 collisions"), the same for every method.
bool is_success(const TrialOutcome& o);

// Everything that decides a trial's result: the instance's generator spec (class, N, density,
// workspace, unknown mix and shapes, instance seed, the other generator settings), the
// method, the planner seed and the time limit.
struct TrialSettings {
  std::string method;
  scenario::InstanceSpec instance;
  int rep = 0;                 // repetition within the cell
  std::string workspace_rule;  // how the side was chosen (scenario::WorkspaceRule::describe)
  std::uint64_t planner_seed = 0;
  double time_limit_s = 0;
  long query_limit = 0;  // the baselines' motion queries (0: none)
  // The order the method solved the task in (the goal_order column): the instance's for a
  // method that follows the formula's order, "any" for one that ignores it.
  std::string goal_order = "chain";
};

// The instance as generated (filled by the runner from scenario::generate_instance).
struct InstanceInfo {
  std::string name;  // the scenario's name; its file is instances/<name>.yaml
  double achieved_density = 0;
  double footprint_density = 0;
  int familiar = 0, unknown = 0;            // obstacle counts
  scenario::InstanceDifficulty difficulty;  // goal cycles, occupied goals, walled-in objects
  bool witness = false;  // a plan that solves it comes with it (class constructive)
};

struct Provenance {
  std::string revision;  // baked in at build time (provenance.h)
  std::string host;
  std::string cpu_model;
  // When the trial ended, UTC, ISO 8601 ("2026-12-07T15:04:05Z"; provenance.h utc_now): the
  // date of the run that produced the row's numbers.
  std::string finished_utc;
};

struct TrialRecord {
  std::size_t index = 0;  // position in the sweep's full trial list (sweep_plan.h)
  std::string sweep;      // the sweep's name
  TrialSettings settings;
  InstanceInfo instance;
  TrialOutcome outcome;
  Provenance provenance;
};

// The resume key: a canonical text of every setting that changes a result (TrialSettings, the
// instance spec field by field, numbers in shortest round-trip form). Two trials with the same
// key give the same row apart from the timing columns.
std::string resume_key(const TrialSettings& s);

}  // namespace rearm::experiment
