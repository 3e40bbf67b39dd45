// Tests of the direct LTL evaluator on lasso words (tests/support/lasso.h), the oracle the
// translator is checked against: hand-computed cases for every operator, a second,
// differently built evaluator (walk the lasso from each position) on random formulas, and
// invariance under re-rolling the lasso.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "support/lasso.h"
#include "support/random_formula.h"

namespace rearm::test_support {
namespace {

using ltl::Formula;
using ltl::Op;
using Letters = std::vector<std::vector<std::string>>;

Formula p() { return Formula::ap("p"); }
Formula q() { return Formula::ap("q"); }
Formula r() { return Formula::ap("r"); }
Formula neg(Formula a) { return Formula::lnot(std::move(a)); }
Formula X(Formula a) { return Formula::next(std::move(a)); }
Formula F(Formula a) { return Formula::eventually(std::move(a)); }
Formula G(Formula a) { return Formula::always(std::move(a)); }
Formula U(Formula a, Formula b) { return Formula::until(std::move(a), std::move(b)); }
Formula R(Formula a, Formula b) { return Formula::release(std::move(a), std::move(b)); }
Formula W(Formula a, Formula b) { return Formula::weak_until(std::move(a), std::move(b)); }
Formula M(Formula a, Formula b) { return Formula::strong_release(std::move(a), std::move(b)); }

// u·v^ω over {p, q, r}.
Lasso L(const Letters& u, const Letters& v) { return Lasso::from_names(u, v, {"p", "q", "r"}); }

struct Case {
  Formula f;
  Lasso w;
  bool expected;
  const char* why;
};

TEST(LassoEval, HandComputedCases) {
  const std::vector<Case> cases = {
      // Boolean layer.
      {Formula::tt(), L({}, {{}}), true, "true"},
      {Formula::ff(), L({}, {{"p"}}), false, "false"},
      {p(), L({{"p"}}, {{}}), true, "p at position 0"},
      {p(), L({}, {{}, {"p"}}), false, "p only later"},
      {r(), L({}, {{"p", "q"}}), false, "r never true"},
      {Formula::ap("zz"), L({}, {{"p"}}), false, "a name outside the lasso's aps is false"},
      {neg(p()), L({}, {{}}), true, "!p"},
      {Formula::conj(p(), q()), L({}, {{"p", "q"}}), true, "p & q both"},
      {Formula::conj(p(), q()), L({}, {{"p"}}), false, "p & q, q missing"},
      {Formula::conj({p(), q(), r()}), L({}, {{"p", "q", "r"}}), true, "3-ary and"},
      {Formula::conj({p(), q(), r()}), L({}, {{"p", "r"}}), false, "3-ary and, q missing"},
      {Formula::disj(p(), q()), L({}, {{"q"}}), true, "p | q via q"},
      {Formula::disj(p(), q()), L({}, {{}}), false, "p | q neither"},
      {Formula::disj({p(), q(), r()}), L({}, {{"r"}}), true, "3-ary or via r"},
      {Formula::implies(p(), q()), L({}, {{}}), true, "p -> q vacuous"},
      {Formula::implies(p(), q()), L({}, {{"p"}}), false, "p -> q broken"},
      {Formula::equiv(p(), q()), L({}, {{}}), true, "p <-> q both false"},
      {Formula::equiv(p(), q()), L({}, {{"p"}}), false, "p <-> q differ"},
      {Formula::lxor(p(), q()), L({}, {{"p"}}), true, "p xor q differ"},
      {Formula::lxor(p(), q()), L({}, {{"p", "q"}}), false, "p xor q both"},
      // Next: the successor of the last position is the loop start.
      {X(p()), L({{}}, {{"p"}}), true, "X p into the loop"},
      {X(p()), L({}, {{"p"}, {}}), false, "X p sees position 1"},
      {X(p()), L({}, {{"p"}}), true, "X p wraps onto itself"},
      {X(X(p())), L({}, {{}, {"p"}}), false, "X X p wraps back to position 0"},
      {X(X(X(p()))), L({{}}, {{"p"}, {}}), true, "X X X p: 0,1,2, then loop start 1"},
      {X(neg(p())), L({{"p"}}, {{"p"}}), false, "X !p"},
      // Eventually / Always.
      {F(p()), L({{}, {}}, {{}, {"p"}}), true, "F p reached in the loop"},
      {F(p()), L({{"p"}}, {{}}), true, "F p in the prefix only"},
      {F(p()), L({{}}, {{}}), false, "F p never"},
      {G(p()), L({{"p"}}, {{"p"}, {"p"}}), true, "G p"},
      {G(p()), L({{"p"}}, {{"p"}, {}}), false, "G p broken in the loop"},
      {G(p()), L({{}}, {{"p"}}), false, "G p broken in the prefix"},
      {G(F(p())), L({}, {{"p"}, {}}), true, "G F p on (p !p)^w"},
      {G(F(p())), L({{"p"}, {"p"}}, {{}}), false, "G F p, p only in the prefix"},
      {F(G(p())), L({{}}, {{"p"}}), true, "F G p"},
      {F(G(p())), L({}, {{"p"}, {}}), false, "F G p on (p !p)^w"},
      {G(Formula::tt()), L({}, {{}}), true, "G true"},
      {F(Formula::ff()), L({}, {{"p"}}), false, "F false"},
      // Until: least fixpoint; looping on p without q is not enough.
      {U(p(), q()), L({{"p"}, {"p"}}, {{"q"}}), true, "p U q reached"},
      {U(p(), q()), L({}, {{"p"}}), false, "p U q, q never: least fixpoint"},
      {U(p(), q()), L({}, {{"p"}, {"p"}}), false, "p U q, p forever on a 2-loop"},
      {U(p(), q()), L({{"p"}, {}}, {{"q"}}), false, "p U q, p fails before q"},
      {U(p(), q()), L({}, {{"q"}}), true, "p U q, q at once"},
      {U(p(), q()), L({{"p"}}, {{"p"}, {"q"}}), true, "p U q, q in the second loop letter"},
      // Release: greatest fixpoint; q forever is enough.
      {R(p(), q()), L({}, {{"q"}}), true, "p R q, q forever: greatest fixpoint"},
      {R(p(), q()), L({{"q"}}, {{"q"}, {"q"}}), true, "p R q, q forever on a 2-loop"},
      {R(p(), q()), L({{"q"}}, {{}}), false, "p R q, q stops, never released"},
      {R(p(), q()), L({{"q"}, {"p", "q"}}, {{}}), true, "p R q, released by p & q"},
      {R(p(), q()), L({{"q"}, {"p"}}, {{}}), false, "p R q, p without q does not release"},
      {R(p(), q()), L({}, {{"q"}, {"p", "q"}}), true, "p R q, released in the loop"},
      // Weak until: greatest fixpoint of the until expansion.
      {W(p(), q()), L({}, {{"p"}}), true, "p W q, p forever"},
      {W(p(), q()), L({{"p"}}, {{}}), false, "p W q, p stops without q"},
      {W(p(), q()), L({{"p"}}, {{"q"}}), true, "p W q, q reached"},
      // Strong release: least fixpoint of the release expansion.
      {M(p(), q()), L({}, {{"q"}}), false, "p M q, never released"},
      {M(p(), q()), L({{"q"}}, {{"p", "q"}}), true, "p M q, released"},
      {M(p(), q()), L({}, {{"p", "q"}}), true, "p M q at once"},
      {M(p(), q()), L({{"q"}, {}}, {{"p", "q"}}), false, "p M q, q fails before p"},
      // Nesting.
      {G(Formula::implies(p(), F(q()))), L({}, {{"p"}, {"q"}}), true, "response holds"},
      {G(Formula::implies(p(), F(q()))), L({{"p"}}, {{}}), false, "response never answered"},
      {G(Formula::implies(p(), X(q()))), L({}, {{"p"}, {"q"}}), true, "p then q next"},
      {G(Formula::implies(p(), X(q()))), L({}, {{"p", "q"}, {}}), false, "q missing after p"},
      {F(Formula::conj(p(), X(neg(p())))), L({}, {{"p"}}), false, "p never falls"},
      {F(Formula::conj(p(), X(neg(p())))), L({}, {{"p"}, {}}), true, "p falls"},
      {Formula::conj(G(F(p())), G(F(q()))), L({}, {{"p"}, {"q"}}), true, "two recurrences"},
      {Formula::conj(G(F(p())), G(F(q()))), L({{"q"}}, {{"p"}}), false, "q not recurrent"},
      {U(F(p()), G(q())), L({{"p"}}, {{"q"}}), true, "F p U G q: G q at position 1"},
      {U(F(p()), G(q())), L({{}}, {{"q"}}), false, "F p U G q: F p false at 0"},
      {U(G(p()), q()), L({}, {{"p"}}), false, "G p U q, q never"},
      {R(Formula::ff(), p()), L({{"p"}}, {{"p"}}), true, "false R p = G p"},
      {U(Formula::tt(), p()), L({{}}, {{}, {"p"}}), true, "true U p = F p"},
      {X(U(p(), q())), L({{}}, {{"p"}, {"q"}}), true, "X (p U q) from the prefix"},
  };
  ASSERT_GE(cases.size(), 30u);
  for (const Case& c : cases) {
    EXPECT_EQ(evaluate(c.f, c.w), c.expected)
        << c.why << ": " << c.f.to_string() << " on " << c.w.to_string();
  }
}

TEST(LassoEval, TruthAtEveryPosition) {
  // u = ({}) v = ({p} {} {q}); positions 0..3, the successor of 3 is 1.
  const Lasso w = L({{}}, {{"p"}, {}, {"q"}});
  EXPECT_EQ(evaluate_all(p(), w), (std::vector<bool>{false, true, false, false}));
  EXPECT_EQ(evaluate_all(X(p()), w), (std::vector<bool>{true, false, false, true}));
  EXPECT_EQ(evaluate_all(F(q()), w), (std::vector<bool>{true, true, true, true}));
  EXPECT_EQ(evaluate_all(G(neg(q())), w), (std::vector<bool>{false, false, false, false}));
  EXPECT_EQ(evaluate_all(U(neg(q()), p()), w), (std::vector<bool>{true, true, false, false}));
  EXPECT_EQ(evaluate_all(R(q(), neg(p())), w), (std::vector<bool>{false, false, true, true}));
  EXPECT_EQ(evaluate_all(W(neg(p()), q()), w), (std::vector<bool>{false, false, true, true}));
  EXPECT_EQ(evaluate_all(M(p(), neg(q())), w), (std::vector<bool>{true, true, false, false}));
}

TEST(LassoEval, RejectsAnEmptyLoop) {
  Lasso w = L({{"p"}}, {{}});
  w.loop.clear();
  EXPECT_THROW(evaluate(p(), w), std::invalid_argument);
}

TEST(LassoEval, GeneratorsAreSeededAndRespectTheirRanges) {
  Rng a(7), b(7);
  const std::vector<std::string> aps = {"x", "y", "z"};
  LassoOptions one_hot;
  one_hot.one_hot = true;
  for (int i = 0; i < 200; ++i) {
    const Lasso w1 = random_lasso(a, aps);
    const Lasso w2 = random_lasso(b, aps);
    EXPECT_EQ(w1.to_string(), w2.to_string());
    EXPECT_LE(w1.prefix.size(), 4u);
    EXPECT_GE(w1.loop.size(), 1u);
    EXPECT_LE(w1.loop.size(), 4u);
    const Lasso h = random_lasso(a, aps, one_hot);
    random_lasso(b, aps, one_hot);
    for (std::size_t k = 0; k < h.size(); ++k) EXPECT_LE(h.true_aps(k).size(), 1u);
  }
  RandomFormulaOptions fo;
  fo.min_size = 5;
  fo.max_size = 20;
  Rng c(11), d(11);
  for (int i = 0; i < 300; ++i) {
    const Formula f = random_formula(c, fo);
    EXPECT_EQ(f, random_formula(d, fo));
    EXPECT_GE(f.size(), 5u);
    EXPECT_LE(f.size(), 20u);
  }
  // Restricted negation: every Not is directly above a proposition; spin-safe: no X.
  fo.negation_anywhere = false;
  fo.spin_safe = true;
  for (int i = 0; i < 300; ++i) {
    const Formula f = random_formula(c, fo);
    EXPECT_FALSE(f.has_next()) << f.to_string();
    std::vector<Formula> stack{f};
    while (!stack.empty()) {
      const Formula g = stack.back();
      stack.pop_back();
      if (g.op() == Op::Not) {
        EXPECT_EQ(g.child(0).op(), Op::Ap) << f.to_string();
      }
      for (const Formula& ch : g.children()) stack.push_back(ch);
    }
  }
}

TEST(LassoEval, ExhaustiveEnumerationCountsEveryLasso) {
  std::size_t n = 0;
  for_each_lasso({"a", "b"}, 1, 2, false, [&](const Lasso&) { return ++n, true; });
  // (1 + 4) prefixes × (4 + 16) loops.
  EXPECT_EQ(n, 5u * 20u);
  n = 0;
  for_each_lasso({"a", "b"}, 2, 1, true, [&](const Lasso&) { return ++n, true; });
  EXPECT_EQ(n, (1u + 3u + 9u) * 3u);
}

// ---------------------------------------------------------------------------------------
// A second evaluator built differently: from each position walk the lasso for |w| steps
// (which visits every position reachable from it) and apply the operators' definitions
// over that finite walk ("exists j: b at j and a before j" etc.).

class WalkEvaluator {
 public:
  explicit WalkEvaluator(const Lasso& w) : w_(w) {}

