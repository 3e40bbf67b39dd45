// HOA, never-claim and DOT input/output. Independent truth (docs/architecture.md rule 9):
// languages are compared by a local lasso-acceptance check (the product of the automaton
// with the positions of u·v^ω, searched for a reachable cycle through an accepting state);
// spin's never claims (captured in tests/ltl/data/spin_<n>.never and, when spin is
// installed, produced live) are checked against the formulas' meaning on hand-chosen words
// and against the direct LTL evaluator of tests/support on seeded random words.
#include "ltl/automaton_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "ltl/formula.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"

namespace rearm::ltl {
namespace {

using test_support::Lasso;
using Ref = BddManager::Ref;

using test_support::accepts;  // lasso acceptance oracle (support/nba_oracle.h)

// ---------------------------------------------------------------------------------------
// Helpers.

Lasso word(const std::vector<std::vector<std::string>>& u,
           const std::vector<std::vector<std::string>>& v,
           const std::vector<std::string>& aps = {"p", "q", "r"}) {
  return Lasso::from_names(u, v, aps);
}

Lasso random_word(Rng& rng, const std::vector<std::string>& aps, bool one_hot) {
  test_support::LassoOptions o;
  o.max_prefix = 3;
  o.one_hot = one_hot;
  return test_support::random_lasso(rng, aps, o);
}

// Same word with the propositions renamed (position i of aps to names[i]).
Lasso renamed(Lasso w, const std::vector<std::string>& names) {
  w.aps = names;
  return w;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << path << " (tests run from the project root)";
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

template <class F>
void expect_error(F f, int line, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no rearm::Error; expected one at line " << line << " about " << fragment;
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("line " + std::to_string(line) + ":"), std::string::npos) << m;
    EXPECT_NE(m.find(fragment), std::string::npos) << m;
  }
}

void expect_hoa_error(const std::string& text, int line, const std::string& fragment) {
  expect_error([&] { read_hoa(text); }, line, fragment);
}

void expect_never_error(const std::string& text, int line, const std::string& fragment) {
  expect_error([&] { read_never_claim(text); }, line, fragment);
}

std::string state_name(const GeneralNba& a, std::uint32_t q) {
  return q < a.state_names.size() ? a.state_names[q] : std::string();
}

// Exact equality of two automata whose alphabets share one BDD manager (guards are then
// canonical: equal functions have equal Refs).
void expect_same_structure(const GeneralNba& x, const GeneralNba& y) {
  ASSERT_EQ(x.alphabet.bdd_ptr(), y.alphabet.bdd_ptr());
  EXPECT_EQ(x.alphabet.aps(), y.alphabet.aps());
  ASSERT_EQ(x.num_states(), y.num_states());
  EXPECT_EQ(x.initial, y.initial);
  EXPECT_EQ(x.accepting, y.accepting);
  for (std::uint32_t q = 0; q < x.num_states(); ++q) {
    EXPECT_EQ(state_name(x, q), state_name(y, q)) << "state " << q;
    ASSERT_EQ(x.out[q].size(), y.out[q].size()) << "state " << q;
    for (std::size_t k = 0; k < x.out[q].size(); ++k) {
      EXPECT_EQ(x.out[q][k].dst, y.out[q][k].dst) << "state " << q << " edge " << k;
      EXPECT_EQ(x.out[q][k].guard, y.out[q][k].guard) << "state " << q << " edge " << k;
    }
  }
}

void expect_same_language(const GeneralNba& x, const GeneralNba& y, std::uint64_t seed,
                          int words = 300) {
  Rng rng(seed);
  std::vector<std::string> aps = x.alphabet.aps();
  for (const std::string& p : y.alphabet.aps()) {
    if (x.alphabet.find_ap(p) < 0) aps.push_back(p);
  }
  for (int i = 0; i < words; ++i) {
    const Lasso w = random_word(rng, aps, false);
    ASSERT_EQ(accepts(x, w), accepts(y, w)) << w.to_string();
  }
}

Ref random_guard(Rng& rng, const GeneralAlphabet& alphabet) {
  if (rng.bernoulli(0.15)) return alphabet.top();
  Ref g = alphabet.bottom();
  const int cubes = 1 + static_cast<int>(rng.index(2));
  for (int c = 0; c < cubes; ++c) {
    Ref cube = alphabet.top();
    for (std::uint32_t i = 0; i < alphabet.aps().size(); ++i) {
      const std::uint64_t k = rng.index(3);  // absent, positive, negative
      if (k > 0) cube = alphabet.conj(cube, alphabet.ap(i, k == 1));
    }
    g = alphabet.disj(g, cube);
  }
  return g;
}

GeneralNba random_general(Rng& rng, std::vector<std::string> aps) {
  GeneralNba a;
  a.alphabet = GeneralAlphabet(std::move(aps));
  const std::uint32_t n = 1 + static_cast<std::uint32_t>(rng.index(6));
  for (std::uint32_t q = 0; q < n; ++q) a.add_state(rng.bernoulli(0.4));
  a.initial.push_back(static_cast<std::uint32_t>(rng.index(n)));
  if (n > 1 && rng.bernoulli(0.3)) {
    const auto other = static_cast<std::uint32_t>(rng.index(n));
    if (other != a.initial[0]) a.initial.push_back(other);
  }
  for (std::uint32_t q = 0; q < n; ++q) {
    const std::uint64_t edges = rng.index(4);
    for (std::uint64_t k = 0; k < edges; ++k) {
      a.add_edge(q, static_cast<std::uint32_t>(rng.index(n)), random_guard(rng, a.alphabet));
    }
  }
  if (rng.bernoulli(0.3)) {
    for (std::uint32_t q = 0; q < n; ++q) {
      a.state_names.push_back(rng.bernoulli(0.5) ? "s\"" + std::to_string(q) + "\\ */" : "");
    }
  }
  return a;
}

ActionNba random_action(Rng& rng, std::vector<std::string> aps) {
  ActionNba a;
  a.alphabet = ActionAlphabet(std::move(aps));
  const std::uint32_t n = 1 + static_cast<std::uint32_t>(rng.index(5));
  for (std::uint32_t q = 0; q < n; ++q) a.add_state(rng.bernoulli(0.4));
  a.initial.push_back(static_cast<std::uint32_t>(rng.index(n)));
  for (std::uint32_t q = 0; q < n; ++q) {
    const std::uint64_t edges = rng.index(4);
    for (std::uint64_t k = 0; k < edges; ++k) {
      LetterSet g(a.alphabet.num_letters());
      for (std::size_t l = 0; l < g.universe(); ++l) {
        if (rng.bernoulli(0.5)) g.set(l);
      }
      a.add_edge(q, static_cast<std::uint32_t>(rng.index(n)), g);
    }
  }
  return a;
}

// GF a & GF b over the general alphabet: 3 states, hand-built.
GeneralNba gfa_gfb() {
  GeneralNba a;
  a.alphabet = GeneralAlphabet({"a", "b"});
  const GeneralAlphabet& s = a.alphabet;
  for (int q = 0; q < 3; ++q) a.add_state(q == 2);
  a.initial = {0};
  a.state_names = {"wait a", "wait b", "seen both"};
  a.add_edge(0, 0, s.ap(0, false));
  a.add_edge(0, 1, s.conj(s.ap(0, true), s.ap(1, false)));
  a.add_edge(0, 2, s.conj(s.ap(0, true), s.ap(1, true)));
  a.add_edge(1, 1, s.ap(1, false));
  a.add_edge(1, 2, s.ap(1, true));
  a.add_edge(2, 0, s.top());
  return a;
}

// ---------------------------------------------------------------------------------------
// The lasso oracle itself, on automata whose languages are obvious.

TEST(LassoOracle, AgreesWithHandBuiltAutomaton) {
  const GeneralNba a = gfa_gfb();
  const std::vector<std::string> ab = {"a", "b"};
  EXPECT_TRUE(accepts(a, word({}, {{"a"}, {"b"}}, ab)));
  EXPECT_TRUE(accepts(a, word({{}}, {{"a", "b"}}, ab)));
  EXPECT_FALSE(accepts(a, word({}, {{"a"}}, ab)));
  EXPECT_FALSE(accepts(a, word({{"a"}, {"b"}}, {{}}, ab)));
}

// ---------------------------------------------------------------------------------------
// HOA writer and round trips.

TEST(HoaWriter, HeaderAndBody) {
  const std::string text = to_hoa(gfa_gfb(), "GFa & GFb");
  EXPECT_EQ(text.rfind("HOA: v1\n", 0), 0u) << text;
  for (const char* line : {"name: \"GFa & GFb\"\n", "States: 3\n", "Start: 0\n",
                           "AP: 2 \"a\" \"b\"\n", "acc-name: Buchi\n", "Acceptance: 1 Inf(0)\n",
                           "properties: trans-labels explicit-labels state-acc\n", "--BODY--\n",
                           "State: 0 \"wait a\"\n", "State: 2 \"seen both\" {0}\n", "[!0] 0\n",
                           "[t] 0\n", "--END--\n"}) {
    EXPECT_NE(text.find(line), std::string::npos) << "missing " << line << " in\n" << text;
  }
  EXPECT_EQ(text.find("rearm-alphabet"), std::string::npos);
}

TEST(HoaWriter, EmptyAutomatonAndEscapes) {
  GeneralNba a;
  a.alphabet = GeneralAlphabet({"x\"y", "back\\slash"});
  const std::string text = to_hoa(a);
  EXPECT_NE(text.find("States: 0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("Start:"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nname:"), std::string::npos) << text;
  EXPECT_NE(text.find(R"(AP: 2 "x\"y" "back\\slash")"), std::string::npos) << text;
  const GeneralNba b = read_hoa(text);
  EXPECT_EQ(b.num_states(), 0u);
  EXPECT_TRUE(b.initial.empty());
  EXPECT_EQ(b.alphabet.aps(), a.alphabet.aps());
}

TEST(HoaRoundTrip, HandBuiltIsExact) {
  const GeneralNba a = gfa_gfb();
  expect_same_structure(a, read_hoa(to_hoa(a), a.alphabet));
}

TEST(HoaRoundTrip, RandomGeneralIsExactAndKeepsTheLanguage) {
  Rng rng(20240601);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const GeneralNba a = random_general(rng, {"a", "b", "c"});
    const std::string text = to_hoa(a, "random " + std::to_string(trial));
    // Read into the same manager: exact structural equality.
    expect_same_structure(a, read_hoa(text, a.alphabet));
    // Read into a fresh alphabet: the same language.
    const GeneralNba fresh = read_hoa(text);
    EXPECT_EQ(fresh.alphabet.aps(), a.alphabet.aps());
    expect_same_language(a, fresh, 1000 + static_cast<std::uint64_t>(trial), 60);
    if (HasFatalFailure()) return;
  }
}

TEST(HoaRoundTrip, ReadsIntoAnExistingAlphabetByName) {
  // The target alphabet already has b (and an unrelated z) in another order.
  GeneralAlphabet target({"z", "b"});
  const GeneralNba a = gfa_gfb();
  const GeneralNba b = read_hoa(to_hoa(a), target);
  EXPECT_EQ(b.alphabet.aps(), (std::vector<std::string>{"z", "b", "a"}));
  EXPECT_EQ(b.alphabet.bdd_ptr(), target.bdd_ptr());
  expect_same_language(a, b, 7);
}

TEST(HoaRoundTrip, ActionAlphabetIsExactOnOneActionSymbols) {
  Rng rng(77);
  const std::vector<std::string> aps = {"move(l1)", "grasp(M1)", "release(M1,l2)"};
  for (int trial = 0; trial < 100; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const ActionNba a = random_action(rng, aps);
    const std::string text = to_hoa(a);
    EXPECT_NE(text.find("rearm-alphabet: \"one-action\""), std::string::npos) << text;
    const GeneralNba g = read_hoa(text);
    EXPECT_EQ(g.alphabet.aps(), aps);
    EXPECT_EQ(g.num_states(), a.num_states());
    for (int i = 0; i < 60; ++i) {
      const Lasso w = random_word(rng, aps, /*one_hot=*/true);
      ASSERT_EQ(accepts(a, w), accepts(g, w)) << w.to_string() << "\n" << text;
    }
  }
}

// ---------------------------------------------------------------------------------------
// HOA reader on hand-written text in the style of Spot (HOA v1 specification).

TEST(HoaReader, TransitionBasedBuchiIsSplitOntoStates) {
  // Spot's `ltl2tgba 'GFa'`: one state, acceptance on the transition reading a.
  const char* text = R"txt(HOA: v1
name: "G F a"
States: 1
Start: 0
AP: 1 "a"
acc-name: Buchi
Acceptance: 1 Inf(0)
properties: trans-labels explicit-labels trans-acc complete
properties: deterministic stutter-invariant
--BODY--
State: 0
[0] 0 {0}
[!0] 0
--END--
)txt";
  const GeneralNba a = read_hoa(text);
  EXPECT_EQ(a.num_states(), 2u);  // (0, unmarked) and (0, marked)
  EXPECT_EQ(a.initial.size(), 1u);
  const std::vector<std::string> aps = {"a"};
  EXPECT_TRUE(accepts(a, word({}, {{"a"}}, aps)));
  EXPECT_TRUE(accepts(a, word({{}}, {{}, {"a"}}, aps)));
  EXPECT_FALSE(accepts(a, word({{"a"}}, {{}}, aps)));
  EXPECT_FALSE(accepts(a, word({}, {{}}, aps)));
}

