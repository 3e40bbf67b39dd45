// rearm sweep: the Monte Carlo study (experiments/sweeps/README.md) — a thin shell over the
// experiment layer: load the sweep file, wire rearm and the baselines into the method registry,
// run (one shard of) the sweep; merge shards; report (tables, plots, OMPL benchmark logs).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "baselines/baseline_method.h"
#include "baselines/constructive.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/text.h"
#include "experiment/cell_check.h"
#include "experiment/csv.h"
#include "experiment/ompl_log.h"
#include "experiment/progress.h"
#include "experiment/rearm_method.h"
#include "experiment/sweep_merge.h"
#include "experiment/sweep_plan.h"
#include "experiment/sweep_runner.h"
#include "options.h"
#include "python_plot.h"
#include "scenario/random_instance.h"
#include "scenario/sweep_file.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;

// The help text; the density tolerance is the generator's own (random_instance.h).
std::string footer() {
  return std::string(
             "Runs a Monte Carlo sweep (format: experiments/sweeps/README.md): every method of\n"
             "the file on seeded random instances of every cell (goal class x object count x\n"
             "target obstacle density x footprint x unknown fraction x unknown shapes), `seeds`\n"
             "instances per cell, on T threads (oneTBB). One row per trial is appended to\n"
             "DIR/trials.csv as it ends; a rerun with the same --out runs only the trials that\n"
             "are missing (a row cut by an interruption is dropped and run again). Every instance\n"
             "is kept as DIR/instances/<name>.yaml for rearm run and rearm baseline. Progress\n"
             "goes to stderr.\n"
             "Before any trial, every instance of the cells to run is generated: a cell with an\n"
             "instance that cannot be generated or misses its target obstacle density by more\n"
             "than ") +
         fixed(scenario::kDensityTolerance, 2) +
         " is refused, and the sweep stops listing the refused cells\n"
         "(`refused_cells: skip` in the file runs the others); the verdicts go to\n"
         "DIR/cells.csv. --check-cells does only that.\n"
         "--shard I/N: run only the instances whose index is I mod N (0 <= I < N), each with all\n"
         "its methods; merge the shards' folders after.\n"
         "--checked: rearm's trials check the closed loop's invariants on every tick (finite\n"
         "commands, no overlap beyond Box2D's slop, det Dh > 0, the law's model point in the "
         "model\n"
         "freespace); a violation ends the trial with status error and names it.\n"
         "'rearm sweep merge --help' and 'rearm sweep report --help' describe the other two.\n"
         "Exit: 0 when every trial ran (whatever its outcome), 1 when a trial ended in `error`,\n"
         "2 for bad usage or an invalid sweep file.";
}

constexpr int kMaxThreads = 256;

// The command line of `rearm sweep` and its merge and report subcommands, parsed.
struct SweepArgs {
  std::string path, shard;
  experiment::SweepOptions options;
  bool quiet = false;
  std::vector<std::string> merge_dirs;
  std::string merge_out, report_dir, report_out;
  bool no_plot = false;
  bool check_only = false;
};

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

int run_merge(const SweepArgs& a) {
  const std::vector<std::string>& dirs = a.merge_dirs;
  const std::string& out = a.merge_out;
  const experiment::MergeSummary m = experiment::merge_sweeps(dirs, out, registry());
  std::printf(
      "merged %zu folders into %s: %zu of %zu trials (%zu duplicates, %zu cut lines dropped)\n",
      dirs.size(), out.c_str(), m.rows, m.total_trials, m.duplicates, m.dropped_torn);
  if (m.rows < m.total_trials) {
    std::printf(
        "next: %zu trials are missing; run the missing shards (or resume one with "
        "'rearm sweep SWEEP.yaml --out %s'), then merge again\n",
        m.total_trials - m.rows, out.c_str());
  } else {
    std::printf("next: rearm sweep report %s\n", out.c_str());
  }
  return kExitOk;
}

// DIR's tables, figures and OMPL logs, written into --out (default DIR): DIR is only read.
int run_report(const SweepArgs& a) {
  const std::string& dir = a.report_dir;
  const std::string out = a.report_out.empty() ? dir : a.report_out;
  const experiment::CsvTable t =
      experiment::read_csv((fs::path(dir) / experiment::kTrialsCsv).string());
  const std::string setup = read_file((fs::path(dir) / experiment::kSweepCopy).string());
  const auto logs = experiment::write_ompl_logs(t, setup, (fs::path(out) / "ompl").string());
  std::printf("wrote %zu OMPL benchmark logs to %s/ompl\n", logs.size(), out.c_str());
  if (a.no_plot) return kExitOk;
  if (run_plot("sweep report", "sweep.py", {"matplotlib"}, {dir, out}) == PlotOutcome::kFailed) {
    return kExitFailure;
  }
  return kExitOk;
}

