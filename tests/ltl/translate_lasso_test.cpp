// The translator against the direct lasso evaluator (docs/symbolic.md "Correctness is
// tested against independent truth", item 1): for seeded random formulas (tree size 5–20,
// 2–5 propositions, with and without X and unrestricted !) and random lasso words, the
// automaton accepts the word iff the evaluator says the word satisfies the formula. Both
// alphabets: translate_general on arbitrary words, translate_actions on words with at most
// one true proposition per letter.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "ltl/parser.h"
#include "ltl/translate.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"
#include "support/random_formula.h"
#include "support/scale.h"

namespace rearm::test_support {
namespace {

using ltl::Formula;
using ltl::TranslateOptions;

// Mismatches printed in full per test (all are counted).
constexpr std::size_t kMaxReported = 20;

struct Tally {
  std::size_t formulas = 0, checks = 0, mismatches = 0, errors = 0;
  std::size_t accepted = 0;  // words the evaluator said satisfy the formula
  double translate_ms = 0.0;
};

// Translation options cycled over the formulas: the default pipeline most often, and the
// raw translation without rewriting or without automaton simplification, so a rewriting
// rule cannot hide a translation bug (and vice versa).
TranslateOptions variant(std::size_t i) {
  TranslateOptions o;
  switch (i % 4) {
    case 1:
      o.rewrite = false;
      break;
    case 3:
      o.simplify = false;
      break;
    default:
      break;
  }
  return o;
}

std::string describe(const TranslateOptions& o) {
  std::ostringstream s;
  s << "{rewrite=" << o.rewrite << ", simplify=" << o.simplify << "}";
  return s.str();
}

template <class Nba>
void check_words(const Nba& a, const Formula& f, const std::vector<std::string>& aps,
                 const TranslateOptions& o, Rng& rng, const LassoOptions& lo, std::size_t num_words,
                 const char* which, Tally& t) {
  for (std::size_t j = 0; j < num_words; ++j) {
    const Lasso w = random_lasso(rng, aps, lo);
    const bool truth = evaluate(f, w);
    const bool verdict = accepts(a, w);
    ++t.checks;
    t.accepted += truth ? 1 : 0;
    if (truth != verdict) {
      if (++t.mismatches <= kMaxReported) {
        ADD_FAILURE() << which << " mismatch: formula " << f.to_string(ltl::Syntax::Spot)
                      << "  word " << w.to_string() << "  evaluator " << truth << "  automaton "
                      << verdict << "  options " << describe(o) << "  (" << a.num_states()
                      << " states)";
      }
    }
  }
}

// Translates `num_formulas` random formulas with both translators and checks each automaton
// on `words_per_automaton` random words.
Tally run(std::uint64_t seed, const RandomFormulaOptions& fo, std::size_t num_formulas,
          std::size_t words_per_automaton) {
  Tally t;
  Rng rng(seed);
  LassoOptions general_words;
  LassoOptions action_words;
  action_words.one_hot = true;
  for (std::size_t i = 0; i < num_formulas; ++i) {
    const std::vector<std::string> aps = random_aps(rng, fo);
    const Formula f = random_formula(rng, aps, fo);
    const TranslateOptions o = variant(i);
    ++t.formulas;
    try {
      const auto start = std::chrono::steady_clock::now();
      // Every other general automaton also gets the unused propositions (extra_aps); the
      // action automaton always does, since an unused action is still a distinct letter.
      const ltl::GeneralNba g =
          ltl::translate_general(f, o, nullptr, i % 2 ? aps : std::vector<std::string>{});
      const ltl::ActionNba act = ltl::translate_actions(f, o, nullptr, aps);
      t.translate_ms +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      check_words(g, f, aps, o, rng, general_words, words_per_automaton, "general", t);
      check_words(act, f, aps, o, rng, action_words, words_per_automaton, "actions", t);
    } catch (const std::exception& e) {
      ++t.errors;
      ADD_FAILURE() << "translation threw for " << f.to_string() << " options " << describe(o)
                    << ": " << e.what();
    }
  }
  return t;
}

void print(const char* name, const Tally& t, double total_ms) {
  std::cout << "[translate_lasso] " << name << ": " << t.formulas << " formulas, " << t.checks
            << " (formula, word) checks, " << t.accepted << " satisfied, " << t.mismatches
            << " mismatches, " << t.errors << " translation errors; translation " << t.translate_ms
            << " ms, total " << total_ms << " ms\n";
}

// 12,000 formulas × 2 alphabets × 20 words = 480,000 checks per test, 960,000 in all
// (about 7 s in Release on 2 cores; the budget is 60 s).
// REARM_TEST_SCALE shrinks the run for the sanitizer stage (support/scale.h).
constexpr std::size_t kFormulasPerTest = 12000;
constexpr std::size_t kWordsPerAutomaton = 20;
constexpr std::size_t kChecksPerTest = kFormulasPerTest * 2 * kWordsPerAutomaton;

// One random family: formulas of size 5–20 over 2–5 propositions, with or without X and
// negation above the propositions.
void check_family(const char* label, std::uint64_t seed, bool next_and_negation) {
  RandomFormulaOptions fo;
  fo.min_size = 5;
  fo.max_size = 20;
  fo.min_aps = 2;
  fo.max_aps = 5;
  fo.allow_next = next_and_negation;
  fo.negation_anywhere = next_and_negation;
  const auto start = std::chrono::steady_clock::now();
  const Tally t = run(seed, fo, scaled(kFormulasPerTest), kWordsPerAutomaton);
  print(
      label, t,
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  EXPECT_EQ(t.mismatches, 0u);
  EXPECT_EQ(t.errors, 0u);
  EXPECT_GE(t.checks, scaled(kChecksPerTest));
}

TEST(TranslateLasso, WithNextAndUnrestrictedNegation) {
  check_family("with X and !", 0x5eed0001, true);
}

TEST(TranslateLasso, WithoutNextNegationOnPropositions) {
  check_family("no X, ! on propositions", 0x5eed0002, false);
}

// Formulas that exercise corner cases of the construction (and past failures): each is
// checked on many words with every option variant.
TEST(TranslateLasso, Corpus) {
  const std::vector<std::string> corpus = {
      "G F p0 & F G p1",
      "(p0 U p1) R p2",
      "X X p0 U !p1",
      "p0 W (p1 M p2)",
      "F(p0 & X(p1 U p2))",
      "G(p0 -> X(!p0 U p1))",
      "true U false",
      "false R true",
      "!(p0 xor p1) U (p0 <-> X p1)",
      "G F(p0 & F(p1 & F p2))",
      "F G(p0 | X p1) & G F !p0",
      "(G F p0 -> G F p1) & (F G p2 -> F G !p1)",
      "X(p0 R X p1) W G !p0",
      "!(G F p0 | F G p1) M (p0 U (p1 W p2))",
      "F(p0 & G !p0)",
      "G(p0 xor X p0)",
      "p0 M (X p1 <-> F p0)",
      "(p0 R p1) U (p0 M p1)",
  };
  Rng rng(77);
  LassoOptions general_words;
  general_words.max_prefix = 5;
  general_words.max_loop = 5;
  LassoOptions action_words = general_words;
  action_words.one_hot = true;
  Tally t;
  for (const std::string& text : corpus) {
    const Formula f = ltl::parse(text);
    const std::vector<std::string> aps = f.atomic_propositions();
    for (std::size_t v = 0; v < 4; ++v) {
      TranslateOptions o;
      o.rewrite = v % 2 == 0;
      o.simplify = v < 2;
      const ltl::GeneralNba g = ltl::translate_general(f, o);
      const ltl::ActionNba act = ltl::translate_actions(f, o);
      check_words(g, f, aps, o, rng, general_words, 500, "general", t);
      check_words(act, f, aps, o, rng, action_words, 500, "actions", t);
    }
  }
  EXPECT_EQ(t.mismatches, 0u);
}

}  // namespace
}  // namespace rearm::test_support
