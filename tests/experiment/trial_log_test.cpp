// The sweep's CSV (experiment/csv.h, trial_log.h): RFC 4180 quoting read back by an
// independent reader (Python's csv module, run as a real process), a cut last line dropped on
// resume and its trial counted as not done, damage in the middle refused, the header checked.
#include "experiment/trial_log.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "core/error.h"
#include "experiment/csv.h"
#include "experiment/trial_columns.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the system's temporary directory, removed with its contents when the
// test ends (passed or not).
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("rearm_trial_log_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TrialRecord record(std::size_t index, const std::string& reason) {
  TrialRecord r;
  r.index = index;
  r.sweep = "t";
  r.settings.method = "rearm";
  r.settings.instance.seed = 100 + index;
  r.settings.workspace_rule = "side 10";
  r.outcome.status = TrialStatus::kStuck;
  r.outcome.reason = reason;
  r.provenance = Provenance{"rev", "host", "cpu, with a comma", "2026-12-07T15:04:05Z"};
  return r;
}

TEST(Csv, QuotedFieldsReadBackByPythonsCsvModule) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "", "line\nbreak"};
  const TempDir dir("python");
  const fs::path& d = dir.path;
  {
    std::ofstream out(d / "x.csv");
    out << csv_line(fields) << "\n";
  }
  const std::string cmd =
      "python3 -c 'import csv,sys; r=next(csv.reader(open(sys.argv[1]))); "
      "print(len(r)); print(\"|\".join(r))' " +
      (d / "x.csv").string() + " > " + (d / "out.txt").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(slurp(d / "out.txt"), "5\nplain|a,b|say \"hi\"||line break\n");
  EXPECT_EQ(parse_csv_line(csv_line(fields)),
            (std::vector<std::string>{"plain", "a,b", "say \"hi\"", "", "line break"}));
  EXPECT_THROW(parse_csv_line("\"open"), Error);
  EXPECT_THROW(parse_csv_line("\"a\"b"), Error);
}

TEST(TrialLog, ANewFileGetsTheHeaderAndRowsAreDurableLines) {
  const TempDir dir("new");
  const fs::path& d = dir.path;
  const fs::path csv = d / "sub" / "trials.csv";
  {
    TrialLog log(csv.string());
    EXPECT_TRUE(log.done().empty());
    log.append(trial_row(record(0, "a, b")));
    log.append(trial_row(record(1, "c")));
  }
  const CsvTable t = read_csv(csv.string());
  EXPECT_EQ(t.header, trial_columns());
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][t.column("reason")], "a, b");
  EXPECT_EQ(t.rows[1][t.column("trial")], "1");
  TrialLog again(csv.string());
  EXPECT_EQ(again.done().size(), 2u);
  EXPECT_FALSE(again.dropped_torn_line());
}

TEST(TrialLog, ACutLastLineIsDroppedAndItsTrialIsNotDone) {
  const TempDir dir("torn");
  const fs::path& d = dir.path;
  const fs::path csv = d / "trials.csv";
  const std::string full = trial_row(record(7, "complete"));
  const std::string cut = trial_row(record(8, "cut"));
  {
    std::ofstream out(csv, std::ios::binary);
    out << trial_header() << "\n" << full << "\n" << cut.substr(0, cut.size() / 2);
  }
  TrialLog log(csv.string());
  EXPECT_TRUE(log.dropped_torn_line());
  EXPECT_EQ(log.done().size(), 1u);
  EXPECT_TRUE(log.done().count(key_column(record(7, "").settings)));
  EXPECT_FALSE(log.done().count(key_column(record(8, "").settings)));
  log.append(cut);
  EXPECT_EQ(slurp(csv), trial_header() + "\n" + full + "\n" + cut + "\n");
}

TEST(TrialLog, DamageInTheMiddleAndAForeignHeaderAreRefused) {
  const TempDir dir("damaged");
  const fs::path& d = dir.path;
  {
    std::ofstream out(d / "mid.csv", std::ios::binary);
    out << trial_header() << "\n1,2,3\n" << trial_row(record(1, "x")) << "\n";
  }
  EXPECT_THROW(TrialLog((d / "mid.csv").string()), Error);
  {
    std::ofstream out(d / "other.csv", std::ios::binary);
    out << "method,class,objects\nrearm,random,1\n";
  }
  try {
    TrialLog log((d / "other.csv").string());
    FAIL() << "a foreign header was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not a trial log"), std::string::npos) << e.what();
  }
}

// A log of the version before first_action_time_s: the same fields without that one.
std::string without_first_action(std::vector<std::string> f) {
  f.erase(f.begin() + static_cast<std::ptrdiff_t>(trial_column("first_action_time_s")));
  return csv_line(f);
}

