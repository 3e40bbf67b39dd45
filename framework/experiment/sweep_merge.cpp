#include "experiment/sweep_merge.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "experiment/csv.h"
#include "experiment/log_layout.h"
#include "experiment/sweep_runner.h"
#include "experiment/trial_columns.h"
#include "scenario/sweep_file.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw Error(p.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The complete rows of a folder's CSV (a cut last line dropped, counted in torn).
std::vector<std::vector<std::string>> complete_rows(const fs::path& csv, std::size_t& torn) {
  std::string text = read_all(csv);
  const std::size_t end = text.rfind('\n');
  if (end == std::string::npos || end + 1 < text.size()) {
    ++torn;
    text.erase(end == std::string::npos ? 0 : end + 1);
  }
  if (text.empty()) throw Error(csv.string() + ": empty (no header)");
  // A log of an earlier version reads in this version's columns (log_layout.h).
  return read_log_rows(text, csv.string()).rows;
}

bool same_result(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!is_timing_column(trial_columns()[i]) && a[i] != b[i]) return false;
  }
  return true;
}

void copy_instances(const fs::path& from, const fs::path& to) {
  if (!fs::is_directory(from)) return;
  for (const auto& e : fs::directory_iterator(from)) {
    const fs::path target = to / e.path().filename();
    if (!fs::exists(target)) write_file_atomically(target.string(), read_all(e.path()));
  }
}

// The cell index that starts line `n` of a cells.csv; throws rearm::Error naming the file,
// the line and the field when it is not one.
std::size_t cell_index(const std::string& line, const fs::path& p, int n) {
  const std::string field = line.substr(0, line.find(','));
  std::size_t v = 0;
  const char* end = field.data() + field.size();
  const auto [stop, ec] = std::from_chars(field.data(), end, v);
  if (field.empty() || ec != std::errc() || stop != end) {
    throw Error("merge: " + p.string() + " line " + std::to_string(n) + ": '" + field +
                "' is not a cell index (a cells.csv row starts with one)");
  }
  return v;
}

// The shards' cell verdicts (DIR/cells.csv, cell_check.h) united by cell index; "" when no
// folder has them.
std::string merged_cells(const std::vector<std::string>& dirs) {
  std::map<std::size_t, std::string> lines;
  std::string header;
  for (const std::string& d : dirs) {
    const fs::path p = fs::path(d) / kCellsCsv;
    if (!fs::exists(p)) continue;
    std::istringstream in(read_all(p));
    std::string line;
    std::getline(in, header);
    for (int n = 2; std::getline(in, line); ++n) {
      if (!line.empty()) lines.emplace(cell_index(line, p, n), line);
    }
  }
  if (lines.empty()) return "";
  std::string text = header + "\n";
  for (const auto& [cell, line] : lines) text += line + "\n";
  return text;
}

}  // namespace

MergeSummary merge_sweeps(const std::vector<std::string>& dirs, const std::string& out_dir,
                          const MethodRegistry& methods) {
  if (dirs.empty()) throw Error("merge: give at least one sweep folder");
  MergeSummary summary;
  const std::string spec = read_all(fs::path(dirs.front()) / kSweepCopy);
  const scenario::SweepFile file =
      scenario::parse_sweep_file(spec, (fs::path(dirs.front()) / kSweepCopy).string());
  summary.total_trials = file.trial_count([&](const std::string& m) {
    return methods.contains(m) && methods.get(m).follows_task_order();
  });
  const std::size_t key = trial_column("key");
  const std::size_t index = trial_column("trial");
  std::map<std::string, std::vector<std::string>> rows;
  for (const std::string& d : dirs) {
    if (read_all(fs::path(d) / kSweepCopy) != spec) {
      throw Error("merge: " + d + " holds another sweep than " + dirs.front() +
                  " (their sweep.yaml differ)");
    }
    for (auto& row : complete_rows(fs::path(d) / kTrialsCsv, summary.dropped_torn)) {
      const auto it = rows.find(row[key]);
      if (it == rows.end()) {
        rows.emplace(row[key], std::move(row));
        continue;
      }
      if (!same_result(it->second, row)) {
        throw Error("merge: trial " + row[index] + " has two different results (in " + d +
                    " and an earlier folder): rows of different builds?");
      }
      ++summary.duplicates;
    }
  }
  std::vector<const std::vector<std::string>*> sorted;
  for (const auto& [k, row] : rows) sorted.push_back(&row);
  std::sort(sorted.begin(), sorted.end(), [&](const auto* a, const auto* b) {
    return std::stoull((*a)[index]) < std::stoull((*b)[index]);
  });
  std::string text = trial_header() + "\n";
  for (const auto* row : sorted) text += csv_line(*row) + "\n";
  const fs::path out(out_dir);
  write_file_atomically((out / kTrialsCsv).string(), text);
  write_file_atomically((out / kSweepCopy).string(), spec);
  const std::string cells = merged_cells(dirs);
  if (!cells.empty()) write_file_atomically((out / kCellsCsv).string(), cells);
  fs::create_directories(out / kInstancesDir);
  for (const std::string& d : dirs)
    copy_instances(fs::path(d) / kInstancesDir, out / kInstancesDir);
  summary.rows = sorted.size();
  return summary;
}

}  // namespace rearm::experiment
