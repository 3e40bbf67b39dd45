#include "experiment/trial_columns.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <system_error>

#include "core/error.h"
#include "experiment/csv.h"

namespace rearm::experiment {
namespace {

const char* const kTimingColumns[] = {
    "planning_time_s", "planning_wall_s", "mission_time_s", "topology_time_s",
    "rebuild_time_s",  "control_time_s",  "compute_time_s", "first_action_time_s",
    "wall_time_s",     "cpu_time_s",      "revision",       "host",
    "cpu_model",       "finished_utc"};

// Shortest text that reads back to x (deterministic columns); "" for non-finite.
std::string exact(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

std::string timing(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string integer(long long x) { return std::to_string(x); }

// Settings and instance columns.
void settings_fields(const TrialRecord& r, std::vector<std::string>& f) {
  const TrialSettings& s = r.settings;
  const scenario::InstanceSpec& i = s.instance;
  f.push_back(integer(static_cast<long long>(r.index)));
  f.push_back(key_column(s));
  f.push_back(r.sweep);
  f.push_back(s.method);
  f.push_back(scenario::to_string(i.goal_class));
  f.push_back(s.goal_order);
  f.push_back(i.goal_class == scenario::GoalClass::kConstructive ? integer(i.scatter_move_count())
                                                                 : "");
  f.push_back(integer(i.objects));
  f.push_back(exact(i.obstacle_density));
  f.push_back(exact(r.instance.achieved_density));
  f.push_back(exact(r.instance.footprint_density));
  f.push_back(exact(i.width));
  f.push_back(exact(i.height));
  f.push_back(s.workspace_rule);
  f.push_back(exact(i.unknown_fraction));
  f.push_back(i.round_unknown ? "round" : "polygon");
  f.push_back(integer(r.instance.familiar));
  f.push_back(integer(r.instance.unknown));
  f.push_back(integer(r.instance.difficulty.goal_cycle_objects));
  f.push_back(integer(r.instance.difficulty.goals_occupied));
  f.push_back(integer(r.instance.difficulty.walled_in));
  f.push_back(r.instance.witness ? "1" : "0");
  f.push_back(integer(s.rep));
  f.push_back(std::to_string(i.seed));
  f.push_back(std::to_string(s.planner_seed));
  f.push_back(exact(s.time_limit_s));
  f.push_back(integer(s.query_limit));
}

void outcome_fields(const TrialRecord& r, std::vector<std::string>& f) {
  const TrialOutcome& o = r.outcome;
  const bool planner = o.plans_offline;
  f.push_back(to_string(o.status));
  f.push_back(is_success(o) ? "1" : "0");
  f.push_back(o.goals_reached ? "1" : "0");
  f.push_back(o.reason);
  f.push_back(planner ? timing(o.compute.planning_s) : "");
  f.push_back(planner && std::isfinite(o.planning_wall_s) ? timing(o.planning_wall_s) : "");
  for (double x :
       {o.compute.mission_s, o.compute.topology_s, o.compute.rebuild_s, o.compute.control_s}) {
    f.push_back(planner ? "" : timing(x));
  }
  f.push_back(timing(o.compute.total()));
  f.push_back(std::isfinite(o.first_action_s) ? timing(o.first_action_s) : "");
  f.push_back(timing(o.wall_time_s));
  f.push_back(timing(o.cpu_time_s));
  f.push_back(exact(o.sim_time_s));
  f.push_back(exact(o.robot_path_m));
  f.push_back(exact(o.object_path_m));
  f.push_back(integer(o.actions));
  f.push_back(integer(o.fix_mode_entries));
  f.push_back(integer(o.replans));
  for (const executive::RecoveryField& k : executive::kRecoveryFields) {
    f.push_back(integer(o.recoveries.*k.count));
  }
  f.push_back(integer(o.collisions));
  f.push_back(exact(o.min_clearance_m));
  f.push_back(integer(o.queries));
  f.push_back(integer(o.subqueries));
  f.push_back(integer(o.nodes));
}

}  // namespace

std::vector<std::string> recovery_names() {
  std::vector<std::string> out;
  for (const executive::RecoveryField& f : executive::kRecoveryFields) out.emplace_back(f.name);
  return out;
}

const std::vector<std::string>& trial_columns() {
  static const std::vector<std::string> columns = {"trial",
                                                   "key",
                                                   "sweep",
                                                   "method",
                                                   "class",
                                                   "goal_order",
                                                   "scatter_moves",
                                                   "objects",
                                                   "target_density",
                                                   "achieved_density",
                                                   "footprint_density",
                                                   "workspace_width_m",
                                                   "workspace_height_m",
                                                   "workspace_rule",
                                                   "unknown_fraction",
                                                   "unknown_shapes",
                                                   "familiar_obstacles",
                                                   "unknown_obstacles",
                                                   "goal_cycle_objects",
                                                   "goals_occupied",
                                                   "walled_in",
                                                   "witness",
                                                   "rep",
                                                   "instance_seed",
                                                   "planner_seed",
                                                   "time_limit_s",
                                                   "query_limit",
                                                   "status",
                                                   "success",
                                                   "goals_reached",
                                                   "reason",
                                                   "planning_time_s",
                                                   "planning_wall_s",
                                                   "mission_time_s",
                                                   "topology_time_s",
                                                   "rebuild_time_s",
                                                   "control_time_s",
                                                   "compute_time_s",
                                                   "first_action_time_s",
                                                   "wall_time_s",
                                                   "cpu_time_s",
                                                   "sim_time_s",
                                                   "robot_path_m",
                                                   "object_path_m",
                                                   "actions",
                                                   "fix_mode_entries",
                                                   "replans",
                                                   "guides",
                                                   "back_outs",
                                                   "singular_switches",
                                                   "convex_fallbacks",
                                                   "restores",
                                                   "early_releases",
                                                   "withdrawals",
                                                   "release_points",
                                                   "release_poses",
                                                   "object_fixes",
                                                   "early_docks",
                                                   "faces",
                                                   "narrows",
                                                   "fragment_fixes",
                                                   "pocket_drops",
                                                   "redrops",
                                                   "collisions",
                                                   "min_clearance_m",
                                                   "queries",
                                                   "subqueries",
                                                   "nodes",
                                                   "instance",
                                                   "revision",
                                                   "host",
                                                   "cpu_model",
                                                   "finished_utc"};
  return columns;
}

std::size_t trial_column(const std::string& name) {
  const auto& c = trial_columns();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] == name) return i;
  }
  REARM_DEMAND(false, "trial_column: no column " + name);
  return 0;
}

std::string trial_header() { return csv_line(trial_columns()); }

std::vector<std::string> trial_fields(const TrialRecord& r) {
  std::vector<std::string> f;
  f.reserve(trial_columns().size());
  settings_fields(r, f);
  outcome_fields(r, f);
  f.push_back(r.instance.name);
  f.push_back(r.provenance.revision);
  f.push_back(r.provenance.host);
  f.push_back(r.provenance.cpu_model);
  f.push_back(r.provenance.finished_utc);
  REARM_DEMAND(f.size() == trial_columns().size(), "trial_fields: column count");
  return f;
}

std::string trial_row(const TrialRecord& r) { return csv_line(trial_fields(r)); }

bool may_be_missing(const std::string& name) {
  return is_timing_column(name) || name == "goal_order" || name == "scatter_moves" ||
         name == "witness";
}

bool is_timing_column(const std::string& name) {
  for (const char* c : kTimingColumns) {
    if (name == c) return true;
  }
  return false;
}

std::string key_column(const TrialSettings& s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64 offset basis
  for (const unsigned char c : resume_key(s)) {
    h ^= c;
    h *= 0x100000001b3ULL;  // FNV-1a 64 prime
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace rearm::experiment
