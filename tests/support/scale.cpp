#include "support/scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace rearm::test_support {

double test_scale() {
  const char* v = std::getenv("REARM_TEST_SCALE");
  if (v == nullptr || *v == '\0') return 1.0;
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (end == v || *end != '\0' || !std::isfinite(x) || x <= 0) {
    std::fprintf(stderr, "REARM_TEST_SCALE must be a positive number, got '%s'\n", v);
    std::exit(2);
  }
  return x;
}

std::size_t scaled(std::size_t n, std::size_t minimum) {
  return std::max(minimum, static_cast<std::size_t>(std::llround(n * test_scale())));
}

}  // namespace rearm::test_support
