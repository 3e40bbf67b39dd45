// The sweep's CSV of trials, appended and flushed (and fsync'ed) one row at a time, so that an
// interruption — even SIGKILL — loses no finished trial. On opening an existing file the
// resume rules apply:
//  - the header must be this version's (trial_columns.h) or an earlier one's (log_layout.h: a
//    timing column added since reads empty), else the file is refused; a log of an earlier
//    version is rewritten in this version's columns (atomically) before its first new row;
//  - a last line without its newline is a row cut by the interruption: it is dropped (the file
//    is truncated to the last complete line) and its trial runs again;
//  - every complete row must parse with the header's field count, else the file is refused
//    naming the line (the writer never leaves such a row, so it is damage, not a cut);
//  - the complete rows' `key` column (every setting that changes a result, trial_columns.h)
//    tells which trials are done.
#pragma once

#include <cstdio>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace rearm::experiment {

class TrialLog {
 public:
  // Opens (creating it with the header when absent) the CSV at path. Throws rearm::Error naming
  // the file when it cannot be read, written or resumed.
  explicit TrialLog(const std::string& path);
  ~TrialLog();
  TrialLog(const TrialLog&) = delete;
  TrialLog& operator=(const TrialLog&) = delete;

  // Keys of the complete rows found when opening.
  const std::set<std::string>& done() const { return done_; }
  // Whether the file ended with a cut row, which was dropped.
  bool dropped_torn_line() const { return dropped_torn_; }
  // The columns this version added that the file lacked (empty: the file is this version's).
  const std::vector<std::string>& added_columns() const { return added_; }
  // Revisions of the complete rows found when opening.
  const std::set<std::string>& revisions() const { return revisions_; }

  // Appends one row (no newline in it) and makes it durable before returning. Thread-safe.
  void append(const std::string& row);

 private:
  void resume(const std::string& text);
  void open_for_appending();
  std::string path_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
  std::set<std::string> done_;
  std::set<std::string> revisions_;
  bool dropped_torn_ = false;
  std::vector<std::string> added_;
  std::string upgraded_;  // the file in this version's columns, until the first append
};

}  // namespace rearm::experiment
