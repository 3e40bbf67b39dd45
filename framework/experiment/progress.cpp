#include "experiment/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace rearm::experiment {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%lds", s);
  }
  return buf;
}

double estimate_remaining(const std::map<std::string, std::size_t>& left,
                          const std::map<std::string, double>& done_seconds,
                          const std::map<std::string, std::size_t>& done_count, int threads) {
  double all_seconds = 0;
  std::size_t all_count = 0;
  for (const auto& [kind, n] : done_count) {
    all_count += n;
    all_seconds += done_seconds.at(kind);
  }
  if (all_count == 0) return NAN;
  double work = 0;
  for (const auto& [kind, n] : left) {
    const auto c = done_count.find(kind);
    const double mean = c != done_count.end() && c->second > 0
                            ? done_seconds.at(kind) / static_cast<double>(c->second)
                            : all_seconds / static_cast<double>(all_count);
    work += mean * static_cast<double>(n);
  }
  return work / std::max(1, threads);
}

Progress::Progress(std::FILE* out, const std::vector<std::string>& kinds, std::string label,
                   int threads, double percent_step)
    : out_(out),
      total_(kinds.size()),
      label_(std::move(label)),
      threads_(threads),
      step_(percent_step),
      terminal_(out != nullptr && ::isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      next_percent_(percent_step) {
  for (const std::string& k : kinds) ++left_[k];
}

void Progress::tick(const std::string& kind, double seconds, bool success, bool error) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (!success) ++failures_;
  if (error) ++errors_;
  if (auto it = left_.find(kind); it != left_.end() && it->second > 0) --it->second;
  ++done_count_[kind];
  done_seconds_[kind] += seconds;
  const double percent = total_ == 0 ? 100 : 100.0 * static_cast<double>(done_) / total_;
  if (terminal_) {
    print(false);
  } else if (percent + 1e-9 >= next_percent_ && done_ < total_) {
    print(false);
    while (next_percent_ <= percent + 1e-9) next_percent_ += step_;
  }
}

void Progress::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  print(true);
}

void Progress::print(bool final_line) {
  if (out_ == nullptr) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = estimate_remaining(left_, done_seconds_, done_count_, threads_);
  const double percent = total_ == 0 ? 100 : 100.0 * static_cast<double>(done_) / total_;
  std::fprintf(out_, "%s%s: %zu/%zu trials (%.0f%%), %zu failed, %zu errors, %s elapsed%s%s",
               terminal_ ? "\r" : "", label_.c_str(), done_, total_, percent, failures_, errors_,
               format_duration(elapsed).c_str(), final_line ? "" : ", ETA ",
               final_line ? "" : format_duration(eta).c_str());
  std::fprintf(out_, terminal_ && !final_line ? "\033[K" : "\n");
  std::fflush(out_);
}

}  // namespace rearm::experiment
