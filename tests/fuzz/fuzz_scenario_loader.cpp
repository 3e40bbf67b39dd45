// Fuzz target: the scenario loader (scenario/scenario_io.h: YAML, every key's type and range,
// then validate's geometry) on any byte string. An accepted scenario written back with to_yaml
// parses again to a scenario that writes the same text (to_yaml promises a bit-exact round trip).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "scenario/scenario_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rearm;
  const std::string text(fuzz::as_text(data, size));
  std::string written;
  try {
    written = scenario::to_yaml(scenario::parse_scenario(text, "fuzz"));
  } catch (const Error& e) {
    fuzz::require_message(e.what());
    return 0;
  }
  std::string again;
  try {
    again = scenario::to_yaml(scenario::parse_scenario(written, "fuzz"));
  } catch (const Error& e) {
    fuzz::fuzz_require(false, "to_yaml's output loads again", written + "\n" + e.what());
  }
  fuzz::fuzz_require(again == written, "scenario write-read-write is a fixed point", written);
  return 0;
}
