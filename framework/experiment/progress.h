// Progress of a sweep on a stream (stderr): trials done of the total, failures so far (trials
// that did not succeed), errors, elapsed time and an ETA. The ETA sums, over the trials still to
// run, the mean duration of the finished trials of the same kind (a method: a BiRRT trial at
// 10,000 queries and a rearm trial differ a hundredfold), the overall mean for a kind none of
// whose trials finished yet, divided by the worker threads; the mean over all trials alone said
// 3 s with 16 s left where the slow kinds run last.
// On a terminal one line is rewritten in place; otherwise (a log file, a Slurm job) a line is
// printed every `percent_step` percent and at the end, so a log stays short.
#pragma once

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace rearm::experiment {

// Seconds left: for each kind, the trials left of it times the mean duration of its finished
// trials (the mean over every finished trial when none of its own has), summed and divided by
// `threads`; NaN when no trial has finished.
double estimate_remaining(const std::map<std::string, std::size_t>& left,
                          const std::map<std::string, double>& done_seconds,
                          const std::map<std::string, std::size_t>& done_count, int threads);

class Progress {
 public:
  // `kinds`: the kind of every trial to run (their count is the total).
  Progress(std::FILE* out, const std::vector<std::string>& kinds, std::string label, int threads,
           double percent_step = 5);
  // One trial of `kind` finished after `seconds`.
  void tick(const std::string& kind, double seconds, bool success, bool error);
  // The closing line.
  void finish();

 private:
  void print(bool final_line);
  std::FILE* out_;
  std::size_t total_;
  std::string label_;
  int threads_;
  double step_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::size_t done_ = 0, failures_ = 0, errors_ = 0;
  double next_percent_ = 0;
  std::map<std::string, std::size_t> left_, done_count_;
  std::map<std::string, double> done_seconds_;
};

// "1h02m", "3m05s", "42s".
std::string format_duration(double seconds);

}  // namespace rearm::experiment
