// Checks the baseline planners' tests share (tests/baselines): a plan solved, valid by the
// independent validator (baselines/validator.h) and reaching every goal; the same plan for the
// same seed when the planner runs in several threads at once.
#pragma once

#include <functional>

#include "baselines/plan.h"
#include "baselines/problem.h"

namespace rearm::test_support {

void expect_valid_plan(const baselines::RearrangementProblem& p, const baselines::PlanResult& r);

// Runs `plan` once, then `threads` times in parallel threads: every run equals the first (moves,
// their objects, landings and transfer paths, and the motion queries used).
void expect_same_plan_in_threads(const std::function<baselines::PlanResult()>& plan,
                                 int threads = 4);

}  // namespace rearm::test_support
