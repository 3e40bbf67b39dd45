// The paper's graph G (Appendix I-B exactly, GraphMode::kPaper). Truth: G derived by hand from
// the paper's definitions (the set D of Eq. 3, the runs of Eq. 4 with conditions i-iii,
// accepting edges of Def. 3, V_F of Eq. 6, d_F of Eq. 7) on automata written here, one of
// them the never claim that spin (an independent translator) gives for the formula of Figs.
// 6-7; and the actions the online controller (Appendix I-C) performs.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "ltl/parser.h"
#include "symbolic/mission_controller.h"
#include "symbolic/mission_graph.h"

namespace rearm::symbolic {
namespace {

using ltl::LetterSet;

// Node id of automaton state q (kAux for q_aux), or kInfinity.
std::uint32_t node_of(const MissionGraph& g, std::uint32_t q) {
  for (std::uint32_t v = 0; v < g.num_nodes(); ++v) {
    if (g.node(v).state == q) return v;
  }
  return MissionGraph::kInfinity;
}

// "src->dst:letters[ acc]" for every edge, sorted: G's edges as text independent of order.
std::vector<std::string> edges(const MissionGraph& g) {
  std::vector<std::string> out;
  for (std::uint32_t v = 0; v < g.num_nodes(); ++v) {
    for (const auto& e : g.out(v)) {
      std::string letters;
      for (std::size_t h = e.letters.next(0); h < e.letters.universe(); h = e.letters.next(h + 1))
        letters += std::to_string(h);
      out.push_back(g.describe(v) + "->" + g.describe(e.dst) + ":" + letters +
                    (e.accepting ? " acc" : ""));
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// `spin -f '[]<>p1 && []<>p2'` (spin 6.4.9), p1 = move(l1), p2 = move(l2):
//   T0_init: (p1 && p2) -> accept_S81; (p1) -> T1_S81; (1) -> T0_init
//   accept_S81: (1) -> T0_init
//   T1_S81: (p2) -> accept_S81; (1) -> T1_S81
// as q0 = T0_init, q1 = accept_S81 (final), q2 = T1_S81 over the one-action alphabet
// (letters 0 none, 1 move(l1), 2 move(l2)); the p1 && p2 edge has no letter there (pruned,
// the red dashed edges of Fig. 6).
ltl::ActionNba spin_fig6() {
  ltl::ActionNba nba;
  nba.alphabet = ltl::ActionAlphabet({"move(l1)", "move(l2)"});
  nba.add_state(false);
  nba.add_state(true);
  nba.add_state(false);
  nba.initial = {0};
  const LetterSet p1 = nba.alphabet.ap(0, true), p2 = nba.alphabet.ap(1, true);
  const LetterSet any = ~LetterSet(nba.alphabet.num_letters());
  nba.add_edge(0, 1, p1 & p2);
  nba.add_edge(0, 2, p1);
  nba.add_edge(0, 0, any);
  nba.add_edge(1, 0, any);
  nba.add_edge(2, 1, p2);
  nba.add_edge(2, 2, any);
  return nba;
}

TEST(PaperGraph, Figure7OnSpinsAutomaton) {
  const ltl::ActionNba nba = spin_fig6();
  const MissionGraph g(nba, MissionGraph::Start{{}, 0}, LetterSet(nba.alphabet.num_letters()),
                       GraphMode::kPaper);
  // D = {q_aux, q0, q2}: the final state q1 has no self-loop. Edges by hand: q_aux reads π0 =
  // none into q0 (its self-loop takes it, K = 1); q0 keeps itself under move(l1) and move(l2)
  // and reaches q2 under move(l1); q2 keeps itself under both and, under move(l2), runs
  // q2 -> q1 -> q0 (q1 without a move(l2) self-loop, q0 with one): accepting (q1 is final).
  ASSERT_EQ(g.num_nodes(), 3u);
  const std::uint32_t aux = g.start(), q0 = node_of(g, 0), q2 = node_of(g, 2);
  ASSERT_NE(q0, MissionGraph::kInfinity);
  ASSERT_NE(q2, MissionGraph::kInfinity);
  EXPECT_EQ(node_of(g, 1), MissionGraph::kInfinity);
  EXPECT_EQ(edges(g), (std::vector<std::string>{"q0->q0:12", "q0->q2:1", "q2->q0:2 acc",
                                                "q2->q2:12", "q_aux->q0:0"}));
  // Fig. 7: V_F is one node, d_F = 2, 1, 0 along q_aux, q0, V_F.
  EXPECT_FALSE(g.in_vf(aux));
  EXPECT_FALSE(g.in_vf(q0));
  EXPECT_TRUE(g.in_vf(q2));
  EXPECT_EQ(g.d_f(aux), 2u);
  EXPECT_EQ(g.d_f(q0), 1u);
  EXPECT_EQ(g.d_f(q2), 0u);
}

// Our own translation of the formula of Figs. 6-7 has another shape (its initial state is the
// final one, without a self-loop), and G the same distances: the controller in paper mode
// starts with one region and then alternates forever, as the formula asks.
TEST(PaperGraph, Figure7OnOwnTranslation) {
  MissionOptions o;
  o.graph = GraphMode::kPaper;
  MissionController mc(ltl::parse("[]<>move(l1) && []<>move(l2)"), o);
  const MissionGraph& g = mc.graph();
  ASSERT_EQ(g.num_nodes(), 3u);
  std::vector<std::uint32_t> d;
  int in_vf = 0;
  for (std::uint32_t v = 0; v < g.num_nodes(); ++v) {
    d.push_back(g.d_f(v));
    in_vf += g.in_vf(v);
  }
  EXPECT_EQ(g.d_f(g.start()), 2u);
  std::sort(d.begin(), d.end());
  EXPECT_EQ(d, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(in_vf, 1);
  std::vector<std::string> done;
  for (int k = 0; k < 7; ++k) {
    const auto a = mc.next_action();
    ASSERT_TRUE(a);
    done.push_back(a->to_string());
    mc.report_success();
  }
  for (std::size_t k = 1; k < done.size(); ++k) EXPECT_NE(done[k], done[k - 1]) << k;
  EXPECT_EQ(mc.status(), MissionStatus::Accepting);
}

// The runs of Eq. (4) on a hand-made automaton over {a, b} (letters 1, 2):
//   q0: a, b self-loop; b -> q1; b -> q3
//   q1 (final, no b self-loop): b -> q2
//   q2: b self-loop
//   q3: b self-loop; b -> q4
//   q4: b self-loop
// Under b from q0: q0 -> q1 -> q2 (q1 intermediate, final: accepting), q0 -> q3 (q3 has the b
// self-loop, so the run ends there: condition iii; q3 -> q4 is q3's own edge, not q0's, since
// q3 may not be an intermediate state: condition ii), and q0's own self-loop (K = 1).
TEST(PaperGraph, MultiHopRunsFollowConditionsOneToThree) {
  ltl::ActionNba nba;
  nba.alphabet = ltl::ActionAlphabet({"move(l1)", "move(l2)"});
  for (int q = 0; q < 5; ++q) nba.add_state(q == 1);
  nba.initial = {0};
  const LetterSet none = LetterSet::single(nba.alphabet.num_letters(), 0);
  const LetterSet a = nba.alphabet.ap(0, true), b = nba.alphabet.ap(1, true);
  nba.add_edge(0, 0, a | b | none);
  nba.add_edge(0, 1, b);
  nba.add_edge(0, 3, b);
  nba.add_edge(1, 2, b);
  nba.add_edge(2, 2, b);
  nba.add_edge(3, 3, b);
  nba.add_edge(3, 4, b);
  nba.add_edge(4, 4, b);
  const MissionGraph g(nba, MissionGraph::Start{{}, 0}, LetterSet(nba.alphabet.num_letters()),
                       GraphMode::kPaper);
  EXPECT_EQ(edges(g),
            (std::vector<std::string>{"q0->q0:12", "q0->q2:2 acc", "q0->q3:2", "q2->q2:2",
                                      "q3->q3:2", "q3->q4:2", "q4->q4:2", "q_aux->q0:0"}));
  EXPECT_EQ(node_of(g, 1), MissionGraph::kInfinity);  // no self-loop: not in D
  // The accepting edge q0 -> q2 lies in no cycle: V_F is empty, d_F infinite (no word visits
  // q1 infinitely often).
  EXPECT_EQ(g.d_f(g.start()), MissionGraph::kInfinity);
}

// The gap the self-loop construction closes: q0 -a-> q1 -a-> q0, q1 final, no self-loops:
// holding a visits q1 infinitely often, but no state has a self-loop, so the paper's D is
// {q_aux} and G has no edge.
TEST(PaperGraph, SymbolCyclingWithoutSelfLoopsIsLost) {
  ltl::ActionNba nba;
  nba.alphabet = ltl::ActionAlphabet({"move(l1)"});
  nba.add_state(false);
  nba.add_state(true);
  nba.initial = {0};
  const LetterSet a = nba.alphabet.ap(0, true);
  nba.add_edge(0, 1, a);
  nba.add_edge(1, 0, a);
  const LetterSet none(nba.alphabet.num_letters());
  const MissionGraph paper(nba, MissionGraph::Start{{}, 1}, none, GraphMode::kPaper);
  EXPECT_EQ(paper.num_nodes(), 1u);
  EXPECT_EQ(paper.d_f(paper.start()), MissionGraph::kInfinity);
  const MissionGraph selfloop(nba, MissionGraph::Start{{}, 1}, none, GraphMode::kSelfLoop);
  EXPECT_NE(selfloop.d_f(selfloop.start()), MissionGraph::kInfinity);
}

// A formula whose plan the paper's G loses (found by the property test's measurement,
// mission_property_test PropertyC; it needs the negation extension: in the paper's fragment
// none was found). F !grasp(M1) holds at the first instant (π0 = none), F grasp(M1) after it:
// the word none·grasp(M1)^ω. The self-loop construction performs grasp(M1); the paper's G,
// whose q_aux run of π0 stops at the first state with a none self-loop, finds no plan.
TEST(PaperGraph, FormulaWhosePlanThePapersGraphLoses) {
  auto run = [](GraphMode mode) {
    MissionOptions o;
    o.allow_negation = true;
    o.graph = mode;
    MissionController mc(ltl::parse("F !grasp(M1) & F grasp(M1)"), o);
    std::vector<std::string> done;
    while (const auto a = mc.next_action()) {
      done.push_back(a->to_string());
      mc.report_success();
      if (done.size() > 3) break;
    }
    return std::make_pair(mc.status(), done);
  };
  const auto [paper, paper_done] = run(GraphMode::kPaper);
  EXPECT_EQ(paper, MissionStatus::Infeasible);
  EXPECT_TRUE(paper_done.empty());
  const auto [selfloop, selfloop_done] = run(GraphMode::kSelfLoop);
  EXPECT_EQ(selfloop, MissionStatus::Accepting);
  EXPECT_EQ(selfloop_done, std::vector<std::string>{"grasp(M1)"});
}

TEST(PaperGraph, ModeNames) {
  EXPECT_EQ(parse_graph_mode("paper"), GraphMode::kPaper);
  EXPECT_EQ(parse_graph_mode("selfloop"), GraphMode::kSelfLoop);
  EXPECT_STREQ(to_string(GraphMode::kPaper), "paper");
  EXPECT_THROW(parse_graph_mode("Paper"), Error);
}

}  // namespace
}  // namespace rearm::symbolic
