// Sweep files (scenario/sweep_file.h): a complete file read field by field, defaults, the
// workspace rules, and bad input rejected with the file, the key and the reason.
#include "scenario/sweep_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scenario/scenario_io.h"

namespace rearm::scenario {
namespace {

const char* const kFull = R"(name: study
description: "a study"
methods: [rearm, birrt]
classes: [random, sealed]
objects: [1, 4, 16]
densities: [0.05, 0.35]
workspace: {sides: [[1, 6], [4, 8], [16, 14]]}
unknown_fraction: [0.5, 0]
unknown_shapes: [round, polygon]
seeds: 3
time_limit: 2.5
query_limit: 5000
base_seed: 18446744073709551615
instance: {robot_radius: 0.25, object_radius: 0.3, region_side: 1.2, passage_margin: 0.1}
)";

TEST(SweepFile, ReadsEveryKey) {
  const SweepFile f = parse_sweep_file(kFull, "study.yaml");
  EXPECT_EQ(f.name, "study");
  EXPECT_EQ(f.methods, (std::vector<std::string>{"rearm", "birrt"}));
  EXPECT_EQ(f.classes, (std::vector<GoalClass>{GoalClass::kRandom, GoalClass::kSealed}));
  EXPECT_EQ(f.objects, (std::vector<int>{1, 4, 16}));
  EXPECT_EQ(f.densities, (std::vector<double>{0.05, 0.35}));
  EXPECT_EQ(f.workspace.side_for(4, 0.3), 8);
  EXPECT_THROW(f.workspace.side_for(2, 0.3), Error);
  EXPECT_EQ(f.unknown_fractions, (std::vector<double>{0.5, 0}));
  EXPECT_EQ(f.round_unknown, (std::vector<bool>{true, false}));
  EXPECT_EQ(f.seeds, 3);
  EXPECT_EQ(f.time_limit, 2.5);
  EXPECT_EQ(f.query_limit, 5000);
  EXPECT_EQ(f.base_seed, 18446744073709551615ULL);
  EXPECT_EQ(f.instance.robot_radius, 0.25);
  EXPECT_EQ(f.instance.object_radius, 0.3);
  EXPECT_EQ(f.instance.passage_margin, 0.1);
  // 2 classes x 3 N x 2 densities x 2 fractions x 2 shapes x 3 seeds x 2 methods.
  EXPECT_EQ(f.trial_count(), 2u * 3 * 2 * 2 * 2 * 3 * 2);
}

TEST(SweepFile, DefaultsAndTheFootprintRule) {
  const SweepFile f = parse_sweep_file(
      "name: s\nmethods: rearm\nclasses: cyclic\nobjects: [8]\ndensities: 0.1\n"
      "workspace: {footprint_density: 0.05, min_side: 9}\n");
  EXPECT_EQ(f.seeds, 10);
  EXPECT_EQ(f.time_limit, 10);
  EXPECT_EQ(f.query_limit, 0);
  EXPECT_EQ(f.base_seed, 0u);
  EXPECT_EQ(f.unknown_fractions, (std::vector<double>{0.5}));
  EXPECT_EQ(f.round_unknown, (std::vector<bool>{true}));
  // Side s with N π ρ² / s² = 0.05 (ρ = 0.25): 8 objects → sqrt(8 π 0.0625 / 0.05) = 5.60 m,
  // below the 9 m floor; 64 objects → 15.85 m.
  EXPECT_EQ(f.workspace.side_for(8, 0.25), 9);
  const double side = f.workspace.side_for(64, 0.25);
  EXPECT_NEAR(64 * std::numbers::pi * 0.0625 / (side * side), 0.05, 1e-12);
}

void expect_error(const std::string& yaml, const std::string& key, const std::string& reason) {
  try {
    parse_sweep_file(yaml, "bad.yaml");
    FAIL() << "accepted:\n" << yaml;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.source(), "bad.yaml");
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

const std::string kBase =
    "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [1]\ndensities: [0.1]\n";

// `footprint_densities`: one footprint rule per value, the side sqrt(N pi rho^2 / F) per cell
// (never below workspace.min_side), and the trials multiplied by the number of footprints.
TEST(SweepFile, FootprintDensitiesAreAGridDimension) {
  const std::string head =
      "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [4, 8]\ndensities: [0.1]\n";
  const SweepFile f = parse_sweep_file(
      head + "footprint_densities: [0.01, 0.05, 0.12]\nworkspace: {min_side: 3}\n");
  ASSERT_EQ(f.workspaces().size(), 3u);
  const double area = std::numbers::pi * 0.25 * 0.25;  // the default object radius
  EXPECT_NEAR(f.workspaces()[0].side_for(8, 0.25), std::sqrt(8 * area / 0.01), 1e-12);
  EXPECT_NEAR(f.workspaces()[1].side_for(8, 0.25), std::sqrt(8 * area / 0.05), 1e-12);
  EXPECT_EQ(f.workspaces()[2].side_for(4, 0.25), 3);  // sqrt(4 area / 0.12) = 2.6 m < 3 m
  EXPECT_EQ(f.workspaces()[2].describe(), "footprint 0.12 (>= 3 m)");
  EXPECT_EQ(f.trial_count(),
            3 * parse_sweep_file(head + "workspace: {footprint_density: 0.05}\n").trial_count());
  expect_error(kBase + "footprint_densities: [0.05]\nworkspace: {side: 8}\n", "workspace",
               "only give min_side");
  expect_error(kBase + "footprint_densities: [0.05, 0.05]\n", "footprint_densities[1]", "repeated");
  expect_error(kBase + "footprint_densities: [0.05, 0.5]\n", "footprint_densities[1]",
               "must be in");
  expect_error(kBase + "footprint_densities: [0]\n", "footprint_densities[0]", "must be in");
  expect_error(kBase + "footprint_densities: [0.05, 0.000001]\n", "footprint_densities",
               "gives a side of 443.");
}

// `scatter_moves`: the constructive class's K, a dimension of that class's cells only; each
// value at most kMaxScatterMovesPerObject times the smallest N (0: K = 2N).
TEST(SweepFile, ScatterMovesAreADimensionOfTheConstructiveClassOnly) {
  const std::string head =
      "name: s\nmethods: [birrt]\nclasses: [random, constructive]\nobjects: [2, 4]\n"
      "densities: [0.1]\nworkspace: {side: 8}\nseeds: 3\n";
  const SweepFile one = parse_sweep_file(head);
  EXPECT_EQ(one.scatter_moves, (std::vector<int>{0}));
  EXPECT_EQ(one.trial_count(), 3u * 2 * 2);
  const SweepFile two = parse_sweep_file(head + "scatter_moves: [0, 16]\n");
  EXPECT_EQ(two.scatter_moves_of(GoalClass::kConstructive), (std::vector<int>{0, 16}));
  EXPECT_EQ(two.scatter_moves_of(GoalClass::kRandom), (std::vector<int>{0}));
  EXPECT_EQ(two.trial_count(), 3u * 2 * (1 + 2));
  EXPECT_EQ(parse_sweep_file(head + "scatter_moves: 5\n").scatter_moves, (std::vector<int>{5}));
  expect_error(head + "scatter_moves: [0, 17]\n", "scatter_moves[1]", "in [0, 16]");
  expect_error(head + "scatter_moves: [-1]\n", "scatter_moves[0]", "in [0, 16]");
  expect_error(head + "scatter_moves: [4, 4]\n", "scatter_moves[1]", "repeated");
  expect_error(head + "scatter_moves: [two]\n", "scatter_moves[0]", "");
}

// `goal_orders`: the chain by default; a method that ignores the order is counted once per
// instance when the caller says which methods follow it.
TEST(SweepFile, GoalOrdersAreADimensionOfTheOrderFollowingMethods) {
  const std::string head =
      "name: s\nmethods: [rearm, birrt, rearm-paper]\nclasses: [random]\nobjects: [4]\n"
      "densities: [0.1]\nworkspace: {side: 8}\nseeds: 5\n";
  const SweepFile chain = parse_sweep_file(head);
  EXPECT_EQ(chain.goal_orders, (std::vector<GoalOrder>{GoalOrder::kChain}));
  const SweepFile both = parse_sweep_file(head + "goal_orders: [chain, any]\n");
  EXPECT_EQ(both.goal_orders, (std::vector<GoalOrder>{GoalOrder::kChain, GoalOrder::kAny}));
  auto rearm_only = [](const std::string& m) { return m.rfind("rearm", 0) == 0; };
  EXPECT_EQ(chain.trial_count(rearm_only), 5u * 3);
  EXPECT_EQ(both.trial_count(rearm_only), 5u * (2 * 2 + 1));
  EXPECT_EQ(both.trial_count(), 5u * 3 * 2);  // every method following: the upper bound
  expect_error(head + "goal_orders: [chain, anyy]\n", "goal_orders[1]", "unknown 'anyy'");
  expect_error(head + "goal_orders: [any, any]\n", "goal_orders[1]", "repeated");
  expect_error(head + "goal_orders: []\n", "goal_orders", "");
  // `role`: what the seeds are for.
  EXPECT_EQ(chain.role, "");
  EXPECT_EQ(parse_sweep_file(head + "role: test\n").role, "test");
  expect_error(head + "role: tuned\n", "role", "expected tuning or test");
}

TEST(SweepFile, BadInputNamesTheKey) {
  expect_error(kBase, "workspace", "required key is missing");
  expect_error(kBase + "workspace: {side: 10}\nseed: 3\n", "seed", "unknown key");
  expect_error(kBase + "workspace: {side: 1e400}\n", "workspace.side", "finite");
  expect_error(kBase + "workspace: {side: .nan}\n", "workspace.side", "finite");
  expect_error(kBase + "workspace: {side: 10, footprint_density: 0.1}\n", "workspace",
               "exactly one");
  expect_error(kBase + "workspace: {footprint_density: 0.9}\n", "workspace.footprint_density",
               "must be in");
  expect_error(kBase + "workspace: {sides: [[2, 8]]}\n", "workspace.sides", "no side for 1");
  // One object of radius 0.25 m at footprint 1e-6 needs a side of sqrt(pi 0.25^2 / 1e-6) = 443 m,
  // beyond the generator's 100 m (a bound the fuzz target checks); at 1e-4 it needs 44.3 m.
  expect_error(kBase + "workspace: {footprint_density: 0.000001}\n", "workspace.footprint_density",
               "gives a side of 443.");
  EXPECT_NEAR(parse_sweep_file(kBase + "workspace: {footprint_density: 0.0001}\n")
                  .workspace.side_for(1, 0.25),
              44.31, 0.01);
  expect_error(kBase + "workspace: {side: 10}\nseeds: 0\n", "seeds", "integer in");
  expect_error(kBase + "workspace: {side: 10}\ntime_limit: -1\n", "time_limit", "must be in");
  expect_error(kBase + "workspace: {side: 10}\nbase_seed: -1\n", "base_seed", "non-negative");
  expect_error(kBase + "workspace: {side: 10}\nquery_limit: -1\n", "query_limit", "integer in");
  expect_error(kBase + "workspace: {side: 10}\nunknown_shapes: square\n", "unknown_shapes",
               "round or polygon");
  expect_error(kBase + "workspace: {side: 10}\ninstance: {robot_radius: 0}\n",
               "instance.robot_radius", "must be in");
  expect_error(
      "name: s\nmethods: []\nclasses: [random]\nobjects: [1]\ndensities: [0.1]\n"
      "workspace: {side: 10}\n",
      "methods", "at least one");
  expect_error(
      "name: s\nmethods: [rearm]\nclasses: [spiral]\nobjects: [1]\ndensities: [0.1]\n"
      "workspace: {side: 10}\n",
      "classes[0]", "unknown");
  expect_error(
      "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [1, 1]\n"
      "densities: [0.1]\nworkspace: {side: 10}\n",
      "objects[1]", "repeated");
  expect_error(
      "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [1000]\n"
      "densities: [0.1]\nworkspace: {side: 10}\n",
      "objects[0]", "integer in");
  expect_error(
      "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [1]\n"
      "densities: [0.9]\nworkspace: {side: 10}\n",
      "densities[0]", "must be in");
  expect_error("name: a/b\n", "name", "file-name-safe");
  expect_error("name: [s\n", "line 2, column 1", "malformed YAML");
  expect_error("", "<document>", "empty");
  expect_error(kBase + "workspace: {side: 10}\nseeds: 100000\nobjects: [1]\n", "objects",
               "repeated key");
  expect_error(
      "name: s\nmethods: [rearm]\nclasses: [random]\nobjects: [1, 2, 3, 4]\n"
      "densities: [0, 0.1, 0.2, 0.3, 0.4]\nworkspace: {side: 10}\nseeds: 100000\n"
      "unknown_fraction: [0, 0.2, 0.4, 0.6, 0.8, 1]\n",
      "seeds", "more than");
  EXPECT_THROW(load_sweep_file("/nonexistent/sweep.yaml"), ScenarioError);
}

TEST(SweepFile, TheCommittedSweepFilesLoad) {
  for (const char* f : {"experiments/sweeps/smoke.yaml"}) {
    EXPECT_NO_THROW(load_sweep_file(f)) << f;
  }
}

}  // namespace
}  // namespace rearm::scenario
