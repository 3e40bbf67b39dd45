// rearm plan --formula F [--initial ACTION] [--infeasible ACTION ...] [--objects ..]
//            [--regions ..] [--allow-negation] [--graph paper|selfloop] [--show-graph]
// Runs the mission controller against a perfect executor (every action succeeds except the
// listed ones) and prints the action lasso.
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "ltl/parser.h"
#include "symbolic/mission_controller.h"

namespace rearm::cli {
namespace {

constexpr const char* kUsage =
    "usage: rearm plan --formula F [--initial ACTION] [--infeasible ACTION ...]\n"
    "                  [--objects M1,M2,...] [--regions l1,l2,...] [--max-steps N]\n"
    "                  [--allow-negation] [--graph paper|selfloop] [--show-graph]\n\n"
    "Runs the online mission controller (paper Section III, Appendix I) against a perfect\n"
    "executor in which every action succeeds except the --infeasible ones, and prints the\n"
    "resulting action lasso:\n"
    "  prefix: a1 a2 ...      actions performed once\n"
    "  cycle: b1 b2 ...       actions repeated forever; 'cycle: idle' when the mission idles\n"
    "                         in an accepting self-loop holding its last action\n"
    "or, when no satisfying plan remains:\n"
    "  infeasible: <reason>\n\n"
    "ACTION is an action predicate: move(l), grasp(M) or release(M,l). --initial is the\n"
    "predicate holding at the start (the paper's pi_0; default: none). --objects and\n"
    "--regions list the scenario's names; predicates naming others are errors.\n"
    "The formula is in the paper's fragment (Section II-B): no X and no negation (! -> <->\n"
    "xor), exit 2 otherwise. --allow-negation (beyond the paper) plans negation over Boolean\n"
    "combinations of predicates; rearm run never accepts it (Fix mode could grasp or move\n"
    "what the formula forbids, footnote 4).\n"
    "--graph chooses G's construction: selfloop (default; the self-loopized automaton, which\n"
    "also plans a symbol that cycles through states without self-loops) or paper (Appendix I-B\n"
    "exactly: the multi-hop runs of Eq. 4). --show-graph prints G first: its nodes with d_F\n"
    "(Eq. 7) and V_F (Eq. 6), its edges with the symbols driving them (Eq. 9), accepting\n"
    "edges (Def. 3) marked.\n";

constexpr std::size_t kDefaultMaxSteps = 100000;

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) throw Error("empty name in the list '" + s + "'");
    out.push_back(item);
  }
  return out;
}

std::string join(const std::vector<symbolic::Action>& as) {
  std::string s;
  for (const auto& a : as) s += " " + a.to_string();
  return s;
}

}  // namespace

int run_plan(const std::vector<std::string>& args) {
  std::string formula;
  bool have_formula = false;
  symbolic::MissionOptions options;
  std::vector<symbolic::Action> infeasible;
  std::size_t max_steps = kDefaultMaxSteps;
  bool show_graph = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& { return option_value(args, i); };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    } else if (a == "--formula") {
      formula = value();
      have_formula = true;
    } else if (a == "--initial") {
      options.initial = symbolic::Action::parse(value());
    } else if (a == "--infeasible") {
      infeasible.push_back(symbolic::Action::parse(value()));
      while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) {
        infeasible.push_back(symbolic::Action::parse(args[++i]));
      }
    } else if (a == "--graph") {
      options.graph = symbolic::parse_graph_mode(value());
    } else if (a == "--show-graph") {
      show_graph = true;
    } else if (a == "--allow-negation") {
      options.allow_negation = true;
    } else if (a == "--objects") {
      options.vocabulary.objects = split_list(value());
    } else if (a == "--regions") {
      options.vocabulary.regions = split_list(value());
    } else if (a == "--max-steps") {
      const std::string& v = value();
      if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 9) {
        throw Error("--max-steps expects a positive integer, got '" + v + "'");
      }
      max_steps = std::stoul(v);
      if (max_steps == 0) throw Error("--max-steps expects a positive integer");
    } else {
      throw Error("unknown argument '" + a + "'\n" + kUsage);
    }
  }
  if (!have_formula) throw Error(std::string("missing --formula\n") + kUsage);
  for (const auto& a : infeasible) options.vocabulary.check(a);

  symbolic::MissionController mc(ltl::parse(formula), options);
  if (show_graph) std::fputs(mc.graph().to_text().c_str(), stdout);
  auto is_infeasible = [&](const symbolic::Action& a) {
    for (const auto& b : infeasible) {
      if (a == b) return true;
    }
    return false;
  };
  // The controller is deterministic: its decision state (G's generation and node, the held
  // letter, the infeasible actions known) repeating closes the lasso.
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::size_t, std::size_t>, std::size_t> seen;
  std::vector<symbolic::Action> trace;
  for (std::size_t step = 0; step < max_steps; ++step) {
    const auto key = std::make_tuple(mc.generation(), mc.node(), mc.held_letter(),
                                     mc.infeasible_actions().size());
    if (auto it = seen.find(key); it != seen.end()) {
      const std::vector<symbolic::Action> prefix(trace.begin(), trace.begin() + it->second);
      const std::vector<symbolic::Action> cycle(trace.begin() + it->second, trace.end());
      std::printf("prefix:%s\ncycle:%s\n", join(prefix).c_str(),
                  cycle.empty() ? " idle" : join(cycle).c_str());
      return kExitOk;
    }
    seen.emplace(key, trace.size());
    const auto action = mc.next_action();
    if (!action) {
      if (mc.status() == symbolic::MissionStatus::Infeasible) {
        std::printf("infeasible: %s\n", mc.reason().c_str());
      } else {
        std::printf("prefix:%s\ncycle: idle\n", join(trace).c_str());
      }
      return kExitOk;
    }
    if (is_infeasible(*action)) {
      mc.report_infeasible(*action);
    } else {
      mc.report_success();
      trace.push_back(*action);
    }
  }
  throw BudgetExceeded("no lasso within --max-steps " + std::to_string(max_steps) + " steps");
}

}  // namespace rearm::cli
