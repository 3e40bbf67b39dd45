// One baseline trial on a scenario (docs/experiments.md, "Baseline"): plan with B1
// (mRS), B2 (BiRRT over arrangements) or the replanning variant, check the plan with the
// independent validator, execute it in the same Box2D world as rearm's runs, and write the same
// metrics as `rearm run` plus planning_time_s, subqueries and nodes.
//
// B1 and B2 get the full map offline (every familiar and unknown obstacle where it truly is).
// The replanning variant knows only what the sensor has seen (familiar obstacles localized
// whole, unknown ones as visible fragments, as rearm's perception reports them): it plans with
// B2 on that map, executes, and replans from where it stands whenever a newly seen obstacle
// meets the rest of the plan's swept disks. A transfer interrupted that way is continued by one
// transfer query from the pair's current centre before the rest is replanned.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "baselines/birrt.h"
#include "baselines/buffer.h"
#include "baselines/executor.h"
#include "scenario/scenario.h"

namespace rearm::baselines {

// kBufferStrict: the buffer baseline without TRLB's allocation (BufferOptions::lifetime_spots).
enum class Method { kMrs, kBirrt, kReplan, kBuffer, kFmrs, kBirrtFmrs, kBufferStrict };
// "mrs", "birrt", "replan", "buffer", "fmrs", "birrt-fmrs", "buffer-strict"
const char* to_string(Method m);
Method method_from_string(const std::string& s);  // throws rearm::Error naming the choices

struct BaselineOptions {
  Method method = Method::kBirrt;
  double time_limit = 10;  // s of planning (wall) time per trial, all replans together
  std::uint64_t seed = 0;
  bool execute = true;  // execute a solved plan in Box2D
  bool record = true;   // keep the executed trajectory (figure, animation)
  BaselineParams params;
  BirrtOptions birrt;
  BufferOptions buffer;
  FmrsOptions fmrs;  // fmrs and birrt-fmrs (birrt.extension is set by the method)
  int iterations_per_query = 20000;
  // Motion queries for the whole trial, all replans together (0: no limit;
  // PlannerOptions::max_queries): the deterministic budget of the Monte Carlo sweeps.
  long query_limit = 0;
};

struct BaselineRecord {
  std::string scenario;
  Method method = Method::kBirrt;
  std::uint64_t seed = 0;
  double time_limit = 0;
  // "completed" (solved, valid, executed with every goal reached), "infeasible" (proven for the
  // method: B1 on a non-monotone instance), "unsolved", "timeout", "invalid_plan" (the validator
  // objected), "failed" (the execution failed or missed a goal).
  std::string status;
  std::string reason;
  PlanStatus plan_status = PlanStatus::kTimeout;
  Plan plan;                            // the last plan
  std::vector<std::string> violations;  // the validator's, for the last plan
  bool executed = false;
  ExecutionLog execution;
  int replans = 0;
  double planning_time_s = 0;  // the planning thread's CPU time, summed over replans (budgeted)
  double planning_wall_s = 0;  // the wall time of the same
  // The planning time before the robot's first act: a valid plan is complete (the replanning
  // variant: its first one). NaN when no plan was executed (rearm's counterpart:
  // executive::TaskResult::first_action_time).
  double first_action_time_s = std::numeric_limits<double>::quiet_NaN();
  long subqueries = 0, nodes = 0, arrangement_nodes = 0, queries = 0;
  double wall_time_s = 0;  // planning + validation + execution
};

// Throws scenario::ScenarioError for a task the baselines cannot plan (problem.h) and
// rearm::Error for bad options (non-positive or non-finite time limit, ...).
BaselineRecord run_baseline(const scenario::Scenario& s, const BaselineOptions& o);

// metrics.json with the keys of `rearm run` (experiment::metrics_json) plus method,
// time_limit_s, planning_time_s, subqueries, nodes, arrangement_nodes, replans, plan_moves
// (the last plan's), moves_executed,
// violations. Identical bytes for identical runs apart from the timing fields (wall_time_s,
// controller_time_s, first_action_time_s, planning_time_s, real_time_factor).
std::string baseline_metrics_json(const scenario::Scenario& s, const BaselineRecord& r);
// trajectory.json in the format of experiment::trajectory_json (experiments/plot/run.py draws
// it); familiar obstacles count as localized from the start (the map is given offline).
std::string baseline_trajectory_json(const scenario::Scenario& s, const BaselineRecord& r,
                                     int stride = 10);

}  // namespace rearm::baselines
