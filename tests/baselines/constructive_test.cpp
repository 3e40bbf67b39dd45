// The constructive class against independent truth: every witness passes the baselines'
// validator (sampled disk clearances, not the planners' exact segment tests) on the instance as
// written, ends with every object inside its goal region (exact point location), and a sample
// runs in Box2D to the goal without a contact; objects start outside their own regions (every
// object moved when K >= N; with K < N exactly K of them, the others at their goal points);
// the same spec gives the same bytes; bad specs are refused with a clear error.
#include "baselines/constructive.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "baselines/executor.h"
#include "baselines/plan_json.h"
#include "baselines/validator.h"
#include "core/error.h"
#include "experiment/csv.h"
#include "experiment/sweep_runner.h"
#include "scenario/scenario_io.h"
#include "scenario/sweep_file.h"

namespace rearm::baselines {
namespace {

scenario::InstanceSpec spec(int n, double footprint, std::uint64_t seed, int k = 0) {
  scenario::InstanceSpec s;
  s.goal_class = scenario::GoalClass::kConstructive;
  s.objects = n;
  s.footprint_density = footprint;
  s.width = s.height = 10;
  s.obstacle_density = 0.05;
  s.seed = seed;
  s.scatter_moves = k;
  return s;
}

// Objects whose start lies inside their own goal region (exact point location).
int at_goal(const scenario::Scenario& s) {
  int n = 0;
  for (std::size_t i = 0; i < s.regions.size(); ++i)
    n += geometry::contains(s.regions[i].polygon, s.objects[i].disk.center) ? 1 : 0;
  return n;
}

void expect_valid(const ConstructiveInstance& c, int k) {
  const scenario::Scenario& s = c.instance.scenario;
  EXPECT_NO_THROW(scenario::validate(s));
  const RearrangementProblem p = problem_from_scenario(s);
  EXPECT_EQ(static_cast<int>(c.witness.moves.size()), k) << s.name;
  EXPECT_TRUE(validate_plan(p, c.witness, BaselineParams{}).empty()) << s.name;
  EXPECT_TRUE(p.goals_reached(c.witness.final_arrangement)) << s.name;
  // The stored JSON is the witness, bit for bit.
  const Plan back = plan_from_json(c.instance.witness, p.object_names, s.name);
  EXPECT_EQ(plan_to_json(back, p.object_names), c.instance.witness);
  ASSERT_EQ(back.moves.size(), c.witness.moves.size());
  for (std::size_t i = 0; i < back.moves.size(); ++i) {
    EXPECT_EQ(back.moves[i].transfer, c.witness.moves[i].transfer);
    EXPECT_EQ(back.moves[i].release_heading, c.witness.moves[i].release_heading);
  }
}

TEST(Constructive, WitnessesValidAcrossFootprints) {
  for (const double footprint : {0.02, 0.05, 0.08}) {
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      const ConstructiveInstance c = constructive_instance(spec(6, footprint, seed));
      SCOPED_TRACE(c.instance.scenario.name + " footprint " + std::to_string(footprint));
      expect_valid(c, 12);
      EXPECT_EQ(at_goal(c.instance.scenario), 0);  // K = 2N >= N: every object moved away
    }
  }
}

TEST(Constructive, FewerMovesThanObjectsLeaveTheOthersAtTheirGoals) {
  const ConstructiveInstance c = constructive_instance(spec(5, 0.05, 3, 2));
  expect_valid(c, 2);
  const scenario::Scenario& s = c.instance.scenario;
  int at_goal_point = 0;
  for (std::size_t i = 0; i < c.instance.goals.size(); ++i)
    at_goal_point += s.objects[i].disk.center == c.instance.goals[i] ? 1 : 0;
  EXPECT_EQ(at_goal_point, 3);
  EXPECT_EQ(at_goal(s), 3);
}

TEST(Constructive, WitnessRunsInBox2DToTheGoal) {
  for (const double footprint : {0.05, 0.08}) {
    const ConstructiveInstance c = constructive_instance(spec(8, footprint, 1));
    const scenario::Scenario& s = c.instance.scenario;
    const RearrangementProblem p = problem_from_scenario(s);
    ExecutionOptions o;
    o.record = false;
    o.time_budget = s.simulation.time_budget;
    const ExecutionLog log = execute_plan(s, p, c.witness, BaselineParams{}, o);
    EXPECT_EQ(log.status, ExecStatus::kCompleted) << s.name << ": " << log.reason;
    EXPECT_TRUE(log.goals_reached) << s.name;
    EXPECT_EQ(log.collisions, 0) << s.name;
    EXPECT_EQ(log.moves_done, c.witness.moves.size());
  }
}

TEST(Constructive, SameSpecSameBytes) {
  const ConstructiveInstance a = constructive_instance(spec(6, 0.05, 5));
  const ConstructiveInstance b = constructive_instance(spec(6, 0.05, 5));
  EXPECT_EQ(scenario::to_yaml(a.instance.scenario), scenario::to_yaml(b.instance.scenario));
  EXPECT_EQ(a.instance.witness, b.instance.witness);
  const ConstructiveInstance other = constructive_instance(spec(6, 0.05, 6));
  EXPECT_NE(scenario::to_yaml(a.instance.scenario), scenario::to_yaml(other.instance.scenario));
}

TEST(Constructive, TheRoomIsTheRandomClassRoom) {
  scenario::InstanceSpec random = spec(4, 0.05, 2);
  random.goal_class = scenario::GoalClass::kRandom;
  const scenario::GeneratedInstance r = scenario::generate_instance(random);
  const ConstructiveInstance c = constructive_instance(spec(4, 0.05, 2));
  EXPECT_EQ(c.instance.goals, r.goals);
  ASSERT_EQ(c.instance.scenario.familiar.size(), r.scenario.familiar.size());
  for (std::size_t i = 0; i < r.scenario.familiar.size(); ++i)
    EXPECT_EQ(c.instance.scenario.familiar[i].polygon.vertices,
              r.scenario.familiar[i].polygon.vertices);
}

// A 2.5 m room at footprint 0.12, where the pair's straight release approach (the baselines'
// primitive) soon fits no goal with the others in theirs, in each of the rooms drawn: refused
// with the reason, not a hang.
TEST(Constructive, AnImpossibleScatterIsAClearError) {
  try {
    constructive_instance(spec(4, 0.12, 0));
    ADD_FAILURE() << "generated";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("constructive instance (N=4, K=8, seed 0)"), std::string::npos) << m;
    EXPECT_NE(m.find("in 10 rooms"), std::string::npos) << m;
    EXPECT_NE(m.find("no object found a target"), std::string::npos) << m;
  }
}

