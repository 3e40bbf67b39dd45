// A sweep's rows in OMPL's benchmark log format, so that Debian's `ompl_benchmark_statistics`
// (package ompl-demos) builds the SQLite database that Planner Arena plots: one log file per
// cell (class, N, target density, workspace, unknown fraction and shapes) — an "experiment"
// whose properties (objects, target_density, ...) become columns of the experiments table —
// with one "planner" per method and one run per trial. Each run has `time` (the method's
// compute: planning for the baselines, the whole online compute for rearm) and `solved` (the
// one success rule) as Planner Arena expects, the status as an enum, and the row's other
// measurements as properties.
#pragma once

#include <string>
#include <vector>

#include "experiment/csv.h"

namespace rearm::experiment {

// Writes DIR/<sweep>_<cell>.log for every cell of the table (rows of trial_columns(); a cell run
// at several budgets, methods NAME@K, gets one log per budget, <sweep>_<cell>_t<T>_q<Q>.log);
// returns the paths written, in cell order. `setup` is the sweep file's text (the experiment's
// setup). Throws rearm::Error for a table that lacks a trial column or a folder it cannot write.
std::vector<std::string> write_ompl_logs(const CsvTable& trials, const std::string& setup,
                                         const std::string& dir);

}  // namespace rearm::experiment
