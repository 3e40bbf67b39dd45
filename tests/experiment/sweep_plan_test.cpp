// Expanding a sweep (experiment/sweep_plan.h): the canonical order and counts, seeds that
// depend on (base seed, N, repetition) only, shards that partition the trials exactly, and
// unknown methods rejected with the key.
#include "experiment/sweep_plan.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "experiment/rearm_method.h"
#include "experiment/trial_columns.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

class Stub final : public Method {
 public:
  explicit Stub(std::string n) : n_(std::move(n)) {}
  std::string name() const override { return n_; }
  std::string summary() const override { return "stub"; }
  TrialOutcome run(const scenario::Scenario&, const MethodInput&) const override { return {}; }

 private:
  std::string n_;
};

MethodRegistry registry() {
  MethodRegistry r;
  r.add(make_rearm_method());
  r.add(std::make_unique<Stub>("birrt"));
  return r;
}

scenario::SweepFile file() {
  return scenario::parse_sweep_file(
      "name: p\nmethods: [rearm, birrt]\nclasses: [random, cyclic, sealed]\nobjects: [1, 3]\n"
      "densities: [0.05, 0.3]\nworkspace: {sides: [[1, 7], [3, 9]]}\nunknown_shapes: "
      "[round, polygon]\nseeds: 4\ntime_limit: 3\nbase_seed: 11\n");
}

TEST(SweepPlan, ExpandsCellsRepetitionsAndMethodsInCanonicalOrder) {
  const SweepPlan p = plan_sweep(file(), registry());
  EXPECT_EQ(p.instances.size(), 3u * 2 * 2 * 2 * 4);
  EXPECT_EQ(p.trials.size(), p.instances.size() * 2);
  EXPECT_EQ(p.total_trials, p.trials.size());
  for (std::size_t i = 0; i < p.trials.size(); ++i) {
    const TrialJob& t = p.trials[i];
    EXPECT_EQ(t.index, i);
    EXPECT_EQ(t.instance, i / 2);
    EXPECT_EQ(t.settings.method, i % 2 == 0 ? "rearm" : "birrt");
    EXPECT_EQ(t.settings.time_limit_s, 3);
    const scenario::InstanceSpec& s = t.settings.instance;
    EXPECT_EQ(s.width, s.objects == 1 ? 7 : 9);
    EXPECT_EQ(s.seed, instance_seed(11, s.objects, t.settings.rep));
    EXPECT_EQ(t.settings.planner_seed, planner_seed(s.seed, t.settings.method));
  }
  // Common random numbers: one seed per (N, repetition), shared by every class and density.
  std::map<std::pair<int, int>, std::set<std::uint64_t>> seeds;
  std::set<std::uint64_t> all;
  for (const InstanceJob& j : p.instances) {
    seeds[{j.spec.objects, j.rep}].insert(j.spec.seed);
    all.insert(j.spec.seed);
  }
  for (const auto& [cell, s] : seeds) EXPECT_EQ(s.size(), 1u);
  EXPECT_EQ(all.size(), 2u * 4);
  EXPECT_NE(instance_seed(11, 3, 0), instance_seed(12, 3, 0));
}

TEST(SweepPlan, ShardsPartitionTheTrials) {
  const SweepPlan p = plan_sweep(file(), registry());
  for (int count : {1, 2, 3, 7, 200}) {
    std::multiset<std::size_t> seen;
    for (int i = 0; i < count; ++i) {
      const SweepPlan s = shard_of(p, Shard{i, count});
      EXPECT_EQ(s.total_trials, p.total_trials);
      for (const TrialJob& t : s.trials) {
        seen.insert(t.index);
        // Both methods of an instance in the same shard, with the instance it names.
        EXPECT_EQ(s.instances[t.instance].index, p.trials[t.index].instance);
        EXPECT_EQ(key_column(t.settings), key_column(p.trials[t.index].settings));
      }
    }
    EXPECT_EQ(seen.size(), p.trials.size());
    for (std::size_t i = 0; i < p.trials.size(); ++i) EXPECT_EQ(seen.count(i), 1u) << i;
  }
  EXPECT_EQ(parse_shard("2/5").index, 2);
  EXPECT_EQ(parse_shard("2/5").count, 5);
  for (const char* bad : {"5/5", "-1/3", "1", "a/3", "1/0", "1/3x", "/"}) {
    EXPECT_THROW(parse_shard(bad), Error) << bad;
  }
}

