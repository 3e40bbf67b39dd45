#include "experiment/trial.h"

#include <charconv>
#include <string>
#include <system_error>

#include "core/error.h"

namespace rearm::experiment {
namespace {

constexpr const char* kStatusNames[kTrialStatusCount] = {"completed", "infeasible", "stuck",
                                                         "timeout",   "unsolved",   "invalid_plan",
                                                         "failed",    "error",      "timeout_wall"};

std::string num(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

}  // namespace

const char* to_string(TrialStatus s) {
  const int i = static_cast<int>(s);
  REARM_DEMAND(i >= 0 && i < kTrialStatusCount, "invalid TrialStatus " + std::to_string(i));
  return kStatusNames[i];
}

TrialStatus trial_status_from_string(std::string_view text) {
  for (int i = 0; i < kTrialStatusCount; ++i) {
    if (text == kStatusNames[i]) return static_cast<TrialStatus>(i);
  }
  throw Error("trial status: unknown '" + std::string(text) + "'");
}

bool is_success(const TrialOutcome& o) {
  return o.status == TrialStatus::kCompleted && o.goals_reached && o.collisions == 0;
}

std::string resume_key(const TrialSettings& s) {
  const scenario::InstanceSpec& i = s.instance;
  std::string k = "method=" + s.method;
  k += ";class=" + std::string(scenario::to_string(i.goal_class));
  k += ";objects=" + std::to_string(i.objects);
  k += ";density=" + num(i.obstacle_density);
  k += ";width=" + num(i.width) + ";height=" + num(i.height);
  k += ";unknown_fraction=" + num(i.unknown_fraction);
  k += ";round_unknown=" + std::to_string(i.round_unknown ? 1 : 0);
  k += ";robot_radius=" + num(i.robot_radius) + ";object_radius=" + num(i.object_radius);
  k += ";region_side=" + num(i.region_side) + ";sensor_range=" + num(i.sensor_range);
  k += ";footprint_density=" + num(i.footprint_density);
  k += ";passage_margin=" + num(i.passage_margin);
  k += ";max_obstacle_side=" + num(i.max_obstacle_side);
  k += ";max_attempts=" + std::to_string(i.max_attempts);
  k += ";instance_seed=" + std::to_string(i.seed);
  k += ";planner_seed=" + std::to_string(s.planner_seed);
  k += ";time_limit=" + num(s.time_limit_s);
  k += ";query_limit=" + std::to_string(s.query_limit);
  // The task's order, named only when it is not the chain, so that the keys of sweeps written
  // before the dimension existed are unchanged.
  if (i.goal_order != scenario::GoalOrder::kChain) {
    k += ";goal_order=" + std::string(scenario::to_string(i.goal_order));
  }
  if (i.goal_class == scenario::GoalClass::kConstructive) {
    k += ";scatter_moves=" + std::to_string(i.scatter_moves);
  }
  return k;
}

}  // namespace rearm::experiment
