// The Monte Carlo runner end to end through the real `rearm sweep` program on
// experiments/sweeps/smoke.yaml: the same rows (timing columns aside) for 1 and 2 threads, the
// union of 3 shards run on 8, 2 and 1 threads equal to the unsharded run on 1 (determinism for
// any thread count and shard, across separate runs), a run killed with SIGKILL and run again losing
// and duplicating nothing, Debian's ompl_benchmark_statistics reading the OMPL logs into SQLite
// with one `runs` row per trial, and the kept instance files reproducing their rows through
// `rearm run` and `rearm baseline`.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "experiment/csv.h"
#include "experiment/trial_columns.h"
#include "scenario/sweep_file.h"
#include "support/scale.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

// The smoke sweep; below scale 1 (REARM_TEST_SCALE: the sanitizer stage, whose rearm is built
// with the sanitizers) a smaller one of the same shape, 16 trials.
const char* const kSmoke = test_support::test_scale() < 1 ? "tests/experiment/smoke_small.yaml"
                                                          : "experiments/sweeps/smoke.yaml";

fs::path work_dir() {
  static const fs::path d = [] {
    const fs::path p = fs::temp_directory_path() / ("rearm_sweep_cli_" + std::to_string(getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
  }();
  return d;
}

int run(const std::string& args) {
  const std::string cmd = std::string(REARM_CLI_PATH) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int sweep(const std::string& out, const std::string& extra = "") {
  return run(std::string("sweep ") + kSmoke + " --out " + out + " --quiet " + extra);
}

// key -> the row's non-timing fields.
using Rows = std::map<std::string, std::vector<std::string>>;

Rows rows_of(const fs::path& csv, std::size_t* count = nullptr) {
  const CsvTable t = read_csv(csv.string());
  EXPECT_EQ(t.header, trial_columns());
  Rows rows;
  for (const auto& row : t.rows) {
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (!is_timing_column(t.header[i])) kept.push_back(row[i]);
    }
    EXPECT_TRUE(rows.emplace(row[t.column("key")], kept).second) << "duplicate " << row[1];
  }
  if (count != nullptr) *count = t.rows.size();
  return rows;
}

// The machine's load average over the last minute, for the report of wall-clock cuts.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? "unknown" : one;
}

// Rows equal key by key, except rows that a wall clock cut (status timeout: the smoke sweep's
// 60 s safety net, which only a loaded machine reaches; the planners stop on their query
// budget, which binds the same everywhere): those are reported with the load, not compared.
// At least half of the rows must be compared, or the check would say nothing.
void expect_same_rows(const Rows& got, const Rows& want) {
  const std::size_t status = [] {
    const std::vector<std::string> all = trial_columns();
    std::size_t k = 0;
    for (const std::string& c : all) {
      if (c == "status") break;
      if (!is_timing_column(c)) ++k;
    }
    return k;
  }();
  ASSERT_EQ(got.size(), want.size());
  std::size_t compared = 0;
  std::vector<std::string> cut;
  for (const auto& [key, row] : want) {
    const auto it = got.find(key);
    ASSERT_NE(it, got.end()) << "missing row " << key;
    if (row.at(status) == "timeout" || it->second.at(status) == "timeout") {
      cut.push_back(key);
      continue;
    }
    EXPECT_EQ(it->second, row) << key;
    ++compared;
  }
  if (!cut.empty()) {
    std::cout << "[ note ] " << cut.size() << " of " << want.size()
              << " rows not compared: a wall clock cut them (load average " << load_average()
              << "), first: " << cut.front() << "\n";
  }
  EXPECT_GE(2 * compared, want.size())
      << "the wall clock cut " << cut.size() << " of " << want.size() << " rows (load average "
      << load_average() << ")";
}

// The system clock's time now, UTC, in a strftime format.
std::string utc(const char* format) {
  const std::time_t t = std::time(nullptr);
  std::tm u{};
  gmtime_r(&t, &u);
  char buf[32];
  std::strftime(buf, sizeof buf, format, &u);
  return buf;
}

std::size_t smoke_trials() { return scenario::load_sweep_file(kSmoke).trial_count(); }

class SweepCli : public ::testing::Test {
 protected:
  // The reference: the smoke sweep unsharded on one thread, run once for the suite.
  static void SetUpTestSuite() {
    reference_dir_ = new fs::path(work_dir() / "one_thread");
    reference_began_ = utc("%Y-%m-%dT%H:%M:%SZ");
    ASSERT_EQ(sweep(reference_dir_->string(), "--threads 1"), 0);
    reference_ended_ = utc("%Y-%m-%dT%H:%M:%SZ");
  }
  static void TearDownTestSuite() {
    delete reference_dir_;
    fs::remove_all(work_dir());
  }
  static Rows reference() { return rows_of(*reference_dir_ / "trials.csv"); }
  static fs::path* reference_dir_;
  // The system clock (UTC) just before and after the reference run.
  static std::string reference_began_, reference_ended_;
};
fs::path* SweepCli::reference_dir_ = nullptr;
std::string SweepCli::reference_began_, SweepCli::reference_ended_;

TEST_F(SweepCli, EveryTrialOnceAndTheSameRowsOnTwoThreads) {
  std::size_t count = 0;
  const Rows one = rows_of(*reference_dir_ / "trials.csv", &count);
  EXPECT_EQ(count, smoke_trials());
  EXPECT_EQ(one.size(), smoke_trials());
  const fs::path two = work_dir() / "two_threads";
  ASSERT_EQ(sweep(two.string(), "--threads 2"), 0);
  expect_same_rows(rows_of(two / "trials.csv"), one);
  // A rerun into a finished folder runs nothing and adds nothing.
  ASSERT_EQ(sweep(two.string(), "--threads 2"), 0);
  std::size_t again = 0;
  rows_of(two / "trials.csv", &again);
  EXPECT_EQ(again, smoke_trials());
}

TEST_F(SweepCli, TheUnionOfThreeShardsIsTheUnshardedRun) {
  // Each shard on another thread count: 8 (more threads than this machine's cores), 2 and 1.
  const char* threads[] = {"8", "2", "1"};
  std::string dirs;
  for (int i = 0; i < 3; ++i) {
    const fs::path d = work_dir() / ("shard_" + std::to_string(i));
    ASSERT_EQ(sweep(d.string(), std::string("--threads ") + threads[i] + " --shard " +
                                    std::to_string(i) + "/3"),
              0);
    dirs += " " + d.string();
  }
  const fs::path merged = work_dir() / "merged";
  ASSERT_EQ(run("sweep merge" + dirs + " --out " + merged.string()), 0);
  expect_same_rows(rows_of(merged / "trials.csv"), reference());
  // Shard folders are not interchangeable: a rerun of shard 0 into shard 1's folder is refused.
  EXPECT_NE(sweep((work_dir() / "shard_1").string(), "--shard 0/3"), 0);
}

// The smoke sweep's first-action column: a baseline acts when its plan is complete (its
// planning time, the same printed number; a replanning one before its replans), rearm after
// part of its compute; empty exactly
// where the method never acted (no plan, or rearm's mission ended before a command).
TEST_F(SweepCli, FirstActionIsAPlannersPlanningAndPartOfRearmsCompute) {
  const CsvTable t = read_csv((*reference_dir_ / "trials.csv").string());
  const std::size_t first = t.column("first_action_time_s");
  std::size_t acted = 0;
  for (const auto& row : t.rows) {
    const std::string& f = row[first];
    if (row[t.column("success")] == "1") {
      EXPECT_FALSE(f.empty()) << row[t.column("key")];
    }
    if (f.empty()) continue;
    ++acted;
    const std::string& planning = row[t.column("planning_time_s")];
    if (!planning.empty() && row[t.column("replans")] == "0") {
      EXPECT_EQ(f, planning) << row[t.column("method")];
    } else if (!planning.empty()) {  // the replanning baseline acts on its first plan
      EXPECT_LE(std::stod(f), std::stod(planning)) << row[t.column("method")];
    } else {
      EXPECT_LE(std::stod(f), std::stod(row[t.column("compute_time_s")]) * (1 + 1e-5));
    }
  }
  EXPECT_GE(2 * acted, t.rows.size());
}

// Every row names when its trial ended, within the reference run by the system clock.
TEST_F(SweepCli, EveryRowNamesWhenItsTrialEnded) {
  const CsvTable t = read_csv((*reference_dir_ / "trials.csv").string());
  for (const auto& row : t.rows) {
    const std::string& d = row[t.column("finished_utc")];
    ASSERT_EQ(d.size(), 20u) << d;
    EXPECT_GE(d, reference_began_);
    EXPECT_LE(d, reference_ended_);
  }
}

// A folder written before first_action_time_s existed: merged with the column empty, and
// resumed, its earlier rows rewritten with the column empty before the new ones.
TEST_F(SweepCli, AFolderOfAnEarlierVersionIsMergedAndResumed) {
  const fs::path old = work_dir() / "earlier_version";
  fs::copy(*reference_dir_, old, fs::copy_options::recursive);
  const CsvTable t = read_csv((*reference_dir_ / "trials.csv").string());
  const std::size_t drop = t.column("first_action_time_s");
  const auto without = [&](std::vector<std::string> f) {
    f.erase(f.begin() + static_cast<std::ptrdiff_t>(drop));
    return csv_line(f) + "\n";
  };
  const std::size_t kept = t.rows.size() - 3;
  {
    std::ofstream out(old / "trials.csv", std::ios::binary | std::ios::trunc);
    out << without(t.header);
    for (std::size_t i = 0; i < kept; ++i) out << without(t.rows[i]);
  }
  const fs::path merged = work_dir() / "earlier_merged";
  ASSERT_EQ(run("sweep merge " + old.string() + " --out " + merged.string()), 0);
  const CsvTable m = read_csv((merged / "trials.csv").string());
  ASSERT_EQ(m.rows.size(), kept);
  for (const auto& row : m.rows) EXPECT_EQ(row[m.column("first_action_time_s")], "");
  ASSERT_EQ(sweep(old.string()), 0);
  expect_same_rows(rows_of(old / "trials.csv"), reference());
  // The earlier rows read empty; the three run again carry the column as the reference does.
  const CsvTable r = read_csv((old / "trials.csv").string());
  std::map<std::string, std::string> first;
  for (const auto& row : r.rows) first[row[r.column("key")]] = row[drop];
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const std::string& got = first.at(t.rows[i][t.column("key")]);
    EXPECT_EQ(got.empty(), i < kept || t.rows[i][drop].empty()) << i;
  }
}

