// Model-space navigation laws (see navigation.h).
#include "reactive/navigation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/error.h"
#include "geometry/convex.h"

namespace rearm::reactive {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

void positive(double v, const char* name) {
  REARM_REQUIRE(std::isfinite(v) && v > 0, "NavParams: ", name,
                " must be finite and positive, got ", v);
}

void check_inputs(const DiffeoEval& at, const Point& y_goal, const char* what) {
  if (!at.h.allFinite() || !at.J.allFinite() || !at.H[0].allFinite() || !at.H[1].allFinite()) {
    throw Error(std::string(what) + ": diffeomorphism value (h, Dh, D²h) is not finite");
  }
  if (!y_goal.allFinite()) throw Error(std::string(what) + ": goal is not finite");
}

void check_regular(const Eigen::Matrix2d& J, const NavParams& p, const char* what) {
  if (!(std::abs(J.determinant()) > p.singular_tolerance * J.squaredNorm())) {
    throw SingularJacobian(std::string(what) + ": Dh is singular at this point (a sharp corner?)");
  }
}

// u = k (Π_LF(y*) − y) in the model space.
Point model_velocity(const ModelSpace& m, const Point& y, const Point& y_goal, const NavParams& p,
                     NavScratch& s) {
  local_freespace(m, y, p.sensor_range, s.lf, s.work, p.sensing_sides);
  return p.k * (geometry::project_onto_convex(s.lf, y_goal) - y);
}

// Dh⁻¹ u without saturation.
Point pulled_back(const ModelSpace& m, const DiffeoEval& at, const Point& y_goal,
                  const NavParams& p, NavScratch& s, const char* what) {
  validate(p);
  check_inputs(at, y_goal, what);
  check_regular(at.J, p, what);
  const Point u = model_velocity(m, at.h, y_goal, p, s);
  return at.J.inverse() * u;
}

}  // namespace

void validate(const NavParams& p) {
  positive(p.k, "k");
  positive(p.k_v, "k_v");
  positive(p.k_omega, "k_omega");
  positive(p.v_max, "v_max");
  positive(p.omega_max, "omega_max");
  positive(p.sensor_range, "sensor_range");
  REARM_REQUIRE(p.sensing_sides >= 3, "NavParams: sensing_sides must be at least 3, got ",
                p.sensing_sides);
  REARM_REQUIRE(std::isfinite(p.singular_tolerance) && p.singular_tolerance >= 0,
                "NavParams: singular_tolerance must be finite and non-negative, got ",
                p.singular_tolerance);
}

Twist limit_common(const Twist& u, double v_max, double omega_max) {
  double lambda = 1;
  if (std::abs(u.v) > v_max) lambda = std::min(lambda, v_max / std::abs(u.v));
  if (std::abs(u.omega) > omega_max) lambda = std::min(lambda, omega_max / std::abs(u.omega));
  return Twist{lambda * u.v, lambda * u.omega};
}

Point fully_actuated_velocity(const ModelSpace& m, const DiffeoEval& at_x, const Point& y_goal,
                              const NavParams& p, NavScratch& scratch) {
  const Point xdot = pulled_back(m, at_x, y_goal, p, scratch, "fully_actuated_velocity");
  const double speed = xdot.norm();
  return speed > p.v_max ? Point(xdot * (p.v_max / speed)) : xdot;
}

Point fully_actuated_velocity(const ModelSpace& m, const DiffeoEval& at_x, const Point& y_goal,
                              const NavParams& p) {
  NavScratch scratch;
  return fully_actuated_velocity(m, at_x, y_goal, p, scratch);
}

