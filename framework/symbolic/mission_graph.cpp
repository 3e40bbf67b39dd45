// Construction of G (paper Appendix I-B) on the self-loopized automaton.
//
// Self-loopization (Michaud & Duret-Lutz, SPIN 2015, `sl`): a node is (q, h): automaton state
// q entered while the robot holds letter h (its last completed action). Holding h longer is
// always possible: when q has a real self-loop under h, reading h again keeps q (and may
// visit q's acceptance); otherwise the node carries an *added* self-loop under h that reads
// the extra copies of h without moving — a non-accepting transition, so the language is that
// of the stutter-closure, i.e. unchanged for stutter-invariant (X-free) formulas. With it,
// the paper's multi-hop run of Eq. (4) always has K = 1 (the node reached after one step
// under σ has a self-loop under σ), so G's edges are the one-step transitions between nodes,
// and a symbol that cycles through several states without any self-loop (which the paper's
// G loses) becomes a cycle of G driven by holding that symbol.
//
// Nodes (q, h) whose h has a real self-loop at q behave the same for every such h and are
// merged into one "stable" node; only (q, h) without a real h-loop stays split. A third
// component records whether an action was performed yet: the empty symbol can be held only
// before the first action (docs/symbolic.md word semantics), so edges under the empty letter
// leave only not-yet-started nodes. Pruning (the paper's b_inf, Eq. 2) is built into the
// one-action alphabet: guards are sets of feasible symbols.
#include "symbolic/mission_graph.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "core/error.h"
#include "core/scc.h"

namespace rearm::symbolic {
using ltl::LetterSet;

MissionGraph::MissionGraph(const ltl::ActionNba& nba, Start start, const LetterSet& excluded)
    : nba_(&nba) {
  const std::size_t num_letters = nba.alphabet.num_letters();
  REARM_DEMAND(excluded.universe() == num_letters, "excluded letters of another alphabet");
  REARM_DEMAND(start.held_letter < num_letters, "held letter outside the alphabet");
  for (std::uint32_t q : start.states) {
    REARM_DEMAND(q < nba.num_states(), "unknown start state");
  }
  // Real self-loop letters per automaton state.
  std::vector<LetterSet> real_loop(nba.num_states(), LetterSet(num_letters));
  for (std::uint32_t q = 0; q < nba.num_states(); ++q) {
    for (const auto& e : nba.out[q]) {
      if (e.dst == q) real_loop[q] |= e.guard;
    }
  }
  const LetterSet allowed = ~excluded;
  const LetterSet none_letter = LetterSet::single(num_letters, 0);

  std::map<std::tuple<std::uint32_t, std::int32_t, bool>, std::uint32_t> ids;
  auto id_of = [&](std::uint32_t q, std::int32_t split, bool started) {
    auto [it, inserted] =
        ids.emplace(std::make_tuple(q, split, started), static_cast<std::uint32_t>(nodes_.size()));
    if (inserted) {
      nodes_.push_back(Node{q, split, started});
      out_.emplace_back();
    }
    return it->second;
  };
  auto class_of = [&](std::uint32_t q, std::size_t h) -> std::int32_t {
    return real_loop[q].test(h) ? -1 : static_cast<std::int32_t>(h);
  };
  auto add_edge = [&](std::uint32_t src, std::uint32_t dst, const LetterSet& letters,
                      bool accepting) {
    for (Edge& e : out_[src]) {
      if (e.dst == dst) {
        e.letters |= letters;
        e.accepting = e.accepting || accepting;
        return;
      }
    }
    out_[src].push_back(Edge{dst, letters, accepting, false});
  };

  const bool start_started = start.held_letter != 0;
  const LetterSet held = LetterSet::single(num_letters, start.held_letter);
  id_of(kAux, -1, start_started);
  if (start.states.empty()) {
    // q_aux (Appendix I-B): the situation before instant 0. π0 is the symbol at instant 0
    // (docs/symbolic.md word semantics), so the automaton reads it from its initial states:
    // q_aux has an edge, enabled by π0 alone, to the successors of each initial state under
    // π0. (The paper's q_aux -> q0 edge consumes π0 without the automaton reading it, which
    // would evaluate the formula on the word without its first symbol.)
    for (std::uint32_t q0 : nba.initial) {
      for (const auto& e : nba.out[q0]) {
        if (!e.guard.test(start.held_letter)) continue;
        const std::uint32_t v = id_of(e.dst, class_of(e.dst, start.held_letter), start_started);
        add_edge(0, v, held, nba.accepting[e.dst]);
      }
    }
  } else {
    // Rebuilt during the mission: the states already reached, entered holding the letter.
    for (std::uint32_t q : start.states) {
      add_edge(0, id_of(q, class_of(q, start.held_letter), start_started), held, false);
    }
  }
  // Explore the nodes reachable from the start (the set D of Eq. 3: every node has a
  // self-loop, real or added).
  for (std::uint32_t v = 0; v < nodes_.size(); ++v) {
    const Node n = nodes_[v];
    if (n.state == kAux) continue;
    for (const auto& e : nba.out[n.state]) {
      LetterSet letters = e.guard & allowed;
      if (n.started) letters &= ~none_letter;  // no going back to the empty symbol
      if (letters.empty()) continue;
      const bool accepting = nba.accepting[e.dst];
      // Letters with a real self-loop at the target: one stable node per "started" value.
      const LetterSet stable = letters & real_loop[e.dst];
      const LetterSet stable_none = stable & none_letter;
      const LetterSet stable_action = stable & ~none_letter;
      if (!stable_none.empty()) add_edge(v, id_of(e.dst, -1, n.started), stable_none, accepting);
      if (!stable_action.empty()) add_edge(v, id_of(e.dst, -1, true), stable_action, accepting);
      // Letters without a real self-loop at the target: one split node per letter.
      const LetterSet split = letters & ~real_loop[e.dst];
      for (std::size_t h = split.next(0); h < num_letters; h = split.next(h + 1)) {
        const bool started = n.started || h != 0;
        add_edge(v, id_of(e.dst, static_cast<std::int32_t>(h), started),
                 LetterSet::single(num_letters, h), accepting);
      }
    }
  }
  // Accepting edges inside an SCC define V_F (Def. 3, Eq. 6); d_F by reverse BFS (Eq. 7).
  const auto comp = strongly_connected_components(out_, [](const Edge& e) { return e.dst; });
  const std::uint32_t n = num_nodes();
  vf_.assign(n, false);
  std::vector<std::vector<std::uint32_t>> in(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (Edge& e : out_[v]) {
      e.in_cycle = comp[e.dst] == comp[v];
      if (e.accepting && e.in_cycle) vf_[v] = true;
      in[e.dst].push_back(v);
    }
  }
  df_.assign(n, kInfinity);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (vf_[v]) {
      df_[v] = 0;
      queue.push_back(v);
    }
  }
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const std::uint32_t w = queue[i];
    for (std::uint32_t u : in[w]) {
      if (df_[u] == kInfinity) {
        df_[u] = df_[w] + 1;
        queue.push_back(u);
      }
    }
  }
}

std::size_t MissionGraph::num_edges() const {
  std::size_t k = 0;
  for (const auto& o : out_) k += o.size();
  return k;
}

std::string MissionGraph::describe(std::uint32_t v) const {
  const Node& n = nodes_[v];
  std::string s = n.state == kAux ? "q_aux" : "q" + std::to_string(n.state);
  if (n.split_letter >= 0) {
    s += "[holding " + nba_->alphabet.letter_name(static_cast<std::size_t>(n.split_letter)) + "]";
  }
  return s;
}

}  // namespace rearm::symbolic
