// The translator against another translator, exactly (docs/symbolic.md "Correctness is
// tested against independent truth", item 2): for seeded random X-free formulas φ,
//   L(ours(φ)) ∩ L(spin(¬φ)) = ∅  and  L(ours(¬φ)) ∩ L(spin(φ)) = ∅,
// by product emptiness over one BDD manager (spin's never claim is read into our
// automaton's alphabet). Together with spin's automata being correct this says
// L(ours(φ)) ⊆ L(φ) and L(ours(¬φ)) ⊆ L(¬φ). The other inclusions are not decided by a
// product (that needs complementation): words sampled from accepting runs of spin(φ) must
// be accepted by ours(φ), here and with random words in translate_lasso_test.
// Every witness of a disagreement is judged by the lasso evaluator, which tells whether our
// automaton or spin's (or the never-claim reader) accepted the wrong word.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.h"
#include "ltl/automaton_io.h"
#include "ltl/translate.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"
#include "support/random_formula.h"
#include "support/scale.h"
#include "support/spin.h"

namespace rearm::test_support {
namespace {

using ltl::Formula;

// Number of random formulas of the exact cross-check (each costs two spin runs) at scale 1
// (REARM_TEST_SCALE shrinks it for the sanitizer stage, support/scale.h).
constexpr std::size_t kNumFormulas = 340;
// The acceptance figure at scale 1: formulas whose both directions (φ and ¬φ) were checked
// exactly; the same share of the formulas at other scales.
constexpr std::size_t kMinBothDirections = 300;
// Largest tolerated share of spin runs that hit the wall-clock bound.
constexpr double kMaxTimeoutShare = 0.10;
// Words sampled from spin's automaton for the formula we translate (ours must accept them).
constexpr std::size_t kGuidedWords = 50;
// Disagreements printed in full.
constexpr std::size_t kMaxReported = 20;

void skip_loudly() {
  std::cerr << "\n********************************************************************\n"
               "*** spin is not installed (Debian package `spin`): the exact       ***\n"
               "*** cross-check of the LTL translator against spin is SKIPPED.     ***\n"
               "********************************************************************\n";
}

RandomFormulaOptions small_spin_formulas() {
  RandomFormulaOptions fo;
  fo.min_size = 5;
  fo.max_size = 12;
  fo.min_aps = 2;
  fo.max_aps = 4;
  fo.spin_safe = true;
  fo.negation_anywhere = true;
  return fo;
}

TEST(SpinRunner, RunsSpinAndReportsFailuresAndTimeouts) {
  if (!spin_installed()) {
    skip_loudly();
    GTEST_SKIP() << "spin not installed";
  }
  const auto claim = spin_never_claim(Formula::eventually(Formula::ap("p")));
  ASSERT_TRUE(claim);
  EXPECT_NE(claim->find("never"), std::string::npos);
  // spin rejects X.
  const SpinRun x = run_spin(Formula::next(Formula::ap("p")));
  EXPECT_EQ(x.status, SpinRun::Status::kFailed) << x.never_claim;
  // F-sequencing of 12 propositions takes spin far longer than 0.2 s (docs/symbolic.md).
  Formula seq = Formula::ap("p12");
  for (int i = 11; i >= 1; --i) {
    seq = Formula::eventually(
        Formula::conj(Formula::ap(std::string("p").append(std::to_string(i))), seq));
  }
  const auto start = std::chrono::steady_clock::now();
  const SpinRun slow = run_spin(seq, 0.2);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(slow.status, SpinRun::Status::kTimeout);
  EXPECT_LT(s, 3.0) << "the wall-clock bound was not enforced";
}

// Disagreements found, by whom the evaluator blames, and the guided words checked.
struct Blame {
  std::size_t ours_wrong = 0, spin_wrong = 0, guided_checks = 0;
  bool report() const { return ours_wrong + spin_wrong <= kMaxReported; }
};

// The exact check: ours(φ) and spin(¬φ) accept no common word; for a common word the evaluator
// says which automaton is wrong.
void product_check(const Formula& ours_f, const Formula& spin_f, const ltl::GeneralNba& ours,
                   const ltl::GeneralNba& theirs, Blame& blame) {
  const auto wit = find_common_word(ours, theirs);
  if (!wit) return;
  const bool satisfies_ours = evaluate(ours_f, wit->word);
  (satisfies_ours ? blame.spin_wrong : blame.ours_wrong) += 1;
  if (!blame.report()) return;
  ADD_FAILURE() << "common word of ours(" << ours_f.to_string() << ") and spin("
                << spin_f.to_string(ltl::Syntax::Spin) << "): " << wit->word.to_string()
                << "; the word " << (satisfies_ours ? "satisfies" : "violates")
                << " the formula we translated, so "
                << (satisfies_ours ? "spin's automaton or the never-claim reader"
                                   : "OUR TRANSLATION")
                << " is wrong (ours: " << ours.num_states()
                << " states, spin: " << theirs.num_states() << " states)\n"
                << wit->to_string();
}

// The other inclusion, by proposal: words of spin's automaton for the same formula must be
// accepted by ours whenever the evaluator confirms them.
void guided_check(const Formula& ours_f, const ltl::GeneralNba& ours, const SpinRun& same,
                  std::size_t k, Blame& blame) {
  if (same.status != SpinRun::Status::kOk) return;
  ltl::GeneralNba spin_same;
  try {
    spin_same = ltl::read_never_claim(same.never_claim, ltl::GeneralAlphabet());
  } catch (const Error&) {
    return;  // counted when the partner job is checked
  }
  Rng word_rng = Rng::derive(0x5a3e, k);
  for (const Lasso& w : sample_accepted_lassos(spin_same, word_rng, kGuidedWords)) {
    ++blame.guided_checks;
    if (!evaluate(ours_f, w)) {
      ++blame.spin_wrong;
      ADD_FAILURE() << "spin(" << ours_f.to_string(ltl::Syntax::Spin) << ") accepts "
                    << w.to_string() << ", which violates the formula";
    } else if (!accepts(ours, w)) {
      ++blame.ours_wrong;
      if (blame.report()) {
        ADD_FAILURE() << "OUR TRANSLATION of " << ours_f.to_string() << " rejects " << w.to_string()
                      << ", a model of the formula (from spin's automaton)";
      }
    }
  }
}

TEST(SpinCrosscheck, OurAutomataAndSpinsHaveNoCommonWordWithTheNegation) {
  if (!spin_installed()) {
    skip_loudly();
    GTEST_SKIP() << "spin not installed";
  }
  Rng rng(0xc0ffee);
  const RandomFormulaOptions fo = small_spin_formulas();
  // (formula we translate, formula spin translates = its negation), for φ and for ¬φ.
  std::vector<std::pair<Formula, Formula>> jobs;
  std::vector<Formula> spin_inputs;
  const std::size_t num_formulas = scaled(kNumFormulas, 10);
  for (std::size_t i = 0; i < num_formulas; ++i) {
    const Formula phi = random_formula(rng, fo);
    jobs.emplace_back(phi, Formula::lnot(phi));
    jobs.emplace_back(Formula::lnot(phi), phi);
    spin_inputs.push_back(Formula::lnot(phi));
    spin_inputs.push_back(phi);
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SpinRun> runs = run_spin_all(spin_inputs);
  const double spin_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t timeouts = 0, spin_failures = 0, reader_errors = 0, checks = 0;
  Blame blame;
  const std::size_t calls = runs.size();
  std::vector<char> checked(jobs.size(), 0);
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const auto& [ours_f, spin_f] = jobs[k];
    const SpinRun& run = runs[k];
    if (run.status == SpinRun::Status::kTimeout) {
      ++timeouts;
      continue;
    }
    if (run.status == SpinRun::Status::kFailed) {
      ++spin_failures;
      ADD_FAILURE() << "spin failed on " << spin_f.to_string(ltl::Syntax::Spin) << ": "
                    << run.diagnostics;
      continue;
    }
    const ltl::GeneralNba ours = ltl::translate_general(ours_f);
    ltl::GeneralNba theirs;
    try {
      theirs = ltl::read_never_claim(run.never_claim, ours.alphabet);
    } catch (const Error& e) {
      ++reader_errors;
      ADD_FAILURE() << "read_never_claim rejected spin's claim for "
                    << spin_f.to_string(ltl::Syntax::Spin) << ": " << e.what() << "\n"
                    << run.never_claim;
      continue;
    }
    ++checks;
    checked[k] = 1;
    product_check(ours_f, spin_f, ours, theirs, blame);
    guided_check(ours_f, ours, runs[k ^ 1], k, blame);  // the partner job: spin(φ) itself
  }
  std::size_t both_directions = 0;
  for (std::size_t i = 0; i < num_formulas; ++i)
    both_directions += checked[2 * i] && checked[2 * i + 1];
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[spin_crosscheck] " << num_formulas << " formulas (" << both_directions
            << " checked in both directions), " << calls << " spin calls, " << timeouts
            << " timed out (skipped, bound " << kSpinTimeoutSeconds << " s), " << spin_failures
            << " spin failures, " << reader_errors << " reader errors, " << checks
            << " exact product checks, " << blame.guided_checks
            << " words of spin's automata checked on ours, " << blame.ours_wrong
            << " disagreements blaming ours, " << blame.spin_wrong << " blaming spin/reader; spin "
            << spin_seconds << " s, total " << seconds << " s\n";
  EXPECT_EQ(blame.ours_wrong, 0u);
  EXPECT_EQ(blame.spin_wrong, 0u);
  EXPECT_GE(both_directions, num_formulas * kMinBothDirections / kNumFormulas);
  EXPECT_EQ(spin_failures, 0u);
  EXPECT_EQ(reader_errors, 0u);
  EXPECT_LE(static_cast<double>(timeouts), kMaxTimeoutShare * static_cast<double>(calls))
      << "too many spin runs timed out for the cross-check to mean anything";
}

// spin's automata, read by read_never_claim, agree with the lasso evaluator: checks the
// reader (and that spin's automata are a trustworthy reference).
TEST(SpinCrosscheck, SpinAutomataPassTheLassoEvaluator) {
  if (!spin_installed()) {
    skip_loudly();
    GTEST_SKIP() << "spin not installed";
  }
  Rng rng(0xbeef);
  const RandomFormulaOptions fo = small_spin_formulas();
  std::vector<std::vector<std::string>> aps;
  std::vector<Formula> formulas;
  for (std::size_t i = 0; i < 100; ++i) {
    aps.push_back(random_aps(rng, fo));
    formulas.push_back(random_formula(rng, aps.back(), fo));
  }
  const std::vector<SpinRun> runs = run_spin_all(formulas);
  std::size_t checks = 0, mismatches = 0, timeouts = 0, reader_errors = 0;
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    const Formula& f = formulas[i];
    const SpinRun& run = runs[i];
    if (run.status == SpinRun::Status::kTimeout) {
      ++timeouts;
      continue;
    }
    ASSERT_EQ(run.status, SpinRun::Status::kOk)
        << f.to_string(ltl::Syntax::Spin) << ": " << run.diagnostics;
    ltl::GeneralNba a;
    try {
      a = ltl::read_never_claim(run.never_claim, ltl::GeneralAlphabet(aps[i]));
    } catch (const Error& e) {
      ++reader_errors;
      ADD_FAILURE() << "read_never_claim rejected spin's claim for "
                    << f.to_string(ltl::Syntax::Spin) << ": " << e.what() << "\n"
                    << run.never_claim;
      continue;
    }
    for (int j = 0; j < 100; ++j) {
      const Lasso w = random_lasso(rng, aps[i]);
      const bool truth = evaluate(f, w);
      ++checks;
      if (accepts(a, w) != truth && ++mismatches <= kMaxReported) {
        ADD_FAILURE() << "spin's automaton (as read) for " << f.to_string(ltl::Syntax::Spin)
                      << " says " << !truth << " on " << w.to_string() << ", evaluator " << truth
                      << "\n"
                      << run.never_claim;
      }
    }
  }
  std::cout << "[spin_crosscheck] reader sanity: " << checks << " checks, " << mismatches
            << " mismatches, " << reader_errors << " reader errors, " << timeouts
            << " spin timeouts\n";
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(reader_errors, 0u);
  EXPECT_LE(timeouts, 10u);
}

}  // namespace
}  // namespace rearm::test_support
