// Numbers as text for messages and files.
#pragma once

#include <string>

namespace rearm {

// The shortest decimal that reads back to x (std::to_chars; "nan", "inf" as they are).
std::string shortest_decimal(double x);

}  // namespace rearm
