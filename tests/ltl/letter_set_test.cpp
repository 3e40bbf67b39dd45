// LetterSet against std::set<size_t> models under seeded random operations, on universes
// around the 64-bit word boundaries.
#include "ltl/letter_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <vector>

#include "core/rng.h"

namespace rearm::ltl {
namespace {

using Model = std::set<std::size_t>;

Model all_letters(std::size_t n) {
  Model m;
  for (std::size_t i = 0; i < n; ++i) m.insert(i);
  return m;
}

Model random_model(Rng& rng, std::size_t n) {
  // Densities from empty to full, so empty()/full() are hit often.
  const double p = static_cast<double>(rng.index(5)) / 4.0;
  Model m;
  for (std::size_t i = 0; i < n; ++i) {
    if (rng.bernoulli(p)) m.insert(i);
  }
  return m;
}

LetterSet from_model(const Model& m, std::size_t n) {
  LetterSet s(n);
  for (std::size_t i : m) s.set(i);
  return s;
}

// Every observer of s agrees with the model.
void expect_matches(const LetterSet& s, const Model& m, std::size_t n) {
  ASSERT_EQ(s.universe(), n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(s.test(i), m.count(i) == 1) << "letter " << i;
  EXPECT_EQ(s.count(), m.size());
  EXPECT_EQ(s.empty(), m.empty());
  EXPECT_EQ(s.full(), m.size() == n);
  // next() enumerates exactly the model, from every starting point.
  std::vector<std::size_t> listed;
  for (std::size_t i = s.next(0); i < n; i = s.next(i + 1)) listed.push_back(i);
  EXPECT_EQ(listed, std::vector<std::size_t>(m.begin(), m.end()));
  for (std::size_t from = 0; from <= n + 1; ++from) {
    const auto it = m.lower_bound(from);
    ASSERT_EQ(s.next(from), it == m.end() ? n : *it) << "next(" << from << ")";
  }
  // Equality and hash see only the set: rebuilding it from the model gives an equal value.
  const LetterSet rebuilt = from_model(m, n);
  EXPECT_EQ(s, rebuilt);
  EXPECT_EQ(s.hash(), rebuilt.hash());
}

Model model_and(const Model& a, const Model& b) {
  Model r;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::inserter(r, r.end()));
  return r;
}

Model model_or(const Model& a, const Model& b) {
  Model r;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::inserter(r, r.end()));
  return r;
}

Model model_not(const Model& a, std::size_t n) {
  Model r;
  for (std::size_t i = 0; i < n; ++i) {
    if (!a.count(i)) r.insert(i);
  }
  return r;
}

class LetterSetRandomTest : public ::testing::TestWithParam<std::size_t> {};

TEST_P(LetterSetRandomTest, AgreesWithSetModel) {
  const std::size_t n = GetParam();
  Rng rng(1000 + n);
  expect_matches(LetterSet(n), {}, n);
  expect_matches(LetterSet(n, true), all_letters(n), n);
  for (std::size_t i = 0; i < n; ++i) expect_matches(LetterSet::single(n, i), {i}, n);

  LetterSet s(n);
  Model m;
  for (int step = 0; step < 600; ++step) {
    const LetterSet o_set = from_model(random_model(rng, n), n);
    Model o;
    for (std::size_t i = 0; i < n; ++i) {
      if (o_set.test(i)) o.insert(i);
    }
    switch (rng.index(9)) {
      case 0: {
        const std::size_t i = rng.index(n);
        s.set(i);
        m.insert(i);
        break;
      }
      case 1: {
        const std::size_t i = rng.index(n);
        s.reset(i);
        m.erase(i);
        break;
      }
      case 2:
        s = s & o_set;
        m = model_and(m, o);
        break;
      case 3:
        s = s | o_set;
        m = model_or(m, o);
        break;
      case 4:
        s &= o_set;
        m = model_and(m, o);
        break;
      case 5:
        s |= o_set;
        m = model_or(m, o);
        break;
      case 6:
        s = ~s;
        m = model_not(m, n);
        break;
      case 7:
        s = o_set;
        m = o;
        break;
      default:
        s = LetterSet(n, rng.bernoulli(0.5));
        m = s.full() ? all_letters(n) : Model{};
        break;
    }
    expect_matches(s, m, n);
    EXPECT_EQ(s.subset_of(o_set), std::includes(o.begin(), o.end(), m.begin(), m.end()));
    EXPECT_EQ(o_set.subset_of(s), std::includes(m.begin(), m.end(), o.begin(), o.end()));
    EXPECT_EQ(s.intersects(o_set), !model_and(m, o).empty());
    EXPECT_EQ(s == o_set, m == o);
    EXPECT_EQ(~~s, s);
    if (HasFatalFailure()) return;
  }
}

INSTANTIATE_TEST_SUITE_P(Universes, LetterSetRandomTest,
                         ::testing::Values(std::size_t{1}, std::size_t{63}, std::size_t{64},
                                           std::size_t{65}, std::size_t{200}));

TEST(LetterSetTest, EmptyUniverseAndDistinctUniverses) {
  const LetterSet e;
  EXPECT_EQ(e.universe(), 0u);
  EXPECT_TRUE(e.empty());
  EXPECT_TRUE(e.full());
  EXPECT_EQ(e.next(0), 0u);
  EXPECT_EQ(~e, e);
  // Same (empty) contents over different universes are different guards.
  EXPECT_NE(LetterSet(3), LetterSet(4));
}

TEST(LetterSetDeathTest, MixingUniversesOrOutOfRangeLettersAborts) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const LetterSet a(10), b(11);
  EXPECT_DEATH((void)(a & b), "different universes");
  EXPECT_DEATH((void)a.subset_of(b), "different universes");
  EXPECT_DEATH((void)a.test(10), "outside the universe");
  LetterSet c(65);
  EXPECT_DEATH(c.set(65), "outside the universe");
}

}  // namespace
}  // namespace rearm::ltl
