#include "experiment/cell_check.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstdio>
#include <map>

#include "experiment/csv.h"
#include "scenario/random_instance.h"

namespace rearm::experiment {
namespace {

// Why one generated instance makes its cell refused, or "" when it does not.
std::string instance_problem(const InstanceJob& job, const GeneratedJob& g) {
  const std::string who =
      "instance r" + std::to_string(job.rep) + " (seed " + std::to_string(job.spec.seed) + ")";
  if (!g.instance) return who + " cannot be generated: " + g.error;
  if (g.instance->density_reached) return "";
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%s reached obstacle density %.3f, target %.3f +- %.2f (after %d redraws)",
                who.c_str(), g.instance->achieved_density, job.spec.obstacle_density,
                scenario::kDensityTolerance, scenario::kMaxRedraws);
  return buf;
}

}  // namespace

std::vector<CellVerdict> check_cells(const std::vector<InstanceJob>& instances, int threads,
                                     GeneratedJobs* keep, const InstanceGenerators& generators) {
  std::vector<std::string> problems(instances.size());
  std::vector<GeneratedJob> generated(instances.size());
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, instances.size(), [&](std::size_t i) {
      generated[i] = generate_job(instances[i], generators);
      problems[i] = instance_problem(instances[i], generated[i]);
    });
  });
  if (keep != nullptr) {
    for (std::size_t i = 0; i < instances.size(); ++i)
      (*keep)[instances[i].index] = std::move(generated[i]);
  }
  std::map<std::size_t, CellVerdict> cells;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    CellVerdict& v = cells[instances[i].cell];
    if (v.name.empty()) {
      v.cell = instances[i].cell;
      v.name = cell_name(instances[i]);
    }
    // The first failing instance in rep order names the reason (independent of threads).
    if (!problems[i].empty() && !v.refused) {
      v.refused = true;
      v.reason = problems[i];
    }
  }
  std::vector<CellVerdict> out;
  for (auto& [cell, v] : cells) out.push_back(std::move(v));
  return out;
}

std::vector<InstanceJob> cells_touched(const SweepPlan& full, const SweepPlan& part) {
  std::vector<char> touched(full.instances.size() + 1, 0);
  for (const InstanceJob& job : part.instances) touched[job.cell] = 1;
  std::vector<InstanceJob> out;
  for (const InstanceJob& job : full.instances) {
    if (touched[job.cell]) out.push_back(job);
  }
  return out;
}

SweepPlan without_cells(const SweepPlan& plan, const std::vector<CellVerdict>& verdicts) {
  std::map<std::size_t, bool> refused;
  for (const CellVerdict& v : verdicts) refused[v.cell] = v.refused;
  return subset_of(plan, [&](const InstanceJob& job) {
    const auto it = refused.find(job.cell);
    return it == refused.end() || !it->second;
  });
}

std::string describe_refused(const std::vector<CellVerdict>& verdicts) {
  std::string text;
  for (const CellVerdict& v : verdicts) {
    if (v.refused) text += "  " + v.name + ": " + v.reason + "\n";
  }
  return text;
}

std::string verdicts_csv(const std::vector<CellVerdict>& verdicts) {
  std::string text = "cell,name,verdict,reason\n";
  for (const CellVerdict& v : verdicts) {
    text += std::to_string(v.cell) + "," + csv_field(v.name) + "," +
            (v.refused ? "refused" : "accepted") + "," + csv_field(v.reason) + "\n";
  }
  return text;
}

}  // namespace rearm::experiment
