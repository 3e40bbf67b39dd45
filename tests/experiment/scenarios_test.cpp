// The five committed scenarios, run in the Box2D world, end completed
// with 0 collisions under Box2D's contact accounting, enter Fix mode where the paper describes
// it, execute the actions their formulas imply, and leave every object in its goal region
// (ground truth from the simulator, exact point location).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "experiment/run_scenario.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

struct Expected {
  std::string name;
  bool fix_mode;                 // the paper's description triggers Fix mode
  std::vector<std::string> ltl;  // succeeded LTL actions, in order (empty: checked apart)
  std::map<std::string, std::string> goals;  // object → region it must end in
};

std::vector<Expected> expectations() {
  return {
      {"fig3", true, {"move(l1)"}, {}},
      {"fig4", true, {"move(l1)", "move(l2)", "grasp(M1)", "release(M1,l3)"}, {{"M1", "l3"}}},
      {"fig5",
       true,
       {"grasp(M1)", "release(M1,l2)", "grasp(M2)", "release(M2,l3)", "grasp(M3)",
        "release(M3,l1)"},
       {{"M1", "l2"}, {"M2", "l3"}, {"M3", "l1"}}},
      {"patrol", false, {}, {}},
      {"four_objects",
       true,
       {"grasp(M1)", "release(M1,l2)", "grasp(M2)", "release(M2,l3)", "grasp(M3)", "release(M3,l4)",
        "grasp(M4)", "release(M4,l1)"},
       {{"M1", "l2"}, {"M2", "l3"}, {"M3", "l4"}, {"M4", "l1"}}},
  };
}

class Scenarios : public ::testing::TestWithParam<Expected> {};

TEST_P(Scenarios, CompleteSafelyWithTheFormulasActions) {
  const Expected& e = GetParam();
  const scenario::Scenario s = scenario::load_scenario("experiments/scenarios/" + e.name + ".yaml");
  RunOptions checked;
  checked.checked = true;  // the closed loop's invariants on every tick (task_runner.h)
  const RunRecord r = run_scenario(s, checked);
  const executive::TaskResult& t = r.result;
  std::cout << e.name << ": " << executive::to_string(t.status) << " (" << t.reason << "), "
            << t.sim_time << " s simulated, " << t.wall_time << " s wall, " << t.fix_mode_entries
            << " Fix mode entries\n";
  ASSERT_EQ(t.status, executive::TaskStatus::kCompleted) << t.reason;
  EXPECT_EQ(t.collisions, 0);
  EXPECT_EQ(t.fix_mode_entries > 0, e.fix_mode) << t.fix_mode_entries;
  std::vector<std::string> ltl;
  for (const auto& a : t.actions) {
    if (!a.fix && a.outcome == executive::ActionOutcome::kSucceeded) ltl.push_back(a.action);
  }
  // The clearance per kind of thing: their least is the plant's clearance (its own geometry);
  // fig5 works through clutter (within 0.5 m of a familiar and of an unknown obstacle).
  const geometry::ClearanceByKind& c = t.clearance_by_kind;
  EXPECT_NEAR(std::min({c.familiar, c.unknown, c.objects, c.boundary}), t.min_clearance, 1e-9);
  if (e.name == "fig5") {
    EXPECT_LE(c.familiar, 0.5);
    EXPECT_LE(c.unknown, 0.5);
  }
  if (e.name == "patrol") {
    // []<>move(l1) && []<>move(l2) && []<>move(l3), 9 actions: every region visited 3 times.
    ASSERT_EQ(ltl.size(), 9u);
    std::map<std::string, int> visits;
    for (const std::string& a : ltl) visits[a]++;
    EXPECT_EQ(visits["move(l1)"], 3);
    EXPECT_EQ(visits["move(l2)"], 3);
    EXPECT_EQ(visits["move(l3)"], 3);
  } else {
    EXPECT_EQ(ltl, e.ltl);
  }
  for (const auto& [object, region] : e.goals) {
    std::size_t i = 0;
    while (i < s.objects.size() && s.objects[i].name != object) ++i;
    ASSERT_LT(i, s.objects.size());
    const geometry::Polygon* poly = nullptr;
    for (const auto& g : s.regions) {
      if (g.name == region) poly = &g.polygon;
    }
    ASSERT_NE(poly, nullptr);
    EXPECT_TRUE(geometry::contains(*poly, r.objects_end[i]))
        << object << " ended at " << r.objects_end[i].transpose() << ", not in " << region;
  }
}

INSTANTIATE_TEST_SUITE_P(Committed, Scenarios, ::testing::ValuesIn(expectations()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace rearm::experiment
