// A corpus of past failures (docs/architecture.md, house style 9): random clutter instances of
// the baseline comparison (scenario::random_instance with round_unknown = false, kept as files in
// tests/corpus/clutter) on which rearm used to end stuck. Two defects caused it, both fixed in
// reactive/:
//  - a released object whose dilated disk overlaps another obstacle merges with it into one
//    curved component, whose extension-cut decomposition left slivers; purging a large piece
//    into a sliver's centre drove det Dh to ~1e-2 and below (the robot turned in place, or Dh
//    was singular): curved components now take the fewest convex pieces first;
//  - the model disk of a movable object was the exact disk of radius ρ + r, while the mapped
//    freespace leaves out the circumscribed polygon, up to 2.2 mm wider: the robot could slide
//    into that band and the next rebuild found it outside the freespace.
// tests/corpus/comparison holds the 21 instances of the earlier baseline comparison
// (results/debian12-2core/baseline_comparison, rows with success 0) on which the paper variant
// ended stuck, most at rest points and limit cycles of [7] beside clusters; the robust variant
// (executive::RobustParams) must complete them. tests/corpus/variants holds instances of the
// variants sweep (results/debian12-2core/variants, N <= 8, density <= 0.25) that the robust
// variant ended stuck on before the face, track and narrow recoveries. tests/corpus/pockets
// holds instances of the scaling sweep (results/debian12-2core/sweep, revision b9add86) that
// ended stuck because the pair's drop point fell back to the paper's target outside the pocket
// visible unknown obstacles close, or because the law stalled with x* in sight; the drop
// point's lower clearance levels and the straight track to x* (executive.h) complete them.
// tests/corpus/recoveries holds more of that sweep's instances, completed by the robust
// variant's memory of unknown obstacles for guide paths (the robot had been guided back into a
// pocket of unknown obstacles it had left), the pair's looked-ahead back-up (a pair wedged
// between a familiar and an unknown obstacle, backing up straight between them), objects named
// by the grown check beside visible unknown obstacles (a gap the exact check finds open and the
// mapped space closes), and the pair centre kept in F_k by turns and back-ups (a turn had swung
// it 3 cm into a dilation, where the law's model point lies in a model obstacle), and one (sealed,
// N = 1, density 0.35) whose DISASSEMBLE ended stuck after four guides toward a drop point past
// unknown obstacles: the guide budget renewed on progress (RobustParams::persist) or another
// drop point (RobustParams::redrop) each completes it alone. tests/corpus/hardening holds
// instances of the hardening run (experiments/sweeps/hardening.yaml) that stopped the process:
// one whose Boolean result had a component that rounding to doubles collapsed to a sliver with
// no positive loop (geometry/boolean.cpp); and two in which the robot touched a flat-faced
// unknown obstacle by up to 0.5 mm: the map's fragment (fragment tolerance 0.1 m) kept missing
// a corner the footprint had cut off while the robot drove up to it (perception/semantic_map.h,
// kFragmentNearFraction).
// Every tick runs in the checked mode (executive/task_runner.h). Truth: the Box2D world's contact
// accounting and the simulator's object positions, located
// exactly in the goal regions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "experiment/run_scenario.h"
#include "geometry/polygon.h"
#include "scenario/scenario_io.h"
#include "support/scale.h"

namespace rearm::experiment {
namespace {

// "DIR/NAME" for every scenario file of the six corpora, in name order.
std::vector<std::string> corpus() {
  std::vector<std::string> files;
  for (const char* dir :
       {"clutter", "comparison", "variants", "pockets", "recoveries", "hardening"}) {
    for (const auto& e : std::filesystem::directory_iterator(std::string("tests/corpus/") + dir)) {
      if (e.path().extension() == ".yaml") {
        files.push_back(std::string(dir) + "/" + e.path().stem().string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Below scale 1 (REARM_TEST_SCALE, the sanitizer stage) only every k-th instance runs, k = the
// corpus size over its scaled size (test_support::scaled); the others are reported skipped (ctest
// lists the names it discovered at build time, so leaving them out of the list would pass them
// without running anything).
bool runs_at_this_scale(const std::string& name) {
  static const std::vector<std::string> all = corpus();  // the directories, read once
  const std::size_t keep = test_support::scaled(all.size());
  if (keep >= all.size()) return true;
  const std::size_t k = all.size() / keep;
  const auto it = std::find(all.begin(), all.end(), name);
  return it != all.end() && static_cast<std::size_t>(it - all.begin()) % k == 0;
}

// tests/corpus/known_stuck.txt: the instances the robust variant does not complete yet.
bool known_stuck(const std::string& name) {
  std::ifstream in("tests/corpus/known_stuck.txt");
  EXPECT_TRUE(in.good()) << "tests/corpus/known_stuck.txt is missing";
  for (std::string line; std::getline(in, line);) {
    if (line == name) return true;
  }
  return false;
}

class ClutterCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(ClutterCorpus, CompletesSafelyWithEveryObjectInItsGoal) {
  if (!runs_at_this_scale(GetParam())) {
    GTEST_SKIP() << "REARM_TEST_SCALE = " << test_support::test_scale()
                 << " runs every k-th corpus instance only (k = corpus size / scaled count)";
  }
  const scenario::Scenario s = scenario::load_scenario("tests/corpus/" + GetParam() + ".yaml");
  RunOptions checked;
  checked.checked = true;  // the closed loop's invariants on every tick (task_runner.h)
  const RunRecord r = run_scenario(s, checked);
  const executive::TaskResult& t = r.result;
  std::cout << GetParam() << ": " << executive::to_string(t.status) << " (" << t.reason << "), "
            << t.sim_time << " s simulated, " << t.fix_mode_entries << " Fix mode entries\n";
  if (known_stuck(GetParam())) {
    EXPECT_EQ(t.collisions, 0) << (t.collision_events.empty() ? "" : t.collision_events.front());
    EXPECT_TRUE(t.status == executive::TaskStatus::kStuck ||
                t.status == executive::TaskStatus::kInfeasible)
        << executive::to_string(t.status)
        << (t.status == executive::TaskStatus::kCompleted
                ? ": it completes now, remove it from tests/corpus/known_stuck.txt"
                : "");
    return;
  }
  ASSERT_EQ(t.status, executive::TaskStatus::kCompleted) << t.reason;
  EXPECT_EQ(t.collisions, 0) << (t.collision_events.empty() ? "" : t.collision_events.front());
  EXPECT_GE(t.min_clearance, 0);
  // Region li is object Mi's goal (random_instance.h); the sealed class's blockers Bi have none.
  ASSERT_EQ(r.objects_end.size(), s.objects.size());
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].name.front() == 'B') continue;
    const std::string goal = "l" + s.objects[i].name.substr(1);
    const geometry::Polygon* poly = nullptr;
    for (const auto& g : s.regions) {
      if (g.name == goal) poly = &g.polygon;
    }
    ASSERT_NE(poly, nullptr) << goal;
    EXPECT_TRUE(geometry::contains(*poly, r.objects_end[i]))
        << s.objects[i].name << " ended at " << r.objects_end[i].transpose() << ", not in " << goal;
  }
}

INSTANTIATE_TEST_SUITE_P(PastFailures, ClutterCorpus, ::testing::ValuesIn(corpus()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace rearm::experiment
