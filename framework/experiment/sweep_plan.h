// A sweep file expanded into its instances and trials (experiments/sweeps/README.md):
// cells = classes × object counts × workspaces (footprints) × target densities × unknown
// fractions × unknown shapes × goal orders, each with `seeds` repetitions (one instance each),
// each instance run by every method (one trial each) but that a method which ignores the order
// (Method::follows_task_order false) runs only the `any` cell's instance when there is one. Indices
// are canonical (that order), so a trial's index, seeds and settings depend on the sweep file alone
// — not on the thread count, the shard or the order trials finish in.
//
// Seeds (house style: every draw from a seeded generator): an instance's seed is derived from (base
// seed, N, repetition) only, so that the cells of one N share their random draws (common random
// numbers): the same object starts, goals and robot in every class, goal order, density and
// shape mix —
// the generator keeps one random stream per placement stage — and the comparisons between
// densities or classes are paired. A trial's planner seed is derived from (instance seed,
// method name).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "experiment/method.h"
#include "experiment/trial.h"
#include "scenario/sweep_file.h"

namespace rearm::experiment {

struct InstanceJob {
  std::size_t index = 0;  // canonical instance index
  std::size_t cell = 0;   // canonical cell index: the cell's instances are its `seeds` reps
  scenario::InstanceSpec spec;
  int rep = 0;
  std::string workspace_rule;
};

struct TrialJob {
  std::size_t index = 0;     // canonical trial index
  std::size_t instance = 0;  // position in SweepPlan::instances
  TrialSettings settings;
};

struct SweepPlan {
  std::string name;
  std::size_t total_trials = 0;  // of the whole sweep, whatever the shard
  std::vector<InstanceJob> instances;
  std::vector<TrialJob> trials;
};

// Deterministic partition for several machines: shard `index` of `count` runs the instances
// whose canonical index is index (mod count), with all their methods.
struct Shard {
  int index = 0;
  int count = 1;
};
// "I/N" with 0 <= I < N <= 100000; throws rearm::Error otherwise.
Shard parse_shard(const std::string& text);
std::string to_string(const Shard& s);

// Expands the sweep. Throws scenario::ScenarioError(source, "methods[i]", ...) for a method the
// registry does not know.
SweepPlan plan_sweep(const scenario::SweepFile& f, const MethodRegistry& methods);
// The part of the plan one shard runs.
SweepPlan shard_of(const SweepPlan& plan, const Shard& shard);
// The plan's instances that `keep` accepts, with their trials (canonical indices kept).
SweepPlan subset_of(const SweepPlan& plan, const std::function<bool(const InstanceJob&)>& keep);

// The cell's name, e.g. "cyclic_n8_d0.05_side5.6_u0.5_round" (class, N, target density,
// workspace side, unknown fraction and shapes), and the instance's: the cell's with "_r<rep>",
// unique within the sweep (the name of its file under DIR/instances).
std::string cell_name(const InstanceJob& job);
std::string instance_name(const InstanceJob& job);

// The derivations above, exposed for tests.
std::uint64_t instance_seed(std::uint64_t base_seed, int objects, int rep);
std::uint64_t planner_seed(std::uint64_t instance_seed, const std::string& method);
// FNV-1a 64 of the text (stable across platforms).
std::uint64_t fnv1a(const std::string& text);

}  // namespace rearm::experiment
