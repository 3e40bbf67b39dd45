// Benchmarks of the OMPL rearrangement baselines:
//  - TimeLimit/<method>: the wall time a planner takes when given 1 s on an instance no
//    rearrangement planner can solve (experiments/scenarios/pocket.yaml: the goal lies in a
//    pocket too narrow for the robot–object pair). Acceptance: back within 1.2 s. Counters:
//    overrun_s (wall time − limit, max over iterations), status (1 = timeout, 2 = infeasible,
//    3 = unsolved).
//  - Plan/<method>/<scenario>: planning time of B1 and B2 on the monotone instance and of B2
//    on Fig. 5's cyclic shift (full map, seed = iteration index so the sample is a spread of
//    seeds), with motion queries and tree nodes as counters.
//  - Crowded/<method>/<N>: planning time (no execution) of every planner on crowded rooms:
//    N = 4, 8, 16 objects of radius 0.25 m covering 5% of the floor (the footprint rule sizes
//    the room), sparse fixed obstacles (target density 0.05), four instances per N (seeds 1-4,
//    random goals for odd seeds, the cyclic shift for even ones), one per iteration, at the
//    studies' budget of 3,000 motion queries. Counters: solved (fraction), queries (mean).
//    The family compiles against an earlier revision too (scripts/bench_baselines.sh OLD
//    builds this file there): planners that revision lacks are left out.
// Run from the repository root (scripts/bench_baselines.sh): the scenario files are read from
// experiments/scenarios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "baselines/birrt.h"
#include "baselines/mrs.h"
#include "scenario/random_instance.h"
#include "scenario/scenario_io.h"
#if __has_include("baselines/buffer.h")
#include "baselines/buffer.h"
#define REARM_BENCH_HAS_BUFFER 1
#endif
#if __has_include("baselines/fmrs.h")
#include "baselines/fmrs.h"
#define REARM_BENCH_HAS_FMRS 1
#endif

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

enum class Planner { kMrs, kBirrt, kBuffer, kFmrs, kBirrtFmrs };

// The crowded instances of one N, built once per process (outside the timed loop).
const std::vector<RearrangementProblem>& crowded(int n) {
  static std::map<int, std::vector<RearrangementProblem>> cache;
  auto& out = cache[n];
  for (std::uint64_t seed = 1; out.size() < 4; ++seed) {
    scenario::InstanceSpec spec;
    spec.objects = n;
    spec.obstacle_density = 0.05;
    spec.footprint_density = 0.05;
    spec.goal_class = seed % 2 ? scenario::GoalClass::kRandom : scenario::GoalClass::kCyclic;
    spec.seed = seed;
    out.push_back(problem_from_scenario(scenario::random_instance(spec)));
  }
  return out;
}

PlanResult plan_crowded(Planner planner, const RearrangementProblem& p) {
  PlannerOptions o;
  o.time_limit = 300;  // a safety net: the query budget ends every run first
  o.max_queries = 3000;
  o.seed = 1;
  switch (planner) {
    case Planner::kMrs:
      return plan_mrs(p, {}, o);
    case Planner::kBirrt:
      return plan_birrt(p, {}, o);
#ifdef REARM_BENCH_HAS_BUFFER
    case Planner::kBuffer:
      return plan_buffer(p, {}, o);
#endif
#ifdef REARM_BENCH_HAS_FMRS
    case Planner::kFmrs:
      return plan_fmrs(p, {}, o);
    case Planner::kBirrtFmrs: {
      BirrtOptions b;
      b.extension = BirrtOptions::Extension::kFmrs;
      return plan_birrt(p, {}, o, b);
    }
#endif
    default:
      break;
  }
  return {};
}

void Crowded(benchmark::State& state, Planner planner) {
  const auto& problems = crowded(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  long queries = 0, solved = 0, runs = 0;
  for (auto _ : state) {
    const PlanResult r = plan_crowded(planner, problems[k++ % problems.size()]);
    queries += r.queries;
    solved += r.status == PlanStatus::kSolved;
    ++runs;
  }
  state.counters["solved"] = double(solved) / double(runs);
  state.counters["queries"] = double(queries) / double(runs);
}
#define REARM_CROWDED(name, planner)        \
  BENCHMARK_CAPTURE(Crowded, name, planner) \
      ->Arg(4)                              \
      ->Arg(8)                              \
      ->Arg(16)                             \
      ->Iterations(4)                       \
      ->Unit(benchmark::kMillisecond)
REARM_CROWDED(mrs, Planner::kMrs);
REARM_CROWDED(birrt, Planner::kBirrt);
#ifdef REARM_BENCH_HAS_BUFFER
REARM_CROWDED(buffer, Planner::kBuffer);
#endif
#ifdef REARM_BENCH_HAS_FMRS
REARM_CROWDED(fmrs, Planner::kFmrs);
REARM_CROWDED(birrt_fmrs, Planner::kBirrtFmrs);
#endif

}  // namespace
}  // namespace rearm::baselines

BENCHMARK_MAIN();
