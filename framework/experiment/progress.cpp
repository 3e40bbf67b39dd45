#include "experiment/progress.h"

#include <unistd.h>

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

Progress::Progress(std::FILE* out, std::size_t total, std::string label, double percent_step)
    : out_(out),
      total_(total),
      label_(std::move(label)),
      step_(percent_step),
      terminal_(out != nullptr && ::isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      next_percent_(percent_step) {}

void Progress::tick(bool success, bool error) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (!success) ++failures_;
  if (error) ++errors_;
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
  const double eta =
      done_ == 0 ? NAN : elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
  const double percent = total_ == 0 ? 100 : 100.0 * static_cast<double>(done_) / total_;
  std::fprintf(out_, "%s%s: %zu/%zu trials (%.0f%%), %zu failed, %zu errors, %s elapsed%s%s",
               terminal_ ? "\r" : "", label_.c_str(), done_, total_, percent, failures_, errors_,
               format_duration(elapsed).c_str(), final_line ? "" : ", ETA ",
               final_line ? "" : format_duration(eta).c_str());
  std::fprintf(out_, terminal_ && !final_line ? "\033[K" : "\n");
  std::fflush(out_);
}

}  // namespace rearm::experiment
