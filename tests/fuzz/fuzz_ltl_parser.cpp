// Fuzz target: the LTL parser (ltl/parser.h) on any byte string. An accepted formula prints in
// the Spot spelling to text that parses back to an equal tree, and in the spin spelling (no xor:
// a xor b is written !(a <-> b)) to text that parses back to a formula printing the same text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "ltl/parser.h"

namespace {

rearm::ltl::Formula reparse(const std::string& printed) {
  try {
    return rearm::ltl::parse(printed);
  } catch (const rearm::Error& e) {
    rearm::fuzz::fuzz_require(false, "a printed formula parses again", printed + "\n" + e.what());
  }
  return rearm::ltl::Formula::tt();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rearm;
  ltl::Formula f = ltl::Formula::tt();
  try {
    f = ltl::parse(fuzz::as_text(data, size));
  } catch (const Error& e) {
    fuzz::require_message(e.what());
    return 0;
  }
  const ltl::Formula spot = reparse(f.to_string(ltl::Syntax::Spot));
  fuzz::fuzz_require(spot == f, "the Spot spelling parses to an equal tree",
                     f.to_string(ltl::Syntax::Spot));
  const std::string spin = f.to_string(ltl::Syntax::Spin);
  fuzz::fuzz_require(reparse(spin).to_string(ltl::Syntax::Spin) == spin,
                     "the spin spelling parses to a formula with the same spelling", spin);
  return 0;
}
