// rearm plan --formula F [--initial ACTION] [--infeasible ACTION ...] [--objects ..]
//            [--regions ..] [--allow-negation] [--graph paper|selfloop] [--show-graph]
//            [--form auto|explicit|product]
// Runs the mission controller against a perfect executor (every action succeeds except the
// listed ones) and prints the action lasso.
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "ltl/parser.h"
#include "options.h"
#include "symbolic/mission_controller.h"

namespace rearm::cli {
namespace {

constexpr const char* kFooter =
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
    "edges (Def. 3) marked.\n"
    "--form chooses the automaton: auto (default) runs a conjunction of independent parts over\n"
    "disjoint predicates, each able to wait, as one small automaton per part (the product\n"
    "form, docs/symbolic.md: same language, same choices; the any-order task of N objects\n"
    "has 2^N states as one automaton); explicit always translates the whole formula (the\n"
    "paper's construction); product demands the product form.\n"
    "Exit: 0 when a lasso or infeasibility was printed, 1 when --max-steps ran out,\n"
    "2 for bad usage or a formula outside the fragment.";

constexpr std::size_t kDefaultMaxSteps = 100000;
constexpr std::size_t kMostMaxSteps = 999999999;

// The command line of `rearm plan`, parsed.
struct PlanArgs {
  std::string formula, initial, graph, form, objects, regions;
  std::vector<std::string> infeasible;
  std::size_t max_steps = kDefaultMaxSteps;
  bool show_graph = false, allow_negation = false;
};

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

symbolic::MissionOptions mission_options(const PlanArgs& a) {
  symbolic::MissionOptions options;
  if (!a.initial.empty()) options.initial = symbolic::Action::parse(a.initial);
  if (!a.graph.empty()) options.graph = symbolic::parse_graph_mode(a.graph);
  if (!a.form.empty()) options.form = symbolic::parse_mission_form(a.form);
  options.allow_negation = a.allow_negation;
  if (!a.objects.empty()) options.vocabulary.objects = split_list(a.objects);
  if (!a.regions.empty()) options.vocabulary.regions = split_list(a.regions);
  return options;
}

int plan(const PlanArgs& a) {
  const symbolic::MissionOptions options = mission_options(a);
  std::vector<symbolic::Action> infeasible;
  for (const std::string& text : a.infeasible) infeasible.push_back(symbolic::Action::parse(text));
  for (const auto& x : infeasible) options.vocabulary.check(x);
  symbolic::MissionController mc(ltl::parse(a.formula), options);
  if (a.show_graph) std::fputs(mc.graph_text().c_str(), stdout);
  auto is_infeasible = [&](const symbolic::Action& x) {
    for (const auto& b : infeasible) {
      if (x == b) return true;
    }
    return false;
  };
  // The controller is deterministic: its decision state (G's generation and node, the held
  // letter, the infeasible actions known) repeating closes the lasso.
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::size_t, std::size_t>, std::size_t> seen;
  std::vector<symbolic::Action> trace;
  for (std::size_t step = 0; step < a.max_steps; ++step) {
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
  throw BudgetExceeded("no lasso within --max-steps " + std::to_string(a.max_steps) + " steps");
}

}  // namespace

Command add_plan(CLI::App& program) {
  CLI::App* c =
      program.add_subcommand("plan", "run the mission controller against a perfect executor");
  c->footer(kFooter);
  auto a = std::make_shared<PlanArgs>();
  c->add_option("--formula", a->formula, "the LTL task")->required()->type_name("F");
  c->add_option("--initial", a->initial, "the action predicate holding at the start")
      ->type_name("ACTION");
  c->add_option("--infeasible", a->infeasible, "actions the executor fails")->type_name("ACTION");
  c->add_option("--objects", a->objects, "the scenario's objects")->type_name("M1,M2,...");
  c->add_option("--regions", a->regions, "the scenario's regions")->type_name("l1,l2,...");
  c->add_option("--max-steps", a->max_steps, "steps before giving up (exit 1)")
      ->check(count_check())
      ->check(CLI::Range(std::size_t{1}, kMostMaxSteps))
      ->type_name("N");
  c->add_flag("--allow-negation", a->allow_negation, "plan negated predicates (beyond the paper)");
  c->add_option("--graph", a->graph, "G's construction: selfloop (default) or paper")
      ->check(CLI::IsMember({"paper", "selfloop"}));
  c->add_flag("--show-graph", a->show_graph, "print G first");
  c->add_option("--form", a->form, "the automaton: auto (default), explicit or product")
      ->check(CLI::IsMember({"auto", "explicit", "product"}));
  return {c, [a] { return plan(*a); }};
}

}  // namespace rearm::cli
