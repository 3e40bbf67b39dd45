// Runs `spin -f` (Debian package `spin`, the reference translator of docs/symbolic.md
// "Correctness is tested against independent truth", item 2) on a formula and returns the
// never claim it prints.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ltl/formula.h"

namespace rearm::test_support {

// Wall-clock bound of one spin run: spin is slow on large formulas (docs/symbolic.md).
inline constexpr double kSpinTimeoutSeconds = 5.0;

// True when both `spin` and `timeout` (coreutils) are executables on PATH.
bool spin_installed();

struct SpinRun {
  enum class Status { kOk, kTimeout, kFailed };
  Status status = Status::kFailed;
  std::string never_claim;  // spin's standard output when kOk
  std::string diagnostics;  // spin's standard error, or why it could not run
  int exit_code = -1;
};

// Runs `timeout <bound> spin -f '<f printed with Syntax::Spin>'` in a fresh temporary
// directory (mkdtemp, removed afterwards) so concurrent runs never share spin's scratch
// files. kTimeout when the bound expired, kFailed when spin could not run or rejected the
// formula (e.g. X), kOk with the never claim otherwise. Thread-safe.
SpinRun run_spin(const ltl::Formula& f, double timeout_seconds = kSpinTimeoutSeconds);

// run_spin on every formula, `threads` runs at a time (0: std::thread::hardware_concurrency,
// at least 2); results in the order of `formulas`.
std::vector<SpinRun> run_spin_all(const std::vector<ltl::Formula>& formulas,
                                  double timeout_seconds = kSpinTimeoutSeconds,
                                  unsigned threads = 0);

// The never claim, or nullopt on timeout or failure.
std::optional<std::string> spin_never_claim(const ltl::Formula& f,
                                            double timeout_seconds = kSpinTimeoutSeconds);

}  // namespace rearm::test_support