  bool at(const Formula& f, std::size_t pos) {
    const auto key = std::make_pair(f.node_id(), pos);
    const auto it = memo_.find(key);
    if (it != memo_.end()) return it->second;
    const bool v = compute(f, pos);
    memo_[key] = v;
    return v;
  }

 private:
  // Positions pos, succ(pos), ..., |w| of them.
  std::vector<std::size_t> walk(std::size_t pos) const {
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < w_.size(); ++k, pos = w_.successor(pos)) out.push_back(pos);
    return out;
  }

  bool compute(const Formula& f, std::size_t pos) {
    const Formula* a = f.arity() > 0 ? &f.child(0) : nullptr;
    const Formula* b = f.arity() > 1 ? &f.child(1) : nullptr;
    switch (f.op()) {
      case Op::True:
        return true;
      case Op::False:
        return false;
      case Op::Ap:
        return w_.holds(pos, f.name());
      case Op::Not:
        return !at(*a, pos);
      case Op::And:
        for (const Formula& c : f.children()) {
          if (!at(c, pos)) return false;
        }
        return true;
      case Op::Or:
        for (const Formula& c : f.children()) {
          if (at(c, pos)) return true;
        }
        return false;
      case Op::Implies:
        return !at(*a, pos) || at(*b, pos);
      case Op::Equiv:
        return at(*a, pos) == at(*b, pos);
      case Op::Xor:
        return at(*a, pos) != at(*b, pos);
      case Op::Next:
        return at(*a, w_.successor(pos));
      case Op::Eventually:
        for (std::size_t j : walk(pos)) {
          if (at(*a, j)) return true;
        }
        return false;
      case Op::Always:
        for (std::size_t j : walk(pos)) {
          if (!at(*a, j)) return false;
        }
        return true;
      case Op::Until:
      case Op::WeakUntil:
        for (std::size_t j : walk(pos)) {
          if (at(*b, j)) return true;
          if (!at(*a, j)) return false;
        }
        return f.op() == Op::WeakUntil;  // a forever, b never
      case Op::Release:
      case Op::StrongRelease:
        for (std::size_t j : walk(pos)) {
          if (!at(*b, j)) return false;
          if (at(*a, j)) return true;
        }
        return f.op() == Op::Release;  // b forever, never released
    }
    return false;
  }

