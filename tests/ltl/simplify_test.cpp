// Rewriting (ltl/simplify.h) against independent truth: the direct lasso evaluator of
// tests/support must give the same verdict for a formula and its rewriting on random words,
// and the shapes the translator relies on must come out of the rules.
#include "ltl/simplify.h"

#include <gtest/gtest.h>

#include "ltl/parser.h"
#include "support/lasso.h"
#include "support/random_formula.h"

namespace rearm::ltl {
namespace {

using test_support::evaluate;
using test_support::random_formula;
using test_support::random_lasso;

bool is_nnf(const Formula& f) {
  switch (f.op()) {
    case Op::Not:
      return f.child(0).op() == Op::Ap;
    case Op::Implies:
    case Op::Equiv:
    case Op::Xor:
    case Op::WeakUntil:
    case Op::StrongRelease:
      return false;
    default:
      for (const Formula& c : f.children()) {
        if (!is_nnf(c)) return false;
      }
      return true;
  }
}

TEST(SimplifyTest, RewritingPreservesTheSemanticsOnRandomWords) {
  constexpr int kFormulas = 4000;
  constexpr int kWordsPerFormula = 25;
  Rng rng(20261123);
  int checks = 0;
  for (int i = 0; i < kFormulas; ++i) {
    test_support::RandomFormulaOptions o;
    o.allow_next = i % 2 == 0;
    o.negation_anywhere = i % 3 != 0;
    const auto aps = test_support::random_aps(rng, o);
    const Formula f = random_formula(rng, aps, o);
    const Formula n = to_nnf(f);
    const Formula r = rewrite(f);
    ASSERT_TRUE(is_nnf(n)) << n.to_string();
    ASSERT_TRUE(is_nnf(r)) << r.to_string();
    for (int k = 0; k < kWordsPerFormula; ++k) {
      const auto w = random_lasso(rng, aps);
      const bool expected = evaluate(f, w);
      ASSERT_EQ(evaluate(n, w), expected) << "nnf of " << f.to_string() << " on " << w.to_string();
      ASSERT_EQ(evaluate(r, w), expected)
          << f.to_string() << " rewritten to " << r.to_string() << " on " << w.to_string();
      ++checks;
    }
  }
  EXPECT_EQ(checks, kFormulas * kWordsPerFormula);
}

TEST(SimplifyTest, SequencedPatrolBecomesAConjunctionOfGF) {
  // GF(a & F b) == GF a & GF b (docs/symbolic.md), applied recursively.
  const Formula r = rewrite(parse("G F(p1 & F(p2 & F(p3 & F p4)))"));
  EXPECT_EQ(r, rewrite(parse("GF p1 & GF p2 & GF p3 & GF p4"))) << r.to_string();
  ASSERT_EQ(r.op(), Op::And);
  EXPECT_EQ(r.arity(), 4u);
}

TEST(SimplifyTest, TextbookRules) {
  auto same = [](const char* a, const char* b) {
    EXPECT_EQ(rewrite(parse(a)), rewrite(parse(b))) << a << " vs " << b;
  };
  same("F F p", "F p");
  same("G G p", "G p");
  same("p U F q", "F q");
  same("p R G q", "G q");
  same("F G F p", "G F p");
  same("G F G p", "F G p");
  same("X G F p", "G F p");
  same("true U p", "F p");
  same("false R p", "G p");
  same("p & !p", "false");
  same("p | !p", "true");
  same("!(p U q)", "!p R !q");
  same("p W q", "q R (p | q)");
  same("p M q", "q U (p & q)");
  same("F(p & G F q)", "F p & G F q");
  same("G(p & q)", "G p & G q");
  EXPECT_EQ(rewrite(parse("p U false")), Formula::ff());
  EXPECT_EQ(rewrite(parse("G true")), Formula::tt());
}

TEST(SimplifyTest, SyntacticClasses) {
  EXPECT_TRUE(is_eventual(parse("F p")));
  EXPECT_TRUE(is_eventual(parse("G F p")));
  EXPECT_TRUE(is_universal(parse("F G p")));
  EXPECT_TRUE(is_universal(parse("G p")));
  EXPECT_FALSE(is_eventual(parse("p")));
  EXPECT_FALSE(is_universal(parse("p U q")));
  EXPECT_FALSE(is_eventual(parse("G p")));
}

}  // namespace
}  // namespace rearm::ltl
