// Shared by the fuzz targets (tests/fuzz/README.md): what counts as a finding. Bad input must end
// in a rearm::Error with a message; anything else (another exception, a REARM_DEMAND, a sanitizer
// report, a broken round trip checked with fuzz_require) aborts and is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"

namespace rearm::fuzz {

// The fuzzer's bytes as text (any byte, NUL included).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A property of accepted input that must hold: prints what broke and aborts (a finding).
inline void fuzz_require(bool holds, const char* property, const std::string& detail = {}) {
  if (holds) return;
  std::fprintf(stderr, "fuzz property broken: %s\n", property);
  std::fputs(detail.c_str(), stderr);
  std::fputs("\n", stderr);
  std::abort();
}

// A rearm::Error must say what is wrong: an empty message is a finding too.
inline void require_message(const char* what) {
  fuzz_require(what != nullptr && what[0] != '\0', "a rejection carries a message");
}

}  // namespace rearm::fuzz
