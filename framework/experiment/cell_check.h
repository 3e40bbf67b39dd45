// The cell check of a sweep (experiments/sweeps/README.md, "Refused cells"): before any trial
// runs, every instance of every cell is generated, and a cell is refused when one of its
// instances cannot be generated or misses the cell's target obstacle density by more than
// scenario::kDensityTolerance. A refused cell is never run with a silent shortfall: the sweep
// stops with the list, or (refused_cells: skip) runs without those cells and says which.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "experiment/generated_job.h"
#include "experiment/sweep_plan.h"

namespace rearm::experiment {

struct CellVerdict {
  std::size_t cell = 0;  // InstanceJob::cell
  std::string name;      // cell_name()
  bool refused = false;
  // For a refused cell: the first failing instance and why (generation error, or achieved
  // against target density); empty otherwise.
  std::string reason;
};

// The verdicts of the cells that `instances` belong to (every instance of each such cell must be
// among them), in cell order; generated on `threads` threads (the verdicts do not depend on it).
// `keep`: where the generated instances go, for the runner (SweepOptions::generated).
std::vector<CellVerdict> check_cells(const std::vector<InstanceJob>& instances, int threads,
                                     GeneratedJobs* keep = nullptr,
                                     const InstanceGenerators& generators = {});

// The instances of `full` whose cells the shard plan `part` touches: what a shard must check so
// that every shard refuses the same cells.
std::vector<InstanceJob> cells_touched(const SweepPlan& full, const SweepPlan& part);

// `plan` without the instances and trials of the refused cells (canonical indices kept).
SweepPlan without_cells(const SweepPlan& plan, const std::vector<CellVerdict>& verdicts);

// One line per refused cell: "<name>: <reason>".
std::string describe_refused(const std::vector<CellVerdict>& verdicts);

// CSV text "cell,name,verdict,reason" with a header, one row per verdict.
std::string verdicts_csv(const std::vector<CellVerdict>& verdicts);

}  // namespace rearm::experiment