TEST(HoaReader, GeneralizedSpecExampleWithAliasesCommentsAndUnknownHeaders) {
  // Büchi version of the specification's "TGBA with explicit labels using aliases", for
  // GF(a & !(b & c)) with a nested comment, an unknown header and a tool header.
  const char* text = R"txt(HOA: v1 /* a /* nested */ comment */
tool: "hand" "1.0"
name: "GF(a & !(b&c))"
States: 1
Start: 0
spot-state-player: 0 1 "x" t
AP: 3 "a" "b" "c"
Alias: @a 0
Alias: @bc 1 & 2
Alias: @good @a & !@bc
Acceptance: 1 Inf(0)
--BODY--
State: 0 "only"
[!@good] 0
[@good] 0 {0}
--END--
)txt";
  const GeneralNba a = read_hoa(text);
  ASSERT_EQ(a.num_states(), 2u);
  EXPECT_EQ(a.state_names[0], "only");
  EXPECT_TRUE(accepts(a, word({}, {{"a"}, {"b"}})));
  EXPECT_TRUE(accepts(a, word({}, {{"a", "b"}, {"a", "c"}}, {"a", "b", "c"})));
  EXPECT_FALSE(accepts(a, word({{"a"}}, {{"a", "b", "c"}}, {"a", "b", "c"})));
  EXPECT_FALSE(accepts(a, word({{"a"}}, {{"c"}}, {"a", "b", "c"})));
}

