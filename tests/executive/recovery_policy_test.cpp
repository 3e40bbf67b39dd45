// The recovery policy (executive/recovery_policy.h) against its specification, the two tables of
// docs/executive.md "Recoveries: causes, units and the policy table" (written cell by cell from
// the code before the move into units): every cause × action kind cell lists the same units in
// the same order, every unit has the documented switch, requirements and counter; the paper
// variant (all switches off, as a scenario with `variant: paper` gives them) enables no step;
// and the units are reachable from the table only (no file but the policy and the units
// includes their header).
#include "executive/recovery_policy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "experiment/task_from_scenario.h"
#include "scenario/scenario_io.h"

namespace rearm::executive {
namespace {

constexpr const char* kDoc = "docs/executive.md";
constexpr ActionKind kKinds[] = {ActionKind::kMove, ActionKind::kGrasp, ActionKind::kRelease,
                                 ActionKind::kDisassemble};
constexpr Cause kCauses[] = {Cause::kStalled,        Cause::kCentreNotFree,  Cause::kNoLaw,
                             Cause::kGoalCutOff,     Cause::kClosedByMemory, Cause::kBackUpsSpent,
                             Cause::kClosedByObjects};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" `");
  const auto e = s.find_last_not_of(" `");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(trim(part));
  return out;
}

// The body rows of the markdown table whose header row starts with `header`, as cells.
std::vector<std::vector<std::string>> doc_table(const std::string& header) {
  std::ifstream in(kDoc);
  EXPECT_TRUE(in) << kDoc;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line) && line.rfind(header, 0) != 0) {
  }
  std::getline(in, line);  // |---|
  while (std::getline(in, line) && !line.empty() && line[0] == '|') {
    rows.push_back(split(line.substr(1, line.size() - 2), '|'));
  }
  return rows;
}

// RobustParams' switches by key (the scenario keys).
const std::map<std::string, Switch>& switches() {
  static const std::map<std::string, Switch> m = {
      {"guide", &RobustParams::guide},
      {"convex_fallback", &RobustParams::convex_fallback},
      {"back_out", &RobustParams::back_out},
      {"drop", &RobustParams::drop},
      {"early_release", &RobustParams::early_release},
      {"early_dock", &RobustParams::early_dock},
      {"narrow", &RobustParams::narrow},
      {"fragments", &RobustParams::fragments},
      {"memory", &RobustParams::memory},
      {"redrop", &RobustParams::redrop},
      {"object_blockers", &RobustParams::object_blockers}};
  return m;
}

std::string unit_names(std::span<const Step> steps) {
  std::string out;
  for (const Step& s : steps)
    out += (out.empty() ? "" : ", ") + std::string(unit_info(s.unit).name);
  return out.empty() ? "—" : out;
}

TEST(RecoveryPolicy, EveryCellListsTheDocumentedUnitsInOrder) {
  const auto rows = doc_table("| cause | MOVE |");
  ASSERT_EQ(rows.size(), std::size(kCauses));
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 5u) << row[0];
    const auto cause = std::find_if(std::begin(kCauses), std::end(kCauses),
                                    [&](Cause c) { return row[0] == to_string(c); });
    ASSERT_NE(cause, std::end(kCauses)) << "unknown cause in the doc: " << row[0];
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(unit_names(policy(*cause, kKinds[k])), row[k + 1]) << row[0] << " × kind " << k;
    }
  }
}

