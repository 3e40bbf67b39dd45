// rearm translate [--alphabet general|actions] [--format hoa|never|dot|stats] FORMULA
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "ltl/automaton_io.h"
#include "ltl/parser.h"
#include "ltl/translate.h"
#include "options.h"

namespace rearm::cli {
namespace {

constexpr const char* kFooter =
    "Translates an LTL formula (spin or Spot spelling; action predicates move(l),\n"
    "grasp(M), release(M,l)) into a state-based Büchi automaton (Gastin-Oddoux).\n"
    "--alphabet general: guards over all subsets of the propositions; --alphabet actions:\n"
    "one action at a time, the empty symbol plus one symbol per proposition (the paper's\n"
    "Appendix I alphabet). --format stats prints 'key: value' lines.\n"
    "Exit: 0 on success, 1 when the budget (--max-states, --max-seconds) is exceeded,\n"
    "2 for bad usage or a malformed formula.";

// s: the largest time budget (the clock's arithmetic stays far from overflow).
constexpr double kMaxSeconds = 1e15;

// The command line of `rearm translate`, parsed.
struct TranslateArgs {
  std::string alphabet = "general", format = "hoa", formula;
  ltl::TranslateOptions options;
};

std::string stats_text(const ltl::TranslationStats& st) {
  std::string s;
  s += "states: " + std::to_string(st.ba_states) + "\n";
  s += "edges: " + std::to_string(st.ba_edges) + "\n";
  char ms[64];
  std::snprintf(ms, sizeof ms, "%.3f", st.milliseconds);
  s += "milliseconds: " + std::string(ms) + "\n";
  s += "gba_states: " + std::to_string(st.gba_states) + "\n";
  s += "gba_edges: " + std::to_string(st.gba_edges) + "\n";
  s += "acceptance_sets: " + std::to_string(st.acceptance_sets) + "\n";
  s += "vwaa_states: " + std::to_string(st.vwaa_states) + "\n";
  s += "rewritten: " + st.rewritten + "\n";
  return s;
}

int translate(const TranslateArgs& a) {
  const ltl::Formula f = ltl::parse(a.formula);
  ltl::TranslationStats st;
  std::string out;
  if (a.alphabet == "general") {
    const auto nba = ltl::translate_general(f, a.options, &st);
    if (a.format == "hoa") out = ltl::to_hoa(nba, a.formula);
    if (a.format == "never") out = ltl::to_never_claim(nba);
    if (a.format == "dot") out = ltl::to_dot(nba);
  } else {
    const auto nba = ltl::translate_actions(f, a.options, &st);
    if (a.format == "hoa") out = ltl::to_hoa(nba, a.formula);
    if (a.format == "never") out = ltl::to_never_claim(nba);
    if (a.format == "dot") out = ltl::to_dot(nba);
  }
  if (a.format == "stats") out = stats_text(st);
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

}  // namespace

Command add_translate(CLI::App& program) {
  CLI::App* c =
      program.add_subcommand("translate", "translate an LTL formula into a Büchi automaton");
  c->footer(kFooter);
  auto a = std::make_shared<TranslateArgs>();
  c->add_option("FORMULA", a->formula, "the LTL formula (quote it)")->required();
  c->add_option("--alphabet", a->alphabet, "general (default) or actions")
      ->check(CLI::IsMember({"general", "actions"}));
  c->add_option("--format", a->format, "output: hoa (default), never, dot or stats")
      ->check(CLI::IsMember({"hoa", "never", "dot", "stats"}));
  c->add_flag_callback(
      "--no-rewrite", [a] { a->options.rewrite = false; }, "skip the rewriting of the formula");
  c->add_flag_callback(
      "--no-simplify", [a] { a->options.simplify = false; },
      "skip the simplification of the automata");
  c->add_option("--max-states", a->options.max_states, "state budget (exceeding it: exit 1)")
      ->check(count_check())
      ->check(positive_check())
      ->type_name("N");
  c->add_option("--max-seconds", a->options.max_seconds, "time budget (exceeding it: exit 1)")
      ->check(finite_check())
      ->check(positive_check())
      ->check(CLI::Range(0.0, kMaxSeconds))
      ->type_name("S");
  return {c, [a] { return translate(*a); }};
}

}  // namespace rearm::cli
