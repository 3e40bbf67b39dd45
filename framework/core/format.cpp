#include "core/format.h"

#include <charconv>
#include <system_error>

#include "core/error.h"

namespace rearm {

std::string shortest_decimal(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

}  // namespace rearm
