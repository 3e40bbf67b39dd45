#include "experiment/rearm_method.h"

#include <optional>
#include <string>
#include <utility>

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

// What a method forces on the scenario's controller: nothing ("rearm"), the paper variant
// ("rearm-paper"), or the robust variant with one switch off (the ablations).
struct Variant {
  std::string name;
  std::string summary;
  std::string variant;        // "" keeps the scenario's
  const char* off = nullptr;  // the registry key (core/switches.h) of the switch turned off
};

class RearmMethod final : public Method {
 public:
  explicit RearmMethod(Variant v) : v_(std::move(v)) {}
  bool follows_task_order() const override { return true; }
  std::string name() const override { return v_.name; }
  std::string summary() const override { return v_.summary; }

  TrialOutcome run(const scenario::Scenario& scene, const MethodInput& in) const override {
    scenario::Scenario s = scene;
    if (!v_.variant.empty()) scenario::set_variant(s.controller, v_.variant);
    if (v_.off != nullptr) s.controller.switches.set(v_.off, false);
    RunOptions o;
    o.seed = in.seed;
    o.record = false;
    o.checked = in.checked;
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
    out.first_action_s = x.first_action_time;
    out.wall_time_s = x.wall_time;
    out.sim_time_s = x.sim_time;
    out.robot_path_m = x.robot_path_length;
    out.object_path_m = x.object_path_length;
    out.actions = static_cast<int>(x.actions.size());
    out.fix_mode_entries = x.fix_mode_entries;
    out.collisions = x.collisions;
    out.min_clearance_m = x.min_clearance;
    out.recoveries = x.recoveries;
    return out;
  }

 private:
  Variant v_;
};

}  // namespace

std::unique_ptr<Method> make_rearm_method() {
  return std::make_unique<RearmMethod>(Variant{
      "rearm", "the paper's architecture online in Box2D, robust variant (the scenario's switches)",
      "", nullptr});
}

std::vector<std::unique_ptr<Method>> make_rearm_variants() {
  std::vector<std::unique_ptr<Method>> out;
  out.push_back(std::make_unique<RearmMethod>(
      Variant{"rearm-paper", "rearm with the paper's choices only (no robust extension)", "paper",
              nullptr}));
  for (const SwitchInfo& w : kSwitches) {
    out.push_back(std::make_unique<RearmMethod>(
        Variant{ablation_method(w), std::string("rearm, robust variant with ") + w.key + " off",
                "robust", w.key}));
  }
  return out;
}

void register_rearm_methods(MethodRegistry& r) {
  r.add(make_rearm_method());
  for (auto& m : make_rearm_variants()) r.add(std::move(m));
}

}  // namespace rearm::experiment
