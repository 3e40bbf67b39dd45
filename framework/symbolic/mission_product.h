// The product form of a mission (docs/symbolic.md, "Product form"): a negation-free
// conjunction whose conjuncts fall into groups over pairwise disjoint action predicates, each
// group one its automaton can pause in (every state has a self-loop under the empty symbol), is
// run as
// one small automaton and one graph G per group instead of the automaton of the whole formula.
// The any-order task <>release(M1,l1) && ... && <>release(MN,lN) has 2^N states as one
// automaton (the known optimum, docs/symbolic.md) and N automata of 2 states here.
//
// Why it is exact. Language: a word of the one-action alphabet satisfies the conjunction iff
// each group's projection (the group's letters kept, every other letter read as the empty
// symbol) satisfies its group, since a group's formula only reads its own predicates; so the
// product accepts the intersection of the projections, the formula's language. Control: an
// action belongs to one group and moves only that group's automaton; the other groups read
// the empty symbol, under which every state of theirs can stay (the pause condition), so any
// interleaving of the groups' own plans is a plan of the conjunction; conversely, without
// negation a group is monotone in its predicates, so where it reads the empty symbol while
// others act it is served as well by holding its own last action, which is the word its own G
// plans (the paper's held-letter semantics): the conjunction's d_F (paper Eq. 7) is the sum of
// the groups' d_F. The controller of Appendix I-C is applied
// with that sum: a group's action one hop closer to its V_F lowers the sum by one, and among
// all such actions the lowest letter is taken, as the whole automaton's controller does.
// Failures (Appendix I-C) are mirrored: another symbol of the same edge, then another action
// that lowers the sum (of any group), then each stale group's G rebuilt without the
// infeasible actions.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ltl/automaton.h"
#include "ltl/formula.h"
#include "ltl/translate.h"
#include "symbolic/action.h"
#include "symbolic/mission_graph.h"

namespace rearm::symbolic {

// The top-level conjuncts of f grouped by shared atomic propositions (two conjuncts that share
// a proposition are in one group, transitively), each group the conjunction of its conjuncts
// in the formula's order; groups ordered by their first conjunct. One group when f is not a
// conjunction or its conjuncts are all linked.
std::vector<ltl::Formula> independent_groups(const ltl::Formula& f);

// Whether every state of `nba` has a self-loop under the empty symbol (letter 0): the group
// can wait while other groups act.
bool pausable(const ltl::ActionNba& nba);

class ProductMission {
 public:
  struct Options {
    std::optional<Action> initial;  // π0
    ltl::TranslateOptions translate;
    GraphMode graph = GraphMode::kSelfLoop;
  };
  // nullptr when f does not have the product form (one group, or a group that cannot pause);
  // `why` then says which. Throws what translate_actions throws.
  static std::unique_ptr<ProductMission> build(const ltl::Formula& f, const Options& options,
                                               std::string* why = nullptr);

  std::optional<Action> next_action();
  void report_success();
  void report_infeasible(const Action& action);
  // The actions the controller would take as well as the pending one (each lowers d_F by one,
  // or takes an accepting edge), pending first; empty when nothing is pending.
  std::vector<Action> alternatives() const;
  // Makes `action`, one of alternatives(), the pending action (throws rearm::Error otherwise).
  void prefer(const Action& action);

  bool infeasible() const { return infeasible_; }
  bool accepting() const { return accepting_; }
  const std::string& reason() const { return reason_; }
  // Letters: 0 = none, i+1 = aps()[i] (the formula's predicates in order of first occurrence,
  // then π0 when the formula does not name it).
  const std::vector<std::string>& aps() const { return aps_; }
  std::size_t held_letter() const { return held_; }
  std::vector<Action> infeasible_actions() const;
  // The decision state (every group's node and letter), interned: equal ids, equal states.
  std::uint32_t node() const;
  std::uint32_t generation() const;
  // d_F of the conjunction (the sum over groups), MissionGraph::kInfinity when unreachable.
  std::uint32_t d_f() const;
  std::size_t num_groups() const { return groups_.size(); }
  // Part i's formula and automaton (over its own predicates).
  const ltl::Formula& part_formula(std::size_t i) const { return groups_.at(i)->formula; }
  const ltl::ActionNba& part_automaton(std::size_t i) const { return groups_.at(i)->nba; }
  // Every group's automaton and G as text.
  std::string to_text() const;

 private:
  struct Group {
    ltl::Formula formula;
    ltl::ActionNba nba;
    std::vector<std::size_t> global;  // local letter -> global letter (global[0] = 0)
    std::unique_ptr<MissionGraph> graph;
    std::uint32_t node = 0;
    std::size_t last = 0;  // the group's own letter last held (G's word semantics)
    // The robot holds `last` now (the group's view of the held letter), false once another
    // group acted after the group's own letter: it then reads the empty symbol.
    bool holding = true;
    std::vector<std::uint32_t> reachable;  // automaton states of every run so far
    ltl::LetterSet excluded;
    bool current = true;  // graph built with every letter now excluded
    std::uint32_t generation = 0;
  };
  struct Choice {
    std::size_t group;
    std::size_t edge;
    std::size_t letter;  // local
  };
  ProductMission() = default;
  bool idle(const Group& g) const;
  std::optional<Choice> choose(bool only_same_edge, const std::optional<Choice>& failed) const;
  std::vector<Choice> candidates(const Group& g, std::size_t index) const;
  // The candidates of every group not done yet, in group order.
  std::vector<Choice> open_choices() const;
  void rebuild(Group& g);
  bool rebuild_stale();
  void set_infeasible(std::string reason);
  Action action_of(const Choice& c) const;
  std::size_t global_of(const Choice& c) const { return groups_[c.group]->global[c.letter]; }

  std::vector<std::unique_ptr<Group>> groups_;
  std::vector<std::string> aps_;
  std::vector<Action> actions_;  // global letter i+1 is actions_[i]
  std::vector<int> group_of_;    // per global letter: its group, -1 for none (ε, a foreign π0)
  std::size_t held_ = 0;         // global letter held now
  GraphMode mode_ = GraphMode::kSelfLoop;
  std::optional<Choice> pending_;
  ltl::LetterSet excluded_;  // global
  bool infeasible_ = false;
  bool accepting_ = false;
  std::string reason_;
  mutable std::vector<char> scratch_;
  mutable std::map<std::vector<std::uint32_t>, std::uint32_t> interned_;
};

}  // namespace rearm::symbolic
