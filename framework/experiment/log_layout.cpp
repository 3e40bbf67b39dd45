#include "experiment/log_layout.h"

#include <map>
#include <sstream>

#include "core/error.h"
#include "experiment/csv.h"
#include "experiment/trial_columns.h"

namespace rearm::experiment {

LogLayout::LogLayout(const std::vector<std::string>& header, const std::string& where)
    : width_(header.size()) {
  const std::string refused = where + ": not a trial log of this version or an earlier one: ";
  std::map<std::string, std::ptrdiff_t> index;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (!index.emplace(header[i], static_cast<std::ptrdiff_t>(i)).second) {
      throw Error(refused + "the column '" + header[i] + "' appears twice");
    }
  }
  const std::vector<std::string>& columns = trial_columns();
  for (const std::string& name : columns) {
    const auto it = index.find(name);
    if (it != index.end()) {
      source_.push_back(it->second);
      index.erase(it);
      continue;
    }
    if (!may_be_missing(name)) throw Error(refused + "it has no column '" + name + "'");
    missing_.push_back(name);
    source_.push_back(-1);
  }
  if (!index.empty()) {
    throw Error(refused + "this version knows no column '" + index.begin()->first +
                "' (its header differs)");
  }
}

std::vector<std::string> LogLayout::upgrade(const std::vector<std::string>& row) const {
  REARM_DEMAND(row.size() == width_, "LogLayout::upgrade: a row of another width");
  std::vector<std::string> out;
  out.reserve(source_.size());
  for (const std::ptrdiff_t s : source_) {
    out.push_back(s < 0 ? std::string() : row[static_cast<std::size_t>(s)]);
  }
  return out;
}

namespace {

// The fields of line `number` of `where`, its parse error named with the line.
std::vector<std::string> fields_of(const std::string& line, std::size_t number,
                                   const std::string& where) {
  try {
    return parse_csv_line(line);
  } catch (const Error& e) {
    throw Error(where + ": line " + std::to_string(number) + ": " + e.what());
  }
}

}  // namespace

LogRows read_log_rows(const std::string& complete, const std::string& where) {
  std::istringstream lines(complete);
  std::string line;
  std::getline(lines, line);
  const LogLayout layout(fields_of(line, 1, where), where);
  LogRows out{layout.missing(), {}};
  for (std::size_t number = 2; std::getline(lines, line); ++number) {
    const std::vector<std::string> f = fields_of(line, number, where);
    if (f.size() != layout.width()) {
      throw Error(where + ": line " + std::to_string(number) + " has " + std::to_string(f.size()) +
                  " fields, not " + std::to_string(layout.width()) +
                  " (a damaged file: the writer only ever cuts the last line)");
    }
    out.rows.push_back(layout.upgrade(f));
  }
  return out;
}

}  // namespace rearm::experiment