TEST(HoaReader, StateBasedKeepsStateNumbersAndNames) {
  const char* text = R"txt(HOA: v1
States: 3
Start: 2
Start: 0
AP: 2 "p" "q"
acc-name: Buchi
Acceptance: 1 Inf(0)
--BODY--
State: 2 "two"
[0 | 1] 1
State: 0 "zero" {0}
[t] 0
State: 1 "one" {0}
[(0 & !1) | f] 1
[!(0 & !1)] 0
--END--
)txt";
  const GeneralNba a = read_hoa(text);
  ASSERT_EQ(a.num_states(), 3u);
  EXPECT_EQ(a.initial, (std::vector<std::uint32_t>{2, 0}));
  EXPECT_EQ(a.accepting, (std::vector<bool>{true, true, false}));
  EXPECT_EQ(a.state_names, (std::vector<std::string>{"zero", "one", "two"}));
  const GeneralAlphabet& s = a.alphabet;
  ASSERT_EQ(a.out[1].size(), 2u);
  EXPECT_EQ(a.out[1][0].guard, s.conj(s.ap(0, true), s.ap(1, false)));
  EXPECT_EQ(a.out[2][0].guard, s.disj(s.ap(0, true), s.ap(1, true)));
}

TEST(HoaReader, StateLabelsAndMultipleInitialStates) {
  // The specification's "Non-deterministic State-based Büchi automaton (à la Wring)" (GFa).
  const char* text = R"txt(HOA: v1
name: "GFa"
States: 2
Start: 0
Start: 1
acc-name: Buchi
Acceptance: 1 Inf(0)
AP: 1 "a"
--BODY--
State: [0] 0 {0}
  0 1
State: [!0] 1
  0 1
--END--
)txt";
  const GeneralNba a = read_hoa(text);
  const std::vector<std::string> aps = {"a"};
  EXPECT_EQ(a.initial.size(), 2u);
  EXPECT_TRUE(accepts(a, word({}, {{"a"}, {}}, aps)));
  EXPECT_TRUE(accepts(a, word({{}, {}}, {{"a"}}, aps)));
  EXPECT_FALSE(accepts(a, word({{"a"}}, {{}}, aps)));
}

TEST(HoaReader, MixedStateAndTransitionMarksAndUnusedSets) {
  // Two sets declared, only set 1 in the condition; set 0 marks are ignored. State 1's mark
  // applies to all its outgoing edges. Language: F(b) & GF(a | b) over this structure.
  const char* text = R"txt(HOA: v1
States: 2
Start: 0
AP: 2 "a" "b"
Acceptance: 2 Inf(1)
--BODY--
State: 0
[!1] 0 {0}
[1] 1
State: 1 {1}
[0 | 1] 1
[!0 & !1] 1 {0}
--END--
)txt";
  const GeneralNba a = read_hoa(text);
  const std::vector<std::string> ab = {"a", "b"};
  EXPECT_TRUE(accepts(a, word({{}, {"b"}}, {{}}, ab)));
  EXPECT_FALSE(accepts(a, word({}, {{"a"}}, ab)));
}

TEST(HoaReader, TrivialAcceptanceConditions) {
  const std::string body = R"txt(
AP: 1 "a"
--BODY--
State: 0
[0] 0
--END--
)txt";
  const GeneralNba all = read_hoa("HOA: v1\nStart: 0\nacc-name: all\nAcceptance: 0 t" + body);
  EXPECT_EQ(all.accepting, std::vector<bool>{true});
  EXPECT_TRUE(accepts(all, word({}, {{"a"}}, {"a"})));
  const GeneralNba none = read_hoa("HOA: v1\nStart: 0\nAcceptance: 0 f" + body);
  EXPECT_FALSE(accepts(none, word({}, {{"a"}}, {"a"})));
  // t & Inf(0) is Büchi; Inf(0) | t is t.
  const GeneralNba buchi = read_hoa("HOA: v1\nStart: 0\nAcceptance: 1 t & (Inf(0))" + body);
  EXPECT_EQ(buchi.accepting, std::vector<bool>{false});
  const GeneralNba t = read_hoa("HOA: v1\nStart: 0\nAcceptance: 1 Inf(0) | t" + body);
  EXPECT_EQ(t.accepting, std::vector<bool>{true});
  // No Start: the empty language.
  const GeneralNba empty = read_hoa("HOA: v1\nAcceptance: 0 t" + body);
  EXPECT_TRUE(empty.initial.empty());
  EXPECT_FALSE(accepts(empty, word({}, {{"a"}}, {"a"})));
}