std::size_t data_lines(const fs::path& csv) {
  std::ifstream in(csv);
  std::size_t n = 0;
  std::string line;
  while (std::getline(in, line)) ++n;
  return n == 0 ? 0 : n - 1;
}

TEST_F(SweepCli, AKilledSweepRunAgainLosesAndDuplicatesNothing) {
  const fs::path d = work_dir() / "killed";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    const std::string out = d.string();
    execl(REARM_CLI_PATH, REARM_CLI_PATH, "sweep", kSmoke, "--out", out.c_str(), "--threads", "2",
          "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it once a few rows are on disk (bounded wait: the whole smoke sweep takes < 2 min).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (data_lines(d / "trials.csv") < 3 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "it finished before the kill";
  const std::size_t before = data_lines(d / "trials.csv");
  ASSERT_GE(before, 3u);
  ASSERT_LT(before, smoke_trials());
  ASSERT_EQ(sweep(d.string(), "--threads 2"), 0);
  std::size_t count = 0;
  const Rows after = rows_of(d / "trials.csv", &count);  // fails on duplicates
  EXPECT_EQ(count, smoke_trials());
  expect_same_rows(after, reference());
}

// Every file under `dir` (relative path) with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    out[fs::relative(e.path(), dir).string()] = bytes.str();
  }
  return out;
}