// "NAME@K": method NAME with its own budget of K queries; the row keeps the entry as its
// method, the planner seed is NAME's (one search, cut at two budgets).
TEST(SweepPlan, MethodEntriesCarryTheirOwnBudget) {
  const SweepPlan p =
      plan_sweep(scenario::parse_sweep_file("name: b\nmethods: [birrt, birrt@1000, birrt@10000]\n"
                                            "classes: [random]\nobjects: [2]\ndensities: [0.05]\n"
                                            "workspace: {side: 8}\nseeds: 1\nquery_limit: 500\n"),
                 registry());
  ASSERT_EQ(p.trials.size(), 3u);
  EXPECT_EQ(p.trials[0].settings.query_limit, 500);
  EXPECT_EQ(p.trials[1].settings.query_limit, 1000);
  EXPECT_EQ(p.trials[2].settings.query_limit, 10000);
  EXPECT_EQ(p.trials[2].settings.method, "birrt@10000");
  EXPECT_EQ(p.trials[1].settings.planner_seed, p.trials[0].settings.planner_seed);
  EXPECT_NE(key_column(p.trials[1].settings), key_column(p.trials[2].settings));
  for (const char* bad : {"birrt@", "birrt@0", "birrt@x", "@100", "birrt@1e3", "birrt@-5"}) {
    EXPECT_THROW(scenario::method_entry(bad), Error) << bad;
  }
  scenario::SweepFile f = file();
  f.methods.push_back("rrtstar@100");  // the name is checked without its budget
  EXPECT_THROW(plan_sweep(f, registry()), scenario::ScenarioError);
}

// A footprint list of one value plans the very trials of the single footprint rule (same keys,
// seeds and sides), so committed sweeps keep their rows; a longer list adds cells after the
// object count, each footprint's instances sharing the seeds of their N.
TEST(SweepPlan, FootprintDensitiesAddCellsAndKeepTheSingleRulesTrials) {
  const std::string head =
      "name: f\nmethods: [rearm, birrt]\nclasses: [random, cyclic]\nobjects: [2, 8]\n"
      "densities: [0.05]\nseeds: 3\n";
  const SweepPlan one = plan_sweep(
      scenario::parse_sweep_file(head + "workspace: {footprint_density: 0.05}\n"), registry());
  const SweepPlan list =
      plan_sweep(scenario::parse_sweep_file(head + "footprint_densities: [0.05]\n"), registry());
  ASSERT_EQ(one.trials.size(), list.trials.size());
  for (std::size_t k = 0; k < one.trials.size(); ++k) {
    EXPECT_EQ(key_column(one.trials[k].settings), key_column(list.trials[k].settings));
    EXPECT_EQ(one.trials[k].settings.workspace_rule, list.trials[k].settings.workspace_rule);
  }
  const SweepPlan three = plan_sweep(
      scenario::parse_sweep_file(head + "footprint_densities: [0.01, 0.05, 0.1]\n"), registry());
  ASSERT_EQ(three.trials.size(), 3 * one.trials.size());
  std::map<std::pair<int, int>, std::set<std::uint64_t>> seeds;  // (N, rep) -> instance seeds
  std::set<double> sides;
  for (const InstanceJob& j : three.instances) {
    seeds[{j.spec.objects, j.rep}].insert(j.spec.seed);
    sides.insert(j.spec.width);
  }
  for (const auto& [cell, s] : seeds) EXPECT_EQ(s.size(), 1u);
  EXPECT_EQ(sides.size(), 6u);  // two N x three footprints
  // The first cell: random goals, N = 2, footprint 0.01, its three repetitions.
  EXPECT_EQ(three.instances[0].workspace_rule, "footprint 0.01");
  EXPECT_EQ(three.instances[3].workspace_rule, "footprint 0.05");
  EXPECT_EQ(three.instances[3].spec.objects, 2);
}