TEST(HoaReader, WithoutStatesHeaderCountsReferencedStates) {
  const GeneralNba a =
      read_hoa("HOA: v1 Start: 0 AP: 0 Acceptance: 1 Inf(0) --BODY-- State: 0 {0} [t] 3 --END--");
  EXPECT_EQ(a.num_states(), 4u);
  EXPECT_TRUE(a.out[3].empty());
}

TEST(HoaReader, ErrorsNameTheLine) {
  const std::string head = "HOA: v1\nStates: 2\nStart: 0\nAP: 1 \"a\"\nAcceptance: 1 Inf(0)\n";
  // Implicit labels (the specification's ltl2dstar-style example).
  expect_hoa_error(head + "--BODY--\nState: 0 {0}\n 1 1\nState: 1\n[t] 1\n--END--\n", 8,
                   "implicit labels");
  // Generalized Büchi.
  expect_hoa_error(
      "HOA: v1\nStart: 0\nacc-name: generalized-Buchi 2\nAcceptance: 2 Inf(0)&Inf(1)\n"
      "--BODY--\n--END--\n",
      4, "unsupported acceptance condition");
  expect_hoa_error("HOA: v1\nAcceptance: 1 Fin(0)\n--BODY--\n--END--\n", 2,
                   "unsupported acceptance condition");
  expect_hoa_error("HOA: v1\nAcceptance: 2 (Fin(0) & Inf(1))\n--BODY--\n--END--\n", 2,
                   "unsupported acceptance condition");
  expect_hoa_error("HOA: v1\nAcceptance: 1 Inf(!0)\n--BODY--\n--END--\n", 2,
                   "unsupported acceptance condition");
  expect_hoa_error("HOA: v1\nAcceptance: 1 Inf(1)\n--BODY--\n--END--\n", 2, "out of range");
  expect_hoa_error("HOA: v1\nAcceptance: 1 Inf(0) &\n--BODY--\n--END--\n", 2,
                   "incomplete acceptance");
  // Universal branching.
  expect_hoa_error(head + "--BODY--\nState: 0\n[0] 0 & 1\n--END--\n", 8, "universal branching");
  expect_hoa_error("HOA: v1\nStates: 2\nStart: 0 & 1\nAcceptance: 0 t\n--BODY--\n--END--\n", 3,
                   "alternating");
  // Labels.
  expect_hoa_error(head + "--BODY--\nState: 0\n[1] 0\n--END--\n", 8, "proposition 1 out of range");
  expect_hoa_error(head + "--BODY--\nState: 0\n[@x] 0\n--END--\n", 8, "undefined alias @x");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0 & ] 0\n--END--\n", 8, "expected a label");
  expect_hoa_error(head + "--BODY--\nState: 0\n[(0] 0\n--END--\n", 8, "expected ')'");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0 0\n--END--\n", 8, "expected ']'");
  expect_hoa_error(
      "HOA: v1\nAP: 1 \"a\"\nAlias: @a 0\nAlias: @a !0\nAcceptance: 0 t\n--BODY--\n"
      "--END--\n",
      4, "redefined");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0] 0\nState: 0\n--END--\n", 9, "declared twice");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0] 5\n--END--\n", 8, "state 5 out of range");
  expect_hoa_error(head + "--BODY--\nState: 0 [0] 0 {3}\n--END--\n", 7, "acceptance set 3");
  expect_hoa_error(head + "--BODY--\n[0] 0\n--END--\n", 7, "expected 'State:'");
  expect_hoa_error(head + "--BODY--\nState: 0 \"unterminated\n[0] 0\n", 7, "unterminated string");
  expect_hoa_error(head + "/* open\n--BODY--\n", 6, "unterminated comment");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0] 0\n", 9, "missing --END--");
  expect_hoa_error(head + "--BODY--\nState: 0\n--END--\nHOA: v1\n", 9, "after --END--");
  expect_hoa_error(head + "--BODY--\nState: 0\n --ABORT--\n", 8, "--ABORT--");
  expect_hoa_error("HOA: v1\nStates: 1\n--BODY--\n--END--\n", 3, "missing 'Acceptance:'");
  expect_hoa_error("HOA: v1\nStates: 1\nStates: 2\nAcceptance: 0 t\n--BODY--\n--END--\n", 3,
                   "duplicate 'States:'");
  expect_hoa_error("HOA: v1\nAP: 2 \"a\"\nAcceptance: 0 t\n--BODY--\n--END--\n", 2,
                   "declares 2 propositions");
  expect_hoa_error("HOA: v1\nAP: 2 \"a\" \"a\"\nAcceptance: 0 t\n--BODY--\n--END--\n", 2,
                   "listed twice");
  expect_hoa_error("HOA: v2\nAcceptance: 0 t\n--BODY--\n--END--\n", 1, "unsupported HOA version");
  expect_hoa_error("\n\nStates: 1\n", 3, "expected 'HOA:'");
  expect_hoa_error(head + "--BODY--\nState: 0\n[0] 0 # 1\n--END--\n", 8, "unexpected character");
  expect_hoa_error("HOA: v1\nStates: 99999999999\n", 2, "integer too large");
  expect_hoa_error("HOA: v1\nAcceptance: 0 t\nStart: 3\nStates: 2\n--BODY--\n--END--\n", 3,
                   "state 3 out of range");
  expect_hoa_error(head + "--BODY--\nState: [0] 0\n[0] 1\n--END--\n", 8,
                   "edge label on a state that has a state label");
}

TEST(HoaReader, DeepNestingIsAnErrorNotACrash) {
  const std::string deep(100000, '(');
  const std::string tail = "\nAcceptance: 0 t\n--BODY--\n--END--\n";
  expect_hoa_error("HOA: v1\nAP: 1 \"a\"\nAlias: @x " + deep + tail, 3, "nested too deeply");
  const std::string nots(100000, '!');
  expect_hoa_error("HOA: v1\nAP: 1 \"a\"\nAlias: @x " + nots + "0" + tail, 3, "nested too deeply");
}

