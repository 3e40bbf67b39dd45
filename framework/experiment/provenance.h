// Where a row came from: the source revision the binary was built from (baked in at build time
// by framework/experiment/revision.cmake, not read from whatever git checkout the user runs it
// in), the host and the CPU model.
#pragma once

#include <string>

#include "experiment/trial.h"

namespace rearm::experiment {

// `git describe --always --dirty` of the source tree when the binary was built ("+dirty" when
// files outside results/ had uncommitted changes), "unknown" when it was not built from a git
// checkout.
const char* build_revision();

// Host name (gethostname), "unknown" if it fails.
std::string host_name();
// The first "model name" of /proc/cpuinfo, "unknown" where there is none.
std::string cpu_model();

// The revision, host and CPU model (finished_utc is the runner's, per trial).
Provenance this_process();

// The current time, UTC, as "YYYY-MM-DDTHH:MM:SSZ".
std::string utc_now();

}  // namespace rearm::experiment