// goal_orders [chain, any]: a cell per order, the same geometry (instance seed) in both;
// rearm runs both, a method that ignores the order (the stub) only the `any` instance, its row
// saying "any"; the chain cell keeps the name and key of a sweep without the dimension.
TEST(SweepPlan, GoalOrdersMultiplyOnlyTheOrderFollowingMethods) {
  const std::string head =
      "name: p\nmethods: [rearm, birrt]\nclasses: [cyclic]\nobjects: [3]\ndensities: [0.05]\n"
      "workspace: {side: 8}\nseeds: 2\nbase_seed: 5\n";
  const SweepPlan chain = plan_sweep(scenario::parse_sweep_file(head), registry());
  const SweepPlan both =
      plan_sweep(scenario::parse_sweep_file(head + "goal_orders: [chain, any]\n"), registry());
  ASSERT_EQ(both.instances.size(), 4u);
  EXPECT_EQ(both.total_trials, 2u * 2 + 2);
  EXPECT_EQ(both.total_trials, scenario::parse_sweep_file(head + "goal_orders: [chain, any]\n")
                                   .trial_count([](const std::string& m) { return m == "rearm"; }));
  std::map<std::string, int> rows;  // method/goal_order -> trials
  for (const TrialJob& t : both.trials) {
    const InstanceJob& j = both.instances[t.instance];
    EXPECT_EQ(t.settings.instance.goal_order, j.spec.goal_order);
    if (t.settings.method == "birrt") {
      EXPECT_EQ(j.spec.goal_order, scenario::GoalOrder::kAny);
    }
    ++rows[t.settings.method + "/" + t.settings.goal_order];
  }
  EXPECT_EQ(rows,
            (std::map<std::string, int>{{"birrt/any", 2}, {"rearm/any", 2}, {"rearm/chain", 2}}));
  for (int rep = 0; rep < 2; ++rep) {
    const InstanceJob& c = both.instances[static_cast<std::size_t>(rep)];
    const InstanceJob& a = both.instances[static_cast<std::size_t>(2 + rep)];
    EXPECT_EQ(c.spec.seed, a.spec.seed);  // one geometry, two tasks
    EXPECT_EQ(cell_name(a), cell_name(c) + "_any");
    EXPECT_EQ(instance_name(c), instance_name(chain.instances[static_cast<std::size_t>(rep)]));
    auto rearm_trial = [](const SweepPlan& p, std::size_t instance) {
      for (const TrialJob& t : p.trials) {
        if (t.instance == instance && t.settings.method == "rearm") return t.settings;
      }
      return TrialSettings{};
    };
    EXPECT_EQ(resume_key(rearm_trial(both, c.index)), resume_key(rearm_trial(chain, c.index)));
    EXPECT_NE(resume_key(rearm_trial(both, a.index)), resume_key(rearm_trial(chain, c.index)));
  }
  // Without `any`, the baseline runs the chain cell; its row still says "any".
  EXPECT_EQ(chain.trials[1].settings.method, "birrt");
  EXPECT_EQ(chain.trials[1].settings.goal_order, "any");
  EXPECT_EQ(chain.trials[0].settings.goal_order, "chain");
}

TEST(SweepPlan, UnknownMethodsNameTheirKey) {
  scenario::SweepFile f = file();
  f.methods.push_back("rrtstar");
  try {
    plan_sweep(f, registry());
    FAIL();
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.key(), "methods[2]");
    EXPECT_NE(e.reason().find("known: rearm, birrt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rearm::experiment
