#include "experiment/rearm_method.h"

#include <string>

#include "experiment/goals.h"
#include "experiment/run_scenario.h"

namespace rearm::experiment {
namespace {

TrialStatus status_of(executive::TaskStatus s) {
  switch (s) {
    case executive::TaskStatus::kCompleted:
      return TrialStatus::kCompleted;
    case executive::TaskStatus::kInfeasible:
      return TrialStatus::kInfeasible;
    case executive::TaskStatus::kStuck:
      return TrialStatus::kStuck;
    case executive::TaskStatus::kTimeout:
      return TrialStatus::kTimeout;
    case executive::TaskStatus::kRunning:
      break;
  }
  return TrialStatus::kError;  // a run never ends running; reported, not hidden
}

class RearmMethod final : public Method {
 public:
  std::string name() const override { return "rearm"; }
  std::string summary() const override {
    return "the paper's architecture online in Box2D (sensor discovery, Fix mode)";
  }

  TrialOutcome run(const scenario::Scenario& s, const MethodInput& in) const override {
    RunOptions o;
    o.seed = in.seed;
    o.record = false;
    const RunRecord r = run_scenario(s, o);
    const executive::TaskResult& x = r.result;
    TrialOutcome out;
    out.status = status_of(x.status);
    out.reason = x.reason;
    out.goals_reached = goals_reached(s, r.objects_end);
    out.compute.mission_s = x.mission_time;
    out.compute.topology_s = x.topology_time;
    out.compute.rebuild_s = x.rebuild_time;
    out.compute.control_s = x.control_time;
    out.wall_time_s = x.wall_time;
    out.sim_time_s = x.sim_time;
    out.robot_path_m = x.robot_path_length;
    out.object_path_m = x.object_path_length;
    out.actions = static_cast<int>(x.actions.size());
    out.fix_mode_entries = x.fix_mode_entries;
    out.collisions = x.collisions;
    out.min_clearance_m = x.min_clearance;
    return out;
  }
};

}  // namespace

std::unique_ptr<Method> make_rearm_method() { return std::make_unique<RearmMethod>(); }

}  // namespace rearm::experiment
