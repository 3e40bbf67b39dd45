#include "experiment/sweep_runner.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "experiment/progress.h"
#include "experiment/provenance.h"
#include "experiment/trial_columns.h"
#include "experiment/trial_log.h"
#include "scenario/instance_difficulty.h"
#include "scenario/random_instance.h"
#include "scenario/scenario_io.h"

namespace rearm::experiment {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxThreads = 256;

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A generated instance, or why generation failed.
struct Generated {
  std::optional<scenario::Scenario> scenario;
  InstanceInfo info;
  std::string error;
};

InstanceInfo info_of(const scenario::GeneratedInstance& g) {
  InstanceInfo info;
  info.name = g.scenario.name;
  info.achieved_density = g.achieved_density;
  info.footprint_density = g.footprint_density;
  info.familiar = static_cast<int>(g.scenario.familiar.size());
  info.unknown = static_cast<int>(g.scenario.unknown.size());
  info.difficulty = scenario::instance_difficulty(g.scenario, g.goals);
  info.witness = !g.witness.empty();
  return info;
}

// The cell check's instance of the job (SweepOptions::generated) when it made one, else a new one.
GeneratedJob kept_or_generated(const InstanceJob& job, const SweepOptions& o) {
  if (o.generated != nullptr) {
    const auto it = o.generated->find(job.index);
    if (it != o.generated->end()) return it->second;
  }
  return generate_job(job, o.generators);
}

// The job's instance, kept as instances/<name>.yaml (and its witness plan, class constructive,
// as instances/<name>.witness.json), or why it could not be generated.
Generated generate(const InstanceJob& job, const fs::path& instances, const SweepOptions& o) {
  Generated out;
  try {
    GeneratedJob j = kept_or_generated(job, o);
    if (!j.instance) throw Error(j.error);
    scenario::GeneratedInstance& g = *j.instance;
    g.scenario.name = instance_name(job);
    out.info = info_of(g);
    const fs::path file = instances / (g.scenario.name + ".yaml");
    if (!fs::exists(file)) write_file_atomically(file.string(), scenario::to_yaml(g.scenario));
    const fs::path witness = instances / (g.scenario.name + kWitnessSuffix);
    if (!g.witness.empty() && !fs::exists(witness))
      write_file_atomically(witness.string(), g.witness);
    out.scenario = std::move(g.scenario);
  } catch (const std::exception& e) {
    out.error = std::string("instance generation failed: ") + e.what();
  }
  return out;
}

TrialRecord run_one(const SweepPlan& plan, const TrialJob& t, const Generated& g,
                    const MethodRegistry& methods, const Provenance& provenance, bool checked) {
  TrialRecord r;
  r.index = t.index;
  r.sweep = plan.name;
  r.settings = t.settings;
  r.instance = g.info;
  r.provenance = provenance;
  if (!g.scenario) {
    r.outcome.status = TrialStatus::kError;
    r.outcome.reason = g.error;
    r.provenance.finished_utc = utc_now();
    return r;
  }
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  try {
    r.outcome = methods.get(scenario::method_entry(t.settings.method).method)
                    .run(*g.scenario, MethodInput{t.settings.planner_seed, t.settings.time_limit_s,
                                                  t.settings.query_limit, checked});
  } catch (const std::exception& e) {
    r.outcome = TrialOutcome{};
    r.outcome.status = TrialStatus::kError;
    r.outcome.reason = e.what();
    r.outcome.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  }
  r.outcome.cpu_time_s = thread_cpu_seconds() - cpu0;
  r.provenance.finished_utc = utc_now();
  return r;
}

// Checks the folder against the sweep (same sweep file, same revision) and records both.
void prepare_folder(const fs::path& dir, const SweepOptions& o) {
  std::error_code ec;
  fs::create_directories(dir / kInstancesDir, ec);
  if (ec) throw Error(dir.string() + ": cannot create the output folder: " + ec.message());
  const fs::path copy = dir / kSweepCopy;
  if (fs::exists(copy) && read_all(copy) != o.spec_text) {
    throw Error(copy.string() +
                " differs from the sweep file given: this folder holds another "
                "sweep's rows (use another --out)");
  }
  if (!fs::exists(copy)) write_file_atomically(copy.string(), o.spec_text);
  const fs::path shard = dir / kShardFile;
  const std::string shard_text = to_string(o.shard) + "\n";
  if (fs::exists(shard) && read_all(shard) != shard_text) {
    throw Error(shard.string() + " says shard " + read_all(shard).substr(0, 32) + ", not " +
                to_string(o.shard) + " (use another --out per shard)");
  }
  if (!fs::exists(shard)) write_file_atomically(shard.string(), shard_text);
}

void check_revisions(const TrialLog& log, const std::string& path, bool any) {
  for (const std::string& rev : log.revisions()) {
    if (rev == build_revision() || any) continue;
    throw Error(path + " has rows from revision " + rev + ", this binary is " + build_revision() +
                ": use another --out, or --resume-any-revision to pool them");
  }
}

}  // namespace

