// The product form of a mission (symbolic/mission_product.h, docs/symbolic.md "Product
// form") against independent truth:
//  - its language: a one-action lasso is accepted by every part's automaton (the projection)
//    exactly when the explicit automaton of the whole formula accepts it and when the direct
//    evaluator (support/lasso.h) says the formula holds; on the any-order task for N <= 10, per
//    object chains in any order, and random conjunctions of independent fragment formulas;
//  - its choices: against a perfect executor, with and without injected infeasible actions,
//    the product form performs the same actions in the same order as the explicit automaton
//    (MissionForm::kExplicit) and ends the same way; the word it performs satisfies the
//    formula under the evaluator;
//  - at N = 16 and 24, where the explicit automaton has 2^N states, it completes the task in
//    N actions.
#include "symbolic/mission_product.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "ltl/formula.h"
#include "ltl/parser.h"
#include "ltl/translate.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"
#include "support/random_formula.h"
#include "symbolic/mission_controller.h"

namespace rearm::symbolic {
namespace {

using ltl::Formula;
using ltl::Op;
using test_support::Lasso;

constexpr std::uint64_t kSeed = 0x70726f6475637431ULL;  // "product1"

std::string release(int i) {
  return "release(M" + std::to_string(i) + ",l" + std::to_string(i) + ")";
}

// <>release(M1,l1) && ... && <>release(MN,lN): the any-order task.
Formula any_order(int n) {
  std::vector<Formula> parts;
  for (int i = 1; i <= n; ++i) parts.push_back(Formula::eventually(Formula::ap(release(i))));
  return Formula::conj(parts);
}

// Each object's own chain, objects in any order.
Formula chains_any_order(int n) {
  std::vector<Formula> parts;
  for (int i = 1; i <= n; ++i) {
    const Formula g = Formula::ap("grasp(M" + std::to_string(i) + ")");
    parts.push_back(
        Formula::eventually(Formula::conj(g, Formula::eventually(Formula::ap(release(i))))));
  }
  return Formula::conj(parts);
}

MissionOptions form(MissionForm f) {
  MissionOptions o;
  o.form = f;
  return o;
}

// A random one-action lasso over `aps` (each letter none or one predicate): a prefix of up to
// 4 random letters; a loop holding, in half the words, every predicate but each dropped with
// probability 1/(2|aps|) (words at the edge of a conjunction of eventualities: most satisfy
// it, some miss one predicate), else each predicate with probability 1/2; plus up to 2 random
// letters, shuffled.
Lasso random_lasso(Rng& rng, const std::vector<std::string>& aps) {
  auto letter = [&](std::size_t k) {
    Lasso::Letter l(aps.size(), false);
    if (k < aps.size()) l[k] = true;
    return l;
  };
  Lasso w;
  w.aps = aps;
  for (std::int64_t i = rng.uniform_int(0, 4); i > 0; --i)
    w.prefix.push_back(letter(rng.index(aps.size() + 1)));
  const double keep = rng.bernoulli(0.5) ? 1.0 - 0.5 / static_cast<double>(aps.size()) : 0.5;
  for (std::size_t k = 0; k < aps.size(); ++k) {
    if (rng.bernoulli(keep)) w.loop.push_back(letter(k));
  }
  for (std::int64_t i = rng.uniform_int(0, 2); i > 0; --i)
    w.loop.push_back(letter(rng.index(aps.size() + 1)));
  if (w.loop.empty()) w.loop.push_back(letter(aps.size()));
  for (std::size_t k = w.loop.size(); k > 1; --k) std::swap(w.loop[k - 1], w.loop[rng.index(k)]);
  return w;
}

// The product's acceptance: every part accepts the lasso (support's ActionNba acceptance reads
// only the predicates a part knows: the projection).
bool product_accepts(const ProductMission& p, const Lasso& w) {
  for (std::size_t i = 0; i < p.num_groups(); ++i) {
    if (!test_support::accepts(p.part_automaton(i), w)) return false;
  }
  return true;
}

// Language of the product against the explicit automaton and the evaluator on `words` lassos;
// with both_ways, some sampled words must satisfy f and some not.
void check_language(const Formula& f, Rng& rng, int words, bool both_ways = true) {
  const auto product = ProductMission::build(f, {});
  ASSERT_NE(product, nullptr) << f.to_string();
  const ltl::ActionNba whole = ltl::translate_actions(f);
  const std::vector<std::string> aps = f.atomic_propositions();
  int accepted = 0;
  for (int k = 0; k < words; ++k) {
    const Lasso w = random_lasso(rng, aps);
    const bool truth = test_support::evaluate(f, w);
    ASSERT_EQ(product_accepts(*product, w), truth) << f.to_string() << " on " << w.to_string();
    ASSERT_EQ(test_support::accepts(whole, w), truth) << f.to_string() << " on " << w.to_string();
    accepted += truth ? 1 : 0;
  }
  if (!both_ways) return;
  EXPECT_GT(accepted, 0) << f.to_string() << ": no sampled word satisfies it";
  EXPECT_LT(accepted, words) << f.to_string() << ": every sampled word satisfies it";
}

struct Outcome {
  std::vector<std::string> performed;
  MissionStatus status = MissionStatus::InProgress;
};

// A perfect executor: every action succeeds but those in `infeasible`; stops when the
// controller has nothing to do (guarantee formulas end idle) or after max_steps.
Outcome run(MissionController& mc, const std::set<std::string>& infeasible, int max_steps = 400) {
  Outcome r;
  for (int i = 0; i < max_steps; ++i) {
    const std::optional<Action> a = mc.next_action();
    if (!a) break;
    if (infeasible.count(a->to_string())) {
      mc.report_infeasible(*a);
    } else {
      r.performed.push_back(a->to_string());
      mc.report_success();
    }
  }
  r.status = mc.status();
  return r;
}

// The performed word π0 · a1 … ak held forever, as a lasso.
Lasso word_of(const std::vector<std::string>& performed, const std::vector<std::string>& aps,
              const std::string& initial) {
  std::vector<std::vector<std::string>> prefix;
  prefix.push_back(initial.empty() ? std::vector<std::string>{}
                                   : std::vector<std::string>{initial});
  for (const std::string& a : performed) prefix.push_back({a});
  std::vector<std::vector<std::string>> loop = {prefix.back()};
  prefix.pop_back();
  return Lasso::from_names(prefix, loop, aps);
}

TEST(IndependentGroups, LinkedConjunctsShareAGroup) {
  // Conjuncts 1, 3, 4, 5 are linked by release(M3,l3) (3-4), release(M1,l2) (4-5) and
  // release(M1,l1) (5-1); grasp(M3) shares an object with 3, not a predicate.
  const Formula f = ltl::parse(
      "<>release(M1,l1) && <>(grasp(M2) && <>release(M2,l2)) && <>release(M3,l3) && "
      "<>(release(M3,l3) || release(M1,l2)) && <>(release(M1,l2) && <>release(M1,l1)) && "
      "<>grasp(M3)");
  const std::vector<Formula> g = independent_groups(f);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].atomic_propositions(),
            (std::vector<std::string>{"release(M1,l1)", "release(M3,l3)", "release(M1,l2)"}));
  EXPECT_EQ(g[2].to_string(), "F grasp(M3)");
  EXPECT_EQ(g[1].to_string(), "F (grasp(M2) & F release(M2,l2))");
  EXPECT_EQ(independent_groups(ltl::parse("<>(grasp(M1) && <>release(M1,l1))")).size(), 1u);
  EXPECT_EQ(independent_groups(any_order(5)).size(), 5u);
}

