#include "reactive/pth_root.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"

namespace rearm::reactive {
namespace {

// Independent truth without any root function: x ↦ x^p is increasing, so t is within one unit
// in the last place of s^{1/p} iff prev(t)^p < s < next(t)^p, and it is the correctly rounded
// root iff (t − ulp/2)^p <= s <= (t + ulp/2)^p. Powers by repeated long double products
// (relative error about p·2^−64, far below the gaps p·2^−53 being compared).
long double power(long double x, int p) {
  long double r = 1;
  for (int k = 0; k < p; ++k) r *= x;
  return r;
}

bool within_one_ulp(double t, double s, int p) {
  const double below = std::nextafter(t, 0.0), above = std::nextafter(t, 4.0);
  return power(below, p) < s && s < power(above, p);
}

bool correctly_rounded(double t, double s, int p) {
  const long double below = (static_cast<long double>(t) + std::nextafter(t, 0.0)) / 2;
  const long double above = (static_cast<long double>(t) + std::nextafter(t, 4.0)) / 2;
  return power(below, p) <= s && s <= power(above, p);
}

// Arguments as the R-conjunction makes them: 1 + r^p, r in [0, 1] (mostly near 1 or tiny),
// plus the knots of the table and their neighbours.
std::vector<double> arguments(int p) {
  std::vector<double> s{1.0, 2.0, std::nextafter(2.0, 1.0), std::nextafter(1.0, 2.0)};
  for (int i = 0; i <= PthRoot::kKnots; ++i) {
    const double knot = 1.0 + static_cast<double>(i) / PthRoot::kKnots;
    s.push_back(knot);
    if (i > 0) s.push_back(std::nextafter(knot, 1.0));
    if (i < PthRoot::kKnots) s.push_back(std::nextafter(knot, 2.0));
  }
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 40000; ++k) {
    const double r = unit(rng);
    s.push_back(1 + std::pow(r, p));
    s.push_back(1 + unit(rng));
  }
  return s;
}

TEST(PthRoot, WithinOneUlpAndNearlyAlwaysCorrectlyRounded) {
  for (const int p : {2, 4, 20, 64}) {
    const PthRoot root(p);
    int rounded = 0, n = 0;
    for (const double s : arguments(p)) {
      if (s == 1.0) continue;  // checked exactly below
      const double t = root(s);
      ASSERT_TRUE(within_one_ulp(t, s, p)) << "p = " << p << ", s = " << s << ", t = " << t;
      rounded += correctly_rounded(t, s, p);
      ++n;
    }
    EXPECT_GE(rounded, n * 0.995) << "p = " << p << ": " << rounded << " of " << n;
  }
}

TEST(PthRoot, ExactAtOneAndEqualToSqrtForPTwo) {
  for (const int p : {2, 20, 1000}) EXPECT_EQ(PthRoot(p)(1.0), 1.0);
  // For p = 2 the correctly rounded sqrt is an independent reference.
  const PthRoot root(2);
  int same = 0, n = 0;
  for (const double s : arguments(2)) {
    const double t = root(s), ref = std::sqrt(s);
    EXPECT_LE(std::abs(t - ref), std::nextafter(ref, 4.0) - ref) << s;
    same += t == ref;
    ++n;
  }
  EXPECT_GE(same, n * 0.995);
}

TEST(PthRoot, SharedTablesAndBadInput) {
  EXPECT_EQ(&PthRoot::of(20), &PthRoot::of(20));
  EXPECT_EQ(PthRoot::of(8).p(), 8);
  EXPECT_THROW(PthRoot(3), Error);
  EXPECT_THROW(PthRoot(0), Error);
  EXPECT_THROW(PthRoot::of(-2), Error);
  // Outside [1, 2] (never from the R-conjunction) the value is std::pow's.
  const PthRoot root(20);
  for (const double s : {0.5, 3.0, 1e300}) EXPECT_EQ(root(s), std::pow(s, 1.0 / 20)) << s;
  EXPECT_TRUE(std::isnan(root(std::nan(""))));
}

}  // namespace
}  // namespace rearm::reactive
