#include "core/error.h"

#include <cstdio>
#include <cstdlib>

namespace rearm::detail {

void demand_failed(const char* condition, const char* file, int line, const std::string& message) {
  std::fprintf(stderr, "rearm: internal invariant violated at %s:%d: %s (%s)\n", file, line,
               condition, message.c_str());
  std::abort();
}

}  // namespace rearm::detail
