// rearm translate [--alphabet general|actions] [--format hoa|never|dot|stats] FORMULA
#include <cstdio>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "ltl/automaton_io.h"
#include "ltl/parser.h"
#include "ltl/translate.h"

namespace rearm::cli {
namespace {

constexpr const char* kUsage =
    "usage: rearm translate [--alphabet general|actions] [--format hoa|never|dot|stats]\n"
    "                       [--no-rewrite] [--no-simplify] [--max-states N] [--max-seconds S]\n"
    "                       FORMULA\n\n"
    "Translates an LTL formula (spin or Spot spelling; action predicates move(l),\n"
    "grasp(M), release(M,l)) into a state-based Büchi automaton (Gastin-Oddoux).\n\n"
    "  --alphabet general   guards over all subsets of the propositions (default)\n"
    "  --alphabet actions   one action at a time: the empty symbol plus one symbol per\n"
    "                       proposition (the paper's Appendix I alphabet)\n"
    "  --format hoa|never|dot|stats   output (default hoa); stats prints 'key: value' lines\n"
    "  --max-states N, --max-seconds S   budget; exceeding it is a clean error (exit 1)\n";

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

double parse_positive_number(const std::string& flag, const std::string& v) {
  try {
    std::size_t used = 0;
    const double x = std::stod(v, &used);
    if (used != v.size() || !(x > 0) || x != x || x > 1e15) throw std::invalid_argument(v);
    return x;
  } catch (const std::exception&) {
    throw Error(flag + " expects a positive finite number, got '" + v + "'");
  }
}

}  // namespace

int run_translate(const std::vector<std::string>& args) {
  std::string alphabet = "general", format = "hoa", formula;
  bool have_formula = false;
  ltl::TranslateOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw Error(a + " expects a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    } else if (a == "--alphabet") {
      alphabet = value();
      if (alphabet != "general" && alphabet != "actions") {
        throw Error("--alphabet expects 'general' or 'actions', got '" + alphabet + "'");
      }
    } else if (a == "--format") {
      format = value();
      if (format != "hoa" && format != "never" && format != "dot" && format != "stats") {
        throw Error("--format expects hoa, never, dot or stats, got '" + format + "'");
      }
    } else if (a == "--no-rewrite") {
      options.rewrite = false;
    } else if (a == "--no-simplify") {
      options.simplify = false;
    } else if (a == "--max-states") {
      options.max_states = static_cast<std::size_t>(parse_positive_number(a, value()));
    } else if (a == "--max-seconds") {
      options.max_seconds = parse_positive_number(a, value());
    } else if (a.size() > 1 && a[0] == '-' && a[1] == '-') {
      throw Error("unknown option '" + a + "'\n" + kUsage);
    } else if (have_formula) {
      throw Error("expects one FORMULA argument (quote it), got a second: '" + a + "'");
    } else {
      formula = a;
      have_formula = true;
    }
  }
  if (!have_formula) throw Error(std::string("missing FORMULA\n") + kUsage);
  const ltl::Formula f = ltl::parse(formula);
  ltl::TranslationStats st;
  std::string out;
  if (alphabet == "general") {
    const auto nba = ltl::translate_general(f, options, &st);
    if (format == "hoa") out = ltl::to_hoa(nba, formula);
    if (format == "never") out = ltl::to_never_claim(nba);
    if (format == "dot") out = ltl::to_dot(nba);
  } else {
    const auto nba = ltl::translate_actions(f, options, &st);
    if (format == "hoa") out = ltl::to_hoa(nba, formula);
    if (format == "never") out = ltl::to_never_claim(nba);
    if (format == "dot") out = ltl::to_dot(nba);
  }
  if (format == "stats") out = stats_text(st);
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

}  // namespace rearm::cli