// `sweep report DIR --out OUT` reads DIR only: a read-only copy (permissions off; the byte
// comparison holds for a user the permissions do not stop, as root) is left as it was, and the
// report, figures and OMPL logs land in OUT.
TEST_F(SweepCli, ReportOutLeavesTheSweepFolderUntouched) {
  const fs::path ro = work_dir() / "read_only";
  const fs::path out = work_dir() / "report_elsewhere";
  fs::remove_all(ro);
  fs::remove_all(out);
  fs::copy(*reference_dir_, ro, fs::copy_options::recursive);
  fs::remove_all(ro / "ompl");  // the other test's output, if it ran first
  fs::remove(ro / "report.md");
  const std::map<std::string, std::string> before = snapshot(ro);
  for (const auto& e : fs::recursive_directory_iterator(ro)) {
    fs::permissions(e.path(),
                    fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    fs::perm_options::remove);
  }
  fs::permissions(ro, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  ASSERT_EQ(run("sweep report " + ro.string() + " --out " + out.string()), 0);
  fs::permissions(ro, fs::perms::owner_write, fs::perm_options::add);
  EXPECT_EQ(snapshot(ro), before);
  EXPECT_FALSE(fs::is_empty(out / "ompl"));
  bool plots = false;  // as the command looks for a python3 with matplotlib
  const char* env = std::getenv("REARM_PYTHON");
  for (const std::string& py :
       {std::string(env ? env : ""), std::string("python3"), std::string("/usr/bin/python3")}) {
    plots = plots ||
            (!py.empty() &&
             std::system(("'" + py + "' -c 'import matplotlib' > /dev/null 2>&1").c_str()) == 0);
  }
  EXPECT_EQ(fs::exists(out / "report.md"), plots);
  EXPECT_EQ(fs::exists(out / "success_vs_n.png"), plots);
  for (const auto& e : fs::recursive_directory_iterator(ro)) {
    fs::permissions(e.path(), fs::perms::owner_write, fs::perm_options::add);
  }
}

TEST_F(SweepCli, OmplBenchmarkStatisticsReadsTheLogs) {
  ASSERT_EQ(run("sweep report " + reference_dir_->string() + " --no-plot"), 0);
  std::string logs;
  for (const auto& e : fs::directory_iterator(*reference_dir_ / "ompl")) {
    logs += " " + e.path().string();
  }
  ASSERT_FALSE(logs.empty());
  const fs::path db = work_dir() / "sweep.db";
  const std::string stats = "ompl_benchmark_statistics" + logs + " -d " + db.string() + " > " +
                            (work_dir() / "stats.log").string() + " 2>&1";
  ASSERT_EQ(std::system(stats.c_str()), 0) << "see " << (work_dir() / "stats.log");
  const fs::path counts = work_dir() / "counts.txt";
  const std::string query =
      "python3 -c 'import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); "
      "print(c.execute(\"select count(*) from runs\").fetchone()[0]); "
      "print(c.execute(\"select count(*) from runs where solved=1\").fetchone()[0]); "
      "print(c.execute(\"select count(distinct objects) from experiments\").fetchone()[0]); "
      "print(*c.execute(\"select min(date), max(date) from experiments\").fetchone(), "
      "sep=\"T\")' " +
      db.string() + " > " + counts.string();
  ASSERT_EQ(std::system(query.c_str()), 0);
  std::ifstream in(counts);
  std::size_t runs = 0, solved = 0, object_counts = 0;
  in >> runs >> solved >> object_counts;
  // Each log's "Starting at" is when its cell's first trial ended, not the report's time: the
  // earliest and latest cell dates lie inside the reference run.
  std::string first_day, first_time_last_day, last_time;
  in >> first_day >> first_time_last_day >> last_time;
  const std::size_t cut = first_time_last_day.find('T');
  ASSERT_NE(cut, std::string::npos) << first_time_last_day;
  const auto iso = [](const std::string& day, const std::string& time) {
    return day + "T" + time + "Z";
  };
  EXPECT_GE(iso(first_day, first_time_last_day.substr(0, cut)), reference_began_);
  EXPECT_LE(iso(first_time_last_day.substr(cut + 1), last_time), reference_ended_);
  EXPECT_EQ(runs, smoke_trials());
  std::size_t successes = 0;
  const CsvTable t = read_csv((*reference_dir_ / "trials.csv").string());
  for (const auto& row : t.rows) successes += row[t.column("success")] == "1";
  EXPECT_EQ(solved, successes);
  EXPECT_EQ(object_counts, scenario::load_sweep_file(kSmoke).objects.size());
}

TEST_F(SweepCli, KeptInstancesReproduceTheirRows) {
  const CsvTable t = read_csv((*reference_dir_ / "trials.csv").string());
  int checked = 0;
  for (const auto& row : t.rows) {
    const std::string method = row[t.column("method")];
    if (row[t.column("status")] != "completed" || (method != "rearm" && method != "mrs")) continue;
    const fs::path instance = *reference_dir_ / "instances" / (row[t.column("instance")] + ".yaml");
    ASSERT_TRUE(fs::exists(instance)) << instance;
    const fs::path out = work_dir() / ("rerun_" + row[t.column("trial")]);
    const std::string args =
        method == "rearm"
            ? "run " + instance.string() + " --no-plot --no-animation --out " + out.string()
            : "baseline " + instance.string() + " --method " + method + " --seed " +
                  row[t.column("planner_seed")] + " --time-limit " + row[t.column("time_limit_s")] +
                  " --no-plot --no-animation --out " + out.string();
    ASSERT_EQ(run(args), 0) << args;
    std::ifstream in(out / "metrics.json");
    const nlohmann::json metrics = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(metrics.is_object()) << args << ": metrics.json does not parse";
    EXPECT_EQ(metrics.value("status", ""), "completed") << args;
    EXPECT_DOUBLE_EQ(metrics.value("sim_time_s", -1.0), std::stod(row[t.column("sim_time_s")]))
        << args;
    ++checked;
  }
  EXPECT_GE(checked, 2) << "the smoke sweep completed too few rearm and mrs trials to check";
}

}  // namespace
}  // namespace rearm::experiment