// The cell check of the cells this shard touches (cell_check.h); its verdicts also go to
// DIR/cells.csv with the sweep.
std::vector<experiment::CellVerdict> check_shard_cells(const experiment::SweepPlan& full,
                                                       const experiment::SweepPlan& part,
                                                       experiment::SweepOptions& o,
                                                       experiment::GeneratedJobs& keep) {
  const std::vector<experiment::InstanceJob> check = experiment::cells_touched(full, part);
  if (o.progress != nullptr) {
    std::fprintf(o.progress, "sweep %s: checking the obstacle density of %zu instances\n",
                 full.name.c_str(), check.size());
  }
  std::vector<experiment::CellVerdict> verdicts =
      experiment::check_cells(check, o.threads, &keep, o.generators);
  o.generated = &keep;
  o.cells_csv = experiment::verdicts_csv(verdicts);
  return verdicts;
}

// The shard's plan without the refused cells, or rearm::Error listing them (refused_cells:
// error, the default).
experiment::SweepPlan accepted_part(const scenario::SweepFile& file,
                                    const experiment::SweepPlan& part,
                                    const std::vector<experiment::CellVerdict>& verdicts) {
  const std::string refused = experiment::describe_refused(verdicts);
  if (refused.empty()) return part;
  if (!file.skip_refused_cells) {
    throw Error("sweep " + part.name +
                ": cells refused before any trial ran (an instance cannot be generated or misses "
                "its target obstacle density):\n" +
                refused +
                "lower their densities, enlarge their rooms, or set `refused_cells: skip`");
  }
  std::fprintf(stderr, "sweep %s: skipping refused cells (refused_cells: skip):\n%s",
               part.name.c_str(), refused.c_str());
  return experiment::without_cells(part, verdicts);
}

// --check-cells: DIR/cells.csv and a summary, no trial.
int write_cell_check(const std::string& name, const experiment::SweepOptions& o,
                     const std::vector<experiment::CellVerdict>& verdicts) {
  std::filesystem::create_directories(o.out_dir);
  const std::string path = (std::filesystem::path(o.out_dir) / experiment::kCellsCsv).string();
  write_file_atomically(path, o.cells_csv);
  const auto refused = std::count_if(verdicts.begin(), verdicts.end(),
                                     [](const experiment::CellVerdict& v) { return v.refused; });
  std::printf("sweep %s: %td of %zu cells refused; the verdicts are in %s\n%s", name.c_str(),
              refused, verdicts.size(), path.c_str(),
              experiment::describe_refused(verdicts).c_str());
  return kExitOk;
}

int run_sweep_file(SweepArgs a) {
  if (a.path.empty()) throw Error("missing SWEEP.yaml (or the subcommand merge or report)");
  if (a.options.out_dir.empty()) throw Error("missing --out DIR");
  experiment::SweepOptions& o = a.options;
  if (!a.shard.empty()) o.shard = experiment::parse_shard(a.shard);
  if (a.quiet) o.progress = nullptr;
  const std::string& path = a.path;
  const scenario::SweepFile file = scenario::load_sweep_file(path);
  o.spec_text = read_file(path);
  o.generators.constructive = baselines::generate_constructive;
  const experiment::MethodRegistry methods = registry();
  const experiment::SweepPlan full = experiment::plan_sweep(file, methods);
  const experiment::SweepPlan part = experiment::shard_of(full, o.shard);
  experiment::GeneratedJobs generated;  // by the cell check, for the runner
  const std::vector<experiment::CellVerdict> verdicts = check_shard_cells(full, part, o, generated);
  if (a.check_only) return write_cell_check(full.name, o, verdicts);
  const experiment::SweepPlan plan = accepted_part(file, part, verdicts);
  std::fprintf(stderr, "sweep %s: %zu trials in shard %s (%zu in the sweep), %d threads, into %s\n",
               plan.name.c_str(), plan.trials.size(), experiment::to_string(o.shard).c_str(),
               plan.total_trials, o.threads, o.out_dir.c_str());
  const experiment::SweepSummary s = experiment::run_sweep(plan, methods, o);
  std::printf("sweep %s: %zu trials ran (%zu succeeded, %zu errors), %zu already done%s, %s\n",
              plan.name.c_str(), s.ran, s.succeeded, s.errors, s.already_done,
              s.dropped_torn_line ? " (a cut last row was dropped and run again)" : "",
              experiment::format_duration(s.wall_s).c_str());
  for (const std::string& column : s.added_columns) {
    std::printf("%s: written by an earlier version; its earlier rows leave %s empty\n",
                (fs::path(o.out_dir) / experiment::kTrialsCsv).string().c_str(), column.c_str());
  }
  if (o.shard.count > 1) {
    std::printf(
        "next: once every shard has run, 'rearm sweep merge DIR... --out MERGED', then "
        "'rearm sweep report MERGED'\n");
  } else {
    std::printf(
        "next: 'rearm sweep report %s' (an interrupted run resumes with the same "
        "command)\n",
        o.out_dir.c_str());
  }
  return s.errors > 0 ? kExitFailure : kExitOk;
}