SweepSummary run_sweep(const SweepPlan& plan, const MethodRegistry& methods,
                       const SweepOptions& o) {
  if (o.threads < 1 || o.threads > kMaxThreads) {
    throw Error("threads must be in [1, " + std::to_string(kMaxThreads) + "], got " +
                std::to_string(o.threads));
  }
  const auto start = std::chrono::steady_clock::now();
  const fs::path dir(o.out_dir);
  prepare_folder(dir, o);
  if (!o.cells_csv.empty()) write_file_atomically((dir / kCellsCsv).string(), o.cells_csv);
  const std::string csv = (dir / kTrialsCsv).string();
  TrialLog log(csv);
  check_revisions(log, csv, o.resume_any_revision);

  SweepSummary summary;
  summary.planned = plan.trials.size();
  summary.dropped_torn_line = log.dropped_torn_line();
  summary.added_columns = log.added_columns();
  std::vector<const TrialJob*> todo;
  std::vector<char> needed(plan.instances.size(), 0);
  for (const TrialJob& t : plan.trials) {
    if (log.done().count(key_column(t.settings))) {
      ++summary.already_done;
      continue;
    }
    todo.push_back(&t);
    needed[t.instance] = 1;
  }
  // Largest N first, then canonical order: a long trial started last would leave the other
  // threads idle at the end.
  std::stable_sort(todo.begin(), todo.end(), [&](const TrialJob* a, const TrialJob* b) {
    return a->settings.instance.objects > b->settings.instance.objects;
  });

  const Provenance provenance = this_process();
  std::vector<Generated> generated(plan.instances.size());
  std::vector<std::string> kinds;
  for (const TrialJob* t : todo) kinds.push_back(t->settings.method);
  Progress progress(o.progress, kinds, "sweep " + plan.name, o.threads);
  std::atomic<std::size_t> succeeded{0}, errors{0};
  tbb::task_arena arena(o.threads);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, plan.instances.size(), [&](std::size_t i) {
      if (needed[i]) generated[i] = generate(plan.instances[i], dir / kInstancesDir, o);
    });
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, todo.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const TrialJob& t = *todo[k];
            const auto t0 = std::chrono::steady_clock::now();
            const TrialRecord r =
                run_one(plan, t, generated[t.instance], methods, provenance, o.checked);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            log.append(trial_row(r));
            const bool ok = is_success(r.outcome);
            const bool error = r.outcome.status == TrialStatus::kError;
            if (ok) ++succeeded;
            if (error) ++errors;
            progress.tick(kinds[k], seconds, ok, error);
          }
        },
        tbb::simple_partitioner());
  });
  progress.finish();
  summary.ran = todo.size();
  summary.succeeded = succeeded;
  summary.errors = errors;
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace rearm::experiment
