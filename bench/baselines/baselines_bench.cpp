// Benchmarks of the OMPL rearrangement baselines:
//  - TimeLimit/<method>: the wall time a planner takes when given 1 s on an instance no
//    rearrangement planner can solve (experiments/scenarios/pocket.yaml: the goal lies in a
//    pocket too narrow for the robot–object pair). Acceptance: back within 1.2 s. Counters:
//    overrun_s (wall time − limit, max over iterations), status (1 = timeout, 2 = infeasible,
//    3 = unsolved).
//  - Plan/<method>/<scenario>: planning time of B1 and B2 on the monotone instance and of B2
//    on Fig. 5's cyclic shift (full map, seed = iteration index so the sample is a spread of
//    seeds), with motion queries and tree nodes as counters.
// Run from the repository root (scripts/bench_baselines.sh): the scenario files are read from
// experiments/scenarios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "baselines/birrt.h"
#include "baselines/mrs.h"
#include "scenario/scenario_io.h"

namespace rearm::baselines {
namespace {

RearrangementProblem problem(const std::string& name) {
  return problem_from_scenario(scenario::load_scenario("experiments/scenarios/" + name + ".yaml"));
}

PlanResult plan(bool birrt, const RearrangementProblem& p, double limit, std::uint64_t seed) {
  PlannerOptions o;
  o.time_limit = limit;
  o.seed = seed;
  return birrt ? plan_birrt(p, {}, o) : plan_mrs(p, {}, o);
}

void TimeLimit(benchmark::State& state, bool birrt) {
  const RearrangementProblem p = problem("pocket");
  constexpr double kLimit = 1.0;
  double worst = 0;
  int status = 0;
  std::uint64_t seed = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const PlanResult r = plan(birrt, p, kLimit, seed++);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    worst = std::max(worst, wall - kLimit);
    status = r.status == PlanStatus::kTimeout ? 1 : r.status == PlanStatus::kInfeasible ? 2 : 3;
  }
  state.counters["overrun_s"] = worst;
  state.counters["status"] = status;
}
BENCHMARK_CAPTURE(TimeLimit, birrt, true)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK_CAPTURE(TimeLimit, mrs, false)->Unit(benchmark::kMillisecond)->Iterations(5);

void Plan(benchmark::State& state, bool birrt, const char* scenario) {
  const RearrangementProblem p = problem(scenario);
  std::uint64_t seed = 0;
  long queries = 0, nodes = 0, solved = 0, runs = 0;
  for (auto _ : state) {
    const PlanResult r = plan(birrt, p, 60, seed++);
    queries += r.subqueries;
    nodes += r.nodes;
    solved += r.status == PlanStatus::kSolved;
    ++runs;
  }
  state.counters["subqueries"] = double(queries) / double(runs);
  state.counters["nodes"] = double(nodes) / double(runs);
  state.counters["solved"] = double(solved) / double(runs);
}
BENCHMARK_CAPTURE(Plan, mrs_monotone, false, "monotone")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Plan, birrt_monotone, true, "monotone")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Plan, birrt_fig5, true, "fig5")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Plan, mrs_fig5, false, "fig5")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rearm::baselines

BENCHMARK_MAIN();
