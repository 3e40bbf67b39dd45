// Joining the output folders of a sweep's shards (or of interrupted runs) into one: every
// folder must hold the same sweep file; rows are united by their `key` (a trial run in two
// folders appears once — its two rows must agree in every column but the timing ones, else
// the merge is refused naming the trial), sorted by trial index, and written with the instance
// files to the output folder. A folder's cut last line (an interrupted shard) is dropped.
#pragma once

#include <string>
#include <vector>

#include "experiment/method.h"

namespace rearm::experiment {

struct MergeSummary {
  std::size_t rows = 0;          // in the merged CSV
  std::size_t duplicates = 0;    // identical trials found in more than one folder
  std::size_t total_trials = 0;  // of the whole sweep (its file)
  std::size_t dropped_torn = 0;  // folders whose cut last line was dropped
};

// Throws rearm::Error naming the folder for a folder without sweep.yaml or trials.csv, sweep
// files that differ, a damaged CSV, or conflicting rows for one trial. `methods` tells which of
// the sweep's methods follow the task's order (the total counts them once per goal order).
MergeSummary merge_sweeps(const std::vector<std::string>& dirs, const std::string& out_dir,
                          const MethodRegistry& methods);

}  // namespace rearm::experiment
