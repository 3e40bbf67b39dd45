// BddManager against brute-force truth tables: every function over at most 8 variables is a
// std::bitset<256> indexed by the assignment (bit v of the index = variable v).
#include "ltl/bdd.h"

#include <gtest/gtest.h>

#include <bitset>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"

namespace rearm::ltl {
namespace {

constexpr std::uint32_t kMaxVars = 8;
constexpr std::size_t kRows = std::size_t{1} << kMaxVars;
using Table = std::bitset<kRows>;
using Ref = BddManager::Ref;

Table var_table(std::uint32_t v) {
  Table t;
  for (std::size_t row = 0; row < kRows; ++row) t[row] = (row >> v) & 1u;
  return t;
}

std::vector<bool> assignment(std::size_t row) {
  std::vector<bool> a(kMaxVars);
  for (std::uint32_t v = 0; v < kMaxVars; ++v) a[v] = (row >> v) & 1u;
  return a;
}

Table cube_table(const Cube& c) {
  Table t;
  t.set();
  for (const Literal& l : c) t &= l.positive ? var_table(l.var) : ~var_table(l.var);
  return t;
}

// A random Boolean expression over variables [0, nv), built at once as a BDD and as a truth
// table. Xor and if-then-else are composed from conj/disj/neg, so all three are exercised.
struct Expr {
  Ref f;
  Table t;
};

Expr random_expr(BddManager& m, Rng& rng, std::uint32_t nv, int depth) {
  if (depth == 0 || rng.bernoulli(0.2)) {
    const int kind = static_cast<int>(rng.index(10));
    if (kind == 0) return {BddManager::kTrue, Table().set()};
    if (kind == 1) return {BddManager::kFalse, Table()};
    const auto v = static_cast<std::uint32_t>(rng.index(nv));
    if (kind < 6) return {m.var(v), var_table(v)};
    return {m.nvar(v), ~var_table(v)};
  }
  const Expr a = random_expr(m, rng, nv, depth - 1);
  switch (rng.index(5)) {
    case 0:
      return {m.neg(a.f), ~a.t};
    case 1: {
      const Expr b = random_expr(m, rng, nv, depth - 1);
      return {m.conj(a.f, b.f), a.t & b.t};
    }
    case 2: {
      const Expr b = random_expr(m, rng, nv, depth - 1);
      return {m.disj(a.f, b.f), a.t | b.t};
    }
    case 3: {
      const Expr b = random_expr(m, rng, nv, depth - 1);
      return {m.disj(m.conj(a.f, m.neg(b.f)), m.conj(m.neg(a.f), b.f)), a.t ^ b.t};
    }
    default: {
      const Expr b = random_expr(m, rng, nv, depth - 1);
      const Expr c = random_expr(m, rng, nv, depth - 1);
      return {m.disj(m.conj(a.f, b.f), m.conj(m.neg(a.f), c.f)), (a.t & b.t) | (~a.t & c.t)};
    }
  }
}

// Structural invariants of a reduced ordered BDD, checked on every node below f.
void check_structure(const BddManager& m, Ref f) {
  if (m.is_terminal(f)) {
    EXPECT_EQ(m.top_var(f), m.num_vars());
    return;
  }
  const Ref lo = m.low(f), hi = m.high(f);
  EXPECT_NE(lo, hi) << "unreduced node";
  EXPECT_LT(m.top_var(f), m.num_vars());
  EXPECT_GT(m.top_var(lo), m.top_var(f)) << "order violated";
  EXPECT_GT(m.top_var(hi), m.top_var(f)) << "order violated";
  check_structure(m, lo);
  check_structure(m, hi);
}

void check_cubes(BddManager& m, const Expr& e) {
  const std::vector<Cube> cubes = m.cubes(e.f);
  Table covered;
  Ref rebuilt = BddManager::kFalse;
  for (const Cube& c : cubes) {
    for (std::size_t i = 1; i < c.size(); ++i) ASSERT_LT(c[i - 1].var, c[i].var) << "unsorted";
    const Table ct = cube_table(c);
    ASSERT_TRUE(ct.any());
    ASSERT_TRUE((ct & ~e.t).none()) << "cube outside the on-set";
    ASSERT_TRUE((ct & covered).none()) << "cubes overlap";
    covered |= ct;
    rebuilt = m.disj(rebuilt, m.cube(c));
  }
  EXPECT_EQ(covered, e.t) << "cubes miss part of the on-set";
  EXPECT_EQ(rebuilt, e.f);
}

TEST(BddTest, RandomExpressionsAgreeWithTruthTables) {
  Rng rng(20240611);
  BddManager m(kMaxVars);
  std::map<std::string, Ref> canonical;  // truth table -> the Ref first seen for it
  std::vector<Expr> seen;
  constexpr int kExpressions = 3000;
  for (int i = 0; i < kExpressions; ++i) {
    const auto nv = static_cast<std::uint32_t>(rng.uniform_int(1, kMaxVars));
    const Expr e = random_expr(m, rng, nv, static_cast<int>(rng.uniform_int(1, 7)));
    for (std::size_t row = 0; row < kRows; ++row) {
      ASSERT_EQ(m.eval(e.f, assignment(row)), e.t[row]) << "expression " << i << " row " << row;
    }
    // Canonicity both ways: equal functions share a Ref, different functions do not.
    const auto [it, inserted] = canonical.emplace(e.t.to_string(), e.f);
    ASSERT_EQ(it->second, e.f) << "two Refs for one function";
    if (inserted) {
      for (const auto& [table, ref] : canonical) {
        if (table != it->first) {
          ASSERT_NE(ref, e.f) << "one Ref for two functions";
        }
      }
    }
    EXPECT_EQ(e.f == BddManager::kFalse, e.t.none());
    EXPECT_EQ(e.f == BddManager::kTrue, e.t.all());
    check_structure(m, e.f);
    check_cubes(m, e);

    // implies / intersects against earlier expressions, without allocating nodes.
    for (int k = 0; k < 4 && !seen.empty(); ++k) {
      const Expr& o = seen[rng.index(seen.size())];
      const std::size_t before = m.node_count();
      EXPECT_EQ(m.implies(e.f, o.f), (e.t & ~o.t).none());
      EXPECT_EQ(m.implies(o.f, e.f), (o.t & ~e.t).none());
      EXPECT_EQ(m.intersects(e.f, o.f), (e.t & o.t).any());
      EXPECT_EQ(m.intersects(o.f, e.f), (e.t & o.t).any());
      EXPECT_EQ(m.node_count(), before) << "implies/intersects allocated nodes";
    }
    seen.push_back(e);
  }
  EXPECT_GT(canonical.size(), 500u) << "generator too degenerate to test canonicity";
}

TEST(BddTest, FreshManagersPerExpression) {
  // Managers sized to the expression, so terminals' top_var sentinel and small tables vary.
  Rng rng(7);
  for (int i = 0; i < 500; ++i) {
    const auto nv = static_cast<std::uint32_t>(rng.uniform_int(1, kMaxVars));
    BddManager m(nv);
    const Expr e = random_expr(m, rng, nv, 6);
    for (std::size_t row = 0; row < (std::size_t{1} << nv); ++row) {
      std::vector<bool> a(nv);
      for (std::uint32_t v = 0; v < nv; ++v) a[v] = (row >> v) & 1u;
      ASSERT_EQ(m.eval(e.f, a), e.t[row]);
    }
    check_structure(m, e.f);
    check_cubes(m, e);
  }
}

TEST(BddTest, TerminalsAndLiterals) {
  BddManager m(3);
  EXPECT_EQ(m.num_vars(), 3u);
  EXPECT_EQ(m.node_count(), 2u);
  EXPECT_TRUE(m.is_terminal(BddManager::kFalse));
  EXPECT_TRUE(m.is_terminal(BddManager::kTrue));
  EXPECT_EQ(m.top_var(BddManager::kTrue), 3u);
  EXPECT_EQ(m.neg(BddManager::kTrue), BddManager::kFalse);
  EXPECT_EQ(m.neg(BddManager::kFalse), BddManager::kTrue);
  EXPECT_TRUE(m.cubes(BddManager::kFalse).empty());
  EXPECT_EQ(m.cubes(BddManager::kTrue), std::vector<Cube>{Cube{}});

  const Ref x1 = m.var(1);
  EXPECT_EQ(m.top_var(x1), 1u);
  EXPECT_EQ(m.low(x1), BddManager::kFalse);
  EXPECT_EQ(m.high(x1), BddManager::kTrue);
  EXPECT_EQ(m.var(1), x1);  // hash-consed
  EXPECT_EQ(m.neg(x1), m.nvar(1));
  EXPECT_EQ(m.literal({1, false}), m.nvar(1));
  EXPECT_EQ(m.conj(x1, m.nvar(1)), BddManager::kFalse);
  EXPECT_EQ(m.disj(x1, m.nvar(1)), BddManager::kTrue);

  // cube(): unsorted input, repeated literals, contradictions.
  const Ref c = m.cube({{2, true}, {0, false}, {2, true}});
  EXPECT_EQ(c, m.conj(m.nvar(0), m.var(2)));
  EXPECT_EQ(m.cube({{0, true}, {0, false}}), BddManager::kFalse);
  EXPECT_EQ(m.cube({}), BddManager::kTrue);
  EXPECT_EQ(m.cubes(c), (std::vector<Cube>{{{0, false}, {2, true}}}));
}

TEST(BddTest, AddVarExtendsTheOrderAtTheBottom) {
  BddManager m;
  EXPECT_EQ(m.num_vars(), 0u);
  EXPECT_EQ(m.top_var(BddManager::kTrue), 0u);
  EXPECT_EQ(m.add_var(), 0u);
  const Ref a = m.var(0);
  EXPECT_EQ(m.add_var(), 1u);
  const Ref ab = m.conj(a, m.var(1));
  EXPECT_EQ(m.top_var(ab), 0u);
  EXPECT_EQ(m.top_var(BddManager::kTrue), 2u);
  EXPECT_TRUE(m.eval(ab, {true, true}));
  EXPECT_FALSE(m.eval(ab, {true, false}));
  EXPECT_TRUE(m.implies(ab, a));
  EXPECT_FALSE(m.implies(a, ab));
}

// Equality of two n-bit words x_i == x_{i+n} under the order x_0..x_{2n-1} needs about 2^n
// nodes, so n = 14 overruns a budget of 2000.
TEST(BddTest, NodeBudgetThrowsBudgetExceeded) {
  constexpr std::uint32_t kN = 14;
  BddManager m(2 * kN, 2000);
  Ref f = BddManager::kTrue;
  Ref last_ok = f;
  bool thrown = false;
  try {
    for (std::uint32_t i = 0; i < kN; ++i) {
      const Ref eq = m.disj(m.conj(m.var(i), m.var(i + kN)), m.conj(m.nvar(i), m.nvar(i + kN)));
      f = m.conj(f, eq);
      last_ok = f;
    }
  } catch (const BudgetExceeded& e) {
    thrown = true;
    EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(thrown);
  EXPECT_LE(m.node_count(), 2000u);
  // The manager stays usable after the throw: earlier results still evaluate correctly.
  std::vector<bool> a(2 * kN, false);
  EXPECT_TRUE(m.eval(last_ok, a));
  a[0] = true;
  EXPECT_FALSE(m.eval(last_ok, a));
  EXPECT_EQ(m.conj(last_ok, BddManager::kTrue), last_ok);
}

TEST(BddTest, LargeFunctionsGrowTheTables) {
  // Equality of two 9-bit words in a bad order has ~2^10 nodes: several unique-table and
  // cache growths. Checked against direct evaluation.
  constexpr std::uint32_t kN = 9;
  BddManager m(2 * kN);
  Ref f = BddManager::kTrue;
  for (std::uint32_t i = 0; i < kN; ++i) {
    f = m.conj(f,
               m.neg(m.disj(m.conj(m.var(i), m.nvar(i + kN)), m.conj(m.nvar(i), m.var(i + kN)))));
  }
  EXPECT_GT(m.node_count(), 1000u);
  Rng rng(3);
  for (int k = 0; k < 2000; ++k) {
    std::vector<bool> a(2 * kN);
    for (std::uint32_t v = 0; v < 2 * kN; ++v) a[v] = rng.bernoulli(0.5);
    if (rng.bernoulli(0.5)) {
      for (std::uint32_t v = 0; v < kN; ++v) a[v + kN] = a[v];
    }
    bool expected = true;
    for (std::uint32_t v = 0; v < kN; ++v) expected = expected && a[v] == a[v + kN];
    ASSERT_EQ(m.eval(f, a), expected);
  }
  EXPECT_EQ(m.cubes(f).size(), std::size_t{1} << kN);
}

TEST(BddDeathTest, BadVariablesAndRefsAbort) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  BddManager m(2);
  EXPECT_DEATH(m.var(2), "out of range");
  EXPECT_DEATH(m.conj(12345, BddManager::kTrue), "invalid BDD Ref");
  EXPECT_DEATH(m.low(BddManager::kTrue), "terminal");
}

}  // namespace
}  // namespace rearm::ltl
