// Translator API behaviour: budgets, alphabets, options. Language correctness is tested
// against independent oracles in translate_lasso_test, spin_crosscheck_test and
// known_optima_test.
#include "ltl/translate.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "ltl/parser.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"

namespace rearm::ltl {
namespace {

std::string conj_of(const char* op, int n) {
  std::string s;
  for (int i = 1; i <= n; ++i)
    s += (i > 1 ? " & " : "") + std::string(op) + " p" + std::to_string(i);
  return s;
}

TEST(TranslateTest, StateBudgetGivesACleanError) {
  TranslateOptions o;
  o.max_states = 500;  // F p1 & ... & F p12 needs 4096 generalized states
  try {
    translate_general(parse(conj_of("F", 12)), o);
    FAIL() << "expected BudgetExceeded";
  } catch (const BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("500 states"), std::string::npos) << e.what();
  }
}

TEST(TranslateTest, TimeBudgetGivesACleanError) {
  TranslateOptions o;
  o.max_seconds = 1e-6;
  EXPECT_THROW(translate_general(parse(conj_of("F", 12)), o), BudgetExceeded);
  // F p1 & ... & F p40: its first generalized state has 2^40 transitions, so the budget has to
  // be read inside the transition product and the dominance test (it once ran for minutes
  // past a 60 s budget). The state budget is out of the way; the time budget ends it.
  o.max_states = std::size_t{1} << 40;
  o.max_seconds = 0.2;
  try {
    translate_general(parse(conj_of("F", 40)), o);
    FAIL() << "expected BudgetExceeded";
  } catch (const BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("time budget"), std::string::npos) << e.what();
  }
}

TEST(TranslateTest, ActionAlphabetHasOneLetterPerPropositionPlusNone) {
  TranslationStats st;
  const auto a = translate_actions(parse("F move(l1)"), {}, &st, {"grasp(M1)", "move(l1)"});
  ASSERT_EQ(a.alphabet.aps().size(), 2u);  // move(l1) from the formula, then grasp(M1)
  EXPECT_EQ(a.alphabet.aps()[0], "move(l1)");
  EXPECT_EQ(a.alphabet.num_letters(), 3u);
  EXPECT_EQ(st.ba_states, 2u);
  // Exclusivity: "move(l1) & grasp(M1)" can never hold, so this formula is empty.
  const auto e = translate_actions(parse("F(move(l1) & grasp(M1))"));
  EXPECT_EQ(e.num_states(), 0u);
  EXPECT_TRUE(e.initial.empty());
}

TEST(TranslateTest, UnsatisfiableAndValidFormulas) {
  EXPECT_EQ(translate_general(parse("p & !p")).num_states(), 0u);
  EXPECT_EQ(translate_general(parse("G p & F !p")).num_states(), 0u);
  const auto t = translate_general(parse("true"));
  ASSERT_EQ(t.num_states(), 1u);
  EXPECT_TRUE(t.accepting[0]);
  ASSERT_EQ(t.out[0].size(), 1u);
  EXPECT_EQ(t.out[0][0].guard, BddManager::kTrue);
}

TEST(TranslateTest, OptionsOffStillTranslateCorrectly) {
  // Without rewriting and simplification the automaton is bigger but the language equal.
  const char* formulas[] = {"G(p -> F q)", "p U (q R r)", "!(F G p) & X q", "GF p & GF q"};
  Rng rng(5);
  for (const char* text : formulas) {
    const Formula f = parse(text);
    TranslateOptions raw;
    raw.rewrite = false;
    raw.simplify = false;
    TranslationStats st_raw, st;
    const auto a = translate_general(f, raw, &st_raw);
    const auto b = translate_general(f, {}, &st);
    EXPECT_GE(st_raw.ba_states, st.ba_states) << text;
    for (int k = 0; k < 300; ++k) {
      const auto w = test_support::random_lasso(rng, f.atomic_propositions());
      const bool truth = test_support::evaluate(f, w);
      ASSERT_EQ(test_support::accepts(a, w), truth) << text << " raw, " << w.to_string();
      ASSERT_EQ(test_support::accepts(b, w), truth) << text << ", " << w.to_string();
    }
  }
}

TEST(TranslateTest, StatsDescribeTheResult) {
  TranslationStats st;
  const auto a = translate_general(parse("GF p1 & GF p2 & GF p3"), {}, &st);
  EXPECT_EQ(st.ba_states, a.num_states());
  EXPECT_EQ(st.ba_edges, a.num_edges());
  EXPECT_EQ(st.gba_states, 1u);  // one generalized state: transition-based GF (translate.cpp)
  EXPECT_EQ(st.acceptance_sets, 3u);
  EXPECT_GE(st.milliseconds, 0.0);
  EXPECT_FALSE(st.rewritten.empty());
}

}  // namespace
}  // namespace rearm::ltl
