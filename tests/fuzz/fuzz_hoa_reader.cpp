// Fuzz target: the HOA reader (ltl/automaton_io.h) on any byte string. An accepted automaton,
// written back as HOA, reads again to an automaton that writes the same text (the writer's
// output is a fixed point of read-then-write).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "ltl/automaton_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rearm;
  std::string written;
  try {
    written = ltl::to_hoa(ltl::read_hoa(fuzz::as_text(data, size)));
  } catch (const Error& e) {
    fuzz::require_message(e.what());
    return 0;
  }
  std::string again;
  try {
    again = ltl::to_hoa(ltl::read_hoa(written));
  } catch (const Error& e) {
    fuzz::fuzz_require(false, "the HOA writer's output reads again", written + "\n" + e.what());
  }
  fuzz::fuzz_require(again == written, "HOA read-then-write is a fixed point",
                     written + "\n" + again);
  return 0;
}