void add_merge(CLI::App& sweep, SweepArgs& a) {
  CLI::App* m = sweep.add_subcommand(
      "merge", "unite the rows of shard (or interrupted) folders of one sweep into --out");
  m->add_option("DIR", a.merge_dirs, "the folders to merge")->required();
  m->add_option("--out", a.merge_out, "the merged folder")->required()->type_name("DIR");
  m->footer(
      "Unites the rows of the DIRs (shards of one sweep, or interrupted runs of it) into --out,\n"
      "each trial once (identical rows found twice kept once, a cut last line dropped), with\n"
      "the sweep file. Refuses folders of another sweep file, damaged CSVs and conflicting\n"
      "rows for one trial. Then: 'rearm sweep report OUT'. Exit: 0 merged, 2 bad usage or\n"
      "folders that cannot be merged.");
}

void add_report(CLI::App& sweep, SweepArgs& a) {
  CLI::App* r = sweep.add_subcommand("report", "tables, plots and OMPL benchmark logs of a sweep");
  r->footer(
      "Writes OUT/report.md, the plots OUT/*.png (python3 with matplotlib) and the OMPL\n"
      "benchmark logs OUT/ompl/*.log (ompl_benchmark_statistics OUT/ompl/*.log -d OUT/sweep.db\n"
      "builds Planner Arena's database); OUT is DIR unless --out names another folder, so a\n"
      "committed or read-only sweep is analysed without copying it.");
  r->add_option("DIR", a.report_dir, "the sweep's folder (only read)")->required();
  r->add_option("--out", a.report_out, "write the report there (default DIR)")->type_name("OUT");
  r->add_flag("--no-plot", a.no_plot, "write the report and logs only");
}

}  // namespace

Command add_sweep(CLI::App& program) {
  CLI::App* c = program.add_subcommand(
      "sweep", "Monte Carlo sweeps of rearm and the baselines (run, merge, report)");
  c->footer(footer());
  c->require_subcommand(0, 1);
  auto a = std::make_shared<SweepArgs>();
  c->add_option("SWEEP", a->path, "the sweep file (experiments/sweeps/README.md)")
      ->type_name("SWEEP.yaml");
  c->add_option("--out", a->options.out_dir, "output folder (required)")->type_name("DIR");
  c->add_option("--threads", a->options.threads, "worker threads (default 1)")
      ->check(count_check())
      ->check(CLI::Range(1, kMaxThreads))
      ->type_name("T");
  c->add_option("--shard", a->shard, "run only shard I of N")->type_name("I/N");
  c->add_flag("--resume-any-revision", a->options.resume_any_revision,
              "resume a DIR whose rows came from another build revision");
  c->add_flag("--checked", a->options.checked, "check the closed loop's invariants every tick");
  c->add_flag("--quiet", a->quiet, "no progress lines");
  c->add_flag("--check-cells", a->check_only,
              "only check every cell's obstacle density; write DIR/cells.csv and stop");
  add_merge(*c, *a);
  add_report(*c, *a);
  return {c, [a, c] {
            if (c->got_subcommand("merge")) return run_merge(*a);
            if (c->got_subcommand("report")) return run_report(*a);
            return run_sweep_file(*a);
          }};
}

}  // namespace rearm::cli