TEST(Constructive, BadSpecsAreRefused) {
  scenario::InstanceSpec s = spec(4, 0.05, 1);
  s.goal_class = scenario::GoalClass::kRandom;
  EXPECT_THROW(constructive_instance(s), Error);
  EXPECT_THROW(scenario::generate_instance(spec(4, 0.05, 1)), Error);  // needs this generator
  EXPECT_THROW(constructive_instance(spec(4, 0.05, 1, -1)), Error);
  EXPECT_THROW(constructive_instance(spec(4, 0.05, 1, 4 * scenario::kMaxScatterMovesPerObject + 1)),
               Error);
  try {
    constructive_instance(spec(4, 0.05, 1, -1));
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("scatter_moves"), std::string::npos) << e.what();
  }
}

// A stub method: completes every trial (the sweep's generation is what is under test).
class Completes final : public experiment::Method {
 public:
  std::string name() const override { return "ok"; }
  std::string summary() const override { return "completes"; }
  experiment::TrialOutcome run(const scenario::Scenario&,
                               const experiment::MethodInput&) const override {
    experiment::TrialOutcome o;
    o.status = experiment::TrialStatus::kCompleted;
    o.goals_reached = true;
    return o;
  }
};

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A sweep with the class: K a dimension of its cells only, each instance's witness written beside
// it and valid for the instance file as written (read back from the folder), the rows saying K
// and the witness; without the generator the cells' rows are errors that say why.
TEST(Constructive, SweepsWriteWitnessesBesideTheirInstances) {
  const char* const sweep =
      "name: c\nmethods: [ok]\nclasses: [constructive, random]\nobjects: [4]\n"
      "scatter_moves: [0, 3]\ndensities: [0.05]\nfootprint_densities: [0.05]\n"
      "seeds: 2\nbase_seed: 9\n";
  experiment::MethodRegistry methods;
  methods.add(std::make_unique<Completes>());
  const scenario::SweepFile file = scenario::parse_sweep_file(sweep, "c.yaml");
  EXPECT_EQ(file.trial_count(), 6u);  // constructive x {0, 3} + random, 2 seeds each
  const experiment::SweepPlan plan = experiment::plan_sweep(file, methods);
  const auto dir =
      std::filesystem::temp_directory_path() / ("rearm_cons_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  experiment::SweepOptions o;
  o.out_dir = dir.string();
  o.spec_text = sweep;
  o.progress = nullptr;
  o.generators.constructive = generate_constructive;
  EXPECT_EQ(experiment::run_sweep(plan, methods, o).succeeded, 6u);
  const experiment::CsvTable t = experiment::read_csv((dir / experiment::kTrialsCsv).string());
  ASSERT_EQ(t.rows.size(), 6u);
  int witnesses = 0;
  for (const auto& row : t.rows) {
    const std::string name = row[t.column("instance")];
    const auto instance = dir / experiment::kInstancesDir / (name + ".yaml");
    const auto witness = dir / experiment::kInstancesDir / (name + experiment::kWitnessSuffix);
    if (row[t.column("class")] != "constructive") {
      EXPECT_EQ(row[t.column("witness")], "0");
      EXPECT_EQ(row[t.column("scatter_moves")], "");
      EXPECT_FALSE(std::filesystem::exists(witness));
      continue;
    }
    ++witnesses;
    EXPECT_EQ(row[t.column("witness")], "1");
    const bool k3 = name.find("_k3_") != std::string::npos;
    EXPECT_EQ(row[t.column("scatter_moves")], k3 ? "3" : "8") << name;
    const scenario::Scenario s = scenario::load_scenario(instance.string());
    const RearrangementProblem p = problem_from_scenario(s);
    const Plan w = plan_from_json(read_text(witness), p.object_names, witness.string());
    EXPECT_EQ(w.moves.size(), k3 ? 3u : 8u);
    EXPECT_TRUE(validate_plan(p, w, BaselineParams{}).empty()) << name;
  }
  EXPECT_EQ(witnesses, 4);
  // Without the generator: error rows naming it, the random class's rows unaffected.
  std::filesystem::remove_all(dir);
  o.generators = {};
  EXPECT_EQ(experiment::run_sweep(plan, methods, o).errors, 4u);
  const experiment::CsvTable e = experiment::read_csv((dir / experiment::kTrialsCsv).string());
  for (const auto& row : e.rows) {
    if (row[e.column("class")] == "constructive") {
      EXPECT_NE(row[e.column("reason")].find("no generator"), std::string::npos);
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rearm::baselines
