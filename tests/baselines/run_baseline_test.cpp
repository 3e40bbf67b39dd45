// Baseline trials end to end: plans executed in the same Box2D world as
// rearm's runs, with the outcome judged on the simulator's final object positions against the
// scenario file's region polygons (exact point location), not on the planner's own account.
#include "baselines/run_baseline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "experiment/run_scenario.h"
#include "scenario/scenario_io.h"

namespace rearm::baselines {
namespace {

scenario::Scenario load(const std::string& name) {
  return scenario::load_scenario("experiments/scenarios/" + name + ".yaml");
}

BaselineRecord trial(const scenario::Scenario& s, Method m, std::uint64_t seed = 1,
                     double limit = 60) {
  BaselineOptions o;
  o.method = m;
  o.seed = seed;
  o.time_limit = limit;
  return run_baseline(s, o);
}

// Every release(M, l) of the task: M's simulated final centre lies in l's polygon.
void expect_released_in_regions(const scenario::Scenario& s, const BaselineRecord& r) {
  ASSERT_TRUE(r.executed);
  const auto& end = r.execution.objects_end;
  ASSERT_EQ(end.size(), s.objects.size());
  const std::regex release(R"(release\((\w+),(\w+)\))");
  int checked = 0;
  for (std::sregex_iterator it(s.task.begin(), s.task.end(), release), stop; it != stop; ++it) {
    const std::string object = (*it)[1], region = (*it)[2];
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      if (s.objects[i].name != object) continue;
      for (const auto& g : s.regions) {
        if (g.name != region) continue;
        EXPECT_TRUE(geometry::contains(g.polygon, end[i]))
            << object << " ends at (" << end[i].x() << ", " << end[i].y() << "), outside "
            << region;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(RunBaseline, MonotoneInstanceByB1AndB2InBox2d) {
  const auto s = load("monotone");
  for (Method m : {Method::kMrs, Method::kBirrt}) {
    const BaselineRecord r = trial(s, m);
    EXPECT_EQ(r.status, "completed") << to_string(m) << ": " << r.reason;
    EXPECT_TRUE(r.violations.empty());
    EXPECT_EQ(r.execution.collisions, 0) << to_string(m);
    EXPECT_GE(r.execution.min_clearance, 0) << to_string(m);
    EXPECT_EQ(r.plan.moves.size(), 3u) << to_string(m);
    expect_released_in_regions(s, r);
    // grasp and release per move, each succeeded.
    ASSERT_EQ(r.execution.actions.size(), 6u);
    for (const auto& a : r.execution.actions) EXPECT_EQ(a.outcome, "succeeded") << a.action;
  }
}

TEST(RunBaseline, Fig5CyclicB1ReportsNonMonotoneB2Solves) {
  const auto s = load("fig5");
  const BaselineRecord b1 = trial(s, Method::kMrs);
  EXPECT_EQ(b1.status, "infeasible");
  EXPECT_NE(b1.reason.find("non-monotone"), std::string::npos) << b1.reason;
  EXPECT_FALSE(b1.executed);
  EXPECT_EQ(b1.subqueries, 0);  // the proof needs no sampling
  const BaselineRecord b2 = trial(s, Method::kBirrt);
  EXPECT_EQ(b2.status, "completed") << b2.reason;
  EXPECT_EQ(b2.execution.collisions, 0);
  EXPECT_GE(b2.plan.moves.size(), 4u);
  expect_released_in_regions(s, b2);
  // An offline planner acts once its whole plan is found: its first act comes after all of its
  // planning; B1, which proved the instance non-monotone, never acted.
  EXPECT_EQ(b2.first_action_time_s, b2.planning_time_s);
  EXPECT_GT(b2.first_action_time_s, 0);
  EXPECT_TRUE(std::isnan(b1.first_action_time_s));
}

TEST(RunBaseline, ReplanningNoticesTheUnknownWall) {
  const auto s = load("discovery");
  const BaselineRecord offline = trial(s, Method::kBirrt);
  EXPECT_EQ(offline.status, "completed") << offline.reason;
  EXPECT_EQ(offline.replans, 0);
  const BaselineRecord r = trial(s, Method::kReplan);
  EXPECT_EQ(r.status, "completed") << r.reason;
  EXPECT_GE(r.replans, 1);  // the first plan runs through C1, which it could not see
  EXPECT_EQ(r.execution.collisions, 0);
  // It acts on its first plan: before the replans' planning.
  EXPECT_GT(r.first_action_time_s, 0);
  EXPECT_LT(r.first_action_time_s, r.planning_time_s);
  expect_released_in_regions(s, r);
  // Replanning on the full-knowledge instance Fig. 5 also completes.
  const BaselineRecord f = trial(load("fig5"), Method::kReplan);
  EXPECT_EQ(f.status, "completed") << f.reason;
  EXPECT_EQ(f.execution.collisions, 0);
}

std::string untimed(const std::string& metrics) {
  static const std::regex timing(
      R"re(\n\s*"(wall_time_s|controller_time_s|first_action_time_s|planning_time_s|planning_wall_s|real_time_factor)": [^\n]*)re");
  return std::regex_replace(metrics, timing, "");
}

TEST(RunBaseline, SameSeedSameMetricsApartFromTiming) {
  const auto s = load("fig5");
  const std::string a = baseline_metrics_json(s, trial(s, Method::kBirrt, 9));
  const std::string b = baseline_metrics_json(s, trial(s, Method::kBirrt, 9));
  EXPECT_EQ(untimed(a), untimed(b));
  EXPECT_NE(a.find("\"planning_time_s\""), std::string::npos);
}

// A baseline solves the final arrangement in any order, so the task's goal order does not
// change its trial: fig5's chain and the same goals written in any order (independent truth:
// the order is read by no baseline) give the same metrics apart from timing, for BiRRT and the
// replanning variant. This is why a sweep runs a baseline once per instance.
TEST(RunBaseline, TheTasksOrderDoesNotChangeABaselineTrial) {
  const auto chain = load("fig5");
  auto any = chain;
  any.task = "<>release(M1,l2) && <>release(M2,l3) && <>release(M3,l1)";
  const std::regex task(R"re(\n\s*"task": [^\n]*)re");  // the one field that names the order
  for (const Method m : {Method::kBirrt, Method::kReplan}) {
    EXPECT_EQ(
        std::regex_replace(untimed(baseline_metrics_json(chain, trial(chain, m, 4))), task, ""),
        std::regex_replace(untimed(baseline_metrics_json(any, trial(any, m, 4))), task, ""));
  }
}

// The query budget (BaselineOptions::query_limit) ends B2 on the unsolvable pocket instance
// before its generous time limit: status unsolved with the budget named, exactly the budget's
// queries spent, and the same search (nodes, subqueries) in two runs, as the sweeps need.
TEST(RunBaseline, QueryLimitEndsTheSearchTheSameWayEveryTime) {
  const auto s = load("pocket");
  for (const Method m : {Method::kBirrt}) {
    BaselineOptions o;
    o.method = m;
    o.seed = 3;
    // Generous: a sanitized Debug build spends about 2 s per query on this instance.
    o.time_limit = 1000;
    o.query_limit = 10;
    const BaselineRecord a = run_baseline(s, o);
    const BaselineRecord b = run_baseline(s, o);
    EXPECT_EQ(a.status, "unsolved") << to_string(m) << ": " << a.reason;
    EXPECT_NE(a.reason.find("query limit of 10"), std::string::npos) << a.reason;
    EXPECT_EQ(a.queries, 10) << to_string(m);
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.subqueries, b.subqueries);
    EXPECT_EQ(a.reason, b.reason);
    EXPECT_TRUE(std::isnan(a.first_action_time_s)) << "no plan, no act";
  }
  BaselineOptions bad;
  bad.query_limit = -1;
  EXPECT_THROW(run_baseline(s, bad), Error);
}

TEST(RunBaseline, MetricsCarryEveryKeyOfRearmRun) {
  const auto s = load("fig3");
  experiment::RunOptions o;
  o.plant = experiment::PlantKind::kKinematic;
  o.record = false;
  const std::string rearm = experiment::metrics_json(s, experiment::run_scenario(s, o));
  const auto fig5 = load("fig5");
  const std::string base = baseline_metrics_json(fig5, trial(fig5, Method::kBirrt));
  nlohmann::json rearm_keys = nlohmann::json::parse(rearm);
  nlohmann::json base_keys = nlohmann::json::parse(base);
  for (const auto& [k, v] : rearm_keys.items()) EXPECT_TRUE(base_keys.contains(k)) << k;
  EXPECT_GE(rearm_keys.size(), 15u);
  for (const char* extra : {"planning_time_s", "subqueries", "nodes", "method", "replans"})
    EXPECT_TRUE(base_keys.contains(extra)) << extra;
}

TEST(RunBaseline, BadOptionsAndTasksAreClearErrors) {
  const auto s = load("fig5");
  BaselineOptions o;
  for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    o.time_limit = bad;
    EXPECT_THROW(run_baseline(s, o), Error) << bad;
  }
  EXPECT_THROW(method_from_string("prm"), Error);
  EXPECT_EQ(method_from_string("replan"), Method::kReplan);
  o.time_limit = 1;
  EXPECT_THROW(run_baseline(load("patrol"), o), scenario::ScenarioError);
}

}  // namespace
}  // namespace rearm::baselines
