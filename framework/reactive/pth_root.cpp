#include "reactive/pth_root.h"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "core/error.h"

namespace rearm::reactive {

PthRoot::PthRoot(int p) : p_(p) {
  REARM_REQUIRE(p >= 2 && p % 2 == 0, "PthRoot: p must be an even integer >= 2, got ", p);
  // Binomial series (1 + d)^a = Σ binom(a, k) d^k, a = 1/p, in long double.
  const long double a = 1.0L / p;
  long double ck = 1;
  for (int k = 1; k <= kTerms; ++k) {
    ck *= (a - (k - 1)) / k;
    c_[k - 1] = static_cast<double>(ck);
  }
  for (int i = 0; i <= kKnots; ++i) {
    const long double s = 1.0L + static_cast<long double>(i) / kKnots;
    const long double t = std::pow(s, a);
    hi_[i] = static_cast<double>(t);
    lo_[i] = static_cast<double>(t - hi_[i]);
    inv_[i] = static_cast<double>(1.0L / s);
  }
}

const PthRoot& PthRoot::of(int p) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const PthRoot>> tables;
  const std::lock_guard lock(mutex);
  auto& slot = tables[p];
  if (!slot) slot = std::make_unique<const PthRoot>(p);
  return *slot;
}

double PthRoot::slow(double s) const { return std::pow(s, 1.0 / p_); }

}  // namespace rearm::reactive
