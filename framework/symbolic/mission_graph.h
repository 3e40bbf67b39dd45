// The graph G of paper Appendix I-B over the one-action-at-a-time Büchi automaton: pruning
// (the b_inf of Eq. 2 is built into the alphabet), the auxiliary initial state q_aux with
// the initial symbol π0, the set D, single-symbol multi-hop edges (Eq. 4) with every symbol
// that drives them (Eq. 9), accepting edges (Def. 3), V_F (Eq. 6) and d_F (Eq. 7) by BFS.
// Two constructions (GraphMode):
//
// kPaper: Appendix I-B exactly. Nodes are q_aux and the automaton states of D (Eq. 3): states
// with a self-loop that a run of single repeated symbols reaches. An edge q -> q' under σ is a
// run q, q^1, ..., q^K = q' of Eq. (4) reading σ at every step, its intermediate states without
// a σ self-loop (conditions i and ii), q' with one (iii). The edge is accepting (Def. 3) when a
// state it enters is final. q_aux's edges read π0 (b^{q_aux, q0} = π0, then π0 repeated).
//
// kSelfLoop (the default; completeness beyond the paper, the gap being that a symbol cycling
// through several states with no self-loop is a plan the paper's G cannot express): the
// automaton is self-loopized first (Michaud & Duret-Lutz, SPIN 2015, construction `sl`): a
// node is an automaton state together with the letter held when entering it, and holding that
// letter is always possible. For stutter-invariant (X-free) formulas this keeps the language.
// Nodes whose held letter already has a real self-loop are merged ("stable"), so G stays as
// small as the automaton in the common case. See mission_graph.cpp and docs/symbolic.md.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ltl/automaton.h"

namespace rearm::symbolic {

enum class GraphMode {
  kSelfLoop,  // self-loopized automaton (complete; the experiments' mode)
  kPaper,     // Appendix I-B exactly
};
const char* to_string(GraphMode m);
// "paper" or "selfloop"; throws rearm::Error naming the text otherwise.
GraphMode parse_graph_mode(const std::string& text);

// The automaton states a run from `states` can be in after reading `letter` once and then
// holding it (stuttering) as long as it likes: the held-letter word semantics of
// docs/symbolic.md. `scratch` is reused between calls. Sorted.
std::vector<std::uint32_t> read_holding(const ltl::ActionNba& nba,
                                        const std::vector<std::uint32_t>& states,
                                        std::size_t letter, std::vector<char>& scratch);

class MissionGraph;

// One choice of Eq. (8) at a node of G: an out-edge (index into MissionGraph::out) and the
// letter that drives it.
struct EdgeChoice {
  std::size_t edge;
  std::size_t letter;
};
// The choices Eq. (8) admits at node v, in edge order: each edge one hop closer to V_F (in V_F,
// each accepting edge of its cycle), with the held letter when it drives the edge (nothing to
// do; `held` nullopt: no letter may count as held), else its lowest letter not in `excluded`;
// an edge only excluded letters drive is left out. Empty when V_F is unreachable from v.
std::vector<EdgeChoice> eq8_choices(const MissionGraph& g, std::uint32_t v,
                                    std::optional<std::size_t> held,
                                    const ltl::LetterSet& excluded);

class MissionGraph {
 public:
  static constexpr std::uint32_t kInfinity = std::numeric_limits<std::uint32_t>::max();

  struct Node {
    std::uint32_t state;        // automaton state (kAux for q_aux)
    std::int32_t split_letter;  // letter held with only an added self-loop, or -1 (stable)
    bool started;  // some action has been performed (the held letter is not ε); kSelfLoop only
  };
  struct Edge {
    std::uint32_t dst;
    ltl::LetterSet letters;  // every symbol driving the edge (Eq. 9)
    bool accepting;          // enters a final state by a real transition (Def. 3); a (src, dst)
                             // pair has one edge per value (the symbols' runs may differ)
    bool in_cycle;           // dst can reach the source again (same SCC)
  };
  static constexpr std::uint32_t kAux = std::numeric_limits<std::uint32_t>::max();

  // Where G starts. Node 0 is always a start node like q_aux. From the beginning of the
  // mission (`states` empty) it holds π0 = held_letter and its edges lead where the
  // automaton's initial states go on π0. When G is rebuilt during the mission, `states` are
  // the automaton states the word performed so far can have reached (every branch, not just
  // the one the controller was following) and the start node's edges lead to each of them
  // with the letter held now. Letters: 0 = no predicate, i+1 = the automaton's proposition i.
  struct Start {
    std::vector<std::uint32_t> states;
    std::size_t held_letter = 0;
  };
  // `excluded`: letters known to be infeasible; their edges are left out (G and d_F
  // recomputed without infeasible actions). G keeps a pointer to `nba`.
  MissionGraph(const ltl::ActionNba& nba, Start start, const ltl::LetterSet& excluded,
               GraphMode mode = GraphMode::kSelfLoop);

  const ltl::ActionNba& automaton() const { return *nba_; }
  GraphMode mode() const { return mode_; }
  std::uint32_t num_nodes() const { return static_cast<std::uint32_t>(nodes_.size()); }
  // The start node (q_aux, or the current situation of a rebuilt G).
  std::uint32_t start() const { return 0; }
  const Node& node(std::uint32_t v) const { return nodes_[v]; }
  const std::vector<Edge>& out(std::uint32_t v) const { return out_[v]; }
  std::size_t num_edges() const;
  // V_F (Eq. 6), restricted to accepting edges inside an SCC so that an accepting edge
  // never leads to a node from which V_F is unreachable.
  bool in_vf(std::uint32_t v) const { return vf_[v]; }
  // d_F (Eq. 7): hops to V_F, kInfinity when unreachable.
  std::uint32_t d_f(std::uint32_t v) const { return df_[v]; }
  std::string describe(std::uint32_t v) const;
  // G as text: one line per node (name, d_F, V_F membership, initial/final automaton state),
  // then one per edge (source -> target, the symbols driving it, accepting or not).
  std::string to_text() const;

 private:
  void build_selfloop(const Start& start, const ltl::LetterSet& excluded);
  void build_paper(const Start& start, const ltl::LetterSet& excluded);
  std::uint32_t paper_node(std::uint32_t state, std::vector<std::uint32_t>& id_of_state);
  void add_edge(std::uint32_t src, std::uint32_t dst, const ltl::LetterSet& letters,
                bool accepting);
  void distances();

  const ltl::ActionNba* nba_;
  GraphMode mode_;
  std::vector<Node> nodes_;
  std::vector<std::vector<Edge>> out_;
  std::vector<bool> vf_;
  std::vector<std::uint32_t> df_;
};

}  // namespace rearm::symbolic
