#include "support/plan_checks.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "baselines/validator.h"

namespace rearm::test_support {

using baselines::PlanResult;

void expect_valid_plan(const baselines::RearrangementProblem& p, const PlanResult& r) {
  ASSERT_EQ(r.status, baselines::PlanStatus::kSolved) << r.reason;
  const auto v = baselines::validate_plan(p, r.plan, {});
  EXPECT_TRUE(v.empty()) << v.size() << " violations, first: " << (v.empty() ? "" : v.front());
  EXPECT_TRUE(p.goals_reached(r.plan.final_arrangement));
}

void expect_same_plan_in_threads(const std::function<PlanResult()>& plan, int threads) {
  const PlanResult ref = plan();
  ASSERT_EQ(ref.status, baselines::PlanStatus::kSolved) << ref.reason;
  std::vector<PlanResult> runs(static_cast<std::size_t>(threads));
  std::vector<std::thread> pool;
  for (auto& run : runs) pool.emplace_back([&] { run = plan(); });
  for (auto& t : pool) t.join();
  for (const PlanResult& r : runs) {
    ASSERT_EQ(r.plan.moves.size(), ref.plan.moves.size());
    EXPECT_EQ(r.queries, ref.queries);
    for (std::size_t k = 0; k < r.plan.moves.size(); ++k) {
      EXPECT_EQ(r.plan.moves[k].object, ref.plan.moves[k].object);
      EXPECT_EQ(r.plan.moves[k].to, ref.plan.moves[k].to);
      EXPECT_EQ(r.plan.moves[k].transfer, ref.plan.moves[k].transfer);
    }
  }
}

}  // namespace rearm::test_support
