// LTL -> Büchi translation on the formula families of docs/symbolic.md ("Speed and size,
// measured here on the reference tools" and "Our targets"), on both alphabets. Every case
// reports the Büchi automaton's size as the counters `states` and `edges`.
//
// Benchmark names read `<family>/<alphabet>/<n>` with family one of fseq, eq1, patrol,
// seqpatrol, conjf and alphabet general or actions; scripts/bench_ltl.sh reads them back.
//
// `translate_bench --formula=<family>:<n>` prints that family's formula in spin syntax and
// exits, so that scripts/bench_ltl.sh runs `spin -f` on exactly the formulas timed here.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "ltl/formula.h"
#include "ltl/translate.h"

namespace {

using rearm::ltl::Formula;
using rearm::ltl::Syntax;
using rearm::ltl::TranslateOptions;
using rearm::ltl::TranslationStats;

Formula Ap(const std::string& name) { return Formula::ap(name); }

// `prefix` followed by the decimal i (appended, not `"p" + std::to_string(i)`: GCC 12 warns
// falsely on the latter with -Wrestrict, GCC bug 105329).
std::string Name(const char* prefix, int i) {
  std::string name = prefix;
  name += std::to_string(i);
  return name;
}

Formula P(int i) { return Ap(Name("p", i)); }

// F(a1 & F(a2 & ... F an)).
Formula Sequence(const std::vector<Formula>& steps) {
  Formula f = Formula::eventually(steps.back());
  for (auto it = steps.rbegin() + 1; it != steps.rend(); ++it) {
    f = Formula::eventually(Formula::conj(*it, f));
  }
  return f;
}

std::vector<Formula> Props(int n) {
  std::vector<Formula> ps;
  for (int i = 1; i <= n; ++i) ps.push_back(P(i));
  return ps;
}

// F-sequencing: F(p1 & F(p2 & ... F pn)).
Formula FSequence(int n) { return Sequence(Props(n)); }

// Paper Eq. (1) for n objects: grasp(Mi), then release(Mi, l_{(i mod n)+1}), object after
// object (2n action predicates).
Formula Eq1(int n) {
  std::vector<Formula> steps;
  for (int i = 1; i <= n; ++i) {
    const std::string object = Name("M", i);
    steps.push_back(Ap("grasp(" + object + ")"));
    steps.push_back(Ap("release(" + object + "," + Name("l", i % n + 1) + ")"));
  }
  return Sequence(steps);
}

// Patrol: GF p1 & ... & GF pn.
Formula Patrol(int n) {
  std::vector<Formula> parts;
  for (int i = 1; i <= n; ++i) parts.push_back(Formula::always(Formula::eventually(P(i))));
  return Formula::conj(parts);
}

// Sequenced patrol: G F(p1 & F(p2 & ... F pn)).
Formula SeqPatrol(int n) { return Formula::always(FSequence(n)); }

// F p1 & ... & F pn.
Formula ConjF(int n) {
  std::vector<Formula> parts;
  for (int i = 1; i <= n; ++i) parts.push_back(Formula::eventually(P(i)));
  return Formula::conj(parts);
}

struct Family {
  const char* name;
  Formula (*make)(int n);
  std::vector<int> general_n;
  std::vector<int> actions_n;
};

// The n values of docs/symbolic.md, plus those where scripts/bench_ltl.sh runs spin (F-seq
// n=15, Eq. (1) n=3..8) so that both tools appear on the same rows.
const std::vector<Family>& Families() {
  static const std::vector<Family> families = {
      {"fseq", FSequence, {5, 10, 15, 20, 50, 100}, {5, 10, 15, 20, 50, 100}},
      {"eq1", Eq1, {3, 4, 5, 6, 7, 8, 10, 20, 50}, {3, 4, 5, 6, 7, 8, 10, 20, 50}},
      {"patrol", Patrol, {2, 3, 4, 5, 6, 7, 8, 9, 10}, {2, 5, 10, 20}},
      {"seqpatrol",
       SeqPatrol,
       {2, 3, 4, 5, 6, 7, 8, 12, 16, 30},
       {2, 3, 4, 5, 6, 7, 8, 12, 16, 30}},
      {"conjf", ConjF, {2, 3, 4, 5, 6, 7, 8, 9, 10}, {10}},
  };
  return families;
}

enum class Alphabet { kGeneral, kActions };

void BM_Translate(benchmark::State& state, const Formula& f, Alphabet alphabet) {
  const TranslateOptions options;
  TranslationStats stats;
  try {
    for (auto _ : state) {
      if (alphabet == Alphabet::kGeneral) {
        benchmark::DoNotOptimize(rearm::ltl::translate_general(f, options, &stats));
      } else {
        benchmark::DoNotOptimize(rearm::ltl::translate_actions(f, options, &stats));
      }
    }
  } catch (const std::exception& e) {  // a blown budget (rearm::BudgetExceeded)
    state.SkipWithError(e.what());
    return;
  }
  state.counters["states"] = benchmark::Counter(static_cast<double>(stats.ba_states));
  state.counters["edges"] = benchmark::Counter(static_cast<double>(stats.ba_edges));
}

void Register(const Family& family, Alphabet alphabet, int n) {
  const std::string name = std::string(family.name) +
                           (alphabet == Alphabet::kGeneral ? "/general/" : "/actions/") +
                           std::to_string(n);
  benchmark::RegisterBenchmark(name.c_str(), BM_Translate, family.make(n), alphabet)
      ->Unit(benchmark::kMillisecond);
}

void RegisterAll() {
  for (const Family& family : Families()) {
    for (int n : family.general_n) Register(family, Alphabet::kGeneral, n);
    for (int n : family.actions_n) Register(family, Alphabet::kActions, n);
  }
}

// Handles `--formula=<family>:<n>`: prints the formula in spin syntax. Returns the exit
// status, or -1 when the flag is absent.
int PrintFormula(int argc, char** argv) {
  constexpr std::string_view kFlag = "--formula=";
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.substr(0, kFlag.size()) != kFlag) continue;
    const std::string_view spec = arg.substr(kFlag.size());
    const std::size_t colon = spec.find(':');
    if (colon != std::string_view::npos) {
      const std::string family_name(spec.substr(0, colon));
      const int n = std::atoi(std::string(spec.substr(colon + 1)).c_str());
      for (const Family& family : Families()) {
        if (family_name == family.name && n >= 1) {
          std::printf("%s\n", family.make(n).to_string(Syntax::Spin).c_str());
          return 0;
        }
      }
    }
    std::fprintf(stderr, "translate_bench: bad %s (want <family>:<n>, family one of", argv[i]);
    for (const Family& family : Families()) std::fprintf(stderr, " %s", family.name);
    std::fprintf(stderr, ")\n");
    return 2;
  }
  return -1;
}

}  // namespace

int main(int argc, char** argv) {
  if (const int status = PrintFormula(argc, argv); status >= 0) return status;
  RegisterAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