// Each unit's switch, its requirements (per cause where the doc says "(<cause> only)") and its
// counter, as documented.
TEST(RecoveryPolicy, EveryUnitHasTheDocumentedSwitchRequirementsAndCounter) {
  const auto rows = doc_table("| unit | switch |");
  ASSERT_EQ(rows.size(), kUnitCount);
  for (std::size_t i = 0; i < kUnitCount; ++i) {
    const UnitInfo& u = unit_info(static_cast<Unit>(i));
    EXPECT_EQ(u.unit, static_cast<Unit>(i));
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r[0] == u.name; });
    ASSERT_NE(row, rows.end()) << u.name << " is not in the doc's unit table";
    ASSERT_TRUE(switches().count((*row)[1])) << (*row)[1];
    EXPECT_EQ(u.turned_on_by, switches().at((*row)[1])) << u.name;
    EXPECT_EQ((*row)[3] == "—" ? "" : (*row)[3], std::string(u.counter)) << u.name;
    // The documented requirements: "a, b", "drop (goal cut off only)", "memory (raises …)".
    std::vector<std::pair<Switch, std::string>> needs;  // switch, the one cause it holds for
    if ((*row)[2] != "—") {
      for (std::string part : split((*row)[2], ',')) {
        std::string only;
        if (const auto p = part.find(" ("); p != std::string::npos) {
          const std::string note = part.substr(p + 2, part.size() - p - 3);
          if (note.size() > 5 && note.ends_with(" only")) only = note.substr(0, note.size() - 5);
          part = part.substr(0, p);
        }
        ASSERT_TRUE(switches().count(part)) << part;
        needs.emplace_back(switches().at(part), only);
      }
    }
    for (Cause cause : kCauses) {
      for (ActionKind kind : kKinds) {
        for (const Step& s : policy(cause, kind)) {
          if (s.unit != u.unit) continue;
          std::vector<Switch> want;
          for (const auto& [sw, only] : needs) {
            if (only.empty() || only == to_string(cause)) want.push_back(sw);
          }
          std::vector<Switch> got;
          for (Switch sw : s.needs) {
            if (sw != nullptr) got.push_back(sw);
          }
          EXPECT_EQ(got, want) << u.name << " at " << to_string(cause);
        }
      }
    }
  }
}

// Enabled means the unit's switch and every requirement on: each alone turned off disables it.
TEST(RecoveryPolicy, AStepNeedsItsSwitchAndEveryRequirement) {
  for (Cause cause : kCauses) {
    for (ActionKind kind : kKinds) {
      for (const Step& s : policy(cause, kind)) {
        RobustParams r;
        EXPECT_TRUE(enabled(r, s));
        r.*(unit_info(s.unit).turned_on_by) = false;
        EXPECT_FALSE(enabled(r, s));
        for (Switch need : s.needs) {
          if (need == nullptr) continue;
          RobustParams q;
          q.*need = false;
          EXPECT_FALSE(enabled(q, s)) << unit_info(s.unit).name;
        }
      }
    }
  }
}

TEST(RecoveryPolicy, ThePaperVariantIsTheEmptyTable) {
  scenario::Scenario s = scenario::load_scenario("experiments/scenarios/fig5.yaml");
  scenario::set_variant(s.controller, "paper");
  const RobustParams paper = experiment::task_spec(s).executive.robust;
  for (Cause cause : kCauses) {
    for (ActionKind kind : kKinds) {
      for (const Step& step : policy(cause, kind)) {
        EXPECT_FALSE(enabled(paper, step)) << unit_info(step.unit).name;
      }
    }
  }
}

// Each unit is declared in recovery_units.h only, which nothing but the policy and the units
// includes: a unit runs only as a step of the table.
TEST(RecoveryPolicy, UnitsAreReachableFromTheTableOnly) {
  namespace fs = std::filesystem;
  int units = 0;
  for (const char* dir : {"framework", "baselines", "experiments", "tests", "bench"}) {
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (!e.is_regular_file() || !(name.ends_with(".cpp") || name.ends_with(".h"))) continue;
      std::ifstream in(e.path());
      const std::string text((std::istreambuf_iterator<char>(in)), {});
      if (text.find("#include \"executive/recovery_units.h\"") == std::string::npos) continue;
      const bool allowed = e.path().parent_path().filename() == "executive" &&
                           name.rfind("recovery_", 0) == 0 && name.ends_with(".cpp");
      EXPECT_TRUE(allowed) << e.path() << " includes the recovery units";
      if (name != "recovery_policy.cpp") ++units;
    }
  }
  EXPECT_EQ(units, static_cast<int>(kUnitCount));  // one file per unit
}

}  // namespace
}  // namespace rearm::executive
