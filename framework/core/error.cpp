#include "core/error.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rearm::detail {

void demand_failed(const char* condition, const char* file, int line, const std::string& message) {
  std::fprintf(stderr, "rearm: internal invariant violated at %s:%d: %s (%s)\n", file, line,
               condition, message.c_str());
  std::abort();
}

void append(std::string& s, double x) {
  if (std::isnan(x)) {
    s += "nan";
  } else if (std::isinf(x)) {
    s += x > 0 ? "inf" : "-inf";
  } else {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    s.append(buf, r.ptr);
  }
}

void append(std::string& s, long long x) { s += std::to_string(x); }
void append(std::string& s, unsigned long long x) { s += std::to_string(x); }

}  // namespace rearm::detail
