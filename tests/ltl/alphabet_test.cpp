// Alphabets: label() strings, read back by a small independent HOA-label evaluator written
// here, must agree with contains() (and with brute-force truth tables) on every symbol of the
// alphabet's domain.
#include "ltl/alphabet.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"

namespace rearm::ltl {
namespace {

// Evaluates a HOA label expression of the forms label() prints: "t", "f", or a disjunction
// ("|") of conjunctions ("&") of literals "i" / "!i" (i an AP index), spaces anywhere.
// Malformed input is a test failure (returns false after ADD_FAILURE).
class LabelEvaluator {
 public:
  LabelEvaluator(const std::string& text, const std::vector<bool>& values)
      : s_(text), values_(values) {}

  bool evaluate() {
    const bool v = disjunction();
    skip_spaces();
    if (pos_ != s_.size()) fail("trailing text");
    return v;
  }
  bool ok() const { return ok_; }

 private:
  void skip_spaces() {
    while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
  }
  bool accept(char c) {
    skip_spaces();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void fail(const char* why) {
    if (ok_) ADD_FAILURE() << "bad label \"" << s_ << "\": " << why << " at " << pos_;
    ok_ = false;
  }
  bool disjunction() {
    bool v = conjunction();
    while (accept('|')) v = conjunction() || v;
    return v;
  }
  bool conjunction() {
    bool v = literal();
    while (accept('&')) v = literal() && v;
    return v;
  }
  bool literal() {
    if (accept('!')) return !literal();
    if (accept('t')) return true;
    if (accept('f')) return false;
    skip_spaces();
    std::size_t index = 0;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
      index = index * 10 + static_cast<std::size_t>(s_[pos_] - '0');
      ++pos_;
    }
    if (pos_ == start) {
      fail("expected a literal");
      return false;
    }
    if (index >= values_.size()) {
      fail("AP index out of range");
      return false;
    }
    return values_[index];
  }

