// Mission controller benchmarks: building G and d_F (paper Appendix I-B) for the
// rearrangement formula (1) with 1–50 objects and for patrol formulas with 2–20 regions, and
// one online decision (Appendix I-C). Targets: G for 10 objects <= 1 ms; a decision <= 1 µs.
#include <benchmark/benchmark.h>

#include <string>

#include "ltl/parser.h"
#include "ltl/translate.h"
#include "symbolic/mission_controller.h"
#include "symbolic/mission_graph.h"

namespace {

using rearm::ltl::Formula;

// Paper Eq. (1) generalized: grasp object i, release it in region (i mod n) + 1, in order.
std::string rearrangement(int n) {
  std::string s, close;
  for (int i = 1; i <= n; ++i) {
    const std::string m = "M" + std::to_string(i);
    const std::string l = "l" + std::to_string(i % n + 1);
    s +=
        std::string(i > 1 ? " && " : "") + "<>(grasp(" + m + ") && <>(release(" + m + "," + l + ")";
    close += "))";
  }
  return s + close;
}

std::string patrol(int n) {
  std::string s;
  for (int i = 1; i <= n; ++i)
    s += (i > 1 ? " && " : "") + std::string("[]<>move(l") + std::to_string(i) + ")";
  return s;
}

void build_graph(benchmark::State& state, const std::string& text) {
  const auto nba = rearm::ltl::translate_actions(rearm::ltl::parse(text));
  const rearm::ltl::LetterSet none(nba.alphabet.num_letters());
  std::size_t nodes = 0, edges = 0;
  for (auto _ : state) {
    rearm::symbolic::MissionGraph g(nba, rearm::symbolic::MissionGraph::Start{}, none);
    benchmark::DoNotOptimize(g.d_f(g.start()));
    nodes = g.num_nodes();
    edges = g.num_edges();
  }
  state.counters["automaton_states"] = nba.num_states();
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["edges"] = static_cast<double>(edges);
}

void BM_GraphRearrangement(benchmark::State& state) {
  build_graph(state, rearrangement(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_GraphRearrangement)
    ->Arg(1)
    ->Arg(2)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Arg(50)
    ->Unit(benchmark::kMicrosecond);

void BM_GraphPatrol(benchmark::State& state) {
  build_graph(state, patrol(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_GraphPatrol)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

// One decision: next_action() then report_success() on a patrol, which never ends.
void BM_Decision(benchmark::State& state) {
  rearm::symbolic::MissionController mc(
      rearm::ltl::parse(patrol(static_cast<int>(state.range(0)))));
  for (auto _ : state) {
    auto a = mc.next_action();
    benchmark::DoNotOptimize(a);
    mc.report_success();
  }
}
BENCHMARK(BM_Decision)->Arg(2)->Arg(10)->Arg(20)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
