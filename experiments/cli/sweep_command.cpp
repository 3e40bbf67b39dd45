// rearm sweep: the Monte Carlo study (experiments/sweeps/README.md) — a thin shell over the
// experiment layer: load the sweep file, wire rearm and the baselines into the method registry,
// run (one shard of) the sweep; merge shards; report (tables, plots, OMPL benchmark logs).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "baselines/baseline_method.h"
#include "command.h"
#include "core/error.h"
#include "experiment/csv.h"
#include "experiment/ompl_log.h"
#include "experiment/progress.h"
#include "experiment/rearm_method.h"
#include "experiment/sweep_merge.h"
#include "experiment/sweep_plan.h"
#include "experiment/sweep_runner.h"
#include "python_plot.h"
#include "scenario/sweep_file.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: rearm sweep SWEEP.yaml --out DIR [--threads T] [--shard I/N]\n"
    "                  [--resume-any-revision] [--checked] [--quiet]\n"
    "       rearm sweep merge DIR... --out DIR\n"
    "       rearm sweep report DIR [--no-plot]\n\n"
    "Runs a Monte Carlo sweep (format: experiments/sweeps/README.md): every method of the file\n"
    "on seeded random instances of every cell (goal class x object count x target obstacle\n"
    "density x unknown fraction x unknown shapes), `seeds` instances per cell, on T threads\n"
    "(oneTBB). One row per trial is appended to DIR/trials.csv as it ends; a rerun with the\n"
    "same --out runs only the trials that are missing (a row cut by an interruption is dropped\n"
    "and run again). Every instance is kept as DIR/instances/<name>.yaml for rearm run and\n"
    "rearm baseline. Progress goes to stderr.\n"
    "  --threads T            worker threads (default 1)\n"
    "  --shard I/N            run only shard I of N (0 <= I < N): instances whose index is I\n"
    "                         mod N, each with all its methods; merge the shards' folders after\n"
    "  --resume-any-revision  resume a DIR whose rows came from another build revision\n"
    "  --checked              rearm's trials check the closed loop's invariants on every tick\n"
    "                         (finite commands, no overlap beyond Box2D's slop, det Dh > 0,\n"
    "                         the law's model point in the model freespace); a violation\n"
    "                         ends the trial with status error and names it\n"
    "  --quiet                no progress lines\n"
    "merge: unites the rows of shard (or interrupted) folders of one sweep into --out.\n"
    "report: writes DIR/report.md, the plots DIR/*.png (python3 with matplotlib) and the OMPL\n"
    "benchmark logs DIR/ompl/*.log (ompl_benchmark_statistics DIR/ompl/*.log -d DIR/sweep.db\n"
    "builds Planner Arena's database).\n"
    "Exit: 0 when every trial ran (whatever its outcome), 1 when a trial ended in `error`,\n"
    "2 for bad usage or an invalid sweep file.\n";

experiment::MethodRegistry registry() {
  experiment::MethodRegistry r;
  experiment::register_rearm_methods(r);
  baselines::register_methods(r);
  return r;
}

std::string read_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw Error(path + ": cannot read");
  std::string text;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  return text;
}

int run_merge(const std::vector<std::string>& args) {
  std::vector<std::string> dirs;
  std::string out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out") {
      out = option_value(args, i);
    } else if (args[i].rfind("--", 0) == 0) {
      throw Error("sweep merge: unknown option " + args[i] + "\n" + kUsage);
    } else {
      dirs.push_back(args[i]);
    }
  }
  if (dirs.empty() || out.empty())
    throw Error(std::string("sweep merge needs DIR... --out DIR\n") + kUsage);
  const experiment::MergeSummary m = experiment::merge_sweeps(dirs, out);
  std::printf(
      "merged %zu folders into %s: %zu of %zu trials (%zu duplicates, %zu cut lines dropped)\n",
      dirs.size(), out.c_str(), m.rows, m.total_trials, m.duplicates, m.dropped_torn);
  return kExitOk;
}

