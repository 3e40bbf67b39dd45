// The columns of a trial log written by this version or an earlier one (experiments/sweeps/
// README.md, "Trial log"). A later version may add timing columns (is_timing_column: measured
// by the clock, never part of a result, as first_action_time_s was); a log written before such a
// column existed reads with it empty, so that an older sweep folder can still be resumed,
// merged and reported; so does goal_order, a descriptive column (the resume key names the
// order): empty in a row of an older log, whose task was always the chain. Any other difference
// refuses the log: a result column missing, a column this version does not know, a column named
// twice.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rearm::experiment {

class LogLayout {
 public:
  // `header`: the log's first line split into fields; `where` names the file in errors. Throws
  // rearm::Error saying why the header is not one of a trial log of this or an earlier version.
  LogLayout(const std::vector<std::string>& header, const std::string& where);

  std::size_t width() const { return width_; }  // fields per row of the log
  // This version's columns the log lacks, in column order (empty: the log is this version's).
  const std::vector<std::string>& missing() const { return missing_; }
  // A row of the log (width() fields) in this version's columns, the missing ones empty.
  std::vector<std::string> upgrade(const std::vector<std::string>& row) const;

 private:
  std::size_t width_ = 0;
  std::vector<std::string> missing_;
  std::vector<std::ptrdiff_t> source_;  // per current column: its index in the log, or -1
};

// A trial log's complete lines read in this version's columns.
struct LogRows {
  std::vector<std::string> added;  // this version's columns the log lacked (LogLayout::missing)
  std::vector<std::vector<std::string>> rows;
};

// `complete`: a log's text up to its last newline, the header its first line (callers handle a
// log with no complete line). Throws rearm::Error naming `where` and the line for a malformed
// line, a header of no version, or a row whose field count is not its header's (damage: the
// writer only ever cuts the last line).
LogRows read_log_rows(const std::string& complete, const std::string& where);

}  // namespace rearm::experiment
