// The Monte Carlo runner (experiments/sweeps/README.md): a sweep plan's trials on oneTBB, one
// Box2D world per trial (each method's run builds its own), the immutable instances shared
// read-only, every row appended to DIR/trials.csv as soon as its trial ends (trial_log.h: an
// interruption loses no finished trial, a rerun skips the finished ones), every instance kept
// as DIR/instances/<name>.yaml (`rearm run` and `rearm baseline` reproduce any row), the sweep
// file itself kept as DIR/sweep.yaml. A trial that throws becomes an `error` row with its
// message and never stops the sweep.
//
// Two phases: the instances that still have unfinished trials are generated (in parallel),
// then the trials run (in parallel, the largest object counts first to shorten the tail). Rows
// are identical, timing columns aside, for any thread count and any shard, as long as no
// trial is cut by a wall-clock limit: the baselines' deterministic budget is the sweep file's
// query_limit, and a row that ends `timeout` (the time_limit safety net bound first) depends on
// the machine's speed and load.
#pragma once

#include <cstdio>
#include <string>

#include "experiment/method.h"
#include "experiment/sweep_plan.h"

namespace rearm::experiment {

struct SweepOptions {
  std::string out_dir;
  int threads = 1;  // in [1, 256]
  Shard shard;      // recorded in DIR/shard.txt; the plan given is already this shard's
  // The sweep file's text, kept as DIR/sweep.yaml; a rerun into a folder whose sweep.yaml
  // differs is refused (its rows belong to another sweep).
  std::string spec_text;
  // Resume a CSV whose rows came from another build revision (refused by default: rows of two
  // revisions would be pooled silently).
  bool resume_any_revision = false;
  // rearm's trials check the closed loop's invariants on every tick (MethodInput::checked).
  bool checked = false;
  std::FILE* progress = stderr;  // nullptr: silent
  // The cell check's verdicts (cell_check.h, verdicts_csv), written to DIR/cells.csv; empty:
  // not written.
  std::string cells_csv;
};

struct SweepSummary {
  std::size_t planned = 0;       // trials of this shard
  std::size_t already_done = 0;  // found complete in the CSV
  std::size_t ran = 0;
  std::size_t succeeded = 0;
  std::size_t errors = 0;
  bool dropped_torn_line = false;
  // Columns this version added that the folder's trial log lacked (TrialLog::added_columns).
  std::vector<std::string> added_columns;
  double wall_s = 0;
};

// Runs the plan's unfinished trials. Throws rearm::Error for an output folder it cannot use
// (unwritable, another sweep's, another revision's rows) before running anything.
SweepSummary run_sweep(const SweepPlan& plan, const MethodRegistry& methods,
                       const SweepOptions& options);

// The file names inside an output folder.
inline constexpr const char* kTrialsCsv = "trials.csv";
inline constexpr const char* kSweepCopy = "sweep.yaml";
inline constexpr const char* kShardFile = "shard.txt";
inline constexpr const char* kInstancesDir = "instances";
inline constexpr const char* kCellsCsv = "cells.csv";

}  // namespace rearm::experiment