  std::string s_;
  const std::vector<bool>& values_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

bool eval_label(const std::string& label, const std::vector<bool>& values) {
  LabelEvaluator e(label, values);
  const bool v = e.evaluate();
  EXPECT_TRUE(e.ok());
  return v;
}

TEST(LabelEvaluatorTest, ReadsTheHoaForms) {
  const std::vector<bool> v = {true, false, true};
  EXPECT_TRUE(eval_label("t", v));
  EXPECT_FALSE(eval_label("f", v));
  EXPECT_TRUE(eval_label("0&!1", v));
  EXPECT_FALSE(eval_label("1 | !2", v));
  EXPECT_TRUE(eval_label("1 | !2 | 0&2", v));
}

// ---------------------------------------------------------------------------------------
// GeneralAlphabet

std::vector<bool> symbol_of(std::size_t row, std::size_t n) {
  std::vector<bool> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = (row >> i) & 1u;
  return s;
}

// A random guard over n propositions, with its truth table (bit `row` = symbol_of(row)).
struct GeneralGuard {
  GeneralAlphabet::Guard g;
  std::vector<bool> table;
};

GeneralGuard random_general(const GeneralAlphabet& a, Rng& rng, int depth) {
  const std::size_t n = a.aps().size();
  const std::size_t rows = std::size_t{1} << n;
  if (depth == 0 || rng.bernoulli(0.25)) {
    const auto i = static_cast<std::uint32_t>(rng.index(n));
    const bool positive = rng.bernoulli(0.5);
    GeneralGuard out{a.ap(i, positive), std::vector<bool>(rows)};
    for (std::size_t r = 0; r < rows; ++r) out.table[r] = (((r >> i) & 1u) != 0) == positive;
    return out;
  }
  const GeneralGuard x = random_general(a, rng, depth - 1);
  if (rng.bernoulli(0.15)) {
    GeneralGuard out{a.bdd().neg(x.g), x.table};
    out.table.flip();
    return out;
  }
  const GeneralGuard y = random_general(a, rng, depth - 1);
  const bool use_and = rng.bernoulli(0.5);
  GeneralGuard out{use_and ? a.conj(x.g, y.g) : a.disj(x.g, y.g), std::vector<bool>(rows)};
  for (std::size_t r = 0; r < rows; ++r) {
    out.table[r] = use_and ? (x.table[r] && y.table[r]) : (x.table[r] || y.table[r]);
  }
  return out;
}

TEST(GeneralAlphabetTest, LabelsAgreeWithContainsOnAllSymbols) {
  Rng rng(424242);
  int checked = 0;
  for (std::size_t n = 1; n <= 6; ++n) {
    std::vector<std::string> aps;
    for (std::size_t i = 0; i < n; ++i) aps.push_back("p" + std::to_string(i));
    const GeneralAlphabet a(aps);
    for (int k = 0; k < 300; ++k) {
      const GeneralGuard gg = random_general(a, rng, 5);
      const std::string label = a.label(gg.g);
      for (std::size_t row = 0; row < (std::size_t{1} << n); ++row) {
        const std::vector<bool> s = symbol_of(row, n);
        ASSERT_EQ(a.contains(gg.g, s), gg.table[row]) << "contains, row " << row;
        ASSERT_EQ(eval_label(label, s), gg.table[row]) << "label \"" << label << "\" row " << row;
      }
      EXPECT_EQ(label == "t", a.implies(a.top(), gg.g)) << label;
      EXPECT_EQ(label == "f", a.is_false(gg.g)) << label;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1800);
}

// The label is an irredundant sum of products: dropping any cube or any literal changes the
// function. Checked by brute force on random guards.
TEST(GeneralAlphabetTest, LabelsAreIrredundant) {
  Rng rng(99);
  const std::size_t n = 5;
  const GeneralAlphabet a({"a", "b", "c", "d", "e"});
  for (int k = 0; k < 300; ++k) {
    const GeneralGuard gg = random_general(a, rng, 5);
    const std::string label = a.label(gg.g);
    if (label == "t" || label == "f") continue;
    // Split into cubes of literal strings.
    std::vector<std::vector<std::string>> cubes(1);
    std::string lit;
    for (char c : label + " ") {
      if (c == '&' || c == ' ' || c == '|') {
        if (!lit.empty()) cubes.back().push_back(lit);
        lit.clear();
        if (c == '|') cubes.emplace_back();
      } else {
        lit += c;
      }
    }
    auto join = [](const std::vector<std::vector<std::string>>& cs) {
      std::string s;
      for (const auto& c : cs) {
        if (!s.empty()) s += " | ";
        std::string t;
        for (const auto& l : c) t += (t.empty() ? "" : "&") + l;
        s += t.empty() ? "t" : t;
      }
      return s.empty() ? std::string("f") : s;
    };
    auto same_function = [&](const std::string& other) {
      for (std::size_t row = 0; row < (std::size_t{1} << n); ++row) {
        const std::vector<bool> s = symbol_of(row, n);
        if (eval_label(other, s) != gg.table[row]) return false;
      }
      return true;
    };
    ASSERT_TRUE(same_function(join(cubes))) << label;
    for (std::size_t i = 0; i < cubes.size(); ++i) {
      auto fewer = cubes;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
      EXPECT_FALSE(same_function(join(fewer))) << "redundant cube in " << label;
      for (std::size_t j = 0; j < cubes[i].size(); ++j) {
        auto shorter = cubes;
        shorter[i].erase(shorter[i].begin() + static_cast<std::ptrdiff_t>(j));
        EXPECT_FALSE(same_function(join(shorter))) << "redundant literal in " << label;
      }
    }
  }
}

TEST(GeneralAlphabetTest, PropositionsAndSharedManagers) {
  GeneralAlphabet a;
  EXPECT_TRUE(a.aps().empty());
  EXPECT_EQ(a.label(a.top()), "t");
  EXPECT_EQ(a.label(a.bottom()), "f");
  EXPECT_EQ(a.ap_index("x"), 0u);
  EXPECT_EQ(a.ap_index("y"), 1u);
  EXPECT_EQ(a.ap_index("x"), 0u);
  EXPECT_EQ(a.find_ap("y"), 1);
  EXPECT_EQ(a.find_ap("z"), -1);
  EXPECT_EQ(a.bdd().num_vars(), 2u);
  EXPECT_EQ(a.label(a.conj(a.ap(0, true), a.ap(1, false))), "0&!1");
  EXPECT_EQ(a.label(a.ap(1, true)), "1");
  EXPECT_TRUE(a.contains(a.ap(1, true), {false, true}));
  EXPECT_FALSE(a.contains(a.ap(1, true), {true, false}));

  // A second alphabet on the same manager (same proposition order) shares guards.
  const GeneralAlphabet b({"x", "y", "z"}, a.bdd_ptr());
  EXPECT_EQ(b.bdd_ptr(), a.bdd_ptr());
  EXPECT_EQ(a.bdd().num_vars(), 3u);
  EXPECT_EQ(b.ap(0, true), a.ap(0, true));
  EXPECT_EQ(b.label(b.disj(b.ap(2, true), b.ap(0, false))), "!0 | 2");

  EXPECT_THROW(GeneralAlphabet({"p", "q", "p"}), Error);
}

// ---------------------------------------------------------------------------------------
// ActionAlphabet

// Symbol values of letter l over n propositions: letter 0 = all false, l = only aps[l-1].
std::vector<bool> letter_values(std::size_t letter, std::size_t n) {
  std::vector<bool> v(n, false);
  if (letter > 0) v[letter - 1] = true;
  return v;
}

TEST(ActionAlphabetTest, LabelsAgreeWithContainsOnTheDomain) {
  Rng rng(1234);
  int checked = 0;
  for (std::size_t n = 0; n <= 8; ++n) {
    std::vector<std::string> aps;
    for (std::size_t i = 0; i < n; ++i) aps.push_back("act" + std::to_string(i));
    const ActionAlphabet a(aps);
    ASSERT_EQ(a.num_letters(), n + 1);
    for (int k = 0; k < 200; ++k) {
      // Half the guards are random letter sets, half come from the guard algebra.
      ActionAlphabet::Guard g = a.bottom();
      std::set<std::size_t> model;
      if (n == 0 || rng.bernoulli(0.5)) {
        for (std::size_t l = 0; l <= n; ++l) {
          if (rng.bernoulli(0.5)) {
            g.set(l);
            model.insert(l);
          }
        }
      } else {
        const auto i = static_cast<std::uint32_t>(rng.index(n));
        const auto j = static_cast<std::uint32_t>(rng.index(n));
        const bool pi = rng.bernoulli(0.5), pj = rng.bernoulli(0.5);
        const bool use_and = rng.bernoulli(0.5);
        g = use_and ? a.conj(a.ap(i, pi), a.ap(j, pj)) : a.disj(a.ap(i, pi), a.ap(j, pj));
        // Model: evaluate the formula on each letter's symbol (at most one AP true).
        for (std::size_t l = 0; l <= n; ++l) {
          const std::vector<bool> v = letter_values(l, n);
          const bool x = v[i] == pi, y = v[j] == pj;
          if (use_and ? (x && y) : (x || y)) model.insert(l);
        }
      }
      const std::string label = a.label(g);
      for (std::size_t l = 0; l <= n; ++l) {
        ASSERT_EQ(a.contains(g, l), model.count(l) == 1) << "letter " << l;
        ASSERT_EQ(eval_label(label, letter_values(l, n)), model.count(l) == 1)
            << "label \"" << label << "\" letter " << l;
      }
      EXPECT_EQ(label == "t", g.full());
      EXPECT_EQ(label == "f", g.empty());
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1800);
}

TEST(ActionAlphabetTest, GuardsNamesAndLabelForms) {
  const ActionAlphabet a({"grasp", "release", "move"});
  EXPECT_EQ(a.num_letters(), 4u);
  EXPECT_EQ(a.letter_name(0), "none");
  EXPECT_EQ(a.letter_name(2), "release");
  EXPECT_EQ(a.find_ap("move"), 2);
  EXPECT_EQ(a.find_ap("fly"), -1);
  EXPECT_EQ(a.ap(1, true), LetterSet::single(4, 2));
  EXPECT_EQ(a.ap(1, false), ~LetterSet::single(4, 2));
  // Exclusivity: two predicates at once is the empty guard.
  EXPECT_TRUE(a.is_false(a.conj(a.ap(0, true), a.ap(2, true))));
  EXPECT_TRUE(a.implies(a.ap(0, true), a.ap(2, false)));
  EXPECT_EQ(a.label(a.top()), "t");
  EXPECT_EQ(a.label(a.bottom()), "f");
  EXPECT_EQ(a.label(a.disj(a.ap(0, true), a.ap(2, true))), "0 | 2");
  EXPECT_EQ(a.label(a.conj(a.ap(0, false), a.ap(1, false))), "!0&!1");
  EXPECT_EQ(a.label(a.ap(1, true)), "1");
  EXPECT_EQ(a.label(LetterSet::single(4, 0)), "!0&!1&!2");
  EXPECT_EQ(ActionAlphabet::guard_hash(a.ap(1, true)), LetterSet::single(4, 2).hash());
  EXPECT_THROW(ActionAlphabet({"a", "a"}), Error);
}

}  // namespace
}  // namespace rearm::ltl
