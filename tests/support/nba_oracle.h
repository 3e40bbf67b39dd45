// Exact, brute-force questions about Büchi automata for tests (docs/symbolic.md
// "Correctness is tested against independent truth"): does an automaton accept a lasso
// word, and is the intersection of two automata empty. Both are explicit product graphs
// searched for a reachable cycle through accepting states, with no use of the translator.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "ltl/automaton.h"
#include "support/lasso.h"

namespace rearm::test_support {

// Does `a` accept w? The product of automaton states with lasso positions is searched for a
// reachable cycle through an accepting automaton state.
//
// GeneralNba: the symbol at a position is the bit vector over a.alphabet.aps() of the
// lasso's propositions; lasso propositions the automaton does not know are ignored and the
// automaton's propositions absent from the lasso are false.
bool accepts(const ltl::GeneralNba& a, const Lasso& w);

// ActionNba: each letter of w must have at most one true proposition among those the
// automaton knows (others are ignored): the symbol is 0 ("no action") or i+1 for
// a.alphabet.aps()[i]. Throws std::invalid_argument for a letter with two known
// propositions true.
bool accepts(const ltl::ActionNba& a, const Lasso& w);

// A common accepted word of two automata, as a lasso of product states (state of the first,
// state of the second) and the word read along it.
struct ProductWitness {
  using ProductState = std::pair<std::uint32_t, std::uint32_t>;
  // prefix_states[0] is a pair of initial states; the run is
  //   prefix_states[0] .. prefix_states[k-1], then cycle_states repeated forever
  // (the state after prefix_states.back() is cycle_states[0], and after cycle_states.back()
  // again cycle_states[0]). The cycle visits an accepting state of each automaton.
  std::vector<ProductState> prefix_states;
  std::vector<ProductState> cycle_states;
  // The word read: word.prefix[i] leaves prefix_states[i], word.loop[i] leaves
  // cycle_states[i]. Propositions no guard constrains are false. aps: union of both
  // alphabets.
  Lasso word;

  std::string to_string() const;
};

// Exact emptiness of L(a) ∩ L(b) for two automata whose alphabets share one BddManager
// (a proposition's name must denote the same BDD variable in both; checked, throws
// std::invalid_argument otherwise). Product edges are pairs of edges with intersecting
// guards; the product is non-empty iff a reachable strongly connected component (iterative
// Tarjan) with at least one edge contains an accepting state of a and one of b (generalized
// Büchi acceptance of both). Returns nullopt when empty, else a witness.
std::optional<ProductWitness> find_common_word(const ltl::GeneralNba& a, const ltl::GeneralNba& b);

// Up to `count` lassos accepted by `a`, from random walks in the part of `a` that can reach
// an accepting cycle: a walk stops (with probability 1/2 at each chance, always at
// max_length) when it closes a cycle through an accepting state; the lasso is the word read
// along it, its loop the letters of the cycle. Letters are random symbols of the guards
// (propositions a guard leaves free drawn uniformly); aps = a.alphabet.aps(). Returns fewer
// (none for an empty language) when walks fail. Used to propose words of L(a) — e.g. words
// of spin's automaton for φ that a translation of φ must accept.
std::vector<Lasso> sample_accepted_lassos(const ltl::GeneralNba& a, Rng& rng, std::size_t count,
                                          std::size_t max_length = 12);

// Strongly connected components of the part of a graph reachable from `roots`, by an
// iterative Tarjan (no recursion, any depth). Returns for each vertex its component index,
// or -1 when unreachable; components are numbered in reverse topological order.
std::vector<int> strongly_connected_components(const std::vector<std::vector<std::uint32_t>>& adj,
                                               const std::vector<std::uint32_t>& roots);

}  // namespace rearm::test_support
