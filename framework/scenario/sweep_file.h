// Sweep files (experiments/sweeps/README.md): one Monte Carlo study per YAML file — the methods,
// the goal classes, the object counts, the target obstacle densities, the workspace size per
// object count (or the objects' footprint densities, a dimension of their own), the
// unknown-obstacle fractions and shapes, the repetitions per cell, the time limit per trial and the
// base seed. The experiment layer expands it into instances and trials (experiment/sweep_plan.h).
// Read with the same strict YAML rules as the scenario files (yaml_internal.h) and validated the
// same way: errors name the file, the key and the reason.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scenario/random_instance.h"

namespace rearm::scenario {

// How large the square workspace of a cell is, per object count N (so that N and the obstacle
// density are not confounded): one side for every N, a side per N, or the side that gives the
// objects a footprint density (total disk area over workspace area), never below min_side.
struct WorkspaceRule {
  enum class Kind { kSide, kSidePerCount, kFootprint };
  Kind kind = Kind::kSide;
  double side = 10;                 // m, kSide
  std::map<int, double> per_count;  // N -> side (m), kSidePerCount
  double footprint_density = 0.05;  // kFootprint
  double min_side = 0;              // m, kFootprint

  // The side (m) for N objects of radius rho; throws rearm::Error for an N a per-count rule
  // does not list.
  double side_for(int objects, double rho) const;
  // "side 10", "sides per N", "footprint 0.05 (>= 8 m)": for the rows and the plots.
  std::string describe() const;
};

struct SweepFile {
  std::string name;  // file-name safe: it names the output
  std::string description;
  // `role`: "tuning" (behaviour changes are measured on its seeds) or "test" (it carries claims;
  // its base seed no change was measured on); "" when the file does not say.
  std::string role;
  std::string source;  // the file it was read from
  // Checked against the method registry by the caller. An entry "NAME@K" runs method NAME with
  // its own budget of K motion queries (MethodEntry), so the same planner can run at several
  // budgets in one sweep; the rows' method column keeps the entry as written.
  std::vector<std::string> methods;
  std::vector<GoalClass> classes;
  // The task's order (`goal_orders`, default [chain]): a dimension of the cells for the methods
  // that follow the formula's order (rearm); a method that solves the final arrangement in any
  // order (the baselines) runs once per instance, in its `any` cell when the list has it.
  std::vector<GoalOrder> goal_orders = {GoalOrder::kChain};
  std::vector<int> objects;
  // Class constructive's scatter moves K (`scatter_moves`, default [0]: K = 2N), a dimension of
  // that class's cells only; each value in [0, kMaxScatterMovesPerObject · N] for every N.
  std::vector<int> scatter_moves = {0};
  std::vector<double> densities;  // target obstacle densities
  WorkspaceRule workspace;
  // The objects' footprint densities, a grid dimension (`footprint_densities`): each a
  // kFootprint rule with workspace.min_side. Empty: the workspace rule alone.
  std::vector<double> footprints;
  std::vector<double> unknown_fractions;  // probability that an obstacle is unknown
  std::vector<bool> round_unknown;        // unknown shapes: true = ellipses, false = polygons
  int seeds = 10;                         // repetitions per cell
  double time_limit = 10;                 // s of planning per baseline trial
  long query_limit = 0;                   // the baselines' motion queries per trial (0: none)
  std::uint64_t base_seed = 0;
  InstanceSpec instance;  // the generator's other settings (radii, region side, ...)
  // `refused_cells: skip`: a cell the generator cannot give its target density (cell_check.h
  // of the experiment layer) is left out and listed; `error` (the default) stops the sweep.
  bool skip_refused_cells = false;

  // scatter_moves for class constructive, {0} for the others.
  std::vector<int> scatter_moves_of(GoalClass c) const;
  // The workspace rule of each footprint, in file order, or the one rule.
  std::vector<WorkspaceRule> workspaces() const;
  // Cells × repetitions × methods, a method that ignores the order (follows_order false) counted
  // once per instance; without follows_order every method follows it (an upper bound).
  std::size_t trial_count(
      const std::function<bool(const std::string& method)>& follows_order = {}) const;
};

// A methods entry: the method's registry name and, for "NAME@K", its own query budget.
struct MethodEntry {
  std::string method;
  std::optional<long> query_limit;
};
// Splits an entry; throws rearm::Error for an empty name or a budget that is not an integer in
// [1, kMaxQueryLimit].
MethodEntry method_entry(const std::string& entry);

// Bounds of the format (experiments/sweeps/README.md).
inline constexpr int kMaxSweepSeeds = 100000;
inline constexpr double kMaxTrialTimeLimit = 3600;  // s
inline constexpr int kMaxQueryLimit = 100'000'000;
inline constexpr std::size_t kMaxSweepTrials = 10'000'000;
// m: the generator's largest workspace side; a footprint rule that gives more is rejected.
inline constexpr double kMaxSweepSide = 100;

// Reads and validates a sweep file; throws ScenarioError(file, key, reason) for a missing or
// unreadable file, malformed YAML, an unknown or repeated key, a missing required key, a value
// of the wrong type or outside its range, an empty or repeated list entry, an unknown goal class
// or shape, and a sweep of more than kMaxSweepTrials trials.
SweepFile load_sweep_file(const std::string& path);
SweepFile parse_sweep_file(const std::string& yaml, const std::string& source = "<string>");

}  // namespace rearm::scenario
