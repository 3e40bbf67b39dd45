// The online symbolic controller of paper Section III and Appendix I-C: from the current
// node of G it picks a neighbour one hop closer to V_F (Eq. 8), or an accepting edge when in
// V_F, and returns the action of a symbol driving that edge (Eq. 9). On an infeasible action
// it tries another symbol of the same edge, then another neighbour that lowers d_F, then
// (beyond the paper) rebuilds G and d_F without every action known to be infeasible, and
// only then declares the mission infeasible, with the reason.
//
// Word semantics (docs/symbolic.md): the symbol at each instant is the last completed
// visible action (π0 before the first), so each action is held until the next one; X-free
// formulas are stutter-invariant, which is why X is rejected.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ltl/automaton.h"
#include "ltl/formula.h"
#include "ltl/translate.h"
#include "symbolic/action.h"
#include "symbolic/mission_graph.h"
#include "symbolic/mission_product.h"

namespace rearm::symbolic {

enum class MissionStatus {
  InProgress,  // descending towards V_F
  Accepting,   // traversing the accepting cycle: the task is satisfied so far
  Infeasible,  // no accepting cycle is reachable without the infeasible actions
};
const char* to_string(MissionStatus s);

// Rejects, with an explanation, what the mission controller cannot handle (the paper's
// fragment, Section II-B): X anywhere; any negation (including the implicit ones of ->, <->
// and xor: the paper excludes negation, and its Fix mode relies on that, footnote 4);
// propositions that are not action predicates; and names unknown to a non-empty vocabulary.
// allow_negation (beyond the paper, for symbolic planning only: the executive never sets it,
// so Fix mode never meets a formula that forbids something) accepts negation over Boolean
// combinations of predicates, still not over a temporal subformula. Throws rearm::Error.
void check_mission_formula(const ltl::Formula& f, const Vocabulary& vocabulary = {},
                           bool allow_negation = false);

// How the formula becomes an automaton. kExplicit: one automaton of the whole formula (the
// paper's construction, Section III). kAuto (the default): the product form of
// mission_product.h when the formula has it (a conjunction of independent parts that can
// wait; the same language and the same choices, docs/symbolic.md), else kExplicit. kProduct:
// the product form or an error saying why the formula does not have it.
enum class MissionForm { kAuto, kExplicit, kProduct };
const char* to_string(MissionForm f);
// "auto", "explicit" or "product"; throws rearm::Error naming the text otherwise.
MissionForm parse_mission_form(const std::string& text);

struct MissionOptions {
  std::optional<Action> initial;  // π0; none: the empty symbol
  Vocabulary vocabulary;          // empty: any names
  ltl::TranslateOptions translate;
  bool allow_negation = false;  // check_mission_formula's extension (symbolic planning only)
  // G's construction (mission_graph.h): the self-loopized automaton (complete, the default and
  // the experiments' choice) or Appendix I-B exactly.
  GraphMode graph = GraphMode::kSelfLoop;
  MissionForm form = MissionForm::kAuto;
};

class MissionController {
 public:
  // Checks the formula (check_mission_formula), translates it on the one-action alphabet
  // and builds G. Throws rearm::Error for bad input, rearm::BudgetExceeded for blow-ups.
  explicit MissionController(const ltl::Formula& formula, MissionOptions options = {});

  // The action to perform next, or nullopt when there is nothing to do: the mission idles
  // in an accepting self-loop (status Accepting) or is infeasible. Calling it again before
  // a report returns the same action.
  std::optional<Action> next_action();
  // The action returned by next_action() completed.
  void report_success();
  // The action returned by next_action() proved infeasible (throws rearm::Error for any
  // other action).
  void report_infeasible(const Action& action);
  // The actions that would serve as well as the pending one (Eq. 8: each lowers d_F by one, or
  // takes an accepting edge of the cycle when in V_F), the pending one first; empty when
  // nothing is pending. The executive may pick among them by what it sees (prefer()).
  std::vector<Action> alternatives() const;
  // Makes `action`, one of alternatives(), the pending action; throws rearm::Error otherwise.
  void prefer(const Action& action);

  MissionStatus status() const;
  const std::string& reason() const;
  // Whether the product form runs the mission (MissionOptions::form).
  bool product_form() const { return product_ != nullptr; }
  // The current automaton state (MissionGraph::kAux before the first step); whole-automaton
  // form only, as are automaton() and graph() (they throw rearm::Error in the product form).
  std::uint32_t automaton_state() const;
  const ltl::ActionNba& automaton() const;
  const MissionGraph& graph() const;
  // States and edges of the automaton (summed over the parts in the product form).
  std::size_t automaton_states() const;
  std::size_t automaton_edges() const;
  // G (or every part's G in the product form) as text.
  std::string graph_text() const;
  // The predicates: letter i+1 is aps()[i].
  const std::vector<std::string>& aps() const;
  // Current decision node and how often G was rebuilt: together they identify the
  // controller's decision state (used to detect the plan's lasso).
  std::uint32_t node() const;
  // The letter held now (0: none; i+1: aps()[i]).
  std::size_t held_letter() const;
  std::uint32_t generation() const;
  std::vector<Action> infeasible_actions() const;

 private:
  using Choice = EdgeChoice;
  std::optional<Choice> choose(bool only_same_edge, const std::optional<Choice>& failed) const;
  void rebuild();
  // Successors of `states` under `letter`, closed under holding it longer (stuttering).
  std::vector<std::uint32_t> read(const std::vector<std::uint32_t>& states,
                                  std::size_t letter) const;
  Action action_of(std::size_t letter) const;
  void set_infeasible(std::string reason);

  // Per edge of the current node that Eq. 8 allows (in edge order): the held letter when it
  // drives the edge (nothing to do), else the lowest feasible action letter.
  std::vector<Choice> candidates() const;

  std::unique_ptr<ProductMission> product_;  // the product form, when it runs the mission
  ltl::ActionNba nba_;
  std::vector<Action> actions_;  // letter i+1 is actions_[i]
  std::size_t held_ = 0;         // held letter (0: none)
  // Automaton states some run on the word performed so far can be in (all branches).
  std::vector<std::uint32_t> reachable_;
  mutable std::vector<char> read_mark_;  // scratch of read()
  ltl::LetterSet excluded_;
  GraphMode mode_ = GraphMode::kSelfLoop;
  std::unique_ptr<MissionGraph> graph_;
  std::uint32_t node_ = 0;
  std::uint32_t generation_ = 0;
  // Whether graph_ was built with every letter now in excluded_ (else it may still hold
  // edges that only infeasible actions drive).
  bool graph_current_ = true;
  std::optional<Choice> pending_;
  MissionStatus status_ = MissionStatus::InProgress;
  std::string reason_;
};

}  // namespace rearm::symbolic