Twist unicycle_command(const ModelSpace& m, const DiffeoEval& at_x, double psi, const Point& y_goal,
                       const NavParams& p, NavScratch& s) {
  constexpr const char* kWhat = "unicycle_command";
  validate(p);
  check_inputs(at_x, y_goal, kWhat);
  REARM_REQUIRE(std::isfinite(psi), "unicycle_command: heading is not finite, got ", psi);
  const Eigen::Matrix2d& J = at_x.J;
  check_regular(J, p, kWhat);

  const double c = std::cos(psi);
  const double sn = std::sin(psi);
  const Point t(c, sn);
  const Point e = J * t;
  const double e2 = e.squaredNorm();
  const double e_norm = std::sqrt(e2);
  const Point e_xi = e / e_norm;
  const Point e_perp(-e_xi.y(), e_xi.x());
  const Point& y = at_x.h;

  local_freespace(m, y, p.sensor_range, s.lf, s.work, p.sensing_sides);
  // Linear target: the goal projected on the chord LF ∩ {y + τ e_ξ} (y is inside LF, so the
  // chord contains τ = 0; a numerically missed line leaves the robot still).
  const std::optional<geometry::Interval> chord = geometry::line_interval(s.lf, y, e_xi);
  double t_v = 0;
  if (chord) {
    t_v = std::clamp((y_goal - y).dot(e_xi), std::min(chord->lo, 0.0), std::max(chord->hi, 0.0));
  }
  // Angular target: Π_LF(y*).
  const Point to_a = geometry::project_onto_convex(s.lf, y_goal) - y;
  // Arslan & Koditschek's angular law uses atan, not atan2: the heading line turns toward the
  // target in whichever direction is nearer (t_W ∈ [−π/2, π/2]) and the sign of v (from t_V)
  // decides forward or backward. With atan2, a target behind the robot makes t_W jump between
  // ±π, and the turn chatters in place where Dh is strongly anisotropic.
  const double along = to_a.dot(e_xi);
  const double across = to_a.dot(e_perp);
  const double t_w = along != 0 ? std::atan(across / along)
                                : (across > 0 ? kHalfPi : (across < 0 ? -kHalfPi : 0.0));
  s.t_w = t_w;

  const double dxi_dpsi = J.determinant() / e2;
  const double alpha1 = -e.y();  // −(Dh21 c + Dh22 s)
  const double alpha2 = e.x();   //   Dh11 c + Dh12 s
  const double beta1 = t.dot(at_x.H[0] * t);
  const double beta2 = t.dot(at_x.H[1] * t);
  const double d = (alpha1 * beta1 + alpha2 * beta2) / e2;

  // Limits (reactive.md §4: k_v and k_ω reduced so that |v| <= v_max, |ω| <= ω_max). Reducing
  // either gain keeps it positive, which is all the law's convergence needs; clipping ω by
  // itself would not be (it can flip the sign of the effective k_ω and leaves limit cycles).
  //  1. k_v: v is clipped to ±v_max (same sign: the model step stays on the chord).
  //  2. k_ω: the largest k in (0, k_ω] with |k t_W − v D| <= ω_max dξ/dψ, so the robot keeps
  //     turning at full rate while its speed saturates (where ‖e‖ is small the unclipped v is
  //     huge, and a common factor would stall the turn that leads out).
  //  3. If no such k exists (the compensation v D alone is too large), both are scaled by the
  //     common factor that brings ω to its limit.
  double v = std::clamp(p.k_v * t_v / e_norm, -p.v_max, p.v_max);
  const double lim = p.omega_max * dxi_dpsi;  // |k t_W − v D| <= lim
  const double vd = v * d;
  double k = p.k_omega;
  if (std::abs(k * t_w - vd) > lim) {
    double best = -1;
    if (t_w != 0) {
      double lo = (vd - lim) / t_w;
      double hi = (vd + lim) / t_w;
      if (lo > hi) std::swap(lo, hi);
      const double cand = std::min(p.k_omega, hi);
      if (cand > 0 && cand >= lo) best = cand;
    }
    if (best > 0) {
      k = best;
    } else {
      const double scale = lim / std::abs(p.k_omega * t_w - vd);
      v *= scale;
      k = p.k_omega * scale;
    }
  }
  const double omega = std::clamp((k * t_w - v * d) / dxi_dpsi, -p.omega_max, p.omega_max);
  return Twist{v, omega};
}

Twist unicycle_command(const ModelSpace& m, const DiffeoEval& at_x, double psi, const Point& y_goal,
                       const NavParams& p) {
  NavScratch scratch;
  return unicycle_command(m, at_x, psi, y_goal, p, scratch);
}

Point pair_center(const Point& x, double psi, double rho_i) {
  if (!x.allFinite() || !std::isfinite(psi) || !std::isfinite(rho_i)) {
    throw Error("pair_center: position, heading and radius must be finite");
  }
  return x + rho_i * Point(std::cos(psi), std::sin(psi));
}

Twist pair_command(const ModelSpace& m, const DiffeoEval& at_xc, double psi, double rho_i,
                   const Point& y_goal, const NavParams& p, NavScratch& s) {
  REARM_REQUIRE(std::isfinite(psi), "pair_command: heading is not finite, got ", psi);
  REARM_REQUIRE(std::isfinite(rho_i) && rho_i > 0,
                "pair_command: object radius rho_i must be finite and positive, got ", rho_i);
  const Point uc = pulled_back(m, at_xc, y_goal, p, s, "pair_command");
  // T(ψ)⁻¹ = (1/ρ_i) [[ρ_i cos ψ, ρ_i sin ψ], [−sin ψ, cos ψ]] (det T = ρ_i).
  const double c = std::cos(psi);
  const double sn = std::sin(psi);
  const Twist u{c * uc.x() + sn * uc.y(), (-sn * uc.x() + c * uc.y()) / rho_i};
  return limit_common(u, p.v_max, p.omega_max);
}

Twist pair_command(const ModelSpace& m, const DiffeoEval& at_xc, double psi, double rho_i,
                   const Point& y_goal, const NavParams& p) {
  NavScratch scratch;
  return pair_command(m, at_xc, psi, rho_i, y_goal, p, scratch);
}

}  // namespace rearm::reactive
