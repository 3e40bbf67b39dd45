// A scenario's task parsed once (experiment/scenario_task.h) and carried to the executive as a
// tree: against the LTL parser on the text (the same tree) and against the predicate's own
// spelling (π0's kind, object and region).
#include "experiment/scenario_task.h"

#include <gtest/gtest.h>

#include <string>

#include "experiment/task_from_scenario.h"
#include "ltl/parser.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

scenario::Scenario load(const std::string& name) {
  return scenario::load_scenario("experiments/scenarios/" + name + ".yaml");
}

TEST(ScenarioTask, TheExecutiveGetsTheParsedFormulaOfEachScene) {
  for (const char* name : {"fig3", "fig4", "fig5", "four_objects", "patrol", "pocket"}) {
    const scenario::Scenario s = load(name);
    const ScenarioTask t = parse_task(s);
    EXPECT_TRUE(t.formula == ltl::parse(s.task)) << name;
    EXPECT_TRUE(task_spec(s).formula == ltl::parse(s.task)) << name;
    EXPECT_EQ(t.initial.has_value(), !s.initial_predicate.empty()) << name;
  }
}

TEST(ScenarioTask, InitialPredicateBecomesItsAction) {
  scenario::Scenario s = load("patrol");
  s.robot.start = geometry::Point(1.8, 5.0);  // inside l1
  s.initial_predicate = " move( l1 ) ";
  const ScenarioTask t = parse_task(s);
  ASSERT_TRUE(t.initial.has_value());
  EXPECT_EQ(t.initial->kind, symbolic::ActionKind::Move);
  EXPECT_EQ(t.initial->region, "l1");
  EXPECT_TRUE(t.initial->object.empty());
  EXPECT_TRUE(task_spec(s).initial == t.initial);
  scenario::Scenario g = load("fig3");
  g.initial_predicate = "grasp(M1)";  // M1 is fig3's object; the gripper starts open
  try {
    (void)parse_task(g);
    FAIL() << "accepted " << g.initial_predicate;
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.key(), "initial_predicate");
    EXPECT_NE(std::string(e.what()).find("gripper open"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rearm::experiment
