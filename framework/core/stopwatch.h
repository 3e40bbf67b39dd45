// Wall-clock accounting for the compute split of a run (experiments/sweeps/README.md, the
// columns mission, topology, rebuild and control time): a scope adds its duration to a running
// total. Steady clock, so a change of the system time never gives a negative share.
#pragma once

#include <chrono>

namespace rearm {

class ScopedStopwatch {
 public:
  explicit ScopedStopwatch(double& total_s) : total_s_(total_s), start_(Clock::now()) {}
  ScopedStopwatch(const ScopedStopwatch&) = delete;
  ScopedStopwatch& operator=(const ScopedStopwatch&) = delete;
  ~ScopedStopwatch() { total_s_ += std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  double& total_s_;
  Clock::time_point start_;
};

}  // namespace rearm
