#include "experiment/sweep_plan.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <functional>
#include <string>
#include <system_error>

#include "core/error.h"
#include "core/rng.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

constexpr int kMaxShards = 100000;

// Rng::derive streams, disjoint by their top byte.
constexpr std::uint64_t kInstanceStream = 0x01ULL << 56;

int parse_int(const std::string& text, const std::string& whole) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    throw Error("--shard expects I/N with whole numbers, got '" + whole + "'");
  }
  return v;
}

scenario::InstanceSpec cell_spec(const scenario::SweepFile& f, const scenario::WorkspaceRule& w,
                                 scenario::GoalClass c, int n, double density, double unknown,
                                 bool round) {
  scenario::InstanceSpec spec = f.instance;
  spec.goal_class = c;
  spec.objects = n;
  spec.obstacle_density = density;
  spec.unknown_fraction = unknown;
  spec.round_unknown = round;
  spec.width = spec.height = w.side_for(n, spec.object_radius);
  return spec;
}

}  // namespace

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::uint64_t instance_seed(std::uint64_t base_seed, int objects, int rep) {
  const std::uint64_t stream = kInstanceStream | (static_cast<std::uint64_t>(objects) << 32) |
                               static_cast<std::uint32_t>(rep);
  return Rng::derive(base_seed, stream).next() >> 1;
}

std::uint64_t planner_seed(std::uint64_t instance, const std::string& method) {
  return Rng::derive(instance, fnv1a("method=" + method)).next() >> 1;
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) throw Error("--shard expects I/N, got '" + text + "'");
  Shard s{parse_int(text.substr(0, slash), text), parse_int(text.substr(slash + 1), text)};
  if (s.count < 1 || s.count > kMaxShards || s.index < 0 || s.index >= s.count) {
    throw Error("--shard I/N needs 0 <= I < N <= " + std::to_string(kMaxShards) + ", got '" + text +
                "'");
  }
  return s;
}

std::string to_string(const Shard& s) {
  return std::to_string(s.index) + "/" + std::to_string(s.count);
}

// The cell's name: the generator's "random_<class>_n<N>_s<seed>" is shared by the cells of one
// N, which share their seeds; this one says what the cell was.
std::string cell_name(const InstanceJob& job) {
  const scenario::InstanceSpec& s = job.spec;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s_n%d_d%g_side%g_u%g_%s", scenario::to_string(s.goal_class),
                s.objects, s.obstacle_density, s.width, s.unknown_fraction,
                s.round_unknown ? "round" : "polygon");
  std::string name = buf;
  if (s.goal_order == scenario::GoalOrder::kAny) name += "_any";  // chain: the name as before
  if (s.goal_class == scenario::GoalClass::kConstructive && s.scatter_moves != 0) {
    name += "_k" + std::to_string(s.scatter_moves);  // 0 (K = 2N): none
  }
  for (char& c : name) {
    if (c == '+') c = 'p';
  }
  return name;
}

std::string instance_name(const InstanceJob& job) {
  return cell_name(job) + "_r" + std::to_string(job.rep);
}

SweepPlan plan_sweep(const scenario::SweepFile& f, const MethodRegistry& methods) {
  for (std::size_t i = 0; i < f.methods.size(); ++i) {
    if (!methods.contains(scenario::method_entry(f.methods[i]).method)) {
      std::string known;
      for (const auto& m : methods.names()) known += (known.empty() ? "" : ", ") + m;
      throw scenario::ScenarioError(f.source, "methods[" + std::to_string(i) + "]",
                                    "unknown method '" + f.methods[i] + "' (known: " + known + ")");
    }
  }
  SweepPlan plan;
  plan.name = f.name;
  const std::vector<scenario::WorkspaceRule> workspaces = f.workspaces();
  // A method that ignores the order runs once per geometry: in the `any` cell when the sweep
  // has one, else in each (then its only) order's cell.
  const bool has_any = std::find(f.goal_orders.begin(), f.goal_orders.end(),
                                 scenario::GoalOrder::kAny) != f.goal_orders.end();
  for (const scenario::GoalClass c : f.classes)
    for (const int k : f.scatter_moves_of(c))
      for (const int n : f.objects)
        for (const scenario::WorkspaceRule& w : workspaces)
          for (const double density : f.densities)
            for (const double unknown : f.unknown_fractions)
              for (const bool round : f.round_unknown)
                for (const scenario::GoalOrder order : f.goal_orders)
                  for (int rep = 0; rep < f.seeds; ++rep) {
                    InstanceJob job;
                    job.index = plan.instances.size();
                    job.cell = job.index / static_cast<std::size_t>(f.seeds);
                    job.spec = cell_spec(f, w, c, n, density, unknown, round);
                    job.spec.scatter_moves = k;
                    job.spec.goal_order = order;
                    job.spec.seed = instance_seed(f.base_seed, n, rep);  // the same for each order
                    job.rep = rep;
                    job.workspace_rule = w.describe();
                    for (const std::string& m : f.methods) {
                      // "NAME@K": its own budget; the seed is NAME's, so one planner at two budgets
                      // runs the same search, cut at two points.
                      const scenario::MethodEntry e = scenario::method_entry(m);
                      const bool follows = methods.get(e.method).follows_task_order();
                      if (has_any && order != scenario::GoalOrder::kAny && !follows) continue;
                      TrialJob t;
                      t.index = plan.trials.size();
                      t.instance = job.index;
                      t.settings = TrialSettings{m,
                                                 job.spec,
                                                 rep,
                                                 job.workspace_rule,
                                                 planner_seed(job.spec.seed, e.method),
                                                 f.time_limit,
                                                 e.query_limit.value_or(f.query_limit),
                                                 follows ? scenario::to_string(order) : "any"};
                      plan.trials.push_back(std::move(t));
                    }
                    plan.instances.push_back(std::move(job));
                  }
  plan.total_trials = plan.trials.size();
  return plan;
}

SweepPlan subset_of(const SweepPlan& plan, const std::function<bool(const InstanceJob&)>& keep) {
  SweepPlan out;
  out.name = plan.name;
  out.total_trials = plan.total_trials;
  std::vector<std::size_t> position(plan.instances.size(), plan.instances.size());
  for (std::size_t i = 0; i < plan.instances.size(); ++i) {
    if (!keep(plan.instances[i])) continue;
    position[i] = out.instances.size();
    out.instances.push_back(plan.instances[i]);
  }
  for (const TrialJob& t : plan.trials) {
    if (position[t.instance] == plan.instances.size()) continue;
    TrialJob copy = t;
    copy.instance = position[t.instance];
    out.trials.push_back(std::move(copy));
  }
  return out;
}

SweepPlan shard_of(const SweepPlan& plan, const Shard& shard) {
  return subset_of(plan, [&](const InstanceJob& job) {
    return job.index % static_cast<std::size_t>(shard.count) ==
           static_cast<std::size_t>(shard.index);
  });
}

}  // namespace rearm::experiment