TEST(TrialLog, AnEarlierVersionsLogIsResumedWithItsNewTimingColumnEmpty) {
  const TempDir dir("earlier");
  const fs::path csv = dir.path / "trials.csv";
  std::vector<std::string> row7 = trial_fields(record(7, "a, b"));
  const std::string old_text =
      without_first_action(trial_columns()) + "\n" + without_first_action(row7) + "\n";
  {
    std::ofstream out(csv, std::ios::binary);
    out << old_text;
  }
  TrialLog log(csv.string());
  EXPECT_EQ(log.added_columns(), std::vector<std::string>{"first_action_time_s"});
  EXPECT_TRUE(log.done().count(key_column(record(7, "").settings)));
  EXPECT_EQ(slurp(csv), old_text) << "nothing is rewritten before a new row";
  const std::string row8 = trial_row(record(8, "c"));
  log.append(row8);
  row7[trial_column("first_action_time_s")] = "";
  EXPECT_EQ(slurp(csv), trial_header() + "\n" + csv_line(row7) + "\n" + row8 + "\n");
  TrialLog again(csv.string());
  EXPECT_TRUE(again.added_columns().empty());
  EXPECT_EQ(again.done().size(), 2u);
}

TEST(TrialLog, AHeaderMissingAResultColumnOrWithAnUnknownOneIsRefused) {
  const TempDir dir("layouts");
  std::vector<std::string> no_status = trial_columns();
  no_status.erase(no_status.begin() + static_cast<std::ptrdiff_t>(trial_column("status")));
  std::vector<std::string> extra = trial_columns();
  extra.push_back("colour");
  std::vector<std::string> twice = trial_columns();
  twice.back() = twice.front();
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {no_status, "no column 'status'"},
      {extra, "no column 'colour'"},
      {twice, "'trial' appears twice"}};
  for (const auto& [header, why] : cases) {
    const fs::path csv = dir.path / "h.csv";
    {
      std::ofstream out(csv, std::ios::binary | std::ios::trunc);
      out << csv_line(header) << "\n";
    }
    try {
      TrialLog log(csv.string());
      FAIL() << "accepted a header without: " << why;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
}

// experiments/slurm/compare_rows.py (Python, run as a real process) ignores exactly the columns
// that `rearm sweep merge` ignores: the timing and provenance ones.
TEST(TrialColumns, CompareRowsIgnoresTheTimingColumns) {
  const TempDir dir("compare_rows");
  const fs::path out = dir.path / "ignored.txt";
  const std::string cmd =
      "python3 -c 'import sys; sys.path.insert(0, \"experiments/slurm\"); import compare_rows; "
      "print(\"\\n\".join(sorted(compare_rows.IGNORED)))' > " +
      out.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::vector<std::string> timing;
  for (const std::string& c : trial_columns()) {
    if (is_timing_column(c)) timing.push_back(c);
  }
  std::sort(timing.begin(), timing.end());
  std::string want;
  for (const std::string& c : timing) want += c + "\n";
  EXPECT_EQ(slurp(out), want);
}

TEST(TrialColumns, KeysDifferForEverySettingThatChangesAResult) {
  TrialSettings a;
  a.method = "rearm";
  const std::string k = key_column(a);
  auto differs = [&](auto change) {
    TrialSettings b = a;
    change(b);
    return key_column(b) != k;
  };
  EXPECT_TRUE(differs([](TrialSettings& s) { s.time_limit_s = 3; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.method = "birrt"; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.planner_seed = 9; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.seed = 9; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.obstacle_density = 0.2; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.width = 11; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.round_unknown = false; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.unknown_fraction = 0.1; }));
  EXPECT_TRUE(differs([](TrialSettings& s) { s.instance.passage_margin = 0.1; }));
  EXPECT_TRUE(
      differs([](TrialSettings& s) { s.instance.goal_class = scenario::GoalClass::kSealed; }));
  EXPECT_FALSE(differs([](TrialSettings& s) { s.rep = 4; }));  // the seed carries it
}

TEST(TrialColumns, OneSuccessRule) {
  TrialOutcome o;
  o.status = TrialStatus::kCompleted;
  o.goals_reached = true;
  EXPECT_TRUE(is_success(o));
  o.collisions = 1;
  EXPECT_FALSE(is_success(o));
  o.collisions = 0;
  o.goals_reached = false;
  EXPECT_FALSE(is_success(o));
  o.goals_reached = true;
  o.status = TrialStatus::kTimeout;
  EXPECT_FALSE(is_success(o));
  for (int i = 0; i < kTrialStatusCount; ++i) {
    const auto s = static_cast<TrialStatus>(i);
    EXPECT_EQ(trial_status_from_string(to_string(s)), s);
  }
  EXPECT_THROW(trial_status_from_string("done"), Error);
}

}  // namespace
}  // namespace rearm::experiment