TEST(ProductForm, AppliesToIndependentGuaranteesOnly) {
  EXPECT_TRUE(MissionController(any_order(3)).product_form());
  EXPECT_FALSE(MissionController(any_order(3), form(MissionForm::kExplicit)).product_form());
  // One part (the paper's chain): the whole automaton.
  EXPECT_FALSE(MissionController(ltl::parse("<>(grasp(M1) && <>release(M1,l1))")).product_form());
  // A patrol's parts cannot wait (G F p leaves its accepting state on the empty symbol).
  const Formula patrol = ltl::parse("[]<>move(l1) && []<>move(l2)");
  EXPECT_FALSE(MissionController(patrol).product_form());
  try {
    MissionController mc(patrol, form(MissionForm::kProduct));
    FAIL() << "the product form was accepted for a patrol";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot wait"), std::string::npos) << e.what();
  }
}

TEST(ProductForm, LanguageOfTheAnyOrderTaskUpToTen) {
  Rng rng = Rng::derive(kSeed, 1);
  for (int n = 2; n <= 10; ++n) check_language(any_order(n), rng, 300);
}

TEST(ProductForm, LanguageOfChainsInAnyOrder) {
  Rng rng = Rng::derive(kSeed, 2);
  for (int n = 2; n <= 4; ++n) check_language(chains_any_order(n), rng, 400);
}