// ---------------------------------------------------------------------------------------
// Never claims printed by spin 6.5.2 (`spin -f`), stored under tests/ltl/data.

Formula ap(const char* name) { return Formula::ap(name); }

struct SpinCase {
  int file;
  std::string formula;                        // exactly as given to spin -f
  Formula meaning;                            // the same formula, for the direct evaluator
  std::vector<std::pair<Lasso, bool>> words;  // hand-chosen, with the expected verdict
};

std::vector<SpinCase> spin_cases() {
  const Formula p = ap("p"), q = ap("q"), r = ap("r");
  using F = Formula;
  std::vector<SpinCase> cases;
  cases.push_back({1,
                   "<>(p && <>q)",
                   F::eventually(F::conj(p, F::eventually(q))),
                   {{word({}, {{"p", "q"}}), true},
                    {word({{"p"}, {}}, {{"q"}}), true},
                    {word({}, {{"p"}}), false},
                    {word({{"q"}}, {{"p"}}), false},
                    {word({}, {{}}), false}}});
  cases.push_back({2,
                   "[]<>p && []<>q",
                   F::conj(F::always(F::eventually(p)), F::always(F::eventually(q))),
                   {{word({}, {{"p"}, {"q"}}), true},
                    {word({{}}, {{"p", "q"}}), true},
                    {word({}, {{"p"}}), false},
                    {word({{"p"}, {"q"}}, {{}}), false}}});
  cases.push_back({3,
                   "p U q",
                   F::until(p, q),
                   {{word({}, {{"q"}}), true},
                    {word({{"p"}, {"p"}}, {{"q"}}), true},
                    {word({}, {{"p"}}), false},
                    {word({{}}, {{"q"}}), false}}});
  cases.push_back({4,
                   "[](p -> <>q)",
                   F::always(F::implies(p, F::eventually(q))),
                   {{word({}, {{}}), true},
                    {word({}, {{"p"}, {"q"}}), true},
                    {word({{"p"}}, {{"q"}}), true},
                    {word({}, {{"p"}}), false},
                    {word({{"q"}}, {{"p"}, {}}), false}}});
  cases.push_back({5,
                   "!(p U q)",
                   F::lnot(F::until(p, q)),
                   {{word({}, {{"p"}}), true},
                    {word({{}}, {{"q"}}), true},
                    {word({}, {{"q"}}), false},
                    {word({{"p"}}, {{"q"}}), false}}});
  cases.push_back({6, "false", F::ff(), {{word({}, {{}}), false}, {word({}, {{"p"}}), false}}});
  cases.push_back({7, "true", F::tt(), {{word({}, {{}}), true}, {word({}, {{"p", "q"}}), true}}});
  cases.push_back({8,
                   "<>[]p",
                   F::eventually(F::always(p)),
                   {{word({{}, {}}, {{"p"}}), true}, {word({}, {{"p"}, {}}), false}}});
  cases.push_back(
      {9, "[]p", F::always(p), {{word({}, {{"p"}}), true}, {word({{"p"}}, {{"p"}, {}}), false}}});
  cases.push_back({10,
                   "p V q",
                   F::release(p, q),
                   {{word({}, {{"q"}}), true},
                    {word({{"q"}, {"p", "q"}}, {{}}), true},
                    {word({}, {{}}), false},
                    {word({{"q"}}, {{"p"}}), false}}});
  cases.push_back(
      {11,
       "<>p || []q",
       F::disj(F::eventually(p), F::always(q)),
       {{word({}, {{"q"}}), true}, {word({{}}, {{"p"}}), true}, {word({{"q"}}, {{}}), false}}});
  cases.push_back(
      {12,
       "!p",
       F::lnot(p),
       {{word({}, {{}}), true}, {word({{}}, {{"p"}}), true}, {word({}, {{"p"}}), false}}});
  cases.push_back({13,
                   "[](p -> <>q) && [](q -> <>r)",
                   F::conj(F::always(F::implies(p, F::eventually(q))),
                           F::always(F::implies(q, F::eventually(r)))),
                   {{word({}, {{}}), true},
                    {word({}, {{"p"}, {"q"}, {"r"}}), true},
                    {word({{"p"}}, {{"q", "r"}}), true},
                    {word({}, {{"q"}}), false},
                    {word({{"p"}}, {{}}), false}}});
  cases.push_back({14,
                   "(p U q) || [](!p && <>r)",
                   F::disj(F::until(p, q), F::always(F::conj(F::lnot(p), F::eventually(r)))),
                   {{word({}, {{"q"}}), true},
                    {word({}, {{"r"}}), true},
                    {word({}, {{}}), false},
                    {word({{"p"}}, {{"p"}}), false}}});
  return cases;
}

std::string spin_path(int file) { return "tests/ltl/data/spin_" + std::to_string(file) + ".never"; }

TEST(NeverClaimReader, SpinOutputsAcceptTheirFormulasWords) {
  for (const SpinCase& c : spin_cases()) {
    SCOPED_TRACE(c.formula);
    const std::string text = read_text(spin_path(c.file));
    ASSERT_NE(text.find("/* " + c.formula + " */"), std::string::npos)
        << spin_path(c.file) << " is not spin's output for " << c.formula;
    const GeneralNba a = read_never_claim(text);
    for (const auto& [w, expected] : c.words) {
      EXPECT_EQ(accepts(a, w), expected) << w.to_string();
    }
  }
}

TEST(NeverClaimReader, SpinOutputsAgreeWithTheEvaluatorOnRandomWords) {
  Rng rng(4242);
  for (const SpinCase& c : spin_cases()) {
    SCOPED_TRACE(c.formula);
    const GeneralNba a = read_never_claim(read_text(spin_path(c.file)));
    for (int i = 0; i < 300; ++i) {
      const Lasso w = random_word(rng, {"p", "q", "r"}, false);
      ASSERT_EQ(accepts(a, w), test_support::evaluate(c.meaning, w)) << w.to_string();
    }
  }
}

