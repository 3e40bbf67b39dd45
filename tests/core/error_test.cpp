// The error tiers of core/error.h and core/outcome.h: REARM_REQUIRE's message against the
// values written by hand (a double must come back bit for bit from its text), and Outcome's
// value / failure / or_throw against their definitions.
#include "core/error.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "core/outcome.h"

namespace rearm {
namespace {

std::string message_of(double r, std::int64_t k, std::uint64_t n) {
  try {
    REARM_REQUIRE(r > 0, "radius must be > 0, got ", r, " (k = ", k, ", n = ", n, ", ", true, ")");
  } catch (const Error& e) {
    return e.what();
  }
  return "no throw";
}

TEST(ErrorTest, RequireFormatsTheValuesItNames) {
  EXPECT_EQ(message_of(-0.5, -3, 7), "radius must be > 0, got -0.5 (k = -3, n = 7, true)");
  EXPECT_EQ(message_of(0, 0, 18446744073709551615ull),
            "radius must be > 0, got 0 (k = 0, n = 18446744073709551615, true)");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(nan, 1, 1), "radius must be > 0, got nan (k = 1, n = 1, true)");
  EXPECT_EQ(message_of(-std::numeric_limits<double>::infinity(), 1, 1),
            "radius must be > 0, got -inf (k = 1, n = 1, true)");
  EXPECT_EQ(message_of(1.0, 1, 1), "no throw");
  // Shortest round trip: the text reads back as the same double.
  for (const double x : {-0.1, -1e-300, -2.0 / 3.0, -123456789.123456789, -5e-324}) {
    const std::string m = message_of(x, 0, 0);
    const std::string prefix = "radius must be > 0, got ";
    ASSERT_EQ(m.rfind(prefix, 0), 0u) << m;
    const std::string text = m.substr(prefix.size(), m.find(' ', prefix.size()) - prefix.size());
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
  }
}

Outcome<std::vector<int>> halves(int n) {
  if (n % 2 != 0) return Failure{"odd: " + std::to_string(n)};
  return std::vector<int>{n / 2, n / 2};
}

TEST(ErrorTest, OutcomeHoldsAValueOrTheReason) {
  const Outcome<std::vector<int>> even = halves(8);
  ASSERT_TRUE(even.ok());
  EXPECT_EQ(*even, (std::vector<int>{4, 4}));
  EXPECT_EQ(even->size(), 2u);
  const Outcome<std::vector<int>> odd = halves(7);
  ASSERT_FALSE(odd);
  EXPECT_EQ(odd.reason(), "odd: 7");
  EXPECT_EQ(halves(6).or_throw(), (std::vector<int>{3, 3}));
  EXPECT_THROW(
      {
        try {
          (void)halves(5).or_throw();
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(), "odd: 5");
          throw;
        }
      },
      Error);
}

TEST(ErrorTest, AskingAFailureForItsValueIsABug) {
  EXPECT_DEATH((void)*halves(3), "the value of a failure \\(odd: 3\\)");
  EXPECT_DEATH((void)halves(2).reason(), "reason\\(\\) of a value");
}

}  // namespace
}  // namespace rearm
