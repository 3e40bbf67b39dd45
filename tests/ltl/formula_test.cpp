// Formula (ltl/formula.h): structural equality and hash, the strict total order, size,
// is_boolean, has_next, atomic_propositions, is_action_predicate, and the printer's exact
// spellings. Expected values come from hand-built trees and a recursive reference
// implementation of each query written here, independently of formula.cpp.
#include "ltl/formula.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/error.h"
#include "core/rng.h"

namespace rearm::ltl {
namespace {

using F = Formula;

// ---------------------------------------------------------------------------------------
// A seeded random formula generator and reference implementations of the queries.

const std::vector<Op> kUnaryOps = {Op::Not, Op::Next, Op::Eventually, Op::Always};
const std::vector<Op> kBinaryOps = {Op::And,     Op::Or,        Op::Implies,
                                    Op::Equiv,   Op::Xor,       Op::Until,
                                    Op::Release, Op::WeakUntil, Op::StrongRelease};

// A random tree of at most `budget` nodes over `aps` (few names, so duplicates are common).
F random_formula(Rng& rng, const std::vector<std::string>& aps, std::size_t budget) {
  constexpr std::uint64_t kConstantOneIn = 10;
  if (budget <= 1 || rng.index(budget) == 0) {
    const std::uint64_t r = rng.index(kConstantOneIn);
    if (r == 0) return rng.bernoulli(0.5) ? F::tt() : F::ff();
    return F::ap(aps[rng.index(aps.size())]);
  }
  constexpr double kUnaryProbability = 0.3;
  if (rng.bernoulli(kUnaryProbability)) {
    return F::make(kUnaryOps[rng.index(kUnaryOps.size())], {random_formula(rng, aps, budget - 1)});
  }
  const Op op = kBinaryOps[rng.index(kBinaryOps.size())];
  constexpr std::int64_t kMaxNaryArity = 3;
  const std::size_t arity = (op == Op::And || op == Op::Or)
                                ? static_cast<std::size_t>(rng.uniform_int(2, kMaxNaryArity))
                                : 2;
  std::vector<F> children;
  for (std::size_t i = 0; i < arity; ++i) {
    children.push_back(random_formula(rng, aps, std::max<std::size_t>(1, (budget - 1) / arity)));
  }
  return F::make(op, std::move(children));
}

// Rebuilds `f` node by node: an equal tree sharing no node with `f`.
F deep_copy(const F& f) {
  if (f.op() == Op::Ap) return F::ap(f.name());
  if (f.op() == Op::True || f.op() == Op::False) return F::make(f.op(), {});
  std::vector<F> children;
  for (const F& c : f.children()) children.push_back(deep_copy(c));
  return F::make(f.op(), std::move(children));
}

bool reference_equal(const F& x, const F& y) {
  if (x.op() != y.op() || x.name() != y.name() || x.arity() != y.arity()) return false;
  for (std::size_t i = 0; i < x.arity(); ++i) {
    if (!reference_equal(x.child(i), y.child(i))) return false;
  }
  return true;
}

std::size_t reference_size(const F& f) {
  std::size_t n = 1;
  for (const F& c : f.children()) n += reference_size(c);
  return n;
}

bool is_temporal(Op op) {
  return op == Op::Next || op == Op::Eventually || op == Op::Always || op == Op::Until ||
         op == Op::Release || op == Op::WeakUntil || op == Op::StrongRelease;
}

bool reference_has(const F& f, bool (*pred)(Op)) {
  if (pred(f.op())) return true;
  return std::any_of(f.children().begin(), f.children().end(),
                     [&](const F& c) { return reference_has(c, pred); });
}

void reference_aps(const F& f, std::vector<std::string>& out) {
  if (f.op() == Op::Ap) {
    if (std::find(out.begin(), out.end(), f.name()) == out.end()) out.push_back(f.name());
    return;
  }
  for (const F& c : f.children()) reference_aps(c, out);
}

std::vector<F> random_sample(std::uint64_t seed, std::size_t count) {
  constexpr std::int64_t kMaxBudget = 12;
  const std::vector<std::string> aps = {"a", "b", "c"};
  Rng rng(seed);
  std::vector<F> sample;
  for (std::size_t i = 0; i < count; ++i) {
    sample.push_back(
        random_formula(rng, aps, static_cast<std::size_t>(rng.uniform_int(1, kMaxBudget))));
  }
  return sample;
}

const F a = F::ap("a");
const F b = F::ap("b");
const F c = F::ap("c");

// ---------------------------------------------------------------------------------------
// Construction.

TEST(FormulaTest, LeavesAndAccessors) {
  EXPECT_EQ(F().op(), Op::True);
  EXPECT_EQ(F(), F::tt());
  EXPECT_EQ(F::ff().op(), Op::False);
  EXPECT_EQ(a.op(), Op::Ap);
  EXPECT_EQ(a.name(), "a");
  EXPECT_EQ(a.arity(), 0u);
  EXPECT_TRUE(F::lnot(a).name().empty());
  const F u = F::until(a, b);
  EXPECT_EQ(u.arity(), 2u);
  EXPECT_EQ(u.child(0), a);
  EXPECT_EQ(u.child(1), b);
  EXPECT_THROW(u.child(2), std::out_of_range);
}

TEST(FormulaTest, ConjDisjDegenerateCases) {
  EXPECT_EQ(F::conj({}), F::tt());
  EXPECT_EQ(F::disj({}), F::ff());
  EXPECT_EQ(F::conj({a}), a);
  EXPECT_EQ(F::disj({b}), b);
  const F and3 = F::conj({a, b, c});
  EXPECT_EQ(and3.op(), Op::And);
  EXPECT_EQ(and3.arity(), 3u);
}

TEST(FormulaTest, BadArityAndEmptyNameThrow) {
  EXPECT_THROW(F::make(Op::Not, {}), Error);
  EXPECT_THROW(F::make(Op::Until, {a}), Error);
  EXPECT_THROW(F::make(Op::And, {a}), Error);
  EXPECT_THROW(F::make(Op::True, {a}), Error);
  EXPECT_THROW(F::ap(""), Error);
  EXPECT_NO_THROW(F::make(Op::Or, {a, b, c}));
}

// ---------------------------------------------------------------------------------------
// Equality and hash are structural.

TEST(FormulaTest, EqualityIsStructural) {
  const F x = F::until(F::conj(a, F::lnot(b)), F::eventually(c));
  const F y = F::until(F::conj(F::ap("a"), F::lnot(F::ap("b"))), F::eventually(F::ap("c")));
  EXPECT_NE(x.node_id(), y.node_id());
  EXPECT_EQ(x, y);
  EXPECT_EQ(x.hash(), y.hash());
  EXPECT_EQ(FormulaHash()(x), FormulaHash()(y));

  EXPECT_NE(F::conj(a, b), F::conj(b, a));  // order of operands matters
  EXPECT_NE(F::conj(a, b), F::disj(a, b));
  EXPECT_NE(F::conj({a, b, c}), F::conj(F::conj(a, b), c));  // no flattening
  EXPECT_NE(F::until(a, b), F::release(a, b));
  EXPECT_NE(F::weak_until(a, b), F::strong_release(a, b));
  EXPECT_NE(F::eventually(a), F::always(a));
  EXPECT_NE(F::lnot(F::lnot(a)), a);  // no simplification
  EXPECT_NE(a, F::ap("A"));
  EXPECT_NE(F::tt(), F::ff());
  EXPECT_EQ(F::ap("move(l1)"), F::ap("move(l1)"));
}

TEST(FormulaTest, EqualityAndHashAgreeWithReferenceOnRandomPairs) {
  constexpr std::size_t kSample = 400;
  const std::vector<F> sample = random_sample(/*seed=*/31, kSample);
  std::unordered_set<F, FormulaHash> distinct;
  for (const F& f : sample) {
    const F copy = deep_copy(f);
    EXPECT_EQ(copy, f);
    EXPECT_EQ(copy.hash(), f.hash());
    distinct.insert(f);
  }
  for (const F& x : sample) {
    for (const F& y : sample) {
      const bool same = reference_equal(x, y);
      ASSERT_EQ(x == y, same) << x.to_string() << " vs " << y.to_string();
      ASSERT_EQ(x != y, !same);
      if (same) {
        ASSERT_EQ(x.hash(), y.hash());
      }
    }
  }
  // Duplicates are common in the sample and collapse in a hash set.
  EXPECT_LT(distinct.size(), sample.size());
  for (const F& f : sample) EXPECT_EQ(distinct.count(deep_copy(f)), 1u);
}

// ---------------------------------------------------------------------------------------
// operator< is a strict total order consistent with ==.

TEST(FormulaTest, OrderIsStrictTotalOrderOnRandomSample) {
  constexpr std::size_t kSample = 120;
  std::vector<F> sample = random_sample(/*seed=*/47, kSample);
  for (std::size_t i = 0; i < kSample / 2; ++i) sample.push_back(deep_copy(sample[i]));
  for (const F& x : sample) {
    ASSERT_FALSE(x < x);
    for (const F& y : sample) {
      const int relations = (x < y) + (y < x) + (x == y);
      ASSERT_EQ(relations, 1) << x.to_string() << " vs " << y.to_string();
      for (const F& z : sample) {
        if (x < y && y < z) {
          ASSERT_TRUE(x < z);
        }
      }
    }
  }
  std::vector<F> sorted = sample;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i) EXPECT_FALSE(sorted[i + 1] < sorted[i]);
}

// ---------------------------------------------------------------------------------------
// Queries.

TEST(FormulaTest, Size) {
  EXPECT_EQ(a.size(), 1u);
  EXPECT_EQ(F::tt().size(), 1u);
  EXPECT_EQ(F::lnot(a).size(), 2u);
  EXPECT_EQ(F::conj({a, b, c}).size(), 4u);
  EXPECT_EQ(F::until(a, F::eventually(b)).size(), 4u);
  const F shared = F::conj(a, b);
  EXPECT_EQ(F::disj(shared, shared).size(), 7u);  // a tree size: shared nodes count twice
  for (const F& f : random_sample(/*seed=*/5, 200)) EXPECT_EQ(f.size(), reference_size(f));
}

TEST(FormulaTest, IsBoolean) {
  EXPECT_TRUE(F::tt().is_boolean());
  EXPECT_TRUE(a.is_boolean());
  EXPECT_TRUE(F::conj(a, F::lnot(b)).is_boolean());
  EXPECT_TRUE(F::implies(a, F::lxor(b, F::equiv(a, c))).is_boolean());
  EXPECT_FALSE(F::next(a).is_boolean());
  EXPECT_FALSE(F::eventually(a).is_boolean());
  EXPECT_FALSE(F::always(a).is_boolean());
  EXPECT_FALSE(F::until(a, b).is_boolean());
  EXPECT_FALSE(F::release(a, b).is_boolean());
  EXPECT_FALSE(F::weak_until(a, b).is_boolean());
  EXPECT_FALSE(F::strong_release(a, b).is_boolean());
  EXPECT_FALSE(F::conj(a, F::lnot(F::eventually(b))).is_boolean());
  for (const F& f : random_sample(/*seed=*/6, 200)) {
    EXPECT_EQ(f.is_boolean(), !reference_has(f, is_temporal)) << f.to_string();
  }
}

TEST(FormulaTest, HasNext) {
  EXPECT_TRUE(F::next(a).has_next());
  EXPECT_TRUE(F::until(a, F::conj(b, F::next(c))).has_next());
  EXPECT_FALSE(F::eventually(F::always(a)).has_next());
  EXPECT_FALSE(F::until(a, b).has_next());
  EXPECT_FALSE(a.has_next());
  const auto is_next = [](Op op) { return op == Op::Next; };
  for (const F& f : random_sample(/*seed=*/7, 200)) {
    EXPECT_EQ(f.has_next(), reference_has(f, is_next)) << f.to_string();
  }
}

TEST(FormulaTest, AtomicPropositionsInOrderOfFirstOccurrence) {
  const F f = F::conj({b, F::until(a, b), F::eventually(F::ap("move(l1)")), a, c});
  EXPECT_EQ(f.atomic_propositions(), (std::vector<std::string>{"b", "a", "move(l1)", "c"}));
  EXPECT_TRUE(F::tt().atomic_propositions().empty());
  EXPECT_EQ(F::implies(F::next(c), F::lnot(a)).atomic_propositions(),
            (std::vector<std::string>{"c", "a"}));
  for (const F& g : random_sample(/*seed=*/8, 200)) {
    std::vector<std::string> expected;
    reference_aps(g, expected);
    EXPECT_EQ(g.atomic_propositions(), expected) << g.to_string();
  }
}

TEST(FormulaTest, IsActionPredicate) {
  for (const char* yes :
       {"move(l1)", "grasp(M2)", "release(M1,l2)", "move(_x)", "release(F,G)", "grasp(obj_3)"}) {
    EXPECT_TRUE(is_action_predicate(yes)) << yes;
  }
  for (const char* no :
       {"move", "move()", "move(l1,l2)", "release(M1)", "release(M1,l2,l3)", "grasp( M1)",
        "grasp(M1 )", "release(M1, l2)", "move(1a)", "Move(l1)", "moves(l1)", "move(l1))",
        "move(l1", "move l1", "release(,l2)", "release(M1,)", "p1", "(l1)", "move(l-1)"}) {
    EXPECT_FALSE(is_action_predicate(no)) << no;
  }
}

// Nested W and M, printed for spin, stay polynomial: a chain of 24 (nested to the right, as the
// parser reads a W b W c, or to the left) spelt with the larger operand repeated would double
// 24 times, to about 10^8 bytes (a 400-byte formula found by the fuzzer took 14 s to print).
TEST(FormulaTest, SpinSpellingOfNestedWeakOperatorsIsPolynomial) {
  constexpr std::size_t kLevels = 24;
  for (const bool strong : {false, true}) {
    const auto op = [&](F x, F y) {
      return strong ? F::strong_release(x, y) : F::weak_until(x, y);
    };
    F right = F::ap("p0");
    F left = F::ap("p0");
    for (std::size_t i = 1; i < kLevels; ++i) {
      right = op(F::ap("p" + std::to_string(i)), right);
      left = op(left, F::ap("p" + std::to_string(i)));
    }
    // Each level adds one operator and two copies of one proposition: about 20 bytes.
    EXPECT_LT(right.to_string(Syntax::Spin).size(), kLevels * 30u);
    EXPECT_LT(left.to_string(Syntax::Spin).size(), kLevels * 30u);
  }
}

TEST(FormulaTest, PrintedSpellings) {
  EXPECT_EQ(F::eventually(a).to_string(Syntax::Spot), "F a");
  EXPECT_EQ(F::eventually(a).to_string(Syntax::Spin), "<> a");
  EXPECT_EQ(F::always(F::eventually(a)).to_string(Syntax::Spin), "[] (<> a)");
  EXPECT_EQ(F::conj({a, b, c}).to_string(Syntax::Spot), "a & b & c");
  EXPECT_EQ(F::conj({a, b, c}).to_string(Syntax::Spin), "a && b && c");
  EXPECT_EQ(F::disj(F::conj(a, b), c).to_string(Syntax::Spot), "(a & b) | c");
  EXPECT_EQ(F::release(a, b).to_string(Syntax::Spot), "a R b");
  EXPECT_EQ(F::release(a, b).to_string(Syntax::Spin), "a V b");
  // spin has neither W nor M: the expansion repeats the smaller operand (a when sizes tie).
  EXPECT_EQ(F::weak_until(a, b).to_string(Syntax::Spin), "(a U b) || ([] a)");
  EXPECT_EQ(F::strong_release(a, b).to_string(Syntax::Spin), "(a V b) && (<> a)");
  EXPECT_EQ(F::weak_until(F::conj(a, b), c).to_string(Syntax::Spin), "c V ((a && b) || c)");
  EXPECT_EQ(F::strong_release(F::conj(a, b), c).to_string(Syntax::Spin), "c U ((a && b) && c)");
  EXPECT_EQ(F::lxor(a, b).to_string(Syntax::Spin), "!(a <-> b)");
  EXPECT_EQ(F::lnot(a).to_string(Syntax::Spin), "!a");
  EXPECT_EQ(F::ap("release(M1,l2)").to_string(), "release(M1,l2)");
  EXPECT_EQ(F::ap("F1").to_string(), "\"F1\"");  // would read as an operator otherwise
  EXPECT_EQ(F::ap("true").to_string(), "\"true\"");
  EXPECT_EQ(F::ap("a b").to_string(), "\"a b\"");
  EXPECT_EQ(F::ap("p1").to_string(), "p1");
}

}  // namespace
}  // namespace rearm::ltl
