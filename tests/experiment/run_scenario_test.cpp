// Runs of the committed scenario files: the Box2D world and the kinematic plant give
// the same action sequence for Fig. 3; a run repeated gives byte-identical metrics apart from
// the timing fields; the task's names are checked against the scenario with the key named.
#include "experiment/run_scenario.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
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

// metrics.json without the lines of its timing fields.
std::string untimed(const std::string& metrics) {
  static const std::regex timing(
      R"re(\n\s*"(wall_time_s|controller_time_s|real_time_factor|topology_time_s|first_action_time_s)": [^\n]*)re");
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
  EXPECT_EQ(untimed(a), untimed(b));
  EXPECT_EQ(untimed(a).find("wall_time_s"), std::string::npos);
  nlohmann::json j = nlohmann::json::parse(a);
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["collisions"], 0);
  EXPECT_GE(j["fix_mode_entries"].get<int>(), 1);
  EXPECT_FALSE(j["actions"].empty());
  for (const char* key : {"min_clearance", "sim_time_s", "wall_time_s", "controller_time_s",
                          "robot_path_length_m", "object_path_length_m", "real_time_factor"}) {
    EXPECT_TRUE(j[key].is_number()) << key;
  }
  EXPECT_EQ(j["min_clearance_by_kind"].size(), 4u);
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

// rearm run --spaces (the paper's video): one snapshot per diffeomorphism build, and at every
// tick of the law a model point h(x) inside the model freespace of the build in use. Truth:
// the point located against the model space's convex boundary (edge lines) and its disks.
TEST(RunScenario, SpacesRecordEveryBuildAndTheModelPoint) {
  const scenario::Scenario s = load("fig3");
  RunOptions o;
  o.spaces = true;
  const RunRecord r = run_scenario(s, o);
  const executive::TaskResult& t = r.result;
  ASSERT_EQ(t.status, executive::TaskStatus::kCompleted) << t.reason;
  ASSERT_EQ(static_cast<int>(t.spaces.size()), t.rebuilds);
  ASSERT_EQ(t.model_path.size(), t.path.size());
  std::size_t law_ticks = 0;
  for (std::size_t k = 0; k < t.model_path.size(); ++k) {
    const geometry::Point& y = t.model_path[k];
    if (!y.allFinite()) continue;
    ++law_ticks;
    const double time = static_cast<double>(k) * s.simulation.dt;
    std::size_t i = 0;  // the last build taken at or before this tick
    while (i + 1 < t.spaces.size() && t.spaces[i + 1].t <= time + 1e-9) ++i;
    const reactive::ModelSpace& m = t.spaces[i].model;
    for (std::size_t e = 0; e < m.boundary.size(); ++e) {
      const geometry::Point a = m.boundary.vertices[e];
      const geometry::Point b = m.boundary.vertices[(e + 1) % m.boundary.size()];
      const geometry::Point ab = b - a, ay = y - a;
      EXPECT_GT(ab.x() * ay.y() - ab.y() * ay.x(), 0) << "tick " << k << " outside F_e";
    }
    for (const geometry::Disk& d : m.disks) {
      EXPECT_GT((y - d.center).norm(), d.radius) << "tick " << k << " inside a model disk";
    }
  }
  EXPECT_GT(law_ticks, t.model_path.size() / 2);
  const int stride = 10;
  nlohmann::json json = nlohmann::json::parse(trajectory_json(s, r, stride));
  EXPECT_EQ(json["spaces"].size(), t.spaces.size());
  EXPECT_EQ(json["model_path"].size(), (t.model_path.size() + stride - 1) / stride);
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
