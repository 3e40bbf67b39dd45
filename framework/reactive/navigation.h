// The model-space navigation law of Arslan & Koditschek (IJRR 2019) pulled back through the
// diffeomorphism h (docs/reactive.md §4; paper Appendix II and its reference [7]), for a fully
// actuated point, a differential-drive robot and the robot–object pair of a grasp.
//
// Every law works in the model space: y = h(x) is driven toward a projection of the goal
// y* = h(x*) onto the local freespace LF(y) (local_freespace.h), which keeps y inside the
// model freespace; the command is mapped back through Dh (and its second derivatives for the
// unicycle heading).
#pragma once

#include <string>

#include "core/error.h"
#include "geometry/polygon.h"
#include "reactive/diffeomorphism.h"
#include "reactive/kinematics.h"
#include "reactive/local_freespace.h"
#include "reactive/model_space.h"

namespace rearm::reactive {

// Gains, command limits and tolerances of the navigation laws. The defaults are rearm's
// choices (reactive.md leaves them open), sized for a ~0.2 m robot in a 10–20 m workspace.
struct NavParams {
  double k = 1.0;             // fully actuated gain (1/s): u = k (Π_LF(y*) − y)
  double k_v = 1.0;           // unicycle linear gain (1/s)
  double k_omega = 1.0;       // unicycle angular gain (1/s)
  double v_max = 0.4;         // linear speed limit (m/s), also the fully actuated norm limit
  double omega_max = 1.0;     // turn-rate limit (rad/s)
  double sensor_range = 3.0;  // R (m): LF is clipped to B(y, R/2)
  int sensing_sides = kSensingPolygonSides;  // sides of the polygon inscribed in B(y, R/2)
  // Dh counts as singular when |det Dh| <= singular_tolerance · ‖Dh‖_F² (scale-free; h is a
  // diffeomorphism away from sharp corners, so this only fires at or next to a corner).
  double singular_tolerance = 1e-9;
};

// Thrown by the laws when Dh is singular at the evaluation point (next to a sharp corner of a
// purged cluster): an expected outcome the interface layer can answer (the convex fallback of
// reactive_controller.h), unlike malformed input.
class SingularJacobian : public Error {
 public:
  explicit SingularJacobian(const std::string& what) : Error(what) {}
};

// Throws rearm::Error naming the first invalid field (non-finite, non-positive gains or
// limits, fewer than 3 sensing sides, a negative tolerance).
void validate(const NavParams& p);

// Reusable buffers for the local freespace (no allocation once warm).
struct NavScratch {
  geometry::Polygon lf;  // output too: LF(y) of the last command
  geometry::Polygon work;
  double t_w = 0;  // output: t_W of the last unicycle command
};

// Fully actuated law: ẋ = Dh⁻¹ · k (Π_LF(y)(y*) − y), y = at_x.h, with ‖ẋ‖ saturated to v_max.
// Reads h and Dh only (an evaluation at DiffeoOrder::kJacobian suffices; so for pair_command).
// Throws rearm::Error on non-finite inputs, a singular Dh, or y outside the model freespace.
Point fully_actuated_velocity(const ModelSpace& m, const DiffeoEval& at_x, const Point& y_goal,
                              const NavParams& p);
Point fully_actuated_velocity(const ModelSpace& m, const DiffeoEval& at_x, const Point& y_goal,
                              const NavParams& p, NavScratch& scratch);

// Differential-drive law (reactive.md §4). With t = [cos ψ, sin ψ], e = Dh t, ξ = atan2(e):
//   ẏ = v‖e‖ e_ξ,   ξ̇ = ω det(Dh)/‖e‖² + v (e × D²h[t, t])/‖e‖²,
// so v = k_v t_V/‖e‖ and ω = (k_ω t_W − v D)/(dξ/dψ) make ‖ẏ‖ = k_v t_V along e_ξ and
// ξ̇ = k_ω t_W, where t_V is the signed distance along e_ξ to the projection of y* onto
// LF ∩ (heading line) and t_W = atan(((Π_LF(y*) − y)·e_ξ⊥) / ((Π_LF(y*) − y)·e_ξ)) ∈
// [−π/2, π/2], Arslan & Koditschek's angular error (reactive.md writes atan2; atan lets the
// heading line turn the shorter way and the robot back up, with no jump at ±π). Limits: the gains
// are reduced, never made negative: v is clipped to ±v_max (k_v reduced), then k_ω is reduced to
// the largest value that keeps |ω| <= ω_max for that v; only when none exists are both scaled
// by one common factor. The robot thus keeps turning at full rate while its speed saturates
// (a common factor alone would stall the turn wherever ‖e‖ is small). Throws as
// fully_actuated_velocity.
Twist unicycle_command(const ModelSpace& m, const DiffeoEval& at_x, double psi, const Point& y_goal,
                       const NavParams& p);
Twist unicycle_command(const ModelSpace& m, const DiffeoEval& at_x, double psi, const Point& y_goal,
                       const NavParams& p, NavScratch& scratch);

// Centre of the robot–object pair disk: the object of radius ρ_i held in front of the robot,
// x_c = x + ρ_i [cos ψ, sin ψ]ᵀ.
Point pair_center(const Point& x, double psi, double rho_i);

// Gripper engaged (reactive.md §4): the pair centre x_c is controlled as a fully actuated
// point of radius r + ρ_i (at_xc is the pair's diffeomorphism evaluated at x_c). With u_c the
// fully actuated velocity before saturation, ẋ_c = T(ψ)[v, ω]ᵀ,
// T(ψ) = [[cos ψ, −ρ_i sin ψ], [sin ψ, ρ_i cos ψ]], so [v, ω] = T(ψ)⁻¹ u_c, then limited by
// the common factor λ. Throws as fully_actuated_velocity, and when ρ_i is not positive.
Twist pair_command(const ModelSpace& m, const DiffeoEval& at_xc, double psi, double rho_i,
                   const Point& y_goal, const NavParams& p);
Twist pair_command(const ModelSpace& m, const DiffeoEval& at_xc, double psi, double rho_i,
                   const Point& y_goal, const NavParams& p, NavScratch& scratch);

// Scales (v, ω) by λ = min(1, v_max/|v|, ω_max/|ω|).
Twist limit_common(const Twist& u, double v_max, double omega_max);

}  // namespace rearm::reactive
