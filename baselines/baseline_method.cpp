#include "baselines/baseline_method.h"

#include <memory>
#include <string>

#include "baselines/run_baseline.h"
#include "core/error.h"
#include "experiment/goals.h"

namespace rearm::baselines {
namespace {

using experiment::TrialStatus;

// BaselineRecord::status (run_baseline.h) as the runner's one status enum.
TrialStatus status_of(const std::string& s) {
  if (s == "completed") return TrialStatus::kCompleted;
  if (s == "infeasible") return TrialStatus::kInfeasible;
  if (s == "unsolved") return TrialStatus::kUnsolved;
  if (s == "timeout") return TrialStatus::kTimeout;
  if (s == "timeout_wall") return TrialStatus::kTimeoutWall;
  if (s == "invalid_plan") return TrialStatus::kInvalidPlan;
  if (s == "failed") return TrialStatus::kFailed;
  REARM_DEMAND(false, "baseline status '" + s + "' has no trial status");
  return TrialStatus::kError;
}

const char* summary_of(Method m) {
  switch (m) {
    case Method::kMrs:
      return "B1 mRS: depth-first search over move orders (monotone), full map offline";
    case Method::kBirrt:
      return "B2 BiRRT over arrangements with temporary placements, full map offline";
    case Method::kReplan:
      return "B2 on the sensed map, replanning when the sensor reveals an obstacle";
    case Method::kBuffer:
      return "TRLB running-buffer order, lazy spots clear of the goals filled meanwhile";
    case Method::kFmrs:
      return "fmRS: one order from the MCR dependency graph, no backtracking, full map offline";
    case Method::kBirrtFmrs:
      return "BiRRT over arrangements with fmRS as extension primitive, full map offline";
    case Method::kBufferStrict:
      return "buffer without TRLB's allocation: spots clear of every goal, never re-parked";
  }
  return "";
}

class BaselineMethod final : public experiment::Method {
 public:
  explicit BaselineMethod(baselines::Method m) : method_(m) {}
  std::string name() const override { return to_string(method_); }
  std::string summary() const override { return summary_of(method_); }

  experiment::TrialOutcome run(const scenario::Scenario& s,
                               const experiment::MethodInput& in) const override {
    BaselineOptions o;
    o.method = method_;
    o.time_limit = in.time_limit_s;
    o.query_limit = in.query_limit;
    o.seed = in.seed;
    o.record = false;
    const BaselineRecord r = run_baseline(s, o);
    const ExecutionLog& e = r.execution;
    experiment::TrialOutcome out;
    out.status = status_of(r.status);
    out.reason = r.reason;
    out.goals_reached = r.executed && experiment::goals_reached(s, e.objects_end);
    out.plans_offline = true;
    out.compute.planning_s = r.planning_time_s;
    out.planning_wall_s = r.planning_wall_s;
    out.first_action_s = r.first_action_time_s;
    out.wall_time_s = r.wall_time_s;
    out.sim_time_s = e.sim_time;
    out.robot_path_m = e.robot_path_length;
    out.object_path_m = e.object_path_length;
    out.actions = 2 * static_cast<int>(e.moves_done);
    out.replans = r.replans;
    out.collisions = e.collisions;
    out.min_clearance_m = r.executed ? e.min_clearance : 0.0;
    out.queries = r.queries;
    out.subqueries = r.subqueries;
    out.nodes = r.nodes;
    return out;
  }

 private:
  baselines::Method method_;
};

}  // namespace

void register_methods(experiment::MethodRegistry& registry) {
  for (const Method m : {Method::kMrs, Method::kBirrt, Method::kReplan, Method::kBuffer,
                         Method::kFmrs, Method::kBirrtFmrs, Method::kBufferStrict}) {
    registry.add(std::make_unique<BaselineMethod>(m));
  }
}

}  // namespace rearm::baselines
