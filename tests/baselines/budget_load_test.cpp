// A baseline's time budget counts the planning thread's CPU time (baselines/motion_query.h),
// so what else runs on the machine does not change a trial: the same trials run on an idle
// machine and beside spinning threads that keep every core busy (two per hardware thread)
// give the same metrics in every non-timing field. The time limit is set just above the
// trials' CPU time on the idle machine, so that under the load the planning takes longer
// than the limit in wall time (checked): a wall-clock budget would have cut these trials.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "baselines/run_baseline.h"
#include "scenario/scenario_io.h"

namespace rearm::baselines {
namespace {

// The crowded corpus instance on which BiRRT (seed 0) plans for about a third of a second of CPU
// time (at least 0.1 s checked below).
constexpr const char* kInstance =
    "tests/corpus/crowded/cyclic_n8_d0.05_side4.43113_u0_round_r5.yaml";
constexpr std::uint64_t kSeed = 0;
// The limit over the idle run's CPU time: above it by this factor (CPU time varies a little
// from run to run), below the wall time the load gives (the planning thread's share of a core
// falls to about a third with two spinners per hardware thread).
constexpr double kLimitOverIdle = 1.5;

BaselineRecord plan(const scenario::Scenario& s, double limit) {
  BaselineOptions o;
  o.method = Method::kBirrt;
  o.seed = kSeed;
  o.time_limit = limit;
  return run_baseline(s, o);
}

std::string untimed(const scenario::Scenario& s, const BaselineRecord& r) {
  static const std::regex timing(
      R"re(\n\s*"(wall_time_s|controller_time_s|first_action_time_s|planning_time_s|planning_wall_s|real_time_factor)": [^\n]*)re");
  return std::regex_replace(baseline_metrics_json(s, r), timing, "");
}

// Spinning threads, two per hardware thread, for the object's lifetime.
class Load {
 public:
  Load() {
    const unsigned n = 2 * std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 0; i < n; ++i) {
      threads_.emplace_back([this] {
        volatile unsigned long x = 0;
        while (!stop_.load(std::memory_order_relaxed)) x = x + 1;
      });
    }
  }
  ~Load() {
    stop_ = true;
    for (auto& t : threads_) t.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

TEST(BudgetUnderLoad, SameTrialsIdleAndBesideSpinningThreads) {
  const scenario::Scenario s = scenario::load_scenario(kInstance);
  const BaselineRecord probe = plan(s, 60);
  ASSERT_EQ(probe.status, "completed") << probe.reason;
  ASSERT_GT(probe.planning_time_s, 0.1) << "the instance plans too fast to load-test the budget";
  const double limit = kLimitOverIdle * probe.planning_time_s;
  const BaselineRecord idle = plan(s, limit);
  ASSERT_EQ(idle.status, "completed") << idle.reason;
  BaselineRecord loaded;
  {
    const Load load;
    loaded = plan(s, limit);
  }
  EXPECT_EQ(untimed(s, loaded), untimed(s, idle));
  // The load slowed the planning past the limit in wall time: a wall-clock budget would have
  // ended this trial (the CPU budget did not).
  EXPECT_GT(loaded.planning_wall_s, limit)
      << "planning CPU " << loaded.planning_time_s << " s, wall " << loaded.planning_wall_s
      << " s, limit " << limit << " s";
  EXPECT_LE(loaded.planning_time_s, limit);
  RecordProperty("limit_s", std::to_string(limit));
  RecordProperty("loaded_cpu_s", std::to_string(loaded.planning_time_s));
  RecordProperty("loaded_wall_s", std::to_string(loaded.planning_wall_s));
}

}  // namespace
}  // namespace rearm::baselines
