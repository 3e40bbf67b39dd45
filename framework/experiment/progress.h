// Progress of a sweep on a stream (stderr): trials done of the total, failures so far (trials
// that did not succeed), errors, elapsed time and an ETA from the mean time per finished trial.
// On a terminal one line is rewritten in place; otherwise (a log file, a Slurm job) a line is
// printed every `percent_step` percent and at the end, so a log stays short.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace rearm::experiment {

class Progress {
 public:
  Progress(std::FILE* out, std::size_t total, std::string label, double percent_step = 5);
  // One trial finished.
  void tick(bool success, bool error);
  // The closing line.
  void finish();

 private:
  void print(bool final_line);
  std::FILE* out_;
  std::size_t total_;
  std::string label_;
  double step_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::size_t done_ = 0, failures_ = 0, errors_ = 0;
  double next_percent_ = 0;
};

// "1h02m", "3m05s", "42s".
std::string format_duration(double seconds);

}  // namespace rearm::experiment
