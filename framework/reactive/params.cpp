#include "reactive/params.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace rearm::reactive {
namespace {

void positive(double v, const char* name) {
  REARM_REQUIRE(std::isfinite(v) && v > 0, "diffeomorphism parameter ", name,
                " must be finite and > 0, got ", v);
}

}  // namespace

void validate(const DiffeoParams& p) {
  // §3.5: a^p + b^p with negative a, b needs an even integer p (else NaN).
  REARM_REQUIRE(p.p >= 2 && p.p % 2 == 0,
                "diffeomorphism parameter p must be an even integer >= 2, got ", p.p);
  positive(p.epsilon, "epsilon");
  positive(p.mu1, "mu1");
  positive(p.mu2, "mu2");
  positive(p.boundary_center_offset, "boundary_center_offset");
  positive(p.sliver_area, "sliver_area");
  REARM_REQUIRE(p.root_radius_fraction > 0 && p.root_radius_fraction < 1,
                "diffeomorphism parameter root_radius_fraction must lie in (0, 1), got ",
                p.root_radius_fraction);
}

}  // namespace rearm::reactive
