#include "experiment/trial_log.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "experiment/csv.h"
#include "experiment/log_layout.h"
#include "experiment/trial_columns.h"

namespace rearm::experiment {
namespace {

std::string system_reason() { return std::strerror(errno); }

}  // namespace

TrialLog::TrialLog(const std::string& path) : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool exists = fs::exists(path, ec);
  if (exists) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot read the trial log: " + system_reason());
    std::ostringstream text;
    text << in.rdbuf();
    resume(text.str());
  } else if (const fs::path parent = fs::path(path).parent_path(); !parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec) throw Error(path + ": cannot create its folder: " + ec.message());
  }
  if (upgraded_.empty()) open_for_appending();
  if (!exists) append(trial_header());
}

void TrialLog::open_for_appending() {
  file_ = std::fopen(path_.c_str(), "a");
  if (file_ == nullptr) throw Error(path_ + ": cannot open for appending: " + system_reason());
}

TrialLog::~TrialLog() {
  if (file_ != nullptr) std::fclose(file_);
}

void TrialLog::resume(const std::string& text) {
  std::size_t complete = text.rfind('\n');
  complete = complete == std::string::npos ? 0 : complete + 1;
  if (complete < text.size()) {
    // A row cut by an interruption: drop it so that the file ends with a complete line.
    if (::truncate(path_.c_str(), static_cast<off_t>(complete)) != 0) {
      throw Error(path_ + ": cannot drop the cut last line: " + system_reason());
    }
    dropped_torn_ = true;
  }
  if (complete == 0) {
    // Nothing complete, not even the header: start the file afresh.
    if (::truncate(path_.c_str(), 0) != 0)
      throw Error(path_ + ": cannot reset: " + system_reason());
    std::FILE* f = std::fopen(path_.c_str(), "w");
    if (f == nullptr) throw Error(path_ + ": cannot write: " + system_reason());
    std::fprintf(f, "%s\n", trial_header().c_str());
    std::fclose(f);
    return;
  }
  LogRows log = read_log_rows(text.substr(0, complete), path_);
  const std::size_t key = trial_column("key");
  const std::size_t revision = trial_column("revision");
  for (const std::vector<std::string>& f : log.rows) {
    done_.insert(f[key]);
    revisions_.insert(f[revision]);
  }
  if (log.added.empty()) return;
  // A log of an earlier version: rewritten in this version's columns before its first new row.
  added_ = std::move(log.added);
  upgraded_ = trial_header() + "\n";
  for (const std::vector<std::string>& f : log.rows) upgraded_ += csv_line(f) + "\n";
}

void TrialLog::append(const std::string& row) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (file_ == nullptr) {
    // A log of an earlier version: its rows in this version's columns, before the first new row.
    write_file_atomically(path_, upgraded_);
    upgraded_.clear();
    open_for_appending();
  }
  if (std::fprintf(file_, "%s\n", row.c_str()) < 0 || std::fflush(file_) != 0 ||
      ::fsync(fileno(file_)) != 0) {
    throw Error(path_ + ": cannot append a row: " + system_reason());
  }
}

}  // namespace rearm::experiment