// Random conjunctions of 2-3 fragment formulas over disjoint predicate pools; those whose
// parts can all wait are checked (about half; the count is asserted).
TEST(ProductForm, LanguageOfRandomIndependentConjunctions) {
  const std::vector<std::vector<std::string>> pools = {
      {"move(l1)", "grasp(M1)"}, {"move(l2)", "release(M2,l2)"}, {"grasp(M3)", "move(l3)"}};
  test_support::RandomFormulaOptions o;
  o.allow_next = false;
  o.negation_anywhere = false;
  o.allow_constants = false;
  o.ops = {Op::And, Op::Or, Op::Eventually, Op::Until};
  o.min_size = 2;
  o.max_size = 7;
  int checked = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    Rng rng = Rng::derive(kSeed + 3, i);
    std::vector<Formula> parts;
    const std::size_t k = 2 + rng.index(2);
    for (std::size_t j = 0; j < k; ++j) {
      parts.push_back(Formula::eventually(test_support::random_formula(rng, pools[j], o)));
    }
    const Formula f = Formula::conj(parts);
    if (independent_groups(f).size() < 2 || !ProductMission::build(f, {})) continue;
    check_language(f, rng, 60, false);  // some ask two predicates at once: unsatisfiable
    ++checked;
  }
  EXPECT_GE(checked, 100);
}

// The same actions in the same order as the explicit automaton, on the any-order task with a
// random π0 and random infeasible actions; the word satisfies the formula when it ends
// accepting, and both forms agree on the verdict.
TEST(ProductForm, SameChoicesAsTheExplicitAutomaton) {
  for (std::uint64_t i = 0; i < 120; ++i) {
    Rng rng = Rng::derive(kSeed + 4, i);
    const int n = static_cast<int>(rng.uniform_int(2, 8));
    const Formula f = i % 3 == 2 ? chains_any_order(std::min(n, 4)) : any_order(n);
    const std::vector<std::string> aps = f.atomic_propositions();
    std::set<std::string> infeasible;
    if (i % 2 == 1) infeasible.insert(aps[rng.index(aps.size())]);
    MissionOptions po, eo = form(MissionForm::kExplicit);
    std::string initial;
    if (rng.bernoulli(0.3)) {
      initial = aps[rng.index(aps.size())];
      po.initial = eo.initial = Action::parse(initial);
    }
    MissionController product(f, po), whole(f, eo);
    ASSERT_TRUE(product.product_form());
    const Outcome a = run(product, infeasible), b = run(whole, infeasible);
    ASSERT_EQ(a.performed, b.performed) << "case " << i << ": " << f.to_string();
    ASSERT_EQ(a.status, b.status) << "case " << i;
    EXPECT_EQ(product.infeasible_actions(), whole.infeasible_actions()) << "case " << i;
    if (a.status == MissionStatus::Accepting) {
      EXPECT_TRUE(test_support::evaluate(f, word_of(a.performed, aps, initial))) << "case " << i;
    } else {
      EXPECT_EQ(a.status, MissionStatus::Infeasible);
      EXPECT_FALSE(infeasible.empty());
    }
  }
}

// Alternatives: on the any-order task every unplaced object's release is offered, the pending
// one (lowest letter) first; preferring another performs it.
TEST(ProductForm, AlternativesAndPrefer) {
  for (const MissionForm f : {MissionForm::kAuto, MissionForm::kExplicit}) {
    MissionController mc(any_order(4), form(f));
    ASSERT_EQ(mc.next_action()->to_string(), release(1));
    std::vector<std::string> alt;
    for (const Action& a : mc.alternatives()) alt.push_back(a.to_string());
    std::sort(alt.begin() + 1, alt.end());  // the pending one first, then in no set order
    EXPECT_EQ(alt, (std::vector<std::string>{release(1), release(2), release(3), release(4)}));
    mc.prefer(Action::parse(release(3)));
    EXPECT_EQ(mc.next_action()->to_string(), release(3));
    mc.report_success();
    ASSERT_EQ(mc.next_action()->to_string(), release(1));
    EXPECT_EQ(mc.alternatives().size(), 3u);
    EXPECT_THROW(mc.prefer(Action::parse(release(3))), Error);  // done already
  }
}

// Where the explicit automaton has 2^N states: N actions, each object released once, and the
// word satisfies the formula.
TEST(ProductForm, CompletesTheAnyOrderTaskAtSixteenAndTwentyFour) {
  for (const int n : {16, 24}) {
    const Formula f = any_order(n);
    MissionController mc(f);
    ASSERT_TRUE(mc.product_form());
    const Outcome r = run(mc, {});
    EXPECT_EQ(r.status, MissionStatus::Accepting);
    ASSERT_EQ(static_cast<int>(r.performed.size()), n);
    EXPECT_EQ(std::set<std::string>(r.performed.begin(), r.performed.end()).size(),
              static_cast<std::size_t>(n));
    EXPECT_TRUE(test_support::evaluate(f, word_of(r.performed, f.atomic_propositions(), "")));
  }
}

}  // namespace
}  // namespace rearm::symbolic
