// Tests of the automaton oracles (tests/support/nba_oracle.h) on hand-built automata whose
// languages are known: lasso acceptance, product emptiness with a witness, Tarjan SCCs.
#include "support/nba_oracle.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ltl/automaton.h"
#include "support/lasso.h"

namespace rearm::test_support {
namespace {

using ltl::ActionAlphabet;
using ltl::ActionNba;
using ltl::GeneralAlphabet;
using ltl::GeneralNba;
using Letters = std::vector<std::vector<std::string>>;

Lasso L(const Letters& u, const Letters& v) { return Lasso::from_names(u, v, {"p", "q"}); }

// G F p: 0 (initial) -p-> 1 (accepting), both states read !p into 0 and p into 1.
GeneralNba gf_p(GeneralAlphabet al) {
  GeneralNba a;
  a.alphabet = std::move(al);
  const std::uint32_t p = a.alphabet.ap_index("p");
  a.add_state(false);
  a.add_state(true);
  a.initial = {0};
  for (std::uint32_t s : {0u, 1u}) {
    a.add_edge(s, 1, a.alphabet.ap(p, true));
    a.add_edge(s, 0, a.alphabet.ap(p, false));
  }
  return a;
}

// F G `name` (positive) or F G !`name`: 0 loops on everything, jumps to accepting 1 which
// loops on the literal.
GeneralNba fg(GeneralAlphabet al, const std::string& name, bool positive) {
  GeneralNba a;
  a.alphabet = std::move(al);
  const std::uint32_t v = a.alphabet.ap_index(name);
  a.add_state(false);
  a.add_state(true);
  a.initial = {0};
  a.add_edge(0, 0, a.alphabet.top());
  a.add_edge(0, 1, a.alphabet.ap(v, positive));
  a.add_edge(1, 1, a.alphabet.ap(v, positive));
  return a;
}

// F `name`: 0 waits, accepting sink 1.
GeneralNba f_ap(GeneralAlphabet al, const std::string& name) {
  GeneralNba a;
  a.alphabet = std::move(al);
  const std::uint32_t v = a.alphabet.ap_index(name);
  a.add_state(false);
  a.add_state(true);
  a.initial = {0};
  a.add_edge(0, 0, a.alphabet.ap(v, false));
  a.add_edge(0, 1, a.alphabet.ap(v, true));
  a.add_edge(1, 1, a.alphabet.top());
  return a;
}

// G `name` (one accepting state looping on the literal).
GeneralNba g_ap(GeneralAlphabet al, const std::string& name, bool positive) {
  GeneralNba a;
  a.alphabet = std::move(al);
  const std::uint32_t v = a.alphabet.ap_index(name);
  a.add_state(true);
  a.initial = {0};
  a.add_edge(0, 0, a.alphabet.ap(v, positive));
  return a;
}

TEST(NbaOracle, GeneralAcceptanceOfGFp) {
  const GeneralNba a = gf_p(GeneralAlphabet());
  EXPECT_TRUE(accepts(a, L({}, {{}, {"p"}})));
  EXPECT_TRUE(accepts(a, L({}, {{"p"}})));
  EXPECT_TRUE(accepts(a, L({{}, {}}, {{}, {}, {"p", "q"}})));
  EXPECT_FALSE(accepts(a, L({{"p"}}, {{}})));
  EXPECT_FALSE(accepts(a, L({{"p"}, {"p"}}, {{"q"}})));
}

TEST(NbaOracle, AcceptingStateOnlyInThePrefixDoesNotCount) {
  // 0 is accepting and initial but left at once for a non-accepting loop.
  GeneralNba a;
  a.add_state(true);
  a.add_state(false);
  a.initial = {0};
  a.add_edge(0, 1, a.alphabet.top());
  a.add_edge(1, 1, a.alphabet.top());
  EXPECT_FALSE(accepts(a, L({}, {{"p"}})));
  EXPECT_FALSE(accepts(a, L({{"p"}}, {{}})));
}

TEST(NbaOracle, NondeterminismAndSeveralInitialStates) {
  const GeneralNba fgp = fg(GeneralAlphabet(), "p", true);
  EXPECT_TRUE(accepts(fgp, L({{}}, {{"p"}})));
  EXPECT_TRUE(accepts(fgp, L({{"p"}, {}}, {{"p"}})));
  EXPECT_FALSE(accepts(fgp, L({}, {{"p"}, {}})));
  // Union of G p and G q by two initial states.
  GeneralNba u;
  const std::uint32_t p = u.alphabet.ap_index("p");
  const std::uint32_t q = u.alphabet.ap_index("q");
  u.add_state(true);
  u.add_state(true);
  u.initial = {0, 1};
  u.add_edge(0, 0, u.alphabet.ap(p, true));
  u.add_edge(1, 1, u.alphabet.ap(q, true));
  EXPECT_TRUE(accepts(u, L({}, {{"p"}})));
  EXPECT_TRUE(accepts(u, L({}, {{"q"}})));
  EXPECT_FALSE(accepts(u, L({}, {{"p"}, {"q"}})));
}

TEST(NbaOracle, PropositionsAreMatchedByName) {
  const GeneralNba a = gf_p(GeneralAlphabet({"q", "p"}));
  // A lasso proposition unknown to the automaton is ignored.
  EXPECT_TRUE(accepts(a, Lasso::from_names({}, {{"p", "zz"}})));
  // An automaton proposition absent from the lasso is false.
  EXPECT_FALSE(accepts(a, Lasso::from_names({}, {{"q"}})));
}

TEST(NbaOracle, ActionAlphabetAcceptance) {
  // G F a over letters {none, a, b}.
  ActionNba a;
  a.alphabet = ActionAlphabet({"a", "b"});
  a.add_state(false);
  a.add_state(true);
  a.initial = {0};
  for (std::uint32_t s : {0u, 1u}) {
    a.add_edge(s, 1, a.alphabet.ap(0, true));
    a.add_edge(s, 0, a.alphabet.ap(0, false));
  }
  EXPECT_TRUE(accepts(a, Lasso::from_names({}, {{"a"}, {"b"}})));
  EXPECT_TRUE(accepts(a, Lasso::from_names({}, {{}, {"a"}}, {"b"})));
  EXPECT_FALSE(accepts(a, Lasso::from_names({{"a"}}, {{"b"}, {}})));
  EXPECT_THROW(accepts(a, Lasso::from_names({}, {{"a", "b"}})), std::invalid_argument);
  // Unknown names are ignored, so {a, zz} is the letter a.
  EXPECT_TRUE(accepts(a, Lasso::from_names({}, {{"a", "zz"}})));
}

TEST(NbaOracle, EmptyAndNonEmptyIntersections) {
  GeneralAlphabet shared;
  shared.ap_index("p");
  shared.ap_index("q");
  const GeneralNba gfp = gf_p(shared);
  const GeneralNba fg_not_p = fg(shared, "p", false);
  const GeneralNba fg_p = fg(shared, "p", true);
  const GeneralNba f_p = f_ap(shared, "p");
  const GeneralNba g_not_p = g_ap(shared, "p", false);

  EXPECT_FALSE(find_common_word(gfp, fg_not_p)) << "GF p & FG !p";
  EXPECT_FALSE(find_common_word(f_p, g_not_p)) << "F p & G !p";
  EXPECT_FALSE(find_common_word(fg_p, fg_not_p)) << "FG p & FG !p";

  for (const auto& [x, y] : std::vector<std::pair<const GeneralNba*, const GeneralNba*>>{
           {&gfp, &fg_p}, {&gfp, &f_p}, {&f_p, &fg_not_p}, {&gfp, &gfp}}) {
    const auto wit = find_common_word(*x, *y);
    ASSERT_TRUE(wit);
    // The witness is a real common word, and its run is well formed.
    EXPECT_TRUE(accepts(*x, wit->word)) << wit->to_string();
    EXPECT_TRUE(accepts(*y, wit->word)) << wit->to_string();
    ASSERT_FALSE(wit->cycle_states.empty());
    EXPECT_EQ(wit->word.prefix.size(), wit->prefix_states.size());
    EXPECT_EQ(wit->word.loop.size(), wit->cycle_states.size());
    bool acc_x = false, acc_y = false;
    for (const auto& [sx, sy] : wit->cycle_states) {
      acc_x = acc_x || x->accepting[sx];
      acc_y = acc_y || y->accepting[sy];
    }
    EXPECT_TRUE(acc_x && acc_y) << wit->to_string();
  }
}

TEST(NbaOracle, GeneralizedAcceptanceNeedsBothSetsInOneComponent) {
  // F G p & G F !p is empty although each automaton's accepting states are reachable in
  // the product (in different components).
  GeneralAlphabet shared;
  shared.ap_index("p");
  const GeneralNba fg_p = fg(shared, "p", true);
  GeneralNba gf_not_p = gf_p(shared);
  for (auto& edges : gf_not_p.out) {
    for (auto& e : edges) e.guard = shared.bdd().neg(e.guard);
  }
  EXPECT_FALSE(find_common_word(fg_p, gf_not_p));
  // An accepting state in a trivial component (no cycle) does not count.
  GeneralNba once;
  once.alphabet = shared;
  once.add_state(true);
  once.add_state(false);
  once.initial = {0};
  once.add_edge(0, 1, shared.top());
  once.add_edge(1, 1, shared.top());
  EXPECT_FALSE(find_common_word(once, fg_p));
}

TEST(NbaOracle, IntersectionOverDifferentPropositionsOfOneManager) {
  GeneralAlphabet base;
  base.ap_index("p");
  GeneralAlphabet extended = base;  // shares the manager, adds q as the next variable
  const GeneralNba gp = g_ap(base, "p", true);
  const GeneralNba fq = f_ap(extended, "q");
  const auto wit = find_common_word(gp, fq);
  ASSERT_TRUE(wit);
  EXPECT_TRUE(accepts(gp, wit->word));
  EXPECT_TRUE(accepts(fq, wit->word));
  EXPECT_TRUE(evaluate(ltl::Formula::conj(ltl::Formula::always(ltl::Formula::ap("p")),
                                          ltl::Formula::eventually(ltl::Formula::ap("q"))),
                       wit->word))
      << wit->to_string();
  const GeneralNba g_not_q = g_ap(extended, "q", false);
  EXPECT_FALSE(find_common_word(fq, g_not_q));
}

TEST(NbaOracle, RejectsAlphabetsThatDoNotShareAManager) {
  const GeneralNba a = gf_p(GeneralAlphabet());
  const GeneralNba b = gf_p(GeneralAlphabet());
  EXPECT_THROW(find_common_word(a, b), std::invalid_argument);
  // Shared manager, but two copies added different propositions as the same variable.
  GeneralAlphabet base;
  GeneralAlphabet x = base, y = base;
  const GeneralNba fx = f_ap(x, "x");
  const GeneralNba fy = f_ap(y, "y");
  EXPECT_THROW(find_common_word(fx, fy), std::invalid_argument);
}

TEST(NbaOracle, SampledLassosAreAcceptedWords) {
  Rng rng(3);
  const GeneralNba a = gf_p(GeneralAlphabet({"p", "q"}));
  const ltl::Formula gfp = ltl::Formula::always(ltl::Formula::eventually(ltl::Formula::ap("p")));
  const std::vector<Lasso> words = sample_accepted_lassos(a, rng, 100);
  EXPECT_EQ(words.size(), 100u);
  for (const Lasso& w : words) {
    EXPECT_TRUE(accepts(a, w)) << w.to_string();
    EXPECT_TRUE(evaluate(gfp, w)) << w.to_string();
  }
  // An empty language (the accepting state has no cycle) yields no words.
  GeneralNba once;
  once.add_state(true);
  once.add_state(false);
  once.initial = {0};
  once.add_edge(0, 1, once.alphabet.top());
  once.add_edge(1, 1, once.alphabet.top());
  EXPECT_TRUE(sample_accepted_lassos(once, rng, 10).empty());
}

TEST(NbaOracle, StronglyConnectedComponents) {
  // 0 -> 1 -> 2 -> 0, 2 -> 3, 3 -> 3, 4 unreachable, 5 -> 0 unreachable.
  const std::vector<std::vector<std::uint32_t>> adj = {{1}, {2}, {0, 3}, {3}, {}, {0}};
  const std::vector<int> c = strongly_connected_components(adj, {0});
  EXPECT_EQ(c[0], c[1]);
  EXPECT_EQ(c[1], c[2]);
  EXPECT_NE(c[2], c[3]);
  EXPECT_GE(c[3], 0);
  EXPECT_EQ(c[4], -1);
  EXPECT_EQ(c[5], -1);
  // Reverse topological order: the sink component {3} is numbered first.
  EXPECT_LT(c[3], c[0]);
  // A long chain does not overflow the (explicit) stack.
  const std::uint32_t n = 200000;
  std::vector<std::vector<std::uint32_t>> chain(n);
  for (std::uint32_t i = 0; i + 1 < n; ++i) chain[i].push_back(i + 1);
  chain[n - 1].push_back(0);
  const std::vector<int> cc = strongly_connected_components(chain, {0});
  EXPECT_EQ(cc[0], cc[n - 1]);
}

}  // namespace
}  // namespace rearm::test_support
