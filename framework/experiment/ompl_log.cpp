#include "experiment/ompl_log.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "experiment/provenance.h"
#include "experiment/trial.h"

namespace rearm::experiment {
namespace {

// Experiment properties: the cell's settings (name in the table, OMPL's column type).
const std::pair<const char*, const char*> kCellColumns[] = {
    {"class", "VARCHAR(16)"},          {"objects", "INTEGER"},         {"target_density", "REAL"},
    {"workspace_width_m", "REAL"},     {"workspace_height_m", "REAL"}, {"unknown_fraction", "REAL"},
    {"unknown_shapes", "VARCHAR(16)"}, {"time_limit_s", "REAL"},       {"query_limit", "INTEGER"}};

// Run properties after time, solved and status.
const std::pair<const char*, const char*> kRunColumns[] = {{"achieved_density", "REAL"},
                                                           {"footprint_density", "REAL"},
                                                           {"rep", "INTEGER"},
                                                           {"instance_seed", "VARCHAR(24)"},
                                                           {"planner_seed", "VARCHAR(24)"},
                                                           {"wall_time_s", "REAL"},
                                                           {"cpu_time_s", "REAL"},
                                                           {"sim_time_s", "REAL"},
                                                           {"robot_path_m", "REAL"},
                                                           {"object_path_m", "REAL"},
                                                           {"actions", "INTEGER"},
                                                           {"fix_mode_entries", "INTEGER"},
                                                           {"replans", "INTEGER"},
                                                           {"collisions", "INTEGER"},
                                                           {"min_clearance_m", "REAL"},
                                                           {"queries", "INTEGER"},
                                                           {"subqueries", "INTEGER"},
                                                           {"nodes", "INTEGER"},
                                                           {"goals_reached", "BOOLEAN"},
                                                           {"trial", "INTEGER"}};

std::string cell_key(const CsvTable& t, const std::vector<std::string>& row) {
  std::string k;
  for (const auto& [name, type] : kCellColumns) k += row[t.column(name)] + "|";
  return k;
}

std::string file_safe(std::string s) {
  for (char& c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  }
  return s;
}

// The log's name for a cell: sweep, class, N, target density, width and unknown mix.
std::string cell_name(const CsvTable& t, const std::vector<std::string>& first) {
  return file_safe(first[t.column("sweep")] + "_" + first[t.column("class")] + "_n" +
                   first[t.column("objects")] + "_d" + first[t.column("target_density")] + "_w" +
                   first[t.column("workspace_width_m")] + "_u" +
                   first[t.column("unknown_fraction")] + "_" + first[t.column("unknown_shapes")]);
}

// OMPL's "Starting at": when the cell's first trial ended (the rows' finished_utc, ISO 8601, in
// OMPL's "YYYY-MM-DD HH:MM:SS"), the date of the run that produced the log's numbers; "unknown"
// for rows of a log written before that column, never the time of the report.
std::string cell_date(const CsvTable& t, const std::vector<const std::vector<std::string>*>& rows) {
  const auto it = std::find(t.header.begin(), t.header.end(), "finished_utc");
  if (it == t.header.end()) return "unknown (the trial log predates its finished_utc column)";
  const std::size_t c = static_cast<std::size_t>(it - t.header.begin());
  std::string first;
  for (const auto* r : rows) {
    const std::string& d = (*r)[c];
    if (!d.empty() && (first.empty() || d < first)) first = d;
  }
  if (first.empty()) return "unknown (the rows predate their finished_utc column)";
  std::replace(first.begin(), first.end(), 'T', ' ');
  if (first.back() == 'Z') first.pop_back();
  return first;
}

// The runs of one method, one line each: "v1; v2; ...; ".
void write_planner(std::ostringstream& out, const CsvTable& t, const std::string& method,
                   const std::vector<const std::vector<std::string>*>& rows) {
  out << method << "\n0 common properties\n";
  out << (3 + std::size(kRunColumns)) << " properties for each run\n";
  out << "time REAL\nsolved BOOLEAN\nstatus ENUM\n";
  for (const auto& [name, type] : kRunColumns) out << name << " " << type << "\n";
  out << rows.size() << " runs\n";
  for (const auto* r : rows) {
    const std::vector<std::string>& row = *r;
    out << row[t.column("compute_time_s")] << "; " << row[t.column("success")] << "; "
        << static_cast<int>(trial_status_from_string(row[t.column("status")])) << "; ";
    for (const auto& [name, type] : kRunColumns) out << row[t.column(name)] << "; ";
    out << "\n";
  }
  out << ".\n";
}

std::string log_text(const CsvTable& t, const std::string& experiment,
                     const std::vector<const std::vector<std::string>*>& rows,
                     const std::string& setup) {
  const std::vector<std::string>& first = *rows.front();
  std::map<std::string, std::vector<const std::vector<std::string>*>> by_method;
  std::vector<std::string> order;
  double total = 0;
  for (const auto* r : rows) {
    const std::string& m = (*r)[t.column("method")];
    if (!by_method.count(m)) order.push_back(m);
    by_method[m].push_back(r);
    total += std::stod((*r)[t.column("wall_time_s")]);
  }
  std::ostringstream out;
  out << "rearm version " << first[t.column("revision")] << "\n";
  out << "Experiment " << experiment << "\n";
  out << std::size(kCellColumns) << " experiment properties\n";
  for (const auto& [name, type] : kCellColumns) {
    out << name << " " << type << " = " << first[t.column(name)] << "\n";
  }
  out << "Running on " << first[t.column("host")] << "\n";
  out << "Starting at " << cell_date(t, rows) << "\n";
  out << "<<<|\n" << setup << (setup.empty() || setup.back() == '\n' ? "" : "\n") << "|>>>\n";
  out << "<<<|\n" << first[t.column("cpu_model")] << "\n|>>>\n";
  out << first[t.column("instance_seed")] << " is the random seed\n";
  out << first[t.column("time_limit_s")] << " seconds per run\n";
  out << "0 MB per run\n";
  out << total << " seconds spent to collect the data\n";
  out << "1 enum types\nstatus";
  for (int i = 0; i < kTrialStatusCount; ++i) out << "|" << to_string(static_cast<TrialStatus>(i));
  out << "\n" << order.size() << " planners\n";
  for (const std::string& m : order) write_planner(out, t, m, by_method[m]);
  return out.str();
}

}  // namespace

std::vector<std::string> write_ompl_logs(const CsvTable& t, const std::string& setup,
                                         const std::string& dir) {
  std::vector<std::string> cells;
  std::map<std::string, std::vector<const std::vector<std::string>*>> rows;
  for (const auto& row : t.rows) {
    const std::string k = cell_key(t, row);
    if (!rows.count(k)) cells.push_back(k);
    rows[k].push_back(&row);
  }
  std::map<std::string, std::string> names;  // cell key -> file name
  std::map<std::string, int> uses;
  for (const std::string& k : cells) ++uses[names[k] = cell_name(t, *rows[k].front())];
  std::vector<std::string> written;
  for (const std::string& k : cells) {
    const auto& first = *rows[k].front();
    std::string name = names[k];
    // One cell run at several budgets (NAME@K methods): a log per budget, never one over another.
    if (uses[name] > 1) {
      name = file_safe(name + "_t" + first[t.column("time_limit_s")] + "_q" +
                       first[t.column("query_limit")]);
    }
    const std::string path = (std::filesystem::path(dir) / (name + ".log")).string();
    write_file_atomically(path, log_text(t, name, rows[k], setup));
    written.push_back(path);
  }
  return written;
}

}  // namespace rearm::experiment
