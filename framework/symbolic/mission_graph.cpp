// Construction of G (paper Appendix I-B), exactly (GraphMode::kPaper) or on the self-loopized
// automaton (kSelfLoop).
//
// kPaper: a breadth-first search over the nodes reached from q_aux. From a node q and a
// feasible symbol σ, a search over (automaton state, final state entered so far) follows σ
// through states without a σ self-loop (Eq. 4, conditions i and ii) and stops at each state
// with one (iii): an edge q -> q' under σ, accepting (Def. 3) when the run entered a final
// state. The run's intermediate states repeat σ, so a path through a cycle of states without
// σ self-loops reaches nothing a simple path does not. q_aux reads π0 (b^{q_aux,q0} = π0 and,
// the run repeating one symbol, π0 again until a state with a π0 self-loop). The empty symbol
// drives only q_aux's edges: after the first action the robot holds an action (the word
// semantics of docs/symbolic.md), and before it q_aux's run already follows ε as far as it goes.
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
#include <utility>

#include "core/error.h"
#include "core/scc.h"

namespace rearm::symbolic {
using ltl::LetterSet;

const char* to_string(GraphMode m) { return m == GraphMode::kPaper ? "paper" : "selfloop"; }

GraphMode parse_graph_mode(const std::string& text) {
  if (text == "paper") return GraphMode::kPaper;
  if (text == "selfloop") return GraphMode::kSelfLoop;
  throw Error("unknown graph construction '" + text + "' (expected paper or selfloop)");
}

std::vector<std::uint32_t> read_holding(const ltl::ActionNba& nba,
                                        const std::vector<std::uint32_t>& states,
                                        std::size_t letter, std::vector<char>& scratch) {
  std::vector<char>& in = scratch;
  in.assign(nba.num_states(), 0);
  std::vector<std::uint32_t> out;
  for (std::uint32_t q : states) {
    for (const auto& e : nba.out[q]) {
      if (e.guard.test(letter) && !in[e.dst]) {
        in[e.dst] = 1;
        out.push_back(e.dst);
      }
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {  // holding the letter longer
    for (const auto& e : nba.out[out[i]]) {
      if (e.guard.test(letter) && !in[e.dst]) {
        in[e.dst] = 1;
        out.push_back(e.dst);
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<EdgeChoice> eq8_choices(const MissionGraph& g, std::uint32_t v,
                                    std::optional<std::size_t> held, const LetterSet& excluded) {
  std::vector<EdgeChoice> all;
  const std::uint32_t d = g.d_f(v);
  if (d == MissionGraph::kInfinity) return all;
  const bool in_vf = g.in_vf(v);
  const auto& out = g.out(v);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const MissionGraph::Edge& e = out[i];
    const bool candidate = in_vf ? (e.accepting && e.in_cycle) : g.d_f(e.dst) + 1 == d;
    if (!candidate) continue;
    if (held && e.letters.test(*held)) {
      all.push_back(EdgeChoice{i, *held});  // nothing to do
      continue;
    }
    // The lowest feasible action letter (letter 0 cannot be performed).
    std::size_t letter = e.letters.next(1);
    while (letter < e.letters.universe() && excluded.test(letter)) {
      letter = e.letters.next(letter + 1);
    }
    if (letter < e.letters.universe()) all.push_back(EdgeChoice{i, letter});
  }
  return all;
}

MissionGraph::MissionGraph(const ltl::ActionNba& nba, Start start, const LetterSet& excluded,
                           GraphMode mode)
    : nba_(&nba), mode_(mode) {
  const std::size_t num_letters = nba.alphabet.num_letters();
  REARM_DEMAND(excluded.universe() == num_letters, "excluded letters of another alphabet");
  REARM_DEMAND(start.held_letter < num_letters, "held letter outside the alphabet");
  for (std::uint32_t q : start.states) {
    REARM_DEMAND(q < nba.num_states(), "unknown start state");
  }
  if (mode == GraphMode::kPaper) {
    build_paper(start, excluded);
  } else {
    build_selfloop(start, excluded);
  }
  distances();
}

// One edge per (src, dst, accepting): the symbols of one edge all drive an accepting run or
// all a non-accepting one, so choosing any of them traverses the edge the controller chose.
void MissionGraph::add_edge(std::uint32_t src, std::uint32_t dst, const LetterSet& letters,
                            bool accepting) {
  for (Edge& e : out_[src]) {
    if (e.dst == dst && e.accepting == accepting) {
      e.letters |= letters;
      return;
    }
  }
  out_[src].push_back(Edge{dst, letters, accepting, false});
}

namespace {

// Per automaton state, the letters of its self-loop.
std::vector<LetterSet> self_loops(const ltl::ActionNba& nba) {
  std::vector<LetterSet> loop(nba.num_states(), LetterSet(nba.alphabet.num_letters()));
  for (std::uint32_t q = 0; q < nba.num_states(); ++q) {
    for (const auto& e : nba.out[q]) {
      if (e.dst == q) loop[q] |= e.guard;
    }
  }
  return loop;
}

// The ends of the runs of Eq. (4) from `from` reading `letter` at every step: each state with
// a `letter` self-loop reached through states without one, with whether a final state was
// entered on the way (both values when two runs differ). `from` itself is the run's q^0.
std::vector<std::pair<std::uint32_t, bool>> runs_of(const ltl::ActionNba& nba,
                                                    const std::vector<LetterSet>& loop,
                                                    std::uint32_t from, std::size_t letter) {
  std::vector<std::pair<std::uint32_t, bool>> ends;
  std::vector<char> seen(2 * static_cast<std::size_t>(nba.num_states()), 0);
  std::vector<std::pair<std::uint32_t, bool>> stack{{from, false}};
  bool first = true;
  while (!stack.empty()) {
    const auto [q, acc] = stack.back();
    stack.pop_back();
    for (const auto& e : nba.out[q]) {
      if (!e.guard.test(letter)) continue;
      if (first && e.dst == q) continue;  // the source's own self-loop: added below
      const bool entered = acc || nba.accepting[e.dst];
      char& mark = seen[2 * static_cast<std::size_t>(e.dst) + (entered ? 1 : 0)];
      if (mark) continue;
      mark = 1;
      if (loop[e.dst].test(letter)) {
        ends.emplace_back(e.dst, entered);
      } else {
        stack.emplace_back(e.dst, entered);
      }
    }
    first = false;
  }
  if (loop[from].test(letter)) ends.emplace_back(from, nba.accepting[from]);  // K = 1
  return ends;
}

}  // namespace

std::uint32_t MissionGraph::paper_node(std::uint32_t state,
                                       std::vector<std::uint32_t>& id_of_state) {
  if (id_of_state[state] == kInfinity) {
    id_of_state[state] = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{state, -1, true});
    out_.emplace_back();
  }
  return id_of_state[state];
}

// Appendix I-B exactly (see the file's head).
void MissionGraph::build_paper(const Start& start, const LetterSet& excluded) {
  const ltl::ActionNba& nba = *nba_;
  const std::size_t num_letters = nba.alphabet.num_letters();
  const std::vector<LetterSet> loop = self_loops(nba);
  const LetterSet allowed = ~excluded;
  std::vector<std::uint32_t> id_of_state(nba.num_states(), kInfinity);
  nodes_.push_back(Node{kAux, -1, start.held_letter != 0});
  out_.emplace_back();
  const std::size_t h = start.held_letter;
  const LetterSet held = LetterSet::single(num_letters, h);
  // Node 0: q_aux reading π0 from the initial states, or (G rebuilt during the mission) the
  // states the word performed so far can be in, holding its last letter.
  if (start.states.empty()) {
    // The run of Eq. (4) from q_aux: q^1 = q0, then π0 repeated until a π0 self-loop.
    for (std::uint32_t q0 : nba.initial) {
      if (loop[q0].test(h)) {
        add_edge(0, paper_node(q0, id_of_state), held, nba.accepting[q0]);
        continue;
      }
      for (const auto& [q, acc] : runs_of(nba, loop, q0, h)) {
        add_edge(0, paper_node(q, id_of_state), held, acc || nba.accepting[q0]);
      }
    }
  } else {
    // start.states is closed under holding the letter: its states with a self-loop under it.
    for (std::uint32_t q : start.states) {
      if (loop[q].test(h)) add_edge(0, paper_node(q, id_of_state), held, false);
    }
  }
  for (std::uint32_t v = 1; v < nodes_.size(); ++v) {
    const std::uint32_t q = nodes_[v].state;
    for (std::size_t a = allowed.next(1); a < num_letters; a = allowed.next(a + 1)) {
      for (const auto& [q2, acc] : runs_of(nba, loop, q, a)) {
        add_edge(v, paper_node(q2, id_of_state), LetterSet::single(num_letters, a), acc);
      }
    }
  }
}

// The self-loopized construction (see the file's head).
void MissionGraph::build_selfloop(const Start& start, const LetterSet& excluded) {
  const ltl::ActionNba& nba = *nba_;
  const std::size_t num_letters = nba.alphabet.num_letters();
  const std::vector<LetterSet> real_loop = self_loops(nba);
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
}

// Accepting edges inside an SCC define V_F (Def. 3, Eq. 6): an accepting edge that no cycle
// contains (one out of q_aux) can be traversed once, not infinitely often. d_F by reverse BFS
// (Eq. 7).
void MissionGraph::distances() {
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
  if (mode_ == GraphMode::kSelfLoop && n.state != kAux && !n.started) s += "[before acting]";
  return s;
}

std::string MissionGraph::to_text() const {
  const ltl::ActionNba& nba = *nba_;
  std::string vf;
  for (std::uint32_t v = 0; v < num_nodes(); ++v) {
    if (vf_[v]) vf += (vf.empty() ? "" : ", ") + describe(v);
  }
  std::string s = std::string("G (") +
                  (mode_ == GraphMode::kPaper ? "paper construction, Appendix I-B"
                                              : "self-loopized automaton") +
                  "): " + std::to_string(num_nodes()) + " nodes, " + std::to_string(num_edges()) +
                  " edges, V_F = {" + vf + "}\n";
  for (std::uint32_t v = 0; v < num_nodes(); ++v) {
    const Node& n = nodes_[v];
    s += "node " + describe(v) + ": d_F " +
         (df_[v] == kInfinity ? std::string("inf") : std::to_string(df_[v]));
    if (vf_[v]) s += ", in V_F";
    if (n.state != kAux) {
      if (std::find(nba.initial.begin(), nba.initial.end(), n.state) != nba.initial.end()) {
        s += ", initial state";
      }
      if (nba.accepting[n.state]) s += ", final state";
    }
    s += "\n";
  }
  for (std::uint32_t v = 0; v < num_nodes(); ++v) {
    for (const Edge& e : out_[v]) {
      std::string letters;
      for (std::size_t h = e.letters.next(0); h < e.letters.universe(); h = e.letters.next(h + 1)) {
        letters += (letters.empty() ? "" : ", ") + nba.alphabet.letter_name(h);
      }
      s += "edge " + describe(v) + " -> " + describe(e.dst) + ": {" + letters + "}";
      if (e.accepting) s += e.in_cycle ? " accepting" : " accepting (in no cycle)";
      s += "\n";
    }
  }
  return s;
}

}  // namespace rearm::symbolic
