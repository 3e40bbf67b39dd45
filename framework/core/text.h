// Numbers in messages and notes, one spelling for the whole code base.
#pragma once

#include <string>

namespace rearm {

// v with `decimals` digits after the point: fixed(1.25, 3) == "1.250".
std::string fixed(double v, int decimals);
// v with `digits` significant digits, %g style: significant(0.000125, 3) == "0.000125",
// significant(1234567, 3) == "1.23e+06".
std::string significant(double v, int digits);

}  // namespace rearm
