// The cell check (experiment/cell_check.h): a cell whose instances all reach the target obstacle
// density is accepted, and every instance's density is then within kDensityTolerance of the
// target by an independent raster of its obstacles; a cell the generator cannot fill is refused
// with the instance and the reason; the verdicts do not depend on the thread count or the shard.
#include "experiment/cell_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scenario/random_instance.h"
#include "scenario/sweep_file.h"
#include "support/geometry_oracle.h"

namespace rearm::experiment {
namespace {

// Two cells of N = 2 in a 6 m room: density 0.1 (reachable) and 0.45 (beyond what the
// passages leave; few attempts so that the generator gives up quickly).
const char* const kSweep =
    "name: cells\nmethods: [mrs]\nclasses: [random]\nobjects: [2]\n"
    "densities: [0.1, 0.45]\nworkspace: {side: 6}\nseeds: 3\nbase_seed: 11\n"
    "instance: {max_attempts: 150}\n";

class Stub final : public Method {
 public:
  std::string name() const override { return "mrs"; }
  std::string summary() const override { return "stub"; }
  TrialOutcome run(const scenario::Scenario&, const MethodInput&) const override { return {}; }
};

MethodRegistry registry_with_mrs() {
  MethodRegistry r;
  r.add(std::make_unique<Stub>());
  return r;
}

double raster_density(const scenario::Scenario& s, double side) {
  std::vector<geometry::Polygon> obstacles;
  for (const auto& p : s.familiar) obstacles.push_back(p.polygon);
  for (const auto& p : s.unknown) obstacles.push_back(p.polygon);
  return test_support::raster_union_share(obstacles, side, side, 0.01);
}

TEST(CellCheck, AcceptsCellsAtTheirTargetAndRefusesTheOthersWithTheReason) {
  const SweepPlan plan =
      plan_sweep(scenario::parse_sweep_file(kSweep, "cells.yaml"), registry_with_mrs());
  ASSERT_EQ(plan.instances.size(), 6u);
  const std::vector<CellVerdict> v = check_cells(plan.instances, 2);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_FALSE(v[0].refused) << v[0].reason;
  EXPECT_TRUE(v[1].refused);
  EXPECT_NE(v[1].reason.find("instance r"), std::string::npos) << v[1].reason;
  EXPECT_NE(v[1].reason.find("target 0.450"), std::string::npos) << v[1].reason;
  EXPECT_EQ(describe_refused(v).find(v[0].name), std::string::npos);
  EXPECT_NE(describe_refused(v).find(v[1].name), std::string::npos);
  // Independent truth: the accepted cell's instances by a raster of their obstacles (1 cm
  // cells: the raster errs by the boundary cells, well under 0.01 here); the refused cell has
  // an instance that misses its target by more than the tolerance.
  bool missed = false;
  for (const InstanceJob& job : plan.instances) {
    const scenario::GeneratedInstance g = scenario::generate_instance(job.spec);
    const double d = raster_density(g.scenario, 6);
    const double miss = std::abs(d - job.spec.obstacle_density);
    if (job.cell == 0) {
      EXPECT_LE(miss, scenario::kDensityTolerance + 0.01) << instance_name(job) << " " << d;
    } else {
      missed = missed || miss > scenario::kDensityTolerance - 0.01;
    }
  }
  EXPECT_TRUE(missed);
  // The refused cell's trials leave the plan; the accepted one's stay.
  const SweepPlan kept = without_cells(plan, v);
  ASSERT_EQ(kept.instances.size(), 3u);
  for (const TrialJob& t : kept.trials) EXPECT_EQ(kept.instances[t.instance].cell, 0u);
  EXPECT_NE(verdicts_csv(v).find(",refused,"), std::string::npos);
}

TEST(CellCheck, VerdictsAreTheSameForAnyThreadCountAndShard) {
  const SweepPlan plan =
      plan_sweep(scenario::parse_sweep_file(kSweep, "cells.yaml"), registry_with_mrs());
  const std::vector<CellVerdict> one = check_cells(plan.instances, 1);
  EXPECT_EQ(verdicts_csv(check_cells(plan.instances, 3)), verdicts_csv(one));
  // Each shard checks every instance of the cells it touches (not only its own instances).
  for (int i = 0; i < 4; ++i) {
    const SweepPlan part = shard_of(plan, Shard{i, 4});
    const std::vector<InstanceJob> touched = cells_touched(plan, part);
    EXPECT_EQ(touched.size() % 3, 0u);
    for (const CellVerdict& v : check_cells(touched, 2)) {
      ASSERT_LT(v.cell, one.size());
      EXPECT_EQ(v.refused, one[v.cell].refused) << v.name;
      EXPECT_EQ(v.reason, one[v.cell].reason) << v.name;
    }
  }
}

}  // namespace
}  // namespace rearm::experiment