int run_report(const std::vector<std::string>& args) {
  std::string dir;
  bool plot = true;
  for (const std::string& a : args) {
    if (a == "--no-plot") {
      plot = false;
    } else if (a.rfind("--", 0) == 0) {
      throw Error("sweep report: unknown option " + a + "\n" + kUsage);
    } else if (dir.empty()) {
      dir = a;
    } else {
      throw Error("sweep report takes one folder\n" + std::string(kUsage));
    }
  }
  if (dir.empty()) throw Error(std::string("sweep report needs a folder\n") + kUsage);
  const experiment::CsvTable t =
      experiment::read_csv((fs::path(dir) / experiment::kTrialsCsv).string());
  const std::string setup = read_file((fs::path(dir) / experiment::kSweepCopy).string());
  const auto logs = experiment::write_ompl_logs(t, setup, (fs::path(dir) / "ompl").string());
  std::printf("wrote %zu OMPL benchmark logs to %s/ompl\n", logs.size(), dir.c_str());
  if (!plot) return kExitOk;
  if (run_plot("sweep report", "sweep.py", {"matplotlib"}, {dir}) == PlotOutcome::kFailed) {
    return kExitFailure;
  }
  return kExitOk;
}

int run_sweep_file(const std::vector<std::string>& args) {
  std::string path;
  experiment::SweepOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out") {
      o.out_dir = option_value(args, i);
    } else if (a == "--threads") {
      const std::uint64_t t = parse_count(a, option_value(args, i));
      if (t < 1 || t > 256) throw Error("--threads must be in [1, 256]");
      o.threads = static_cast<int>(t);
    } else if (a == "--shard") {
      o.shard = experiment::parse_shard(option_value(args, i));
    } else if (a == "--resume-any-revision") {
      o.resume_any_revision = true;
    } else if (a == "--checked") {
      o.checked = true;
    } else if (a == "--quiet") {
      o.progress = nullptr;
    } else if (a.rfind("--", 0) == 0) {
      throw Error("unknown option " + a + "\n" + kUsage);
    } else if (path.empty()) {
      path = a;
    } else {
      throw Error("sweep takes one sweep file\n" + std::string(kUsage));
    }
  }
  if (path.empty() || o.out_dir.empty())
    throw Error(std::string("sweep needs SWEEP.yaml --out DIR\n") + kUsage);
  const scenario::SweepFile file = scenario::load_sweep_file(path);
  o.spec_text = read_file(path);
  const experiment::MethodRegistry methods = registry();
  const experiment::SweepPlan plan =
      experiment::shard_of(experiment::plan_sweep(file, methods), o.shard);
  std::fprintf(stderr, "sweep %s: %zu trials in shard %s (%zu in the sweep), %d threads, into %s\n",
               plan.name.c_str(), plan.trials.size(), experiment::to_string(o.shard).c_str(),
               plan.total_trials, o.threads, o.out_dir.c_str());
  const experiment::SweepSummary s = experiment::run_sweep(plan, methods, o);
  std::printf("sweep %s: %zu trials ran (%zu succeeded, %zu errors), %zu already done%s, %s\n",
              plan.name.c_str(), s.ran, s.succeeded, s.errors, s.already_done,
              s.dropped_torn_line ? " (a cut last row was dropped and run again)" : "",
              experiment::format_duration(s.wall_s).c_str());
  return s.errors > 0 ? kExitFailure : kExitOk;
}

}  // namespace

int run_sweep(const std::vector<std::string>& args) {
  if (args.empty()) throw Error(std::string("sweep needs arguments\n") + kUsage);
  if (args[0] == "--help" || args[0] == "-h") {
    std::printf("%s", kUsage);
    return kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "merge") return run_merge(rest);
  if (args[0] == "report") return run_report(rest);
  return run_sweep_file(args);
}

}  // namespace rearm::cli