TEST(NeverClaimReader, SpinQuirksGiveTheExpectedStructure) {
  // <>(p && <>q): atomic jumps go to the final `accept_all: skip` state.
  const GeneralNba a = read_never_claim(read_text(spin_path(1)));
  ASSERT_EQ(a.num_states(), 3u);
  EXPECT_EQ(a.state_names, (std::vector<std::string>{"T0_init", "T0_S4", "accept_all"}));
  EXPECT_EQ(a.initial, std::vector<std::uint32_t>{0});
  EXPECT_EQ(a.accepting, (std::vector<bool>{false, false, true}));
  ASSERT_EQ(a.out[2].size(), 1u);
  EXPECT_EQ(a.out[2][0].dst, 2u);
  EXPECT_EQ(a.out[2][0].guard, a.alphabet.top());
  // !(p U q): `accept_init:` then `T0_init:` name one accepting initial state.
  const GeneralNba b = read_never_claim(read_text(spin_path(5)));
  ASSERT_EQ(b.num_states(), 2u);
  EXPECT_EQ(b.initial, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(b.accepting[0]);
  EXPECT_EQ(b.state_names[0], "accept_init");
  // false: the only edge has guard false, so none remains.
  const GeneralNba f = read_never_claim(read_text(spin_path(6)));
  EXPECT_TRUE(f.out[0].empty());
  // An unsatisfiable formula: spin prints `do :: false od`, a bare guard with no goto.
  const GeneralNba e = read_never_claim(read_text(spin_path(15)));
  ASSERT_EQ(e.num_states(), 1u);
  EXPECT_TRUE(e.out[0].empty());
}

TEST(NeverClaimReader, BareGuardInADoLoopStaysInTheState) {
  const GeneralNba a = read_never_claim(
      "never {\naccept_init:\n\tdo\n\t:: (p)\n\t:: (q) -> goto T0_S1\n\tod;\n"
      "T0_S1:\n\tdo\n\t:: (1) -> goto T0_S1\n\tod;\n}\n");
  ASSERT_EQ(a.num_states(), 2u);
  ASSERT_EQ(a.out[0].size(), 2u);
  const int p = a.alphabet.find_ap("p");
  ASSERT_GE(p, 0);
  bool self_loop_on_p = false;
  for (const auto& e : a.out[0]) {
    if (e.dst == 0) self_loop_on_p = e.guard == a.alphabet.ap(static_cast<std::uint32_t>(p), true);
  }
  EXPECT_TRUE(self_loop_on_p);
  // In an if-block a bare guard would fall through: only `false` is accepted there.
  EXPECT_THROW(read_never_claim("never {\nT0_init:\n\tif\n\t:: (p)\n\tfi;\n}\n"), rearm::Error);
  EXPECT_NO_THROW(read_never_claim("never {\nT0_init:\n\tif\n\t:: false\n\tfi;\n}\n"));
}

bool spin_available() { return std::system("command -v spin >/dev/null 2>&1") == 0; }

std::string run_spin(const std::string& formula) {
  const std::string cmd = "spin -f '" + formula + "' 2>/dev/null";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) return {};
  std::string out;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  ::pclose(pipe);
  return out;
}

TEST(NeverClaimReader, LiveSpinMatchesTheStoredOutputs) {
  if (!spin_available()) GTEST_SKIP() << "spin is not installed";
  for (const SpinCase& c : spin_cases()) {
    SCOPED_TRACE(c.formula);
    const GeneralNba stored = read_never_claim(read_text(spin_path(c.file)));
    const GeneralNba live = read_never_claim(run_spin(c.formula), stored.alphabet);
    expect_same_structure(stored, live);
  }
}

// ---------------------------------------------------------------------------------------
// Never claims in ltl2ba's style and other hand-written ones.

TEST(NeverClaimReader, Ltl2baStyle) {
  // ltl2ba 1.3 prints `if`/`fi`, labels with a space before the colon and a comment, and a
  // final `accept_all: skip`.
  const char* eventually = R"txt(never { /* F(p && F q) */
T0_init :    /* init */
	if
	:: (1) -> goto T0_init
	:: (p && q) -> goto accept_all
	:: (p) -> goto T0_S2
	fi;
T0_S2 :    /* 1 */
	if
	:: (1) -> goto T0_S2
	:: (q) -> goto accept_all
	fi;
accept_all :    /* 2 */
	skip
}
)txt";
  const GeneralNba a = read_never_claim(eventually);
  EXPECT_EQ(a.num_states(), 3u);
  EXPECT_TRUE(accepts(a, word({{"p"}, {}}, {{"q"}})));
  EXPECT_FALSE(accepts(a, word({{"q"}}, {{"p"}})));

  const char* gf = R"txt(never { /* G F p */
T0_init:
	if
	:: (!p) -> goto T0_init
	:: (p) -> goto accept_S1
	fi;
accept_S1:
	if
	:: (!p) -> goto T0_init
	:: (p) -> goto accept_S1
	fi;
}
)txt";
  const GeneralNba b = read_never_claim(gf);
  EXPECT_TRUE(accepts(b, word({}, {{}, {"p"}})));
  EXPECT_FALSE(accepts(b, word({{"p"}}, {{}})));

  const GeneralNba f = read_never_claim("never { /* false */\nT0_init:\n\tfalse;\n}\n");
  EXPECT_EQ(f.num_states(), 1u);
  EXPECT_TRUE(f.out[0].empty());
  EXPECT_FALSE(accepts(f, word({}, {{}})));
}

TEST(NeverClaimReader, GuardSyntax) {
  // true/false/1/0 constants, ||, && precedence, nested negation; `do` and `if`.
  const char* text = R"txt(never {
accept_init:
	do
	:: (true && !(!(p) || q)) -> goto accept_init
	:: (0) -> goto T0_dead
	:: false || r && q -> goto T0_dead
	od;
T0_dead:
	if
	:: goto T0_dead
	fi;
}
)txt";
  const GeneralNba a = read_never_claim(text);
  const GeneralAlphabet& s = a.alphabet;
  ASSERT_EQ(a.num_states(), 2u);
  ASSERT_EQ(a.out[0].size(), 2u);
  EXPECT_EQ(a.out[0][0].guard, s.conj(s.ap(s.find_ap("p"), true), s.ap(s.find_ap("q"), false)));
  EXPECT_EQ(a.out[0][1].guard, s.conj(s.ap(s.find_ap("r"), true), s.ap(s.find_ap("q"), true)));
  EXPECT_EQ(a.out[1][0].guard, s.top());
  EXPECT_FALSE(a.accepting[1]);
}

