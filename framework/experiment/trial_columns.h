// The columns of a sweep's CSV, one row per trial (experiments/sweeps/README.md lists them with
// their units). Numbers that decide nothing about timing are written in the shortest form that
// reads back bit for bit, so that two runs of the same trial give the same text in every
// column but the timing and provenance ones (is_timing_column). Not-applicable values (rearm's
// planning time, a baseline's compute split) are empty fields.
#pragma once

#include <string>
#include <vector>

#include "experiment/trial.h"

namespace rearm::experiment {

const std::vector<std::string>& trial_columns();
// The position of a column in trial_columns(); REARM_DEMANDs that it exists.
std::size_t trial_column(const std::string& name);
std::string trial_header();  // the CSV header line, without the newline
// The row of a record, without the newline; as many fields as trial_columns().
std::vector<std::string> trial_fields(const TrialRecord& r);
std::string trial_row(const TrialRecord& r);

// The names of rearm's recovery counts (executive::kRecoveryFields), in column order; also the
// keys of metrics.json's "recoveries".
std::vector<std::string> recovery_names();

// Columns that differ between runs of the same trial: wall-clock times, CPU time, host,
// CPU model and revision.
bool is_timing_column(const std::string& name);
// A column a log of an earlier version may lack (log_layout.h): the timing and provenance ones,
// and goal_order (added with the goal-order dimension; such a log's tasks were all chains).
bool may_be_missing(const std::string& name);

// The `key` column: 16 hex digits of FNV-1a 64 over resume_key(settings).
std::string key_column(const TrialSettings& s);

}  // namespace rearm::experiment
