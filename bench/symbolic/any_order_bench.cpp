// The any-order task <>release(M1,l1) && ... && <>release(MN,lN) at N = 4, 8, 12, 16, 24 in
// both forms of the mission (docs/symbolic.md, "Product form"): the whole formula's automaton
// (MissionForm::kExplicit, 2^N states) against one automaton per part (kProduct), in one run.
//  - BM_AnyOrderSetup: translation plus the mission controller's set-up (G and d_F), i.e. the
//    MissionController constructor; counters: automaton states and edges (summed over the
//    parts) and peak_rss_mb, the memory the construction needs: the peak resident set of a
//    fresh process that builds the controller, less that of one that builds nothing.
//  - BM_AnyOrderDecision: one decision, next_action() then report_success(), averaged over the
//    N decisions of the whole task (manual time; the set-up is not timed).
// The explicit form at N = 24 (16.8 million states) is not run: it exceeds the translator's
// state budget. The explicit form at N = 16 takes seconds per construction and runs two
// iterations.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

#include "ltl/formula.h"
#include "symbolic/mission_controller.h"

namespace {

using rearm::ltl::Formula;
using rearm::symbolic::MissionController;
using rearm::symbolic::MissionForm;
using rearm::symbolic::MissionOptions;

Formula any_order(int n) {
  std::vector<Formula> parts;
  for (int i = 1; i <= n; ++i) {
    const std::string k = std::to_string(i);
    parts.push_back(Formula::eventually(Formula::ap("release(M" + k + ",l" + k + ")")));
  }
  return Formula::conj(parts);
}

MissionOptions options(bool product) {
  MissionOptions o;
  o.form = product ? MissionForm::kProduct : MissionForm::kExplicit;
  o.translate.max_seconds = 120;     // today's construction at N = 16 needs seconds
  o.translate.max_states = 1 << 20;  // and 65,536 states
  return o;
}

constexpr const char* kChildFlag = "--rss-child";

// The peak resident set (MB) of a fresh copy of this program (exec'd, so nothing earlier
// benchmarks left in memory is reused) that builds the controller for N = n (n = 0: builds
// nothing); -1 when the child failed.
double child_peak_rss_mb(int n, bool product) {
  const std::string a = std::to_string(n), b = product ? "1" : "0";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/proc/self/exe", "any_order_bench", kChildFlag, a.c_str(), b.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    return -1;
  }
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KB on Linux
}

void BM_AnyOrderSetup(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool product = state.range(1) != 0;
  const Formula f = any_order(n);
  for (auto _ : state) {
    MissionController mc(f, options(product));
    benchmark::DoNotOptimize(mc.status());
    state.counters["states"] = static_cast<double>(mc.automaton_states());
    state.counters["edges"] = static_cast<double>(mc.automaton_edges());
  }
  const double base = child_peak_rss_mb(0, product);
  const double built = child_peak_rss_mb(n, product);
  state.counters["peak_rss_mb"] = base < 0 || built < 0 ? -1.0 : built - base;
  state.SetLabel(product ? "product" : "explicit");
}

void BM_AnyOrderDecision(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool product = state.range(1) != 0;
  const Formula f = any_order(n);
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    MissionController mc(f, options(product));
    const auto t0 = Clock::now();
    int decisions = 0;
    while (auto a = mc.next_action()) {
      benchmark::DoNotOptimize(a);
      mc.report_success();
      ++decisions;
    }
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (decisions != n) state.SkipWithError("the task did not take N decisions");
    state.SetIterationTime(s / n);
  }
  state.SetLabel(product ? "product" : "explicit");
}

void register_all() {
  for (const int n : {4, 8, 12, 16, 24}) {
    for (const int product : {0, 1}) {
      if (!product && n > 16) continue;  // 2^24 states: over the state budget
      auto* s = benchmark::RegisterBenchmark("BM_AnyOrderSetup", BM_AnyOrderSetup)
                    ->Args({n, product})
                    ->Unit(benchmark::kMillisecond);
      auto* d = benchmark::RegisterBenchmark("BM_AnyOrderDecision", BM_AnyOrderDecision)
                    ->Args({n, product})
                    ->UseManualTime()
                    ->Unit(benchmark::kMicrosecond);
      // Each decision iteration builds a controller untimed: a fixed count, not min_time (which
      // counts only the timed microseconds and would build hundreds of thousands).
      if (!product && n >= 16) {
        s->Iterations(2);
        d->Iterations(2);
      } else {
        d->Iterations(!product && n >= 12 ? 20 : 200);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == kChildFlag) {  // child_peak_rss_mb's child
    const int n = std::stoi(argv[2]);
    if (n > 0) {
      MissionController mc(any_order(n), options(std::string(argv[3]) == "1"));
      benchmark::DoNotOptimize(mc.status());
    }
    return 0;
  }
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
