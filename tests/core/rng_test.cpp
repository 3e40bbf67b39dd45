#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rearm {
namespace {

TEST(RngTest, SameSeedSameStream) {
  Rng a(7), b(7), c(8);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next();
    EXPECT_EQ(x, b.next());
    differs = differs || x != c.next();
  }
  EXPECT_TRUE(differs);
}

TEST(RngTest, FullRangeAndDegenerateRanges) {
  Rng rng(3);
  EXPECT_EQ(rng.uniform_int(4, 4), 4);
  EXPECT_EQ(rng.index(1), 0u);
  bool negative = false, positive = false;
  for (int i = 0; i < 64; ++i) {
    const auto x = rng.uniform_int(INT64_MIN, INT64_MAX);
    negative = negative || x < 0;
    positive = positive || x > 0;
  }
  EXPECT_TRUE(negative && positive);
}

TEST(RngTest, UniformIntIsInRangeAndUnbiased) {
  // Chi-square test of 60,000 draws over 6 cells; the 99.9% quantile of chi2(5) is 20.5.
  Rng rng(12345);
  constexpr int kCells = 6, kDraws = 60000;
  std::vector<int> count(kCells, 0);
  for (int i = 0; i < kDraws; ++i) {
    const auto x = rng.uniform_int(-2, 3);
    ASSERT_GE(x, -2);
    ASSERT_LE(x, 3);
    ++count[x + 2];
  }
  double chi2 = 0;
  const double expected = static_cast<double>(kDraws) / kCells;
  for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, 20.5);
}

TEST(RngTest, Uniform01IsInHalfOpenUnitInterval) {
  Rng rng(99);
  double sum = 0;
  constexpr int kDraws = 100000;
  for (int i = 0; i < kDraws; ++i) {
    const double x = rng.uniform01();
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    sum += x;
  }
  // Mean of U(0,1) is 1/2 with standard error 1/sqrt(12 n) ~ 0.0009.
  EXPECT_NEAR(sum / kDraws, 0.5, 0.005);
}

TEST(RngTest, DerivedStreamsDependOnlyOnSeedAndStream) {
  Rng a = Rng::derive(5, 3);
  Rng b = Rng::derive(5, 3);
  Rng c = Rng::derive(5, 4);
  EXPECT_EQ(a.next(), b.next());
  EXPECT_NE(Rng::derive(5, 3).next(), c.next());
}

}  // namespace
}  // namespace rearm