  const Lasso& w_;
  std::map<std::pair<const void*, std::size_t>, bool> memo_;
};

TEST(LassoEval, AgreesWithTheWalkingEvaluatorOnRandomFormulas) {
  Rng rng(20240601);
  RandomFormulaOptions fo;
  fo.min_size = 1;
  fo.max_size = 25;
  std::size_t checks = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::vector<std::string> aps = random_aps(rng, fo);
    const Formula f = random_formula(rng, aps, fo);
    for (int j = 0; j < 5; ++j) {
      const Lasso w = random_lasso(rng, aps);
      const std::vector<bool> fix = evaluate_all(f, w);
      WalkEvaluator walk(w);
      for (std::size_t k = 0; k < w.size(); ++k, ++checks) {
        ASSERT_EQ(fix[k], walk.at(f, k))
            << f.to_string() << " on " << w.to_string() << " at position " << k;
      }
    }
  }
  EXPECT_GT(checks, 15000u);
}

// Lassos u·v^ω, (u v0)·(v1..vk v0)^ω and u·(v v)^ω denote the same word.
TEST(LassoEval, InvariantUnderRerollingTheLasso) {
  Rng rng(99);
  RandomFormulaOptions fo;
  for (int i = 0; i < 2000; ++i) {
    const std::vector<std::string> aps = random_aps(rng, fo);
    const Formula f = random_formula(rng, aps, fo);
    const Lasso w = random_lasso(rng, aps);
    Lasso rotated = w;
    rotated.prefix.push_back(w.loop.front());
    rotated.loop.erase(rotated.loop.begin());
    rotated.loop.push_back(w.loop.front());
    Lasso doubled = w;
    doubled.loop.insert(doubled.loop.end(), w.loop.begin(), w.loop.end());
    const bool v = evaluate(f, w);
    ASSERT_EQ(v, evaluate(f, rotated)) << f.to_string() << " on " << w.to_string();
    ASSERT_EQ(v, evaluate(f, doubled)) << f.to_string() << " on " << w.to_string();
  }
}

