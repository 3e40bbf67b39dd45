// LTL -> Büchi automaton translation after Gastin & Oddoux (CAV 2001, the algorithm of
// LTL2BA, the translator the paper used): formula rewriting (ltl/simplify.h), very weak
// alternating automaton, transition-based generalized Büchi automaton, Büchi automaton,
// each with its simplifications. See translate.cpp for the construction and its
// departures from the 2001 paper.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ltl/automaton.h"
#include "ltl/formula.h"

namespace rearm::ltl {

struct TranslateOptions {
  // Rewrite the formula first (ltl/simplify.h).
  bool rewrite = true;
  // Simplify each automaton (dominance, state merging, SCC pruning).
  bool simplify = true;
  // Budget: exceeding either throws rearm::BudgetExceeded with the stage that blew up. The
  // default time answers within seconds; the paper's tasks translate in milliseconds.
  std::size_t max_states = 200000;  // per stage (VWAA, GBA, BA)
  double max_seconds = 4.0;
};

// A conjunction of G F over Boolean formulas is built directly (docs/symbolic.md, "Translation"):
// then vwaa_states and gba_edges are 0 and gba_states 1 (no VWAA or product is built).
struct TranslationStats {
  std::size_t vwaa_states = 0;
  std::size_t gba_states = 0, gba_edges = 0, acceptance_sets = 0;
  std::size_t ba_states = 0, ba_edges = 0;
  double milliseconds = 0.0;
  std::string rewritten;  // the formula actually translated (Spot syntax)
};

// General alphabet: guards are BDDs over the formula's propositions (in order of first
// occurrence, then `extra_aps` not already present). Full LTL.
GeneralNba translate_general(const Formula& f, const TranslateOptions& options = {},
                             TranslationStats* stats = nullptr,
                             const std::vector<std::string>& extra_aps = {});

// One action at a time: letters are "no action" and one per proposition (the formula's,
// then `extra_aps`); symbols with two true propositions do not exist and are pruned while
// the automaton is built. Full LTL.
ActionNba translate_actions(const Formula& f, const TranslateOptions& options = {},
                            TranslationStats* stats = nullptr,
                            const std::vector<std::string>& extra_aps = {});

}  // namespace rearm::ltl