TEST(NeverClaimReader, SkipGotoAliasesAndInitialState) {
  // The initial state is the one whose label ends in "init", not the first one. `skip`
  // steps to the next state; `goto` alone is another name for its target.
  const char* text = R"txt(never {
T0_first:
	skip;
T0_second:
	if
	:: (p) -> goto alias
	fi;
T1_init:
	if
	:: (q) -> goto T0_first
	fi;
alias:
	goto T1_init
}
)txt";
  const GeneralNba a = read_never_claim(text);
  ASSERT_EQ(a.num_states(), 3u);
  EXPECT_EQ(a.initial, std::vector<std::uint32_t>{2});
  EXPECT_EQ(a.state_names, (std::vector<std::string>{"T0_first", "T0_second", "T1_init"}));
  ASSERT_EQ(a.out[0].size(), 1u);
  EXPECT_EQ(a.out[0][0].dst, 1u);
  EXPECT_EQ(a.out[0][0].guard, a.alphabet.top());
  ASSERT_EQ(a.out[1].size(), 1u);
  EXPECT_EQ(a.out[1][0].dst, 2u);
  // A claim without accept labels accepts nothing; a final skip accepts every continuation.
  EXPECT_FALSE(accepts(a, word({}, {{"q"}, {}, {"p"}})));
  const GeneralNba b =
      read_never_claim("never { T0_init: if :: (p) -> goto T0_S1 fi; T0_S1: skip }");
  EXPECT_TRUE(b.accepting[1]);
  EXPECT_TRUE(accepts(b, word({{"p"}}, {{}})));
  EXPECT_FALSE(accepts(b, word({}, {{}})));
  // An atomic jump in a claim without accept_all gets a fresh accepting sink.
  const GeneralNba c = read_never_claim(
      "never { T0_init: do :: atomic { (p) -> assert(!(p)) } :: (1) -> goto T0_init od; }");
  ASSERT_EQ(c.num_states(), 2u);
  EXPECT_EQ(c.state_names[1], "accept_all");
  EXPECT_TRUE(accepts(c, word({{}, {"p"}}, {{}})));
  EXPECT_FALSE(accepts(c, word({}, {{}})));
}

TEST(NeverClaimReader, ErrorsNameTheLine) {
  expect_never_error("tl_spin: expected predicate, saw 'X'\n", 1, "expected 'never'");
  expect_never_error("never {\nT0_init:\n\tif\n\t:: (p) -> goto nowhere\n\tfi;\n}\n", 4,
                     "undefined label 'nowhere'");
  expect_never_error("never {\nT0_init:\n\tif\n\t:: (p &&) -> goto T0_init\n\tfi;\n}\n", 4,
                     "expected a guard");
  expect_never_error("never {\nT0_init:\n\tif\n\t:: (p) goto T0_init\n\tfi;\n}\n", 4,
                     "expected '->'");
  expect_never_error("never {\nT0_init:\n\tprintf(\"x\");\n}\n", 3, "unsupported statement");
  expect_never_error("never {\nT0_init:\n\tif\n\t:: (p # q) -> goto T0_init\n\tfi;\n}\n", 4,
                     "found character '#'");
  expect_never_error("never {\nT0_init:\n\tx = 1;\n}\n", 3, "unsupported statement");
  expect_never_error("never {\nT0_init:\n\tfalse;\nT0_init:\n\tfalse;\n}\n", 4, "defined twice");
  expect_never_error("never {\nT0_init:\n\tfalse;\n\tfalse;\n}\n", 4, "expected a state label");
  expect_never_error("never {\nT0_init:\n\tdo\n\t:: atomic { (p) -> assert(!(q)) }\n\tod;\n}\n", 4,
                     "not the negation");
  expect_never_error("never {\nT0_init:\n\tif\n\tfi;\n}\n", 3, "without options");
  expect_never_error("never {\nT0_init:\n\tfalse;\n", 4, "missing '}'");
  expect_never_error("never {\nT0_init:\n\tfalse;\n}\nnever {\n", 5, "after the end");
  expect_never_error("never {\n/* open\nT0_init:\n", 2, "unterminated comment");
  expect_never_error("never {\nT0_init:\n\tif\n\t:: (goto) -> goto T0_init\n\tfi;\n}\n", 4,
                     "keyword 'goto'");
  expect_never_error("never {\nT0_init:\n\tgoto a\na:\n\tgoto T0_init\n}\n", 2, "cycle of gotos");
  expect_never_error("never {\n}\n", 2, "no states");
}

// ---------------------------------------------------------------------------------------
// Never claim writer.

TEST(NeverClaimWriter, RandomGeneralRoundTrip) {
  Rng rng(99);
  for (int trial = 0; trial < 150; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const GeneralNba a = random_general(rng, {"a", "b", "c"});
    const std::string text = to_never_claim(a);
    const GeneralNba b = read_never_claim(text);
    expect_same_language(a, b, 500 + static_cast<std::uint64_t>(trial), 60);
    if (HasFatalFailure()) return;
  }
}

TEST(NeverClaimWriter, NamesStatesAndGuardsTheSpinWay) {
  GeneralNba a = gfa_gfb();
  a.accepting[0] = true;
  const std::string text = to_never_claim(a);
  // The single initial state comes first as accept_init; other states keep their number.
  EXPECT_EQ(text.find("never {\naccept_init:"), 0u) << text;
  EXPECT_NE(text.find("T0_S1:"), std::string::npos) << text;
  EXPECT_NE(text.find("accept_S2:"), std::string::npos) << text;
  EXPECT_NE(text.find(":: (!a) -> goto accept_init\n"), std::string::npos) << text;
  EXPECT_NE(text.find(":: (a && !b) -> goto T0_S1\n"), std::string::npos) << text;
  EXPECT_NE(text.find(":: (1) -> goto accept_init\n"), std::string::npos) << text;
  EXPECT_NE(text.find("/* seen both */"), std::string::npos) << text;
}

