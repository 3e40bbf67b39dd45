// The progress monitor ends an action that makes no progress: against hand-built observation
// sequences whose answer is known (steady approach, standing still, a limit cycle, a drift
// without revisits), plus bad input.
#include "executive/progress_monitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.h"

namespace rearm::executive {
namespace {

using geometry::Point;
constexpr double kDt = 0.01;

// First time (s) the monitor reports stuck within `horizon`, given the pose, distance and map
// version at each time.
template <class F>
std::optional<std::pair<double, std::string>> first_stuck(ProgressMonitor& m, double horizon,
                                                          F&& at) {
  m.reset(0);
  const int steps = static_cast<int>(std::lround(horizon / kDt));
  for (int k = 0; k <= steps; ++k) {
    const double t = k * kDt;
    const auto [pose, dist, version] = at(t);
    if (auto why = m.observe(t, pose, dist, version)) return std::make_pair(t, *why);
  }
  return std::nullopt;
}

TEST(ProgressMonitor, SteadyApproachIsNeverStuck) {
  ProgressMonitor m;
  auto r = first_stuck(m, 200, [](double t) {
    return std::tuple{reactive::Pose{Point(0.1 * t, 0), 0.0}, 30 - 0.1 * t, std::uint64_t{1}};
  });
  EXPECT_FALSE(r) << r->second;
}

TEST(ProgressMonitor, StandingStillIsARevisit) {
  ProgressParams p;
  ProgressMonitor m(p);
  auto r = first_stuck(m, 100, [](double) {
    return std::tuple{reactive::Pose{Point(1, 2), 0.5}, 3.0, std::uint64_t{7}};
  });
  ASSERT_TRUE(r);
  // The first record is at t = 0; it is old enough at revisit_min_age.
  EXPECT_NEAR(r->first, p.revisit_min_age, 1.5 * kDt);
  EXPECT_NE(r->second.find("revisited"), std::string::npos) << r->second;
}

TEST(ProgressMonitor, LimitCycleIsARevisit) {
  // A circle of radius 1 every 4 s around a point 5 m from the target: the robot comes back to
  // the same configuration without coming closer.
  ProgressMonitor m;
  auto r = first_stuck(m, 100, [](double t) {
    const double a = 2 * std::acos(-1.0) * t / 4;
    const Point x(std::cos(a), std::sin(a));
    return std::tuple{
        reactive::Pose{x, std::remainder(a + std::acos(-1.0) / 2, 2 * std::acos(-1.0))},
        (x - Point(5, 0)).norm(), std::uint64_t{2}};
  });
  ASSERT_TRUE(r);
  EXPECT_NE(r->second.find("revisited"), std::string::npos) << r->second;
  EXPECT_LT(r->first, 12.0);  // the first revisit of a >= 5 s old record: at 8 s (two periods)
  EXPECT_GE(r->first, 5.0);
}

TEST(ProgressMonitor, ChangingMapStallsAfterStallTime) {
  // Standing still while the map keeps changing is not a revisit of the same situation; the
  // stall rule ends it after stall_time.
  ProgressParams p;
  p.stall_time = 20;
  ProgressMonitor m(p);
  auto r = first_stuck(m, 100, [](double t) {
    return std::tuple{reactive::Pose{Point(1, 2), 0.5}, 3.0,
                      static_cast<std::uint64_t>(std::lround(t / kDt))};
  });
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->first, 20.0, 1.5 * kDt);
  EXPECT_NE(r->second.find("no progress"), std::string::npos) << r->second;
}

TEST(ProgressMonitor, SlowApproachIsNotStuck) {
  // 5 mm/s on a line: 2.5 cm between records 5 s apart (more than revisit_distance), and
  // progress_step every 4 s (less than stall_time).
  ProgressMonitor m;
  auto r = first_stuck(m, 400, [](double t) {
    return std::tuple{reactive::Pose{Point(0.005 * t, 0), 0.0}, 10 - 0.005 * t, std::uint64_t{1}};
  });
  EXPECT_FALSE(r) << r->second;
}

TEST(ProgressMonitor, CreepingCountsAsStandingStill) {
  // 0.4 mm/s: within revisit_distance of a 5 s old record with less than progress_step gained.
  ProgressMonitor m;
  auto r = first_stuck(m, 400, [](double t) {
    return std::tuple{reactive::Pose{Point(0.0004 * t, 0), 0.0}, 10 - 0.0004 * t, std::uint64_t{1}};
  });
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->first, 5.0, 1.5 * kDt);
}

TEST(ProgressMonitor, CircleAfterProgressIsNotARevisitOfTheOldRecords) {
  // Progress, then a revisit of configurations seen before the progress: not stuck, because
  // the best distance improved since those records.
  ProgressParams p;
  ProgressMonitor m(p);
  m.reset(0);
  EXPECT_FALSE(m.observe(0, {Point(0, 0), 0}, 5.0, 1));
  EXPECT_FALSE(m.observe(6, {Point(1, 0), 0}, 4.0, 1));
  EXPECT_FALSE(m.observe(12, {Point(0, 0), 0}, 5.0, 1));
  // ...but a second revisit of the t = 12 s record with nothing better since is.
  EXPECT_FALSE(m.observe(13, {Point(0.5, 0), 0}, 4.5, 1));
  EXPECT_TRUE(m.observe(18, {Point(0, 0), 0}, 5.0, 1));
}

TEST(ProgressMonitor, BadInput) {
  ProgressParams p;
  p.stall_time = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ProgressMonitor{p}, Error);
  p = {};
  p.revisit_distance = 0;
  EXPECT_THROW(ProgressMonitor{p}, Error);
  ProgressMonitor m;
  m.reset(1);
  EXPECT_THROW(m.observe(0.5, {}, 1, 0), Error);  // time going backwards
  EXPECT_THROW(m.observe(2, {}, std::numeric_limits<double>::infinity(), 0), Error);
  EXPECT_THROW(m.observe(2, {Point(std::nan(""), 0), 0}, 1, 0), Error);
}

}  // namespace
}  // namespace rearm::executive
