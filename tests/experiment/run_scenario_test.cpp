// Runs of the committed scenario files: the Box2D world and the kinematic plant give
// the same action sequence for Fig. 3; a run repeated gives byte-identical metrics apart from
// the timing fields; the task's names are checked against the scenario with the key named.
#include "experiment/run_scenario.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "experiment/task_from_scenario.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

scenario::Scenario load(const std::string& name) {
  return scenario::load_scenario("experiments/scenarios/" + name + ".yaml");
}

std::vector<std::string> succeeded(const RunRecord& r) {
  std::vector<std::string> out;
  for (const auto& a : r.result.actions) {
    if (a.outcome == executive::ActionOutcome::kSucceeded) {
      out.push_back(a.fix ? a.action + "*" : a.action);
    }
  }
  return out;
}

// metrics.json without the lines of the three timing fields.
std::string untimed(const std::string& metrics) {
  static const std::regex timing(
      R"re(\n\s*"(wall_time_s|controller_time_s|real_time_factor)": [^\n]*)re");
  return std::regex_replace(metrics, timing, "");
}

TEST(RunScenario, Fig3OnBothPlants) {
  const scenario::Scenario s = load("fig3");
  const std::vector<std::string> expected = {"grasp(M1)*", "disassemble(M1)*", "move(l1)"};
  for (const PlantKind plant : {PlantKind::kKinematic, PlantKind::kBox2d}) {
    RunOptions o;
    o.plant = plant;
    const RunRecord r = run_scenario(s, o);
    EXPECT_EQ(r.result.status, executive::TaskStatus::kCompleted)
        << to_string(plant) << ": " << r.result.reason;
    EXPECT_EQ(r.result.collisions, 0) << to_string(plant);
    EXPECT_EQ(succeeded(r), expected) << to_string(plant);
    EXPECT_GE(r.result.fix_mode_entries, 1);
    // Both familiar obstacles were localized, after the start.
    ASSERT_EQ(r.localized_at.size(), 2u);
    for (const double t : r.localized_at) EXPECT_GT(t, 0);
  }
}

TEST(RunScenario, MetricsAreReproducibleApartFromTiming) {
  const scenario::Scenario s = load("fig3");
  RunOptions o;
  o.seed = 7;
  const std::string a = metrics_json(s, run_scenario(s, o));
  const std::string b = metrics_json(s, run_scenario(s, o));
  EXPECT_NE(a.find("\"wall_time_s\""), std::string::npos);
  EXPECT_NE(a.find("\"seed\": 7"), std::string::npos);
  EXPECT_EQ(untimed(a), untimed(b));
  EXPECT_EQ(untimed(a).find("wall_time_s"), std::string::npos);
  for (const char* key :
       {"\"status\": \"completed\"", "\"collisions\": 0", "\"min_clearance\"", "\"sim_time_s\"",
        "\"controller_time_s\"", "\"actions\"", "\"fix_mode_entries\"", "\"robot_path_length_m\"",
        "\"object_path_length_m\"", "\"real_time_factor\""}) {
    EXPECT_NE(a.find(key), std::string::npos) << key;
  }
}

TEST(RunScenario, UnknownNamesInTheTaskAreRejected) {
  scenario::Scenario s = load("fig3");
  s.task = "<>(grasp(M9) && <>move(l1))";
  try {
    check_task(s);
    FAIL() << "no error";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.key(), "task");
    EXPECT_NE(std::string(e.what()).find("M9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fig3.yaml"), std::string::npos) << e.what();
  }
  s.task = "<>(move(l1)";
  EXPECT_THROW(check_task(s), scenario::ScenarioError);
  s.task = "X move(l1)";  // outside the mission controller's fragment
  EXPECT_THROW(check_task(s), scenario::ScenarioError);
}

// π0 (Appendix I-B) from the scenario: `[](move(l1) || move(l2))` constrains the first instant,
// so it holds only when the robot starts in l1 and says so; then it must reach l2 (and it
// stays in l1 or l2 ever after: the word the controller performs). Truth: the formula's
// semantics on the performed word (move(l1) held, then move(l2)), and the plant's end pose
// located in l2.
TEST(RunScenario, InitialPredicateIsTheFirstSymbol) {
  scenario::Scenario s = load("patrol");
  s.robot.start = geometry::Point(1.8, 5.0);  // inside l1
  s.task = "[](move(l1) || move(l2)) && <>move(l2)";
  s.simulation.max_actions = 0;
  // Without π0 the first instant holds the empty symbol, which violates the formula.
  {
    const RunRecord r = run_scenario(s, RunOptions{});
    EXPECT_EQ(r.result.status, executive::TaskStatus::kInfeasible) << r.result.reason;
    EXPECT_TRUE(succeeded(r).empty());
  }
  s.initial_predicate = "move(l1)";
  const RunRecord r = run_scenario(s, RunOptions{});
  ASSERT_EQ(r.result.status, executive::TaskStatus::kCompleted) << r.result.reason;
  EXPECT_EQ(succeeded(r), std::vector<std::string>{"move(l2)"});
  EXPECT_EQ(r.result.collisions, 0);
  const geometry::Polygon* l2 = nullptr;
  for (const auto& g : s.regions) {
    if (g.name == "l2") l2 = &g.polygon;
  }
  ASSERT_NE(l2, nullptr);
  EXPECT_TRUE(geometry::contains(*l2, r.result.path.back().x));
  // π0 must hold of the scene: the key is named when it does not.
  auto error_of = [&](const std::string& pi0) {
    scenario::Scenario t = s;
    t.objects.push_back({"M1", geometry::Disk{geometry::Point(6, 5), 0.25}});  // in no region
    t.initial_predicate = pi0;
    try {
      check_task(t);
    } catch (const scenario::ScenarioError& e) {
      EXPECT_EQ(e.key(), "initial_predicate") << pi0;
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error_of("move(l1)"), "accepted");
  EXPECT_NE(error_of("move(l2)").find("not inside region l2"), std::string::npos);
  EXPECT_NE(error_of("move(l9)").find("unknown region 'l9'"), std::string::npos);
  EXPECT_NE(error_of("grasp(M1)").find("gripper open"), std::string::npos);
  EXPECT_NE(error_of("release(M1,l1)").find("M1 does not start inside region l1"),
            std::string::npos);
  EXPECT_NE(error_of("stand(l1)").find("stand(l1)"), std::string::npos);
}

TEST(RunScenario, TaskSpecCarriesTheScenariosParameters) {
  scenario::Scenario s = load("fig3");
  s.controller.p = 14;
  s.controller.k_v = 0.7;
  s.robot.v_max = 0.3;
  s.controller.fragment_tolerance = 0.02;
  s.simulation.max_actions = 5;
  const executive::TaskSpec t = task_spec(s);
  EXPECT_EQ(t.executive.diffeo.p, 14);
  EXPECT_EQ(t.executive.nav.k_v, 0.7);
  EXPECT_EQ(t.executive.nav.v_max, 0.3);
  EXPECT_EQ(t.map_tolerances.fragment, 0.02);
  EXPECT_EQ(t.executive.max_ltl_actions, 5);
  EXPECT_EQ(t.executive.robot_radius, s.robot.radius);
  EXPECT_EQ(t.sensor.range, s.robot.sensor_range);
  EXPECT_EQ(t.world.movable.size(), s.objects.size());
  EXPECT_EQ(t.regions.size(), s.regions.size());
}

}  // namespace
}  // namespace rearm::experiment
