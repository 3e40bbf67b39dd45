// Fuzz target: the sweep-file loader (scenario/sweep_file.h) on any byte string. An accepted
// file counts its trials without overflow (at most kMaxSweepTrials) and gives every N a room side
// in (0, kMaxSweepSide].
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "scenario/sweep_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rearm;
  try {
    const scenario::SweepFile sweep =
        scenario::parse_sweep_file(std::string(fuzz::as_text(data, size)), "fuzz");
    const std::size_t trials = sweep.trial_count();
    fuzz::fuzz_require(trials >= 1 && trials <= scenario::kMaxSweepTrials,
                       "an accepted sweep has between 1 and kMaxSweepTrials trials",
                       std::to_string(trials));
    for (int n : sweep.objects) {
      const double side = sweep.workspace.side_for(n, sweep.instance.object_radius);
      fuzz::fuzz_require(side > 0 && side <= scenario::kMaxSweepSide,
                         "the room side of an accepted sweep is in range", std::to_string(side));
    }
  } catch (const Error& e) {
    fuzz::require_message(e.what());
  }
  return 0;
}