TEST(NeverClaimWriter, DisjunctionsAreParenthesizedLikeSpin) {
  GeneralNba a;
  a.alphabet = GeneralAlphabet({"a", "b", "c"});
  const GeneralAlphabet& s = a.alphabet;
  a.add_state(true);
  a.initial = {0};
  a.add_edge(0, 0, s.disj(s.conj(s.ap(0, true), s.ap(1, false)), s.ap(2, true)));
  const std::string text = to_never_claim(a);
  // The cover of a&!b | c may order the cubes either way.
  const bool ok = text.find(":: ((a && !b) || (c)) -> goto accept_init") != std::string::npos ||
                  text.find(":: ((c) || (a && !b)) -> goto accept_init") != std::string::npos;
  EXPECT_TRUE(ok) << text;
}

TEST(NeverClaimWriter, SeveralInitialStatesAndDeadStates) {
  GeneralNba a;
  a.alphabet = GeneralAlphabet({"a"});
  const GeneralAlphabet& s = a.alphabet;
  for (int q = 0; q < 3; ++q) a.add_state(q == 2);
  a.initial = {0, 1};
  a.add_edge(0, 2, s.ap(0, true));
  a.add_edge(1, 2, s.ap(0, false));
  a.add_edge(2, 2, s.top());
  // State 0 is also a target; its edges must stay reachable after the fresh initial state.
  a.add_edge(2, 0, s.ap(0, true));
  GeneralNba dead = a;
  dead.out[1].clear();
  for (const GeneralNba& x : {a, dead}) {
    const std::string text = to_never_claim(x);
    EXPECT_EQ(text.find("never {\nT0_init:"), 0u) << text;
    const GeneralNba y = read_never_claim(text);
    EXPECT_EQ(y.num_states(), 4u) << text;
    expect_same_language(x, y, 3);
  }
  // Labels number the states by their place in the text: the fresh initial state is place 0,
  // so state 1 is T0_S2.
  EXPECT_NE(to_never_claim(dead).find("T0_S2:\n\tfalse;\n"), std::string::npos);
  GeneralNba none;
  none.alphabet = GeneralAlphabet({"a"});
  none.add_state(true);
  const std::string text = to_never_claim(none);
  EXPECT_EQ(text, "never {\nT0_init:\n\tfalse;\n}\n");
  EXPECT_FALSE(accepts(read_never_claim(text), word({}, {{"a"}}, {"a"})));
}

TEST(NeverClaimWriter, ActionPredicatesBecomeIdentifiers) {
  Rng rng(5);
  const std::vector<std::string> aps = {"move(l1)", "grasp(M1)", "release(M1,l2)", "move_l1", "do"};
  const std::vector<std::string> spin = {"move_l1_2", "grasp_M1", "release_M1_l2", "move_l1",
                                         "do_"};
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const ActionNba a = random_action(rng, aps);
    const std::string text = to_never_claim(a);
    EXPECT_NE(text.find("/* proposition move_l1_2 stands for move(l1) */"), std::string::npos)
        << text;
    EXPECT_NE(text.find("/* proposition release_M1_l2 stands for release(M1,l2) */"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("one-action alphabet"), std::string::npos) << text;
    const GeneralNba g = read_never_claim(text);
    for (const std::string& p : g.alphabet.aps()) {
      EXPECT_NE(std::find(spin.begin(), spin.end(), p), spin.end()) << p;
    }
    for (int i = 0; i < 60; ++i) {
      const Lasso w = random_word(rng, aps, /*one_hot=*/true);
      ASSERT_EQ(accepts(a, w), accepts(g, renamed(w, spin))) << w.to_string() << "\n" << text;
    }
  }
}

TEST(NeverClaimWriter, SpinCompilesTheClaim) {
  if (!spin_available()) GTEST_SKIP() << "spin is not installed";
  char dir[] = "/tmp/rearm_never_XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  ActionNba a;
  a.alphabet = ActionAlphabet({"move(l1)", "grasp(M1)"});
  for (int q = 0; q < 3; ++q) a.add_state(q == 1);
  a.initial = {0, 2};
  a.add_edge(0, 1, a.alphabet.ap(0, true));
  a.add_edge(1, 1, a.alphabet.top());
  a.add_edge(2, 0, a.alphabet.ap(1, false));
  const std::string model = std::string(dir) + "/model.pml";
  {
    std::ofstream out(model);
    out << "bool move_l1, grasp_M1;\n"
           "active proctype env() {\n"
           "  do :: move_l1 = !move_l1 :: grasp_M1 = !grasp_M1 od\n"
           "}\n"
        << to_never_claim(a);
  }
  const std::string cmd = std::string("cd ") + dir + " && spin -a model.pml >spin.log 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << read_text(std::string(dir) + "/spin.log") << read_text(model);
  std::system((std::string("rm -rf ") + dir).c_str());
}

// ---------------------------------------------------------------------------------------
// DOT writer.

TEST(DotWriter, StatesInitialArrowsAndLabels) {
  GeneralNba a = gfa_gfb();
  a.initial = {0, 1};
  const std::string text = to_dot(a);
  EXPECT_EQ(text.rfind("digraph", 0), 0u) << text;
  EXPECT_NE(text.find("2 [label=\"seen both\", shape=doublecircle];"), std::string::npos) << text;
  EXPECT_NE(text.find("0 [label=\"wait a\"];"), std::string::npos) << text;
  EXPECT_NE(text.find("start [label=\"\", shape=point, style=invis"), std::string::npos) << text;
  EXPECT_NE(text.find("start -> 0;"), std::string::npos) << text;
  EXPECT_NE(text.find("start -> 1;"), std::string::npos) << text;
  EXPECT_NE(text.find("0 -> 0 [label=\"!a\"];"), std::string::npos) << text;
  EXPECT_NE(text.find("0 -> 1 [label=\"a & !b\"];"), std::string::npos) << text;
  EXPECT_NE(text.find("2 -> 0 [label=\"true\"];"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("}\n"), std::string::npos);
}

TEST(DotWriter, ActionAlphabetNamesAndEscapes) {
  ActionNba a;
  a.alphabet = ActionAlphabet({"move(l1)", "say(\"hi\")"});
  a.add_state(true);
  a.initial = {0};
  a.add_edge(0, 0, a.alphabet.ap(0, true) | a.alphabet.ap(1, true));
  const std::string text = to_dot(a);
  EXPECT_NE(text.find("one-action alphabet"), std::string::npos) << text;
  EXPECT_NE(text.find(R"txt(0 -> 0 [label="move(l1) | say(\"hi\")"];)txt"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace rearm::ltl
