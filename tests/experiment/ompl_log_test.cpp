// The OMPL benchmark logs of a sweep (experiment/ompl_log.h) read by Debian's
// ompl_benchmark_statistics, run as a real process: a cell run at two budgets (a method and
// NAME@K) gives one log per budget, every trial a run of exactly one of them.
#include "experiment/ompl_log.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "experiment/trial_columns.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

TrialRecord trial(std::size_t index, const std::string& method, long queries) {
  TrialRecord r;
  r.index = index;
  r.sweep = "budgets";
  r.settings.method = method;
  r.settings.instance.objects = 4;
  r.settings.instance.seed = 7 + index;
  r.settings.time_limit_s = 60;
  r.settings.query_limit = queries;
  r.outcome.status = TrialStatus::kCompleted;
  r.outcome.goals_reached = true;
  r.provenance = Provenance{"rev", "host", "cpu", "2026-12-07T15:04:05Z"};
  return r;
}

TEST(OmplLog, ACellAtTwoBudgetsGetsALogPerBudget) {
  const fs::path dir = fs::temp_directory_path() / ("rearm_ompl_log_" + std::to_string(getpid()));
  fs::remove_all(dir);
  CsvTable t;
  t.header = trial_columns();
  t.rows = {trial_fields(trial(0, "birrt", 1000)), trial_fields(trial(1, "buffer", 1000)),
            trial_fields(trial(2, "birrt@10000", 10000))};
  const std::vector<std::string> logs = write_ompl_logs(t, "name: budgets", dir.string());
  ASSERT_EQ(logs.size(), 2u);
  EXPECT_NE(logs[0], logs[1]);
  std::string files;
  for (const std::string& l : logs) files += " " + l;
  const fs::path db = dir / "b.db", out = dir / "out.txt";
  ASSERT_EQ(
      std::system(("ompl_benchmark_statistics" + files + " -d " + db.string() + " > /dev/null 2>&1")
                      .c_str()),
      0);
  const std::string query =
      "python3 -c 'import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); "
      "print(c.execute(\"select count(*) from experiments\").fetchone()[0], "
      "c.execute(\"select count(*) from runs\").fetchone()[0], "
      "c.execute(\"select min(date) from experiments\").fetchone()[0])' " +
      db.string() + " > " + out.string();
  ASSERT_EQ(std::system(query.c_str()), 0);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "2 3 2026-12-07 15:04:05");
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace rearm::experiment
