// CSV as the sweep writes it (RFC 4180 quoting, one record per line): a field with a comma or
// a double quote is quoted, its quotes doubled; line breaks inside a field are written as
// spaces, so that every record is exactly one line and a record cut by an interruption is a
// last line without its newline (trial_log.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rearm::experiment {

std::string csv_field(std::string_view text);
std::string csv_line(const std::vector<std::string>& fields);  // without the newline
// The fields of one line (no newline). Throws rearm::Error for an unterminated quote or text
// after a closing quote.
std::vector<std::string> parse_csv_line(std::string_view line);

// A whole CSV file: its header and its records. Throws rearm::Error naming the file and the line
// for a malformed line or one whose field count differs from the header's.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // The index of a header column; throws rearm::Error naming the file when there is none.
  std::size_t column(const std::string& name) const;
  std::string source;
};
CsvTable read_csv(const std::string& path);

}  // namespace rearm::experiment
