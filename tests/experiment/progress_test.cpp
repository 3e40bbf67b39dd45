// experiment/progress.h: the ETA against hand sums (per-kind means, the overall mean for a kind
// not seen yet, divided by the threads), and the duration format.
#include "experiment/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace rearm::experiment {
namespace {

TEST(EstimateRemaining, PerKindMeansOverThreads) {
  // Nothing finished: no estimate.
  EXPECT_TRUE(std::isnan(estimate_remaining({{"rearm", 3}}, {}, {}, 1)));
  // Two rearm trials took 1 s and 3 s (mean 2 s); 2 rearm and 4 birrt@10000 left, birrt unseen:
  // the overall mean (2 s) stands for it: (2 * 2 + 4 * 2) / 2 threads = 6 s.
  const std::map<std::string, std::size_t> left{{"rearm", 2}, {"birrt@10000", 4}};
  EXPECT_DOUBLE_EQ(estimate_remaining(left, {{"rearm", 4.0}}, {{"rearm", 2}}, 2), 6.0);
  // One birrt@10000 trial took 50 s: its own mean now, (2 * 2 + 4 * 50) / 2 = 102 s, where the
  // mean over all trials (54 / 3 = 18 s) would say 6 * 18 / 2 = 54 s.
  EXPECT_DOUBLE_EQ(estimate_remaining(left, {{"rearm", 4.0}, {"birrt@10000", 50.0}},
                                      {{"rearm", 2}, {"birrt@10000", 1}}, 2),
                   102.0);
  // Nothing left: 0; threads below 1 count as 1.
  EXPECT_DOUBLE_EQ(estimate_remaining({}, {{"rearm", 4.0}}, {{"rearm", 2}}, 2), 0.0);
  EXPECT_DOUBLE_EQ(estimate_remaining({{"rearm", 1}}, {{"rearm", 4.0}}, {{"rearm", 2}}, 0), 2.0);
}

TEST(FormatDuration, HoursMinutesSeconds) {
  EXPECT_EQ(format_duration(42.4), "42s");
  EXPECT_EQ(format_duration(185), "3m05s");
  EXPECT_EQ(format_duration(3720), "1h02m");
  EXPECT_EQ(format_duration(NAN), "?");
  EXPECT_EQ(format_duration(-1), "?");
}

}  // namespace
}  // namespace rearm::experiment
