// The sweep runner through its library interface (experiment/sweep_runner.h), with stub
// methods: a method that throws gives `error` rows carrying its message and the sweep goes on;
// every trial gets one row with its settings; a folder that holds another sweep is refused;
// a rerun runs nothing.
#include "experiment/sweep_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include "core/error.h"
#include "experiment/csv.h"
#include "experiment/trial_columns.h"
#include "scenario/sweep_file.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

class Throws final : public Method {
 public:
  std::string name() const override { return "boom"; }
  std::string summary() const override { return "throws"; }
  TrialOutcome run(const scenario::Scenario&, const MethodInput&) const override {
    throw std::runtime_error("boom: a bug, reported");
  }
};

class Completes final : public Method {
 public:
  std::string name() const override { return "ok"; }
  std::string summary() const override { return "completes"; }
  TrialOutcome run(const scenario::Scenario& s, const MethodInput& in) const override {
    TrialOutcome o;
    o.status = TrialStatus::kCompleted;
    o.goals_reached = true;
    o.reason = s.name + " seed " + std::to_string(in.seed);
    return o;
  }
};

const char* const kSweep =
    "name: stub\nmethods: [boom, ok]\nclasses: [random, cyclic]\nobjects: [1]\n"
    "densities: [0.05]\nworkspace: {side: 8}\nseeds: 2\nbase_seed: 5\n";

TEST(SweepRunner, AThrowingMethodGivesErrorRowsAndTheSweepGoesOn) {
  MethodRegistry methods;
  methods.add(std::make_unique<Throws>());
  methods.add(std::make_unique<Completes>());
  const scenario::SweepFile file = scenario::parse_sweep_file(kSweep, "stub.yaml");
  const SweepPlan plan = plan_sweep(file, methods);
  const fs::path dir = fs::temp_directory_path() / ("rearm_runner_" + std::to_string(getpid()));
  fs::remove_all(dir);
  SweepOptions o;
  o.out_dir = dir.string();
  o.threads = 2;
  o.spec_text = kSweep;
  o.progress = nullptr;
  const SweepSummary s = run_sweep(plan, methods, o);
  EXPECT_EQ(s.ran, 8u);
  EXPECT_EQ(s.errors, 4u);
  EXPECT_EQ(s.succeeded, 4u);
  const CsvTable t = read_csv((dir / kTrialsCsv).string());
  ASSERT_EQ(t.rows.size(), 8u);
  for (const auto& row : t.rows) {
    const bool boom = row[t.column("method")] == "boom";
    EXPECT_EQ(row[t.column("status")], boom ? "error" : "completed");
    EXPECT_EQ(row[t.column("success")], boom ? "0" : "1");
    if (boom) {
      EXPECT_EQ(row[t.column("reason")], "boom: a bug, reported");
    }
    const std::size_t index = std::stoul(row[t.column("trial")]);
    EXPECT_EQ(row[t.column("key")], key_column(plan.trials[index].settings));
    EXPECT_TRUE(fs::exists(dir / kInstancesDir / (row[t.column("instance")] + ".yaml")));
  }
  // A rerun finds every trial done; another sweep's file is refused before anything runs.
  EXPECT_EQ(run_sweep(plan, methods, o).ran, 0u);
  SweepOptions other = o;
  other.spec_text = std::string(kSweep) + "# changed\n";
  EXPECT_THROW(run_sweep(plan, methods, other), Error);
  other = o;
  other.threads = 0;
  EXPECT_THROW(run_sweep(plan, methods, other), Error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rearm::experiment