// Semantic identities between operators; the evaluator implements each operator on its own,
// so these relate independent code paths.
TEST(LassoEval, OperatorDualitiesHold) {
  Rng rng(5);
  RandomFormulaOptions fo;
  fo.min_size = 1;
  fo.max_size = 8;
  for (int i = 0; i < 2000; ++i) {
    const std::vector<std::string> aps = random_aps(rng, fo);
    const Formula a = random_formula(rng, aps, fo);
    const Formula b = random_formula(rng, aps, fo);
    const Lasso w = random_lasso(rng, aps);
    auto same = [&](const Formula& x, const Formula& y) {
      EXPECT_EQ(evaluate_all(x, w), evaluate_all(y, w))
          << x.to_string() << " vs " << y.to_string() << " on " << w.to_string();
    };
    same(neg(U(a, b)), R(neg(a), neg(b)));
    same(neg(W(a, b)), M(neg(a), neg(b)));
    same(F(a), U(Formula::tt(), a));
    same(G(a), R(Formula::ff(), a));
    same(W(a, b), Formula::disj(U(a, b), G(a)));
    same(M(a, b), U(b, Formula::conj(a, b)));
    same(neg(X(a)), X(neg(a)));
    same(U(a, b), Formula::disj(b, Formula::conj(a, X(U(a, b)))));
    same(Formula::lxor(a, b), neg(Formula::equiv(a, b)));
  }
}

}  // namespace
}  // namespace rearm::test_support
