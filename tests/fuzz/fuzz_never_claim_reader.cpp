// Fuzz target: the never-claim reader (ltl/automaton_io.h) on any byte string. An accepted
// automaton, written back as a never claim, reads again to an automaton that writes the same
// claim: read-then-write is a fixed point up to comments (the writer's comments carry the names
// the first text gave the states, e.g. accept_all, which the writer's own labels replace), with
// the propositions in the first reading's order (a claim does not declare them: a second reading
// into a fresh alphabet orders them by first occurrence, and writes b && c as c && b).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "ltl/automaton_io.h"

namespace {

// The claim without its /* ... */ comments and the blanks before them.
std::string without_comments(const std::string& claim) {
  std::string out;
  for (std::size_t i = 0; i < claim.size(); ++i) {
    if (claim.compare(i, 2, "/*") == 0) {
      const std::size_t end = claim.find("*/", i + 2);
      if (end == std::string::npos) break;
      while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
      i = end + 1;
    } else {
      out += claim[i];
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rearm;
  std::string written;
  ltl::GeneralAlphabet alphabet;
  try {
    const ltl::GeneralNba first = ltl::read_never_claim(fuzz::as_text(data, size));
    alphabet = first.alphabet;
    written = ltl::to_never_claim(first);
  } catch (const Error& e) {
    fuzz::require_message(e.what());
    return 0;
  }
  std::string again;
  try {
    again = ltl::to_never_claim(ltl::read_never_claim(written, alphabet));
  } catch (const Error& e) {
    fuzz::fuzz_require(false, "the never-claim writer's output reads again",
                       written + "\n" + e.what());
  }
  fuzz::fuzz_require(without_comments(again) == without_comments(written),
                     "never-claim read-then-write is a fixed point", written + "\n" + again);
  return 0;
}
