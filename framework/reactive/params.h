// Named parameters of the reactive layer (docs/reactive.md §3–4). Defaults follow the
// authors' public navigation code (vvasilo/semnav) where reactive.md gives them.
#pragma once

namespace rearm::reactive {

struct DiffeoParams {
  int p = 20;                           // R-conjunction exponent (§3.5); an even integer
  double epsilon = 1.0;                 // collar width ε (§3.4) and β-switch range (§3.6)
  double mu1 = 1.0;                     // β-switch sharpness μ1 (≈ ε²)
  double mu2 = 0.05;                    // γ-switch sharpness μ2
  double root_radius_fraction = 0.8;    // free root: ρ = 0.8·dist(c, ∂root) (§3.3)
  double boundary_center_offset = 0.3;  // boundary root: c this far beyond its lid edge (m)
  double sliver_area = 1e-6;            // pieces below this area (m²) are dropped (§3.1)
};

// Throws rearm::Error naming the first invalid parameter (odd p, non-positive or non-finite
// values, fraction outside (0, 1)).
void validate(const DiffeoParams& p);

}  // namespace rearm::reactive
