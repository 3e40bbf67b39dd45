// State-based nondeterministic Büchi automaton (paper Definition 1) over either alphabet.
// States are 0..num_states()-1; a run is accepting when it visits an accepting state
// infinitely often. Value type; the GeneralAlphabet's BDD manager is shared by copies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ltl/alphabet.h"

namespace rearm::ltl {

template <class Alphabet>
struct Automaton {
  using Guard = typename Alphabet::Guard;
  struct Edge {
    std::uint32_t dst;
    Guard guard;
  };

  Alphabet alphabet;
  std::vector<std::uint32_t> initial;
  std::vector<bool> accepting;           // per state
  std::vector<std::vector<Edge>> out;    // per state, at most one edge per destination
  std::vector<std::string> state_names;  // optional (empty or one per state)

  std::uint32_t num_states() const { return static_cast<std::uint32_t>(out.size()); }
  std::uint32_t add_state(bool is_accepting = false) {
    out.emplace_back();
    accepting.push_back(is_accepting);
    return num_states() - 1;
  }
  // Adds an edge, or-ing the guard into an existing edge to the same destination.
  void add_edge(std::uint32_t src, std::uint32_t dst, Guard guard) {
    if (alphabet.is_false(guard)) return;
    for (Edge& e : out[src]) {
      if (e.dst == dst) {
        e.guard = alphabet.disj(e.guard, guard);
        return;
      }
    }
    out[src].push_back(Edge{dst, std::move(guard)});
  }
  std::size_t num_edges() const {
    std::size_t n = 0;
    for (const auto& o : out) n += o.size();
    return n;
  }
};

using GeneralNba = Automaton<GeneralAlphabet>;
using ActionNba = Automaton<ActionAlphabet>;

}  // namespace rearm::ltl
