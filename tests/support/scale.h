// Size of the property tests: REARM_TEST_SCALE (a positive number, default 1) multiplies the
// number of random cases. The sanitizer stage of scripts/test.sh runs at a small scale;
// the acceptance figures (e.g. 100,000 lasso checks) hold at scale 1.
#pragma once

#include <cstddef>

namespace rearm::test_support {

// The scale factor; an unset variable is 1, a malformed or non-positive one aborts the test
// run with a message (a typo must not silently shrink the tests).
double test_scale();

// max(minimum, round(n * test_scale())).
std::size_t scaled(std::size_t n, std::size_t minimum = 1);

}  // namespace rearm::test_support
