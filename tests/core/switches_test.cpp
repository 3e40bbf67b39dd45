// The switch registry (core/switches.h) against every place derived from it: the executive's
// parameters (executive::kRobustFlags, both ways), the recovery counters it names as evidence,
// the scenario files (each key read and written back, off and on), the ablation methods
// "rearm-no<key>", and the task a scenario turns into (each switch reaches the executive, or
// the perception's scan). A switch added to the registry fails here until each place has it.
#include "core/switches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "executive/params.h"
#include "experiment/method.h"
#include "experiment/rearm_method.h"
#include "experiment/task_from_scenario.h"
#include "scenario/scenario_io.h"
#include "scenario/sweep_file.h"

namespace rearm {
namespace {

// The method name's rule, written independently of core/switches.h's ablation_method.
std::string without_underscores(std::string key) {
  key.erase(std::remove(key.begin(), key.end(), '_'), key.end());
  return key;
}

// Fig. 5's scene under the robust variant (the file runs the paper variant: every switch off).
scenario::Scenario fig5() {
  scenario::Scenario s = scenario::load_scenario("experiments/scenarios/fig5.yaml");
  scenario::set_variant(s.controller, "robust");
  return s;
}

TEST(Switches, KeysAreUniqueAndIndexed) {
  std::set<std::string> keys;
  for (std::size_t i = 0; i < kSwitchCount; ++i) {
    EXPECT_TRUE(keys.insert(kSwitches[i].key).second) << kSwitches[i].key;
    EXPECT_EQ(switch_index(kSwitches[i].key), i);
  }
  EXPECT_EQ(switch_index("no_such_switch"), std::nullopt);
  SwitchSet s;
  EXPECT_THROW(s.set("no_such_switch", false), Error);
}

TEST(Switches, EveryExecutiveSwitchIsARobustParamsFlagAndBack) {
  for (const SwitchInfo& s : kSwitches) {
    const auto n =
        std::count_if(std::begin(executive::kRobustFlags), std::end(executive::kRobustFlags),
                      [&](const auto& f) { return std::string(f.key) == s.key; });
    EXPECT_EQ(n, s.home == SwitchHome::kExecutive ? 1 : 0) << s.key;
  }
  for (const executive::RobustFlag& f : executive::kRobustFlags) {
    const auto i = switch_index(f.key);
    ASSERT_TRUE(i) << f.key << " is not in the registry";
    EXPECT_EQ(kSwitches[*i].home, SwitchHome::kExecutive) << f.key;
    const auto same =
        std::count_if(std::begin(executive::kRobustFlags), std::end(executive::kRobustFlags),
                      [&](const auto& g) { return g.flag == f.flag; });
    EXPECT_EQ(same, 1) << f.key << ": a RobustParams field listed twice";
  }
}

TEST(Switches, EvidenceIsARecoveryCounter) {
  for (const SwitchInfo& s : kSwitches) {
    const bool known =
        std::any_of(std::begin(executive::kRecoveryFields), std::end(executive::kRecoveryFields),
                    [&](const auto& f) { return std::string(f.name) == s.evidence; });
    EXPECT_TRUE(known) << s.key << ": " << s.evidence;
  }
}

// Each key is a scenario key: written by to_yaml and read back.
TEST(Switches, EveryKeyIsAScenarioKey) {
  for (const SwitchInfo& w : kSwitches) {
    scenario::Scenario s = fig5();
    s.controller.switches.set(w.key, false);
    const std::string yaml = scenario::to_yaml(s);
    EXPECT_NE(yaml.find(std::string(w.key) + ": false"), std::string::npos) << w.key;
    const scenario::Scenario back = scenario::parse_scenario(yaml);
    EXPECT_TRUE(back.controller.switches == s.controller.switches) << w.key;
    EXPECT_FALSE(back.controller.switches.on(w.key));
  }
}

TEST(Switches, EveryKeyHasItsAblationMethod) {
  std::set<std::string> names;
  for (const auto& m : experiment::make_rearm_variants()) names.insert(m->name());
  for (const SwitchInfo& w : kSwitches) {
    EXPECT_TRUE(names.count("rearm-no" + without_underscores(w.key))) << w.key;
    EXPECT_EQ(ablation_method(w), "rearm-no" + without_underscores(w.key));
  }
  EXPECT_EQ(names.size(), kSwitchCount + 1);  // and rearm-paper
}

// The ablation sweeps run every switch off in turn, whatever the registry holds.
TEST(Switches, AblationSweepsCoverEverySwitch) {
  for (const char* path :
       {"experiments/sweeps/ablation.yaml", "experiments/sweeps/ablation_dense.yaml"}) {
    const scenario::SweepFile f = scenario::load_sweep_file(path);
    for (const SwitchInfo& w : kSwitches) {
      EXPECT_EQ(
          std::count(f.methods.begin(), f.methods.end(), "rearm-no" + without_underscores(w.key)),
          1)
          << path << ": " << w.key;
    }
  }
}

// Turning a switch off in the scenario turns it off where it acts, and nothing else.
TEST(Switches, EverySwitchReachesWhereItActs) {
  const executive::TaskSpec on = experiment::task_spec(fig5());
  for (const SwitchInfo& w : kSwitches) {
    scenario::Scenario s = fig5();
    s.controller.switches.set(w.key, false);
    const executive::TaskSpec off = experiment::task_spec(s);
    for (const executive::RobustFlag& f : executive::kRobustFlags) {
      EXPECT_EQ(off.executive.robust.*f.flag, std::string(f.key) != w.key) << w.key;
      EXPECT_TRUE(on.executive.robust.*f.flag);
    }
    const bool scan = std::string(w.key) == "scan";
    EXPECT_EQ(off.map_tolerances.scan_spacing == 0, scan) << w.key;
  }
}

}  // namespace
}  // namespace rearm
