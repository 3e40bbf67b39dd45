// The purging diffeomorphism of docs/reactive.md §3 (Vasilopoulos & Koditschek, WAFR 2018;
// the paper's reference [7]), its per-tick evaluation: implicit functions (§3.5), switches
// (§3.6), deforming factors (§3.7) and one purge (§3.8), composed with first and second
// derivatives. The construction (§3.1–3.4) is in diffeo_trees.cpp (convex decompositions and
// trees) and diffeo_build.cpp (centres, collars, purges, build).
#include "reactive/diffeomorphism.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "reactive/pth_root.h"

namespace rearm::reactive {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using geometry::HalfPlane;

// Points within this distance (m) of a piece count as on its boundary (σ = 1). Without it,
// the rounding of β on the boundary (~1e-15) meets a vanishing σ_γ near the corners of the
// adjacency edge, where σ = σ_γσ_β / (σ_γσ_β + 1 − σ_β) is 0/0 in the limit.
constexpr double kBoundarySnap = 1e-12;

// A scalar function with gradient and Hessian at one point.
struct Scalar2 {
  double v = 0;
  Vector2d g = Vector2d::Zero();
  Matrix2d H = Matrix2d::Zero();
};

double ipow(double x, int k) {
  double r = 1;
  while (k > 0) {
    if (k & 1) r *= x;
    x *= x;
    k >>= 1;
  }
  return r;
}

// R-conjunction (§3.5) a ∧ b = a + b − (a^p + b^p)^{1/p} of inside-positive linear functions
// l_k(y) = offset_k − normal_k·y, folded left to right, with gradient and Hessian. Evaluated
// scaled by m = max(|a|, |b|) so that no power under- or overflows.
// R-conjunction of the negated half-plane values, to order O (the value alone, with the
// gradient, or with the Hessian too; the value and gradient are the same whichever).
template <DiffeoOrder O>
Scalar2 r_conjunction(const std::vector<HalfPlane>& planes, const Point& y, const PthRoot& root) {
  const int p = root.p();
  constexpr bool kGradient = O != DiffeoOrder::kValue;
  constexpr bool kHessian = O == DiffeoOrder::kHessian;
  Scalar2 acc;
  acc.v = -planes.front().value(y);
  if constexpr (kGradient) acc.g = -planes.front().normal;
  for (std::size_t k = 1; k < planes.size(); ++k) {
    const double b = -planes[k].value(y);
    const double a = acc.v;
    const double m = std::max(std::abs(a), std::abs(b));
    if (m == 0) {  // a corner point exactly: value 0, gradient of the sum (not differentiable)
      if constexpr (kGradient) acc.g += -planes[k].normal;
      continue;
    }
    // One of a/m, b/m is ±1 exactly, whose even power p − 2 is 1: only the other is raised.
    const bool a_is_max = std::abs(a) >= std::abs(b);
    const double as = a_is_max ? std::copysign(1.0, a) : a / m;
    const double bs = a_is_max ? b / m : std::copysign(1.0, b);
    const double ap2 = a_is_max ? 1.0 : ipow(as, p - 2);
    const double bp2 = a_is_max ? ipow(bs, p - 2) : 1.0;
    const double ap1 = ap2 * as, bp1 = bp2 * bs;
    const double s = ap1 * as + bp1 * bs;  // in [1, 2]
    const double t = root(s);
    if constexpr (kGradient) {
      const Vector2d bg = -planes[k].normal;
      const double t1 = t / s;  // s^{1/p − 1}
      const double ra = 1 - ap1 * t1;
      const double rb = 1 - bp1 * t1;
      if constexpr (kHessian) {
        const double t2 = t1 / s;  // s^{1/p − 2}
        const double c = (p - 1) / m;
        const double raa = c * (-ap2 * t1 + ap1 * ap1 * t2);
        const double rbb = c * (-bp2 * t1 + bp1 * bp1 * t2);
        const double rab = c * ap1 * bp1 * t2;
        const Matrix2d H = raa * acc.g * acc.g.transpose() +
                           rab * (acc.g * bg.transpose() + bg * acc.g.transpose()) +
                           rbb * bg * bg.transpose() + ra * acc.H;
        acc.H = H;
      }
      acc.g = ra * acc.g + rb * bg;
    }
    acc.v = a + b - m * t;
  }
  return acc;
}

// Is some half-plane's value at y at least eps (y that far outside one edge line)?
bool beyond_collar(const std::vector<HalfPlane>& planes, const Point& y, double eps) {
  return std::any_of(planes.begin(), planes.end(),
                     [&](const HalfPlane& h) { return h.value(y) >= eps; });
}

}  // namespace

namespace {

// The switch σ of one purge (§3.6) at y with its derivatives to order O, from β (negated: below
// zero inside the piece, 0 < β < ε in the collar) and γ > 0.
struct Switch {
  double sigma = 0;
  Vector2d d = Vector2d::Zero();
  Matrix2d dd = Matrix2d::Zero();
};

template <DiffeoOrder O>
Switch switch_of(const Purge& pu, const Point& y, const Scalar2& beta, const Scalar2& gamma,
                 const DiffeoParams& prm) {
  const double eps = prm.epsilon, mu1 = prm.mu1, mu2 = prm.mu2;
  // σ_β = exp(−μ1/(ε−β)) / exp(−μ1/ε); 1 − σ_β by expm1 to keep it accurate near β = 0.
  const double q = eps - beta.v;
  const double expo = -mu1 * beta.v / (eps * q);  // −μ1/(ε−β) + μ1/ε
  const double sb = std::exp(expo);
  const double one_minus_sb = -std::expm1(expo);
  // σ_γ = exp(−μ2/α), α = γ/‖y − c‖.
  const Vector2d w = y - pu.center;
  const double r = w.norm();
  const double alpha = gamma.v / r;
  const double sg = std::exp(-mu2 / alpha);
  // σ = σ_γσ_β / (σ_γσ_β + 1 − σ_β), with u = σ_γ, b = σ_β.
  const double u = sg, b = sb;
  const double den = u * b + one_minus_sb;
  Switch out;
  out.sigma = u * b / den;
  if constexpr (O == DiffeoOrder::kValue) return out;
  const double sb1 = -mu1 * sb / (q * q);
  const Vector2d gb = sb1 * beta.g;
  const Vector2d dr = w / r;
  const Vector2d dalpha = gamma.g / r - gamma.v * dr / (r * r);
  const double sg1 = mu2 * sg / (alpha * alpha);
  const Vector2d gg = sg1 * dalpha;
  const double su = b * one_minus_sb / (den * den);
  const double sbb_ = u / (den * den);
  out.d = su * gg + sbb_ * gb;
  if constexpr (O == DiffeoOrder::kHessian) {
    const double sb2 = sb * (mu1 * mu1 / (q * q * q * q) - 2 * mu1 / (q * q * q));
    const Matrix2d Hb = sb2 * beta.g * beta.g.transpose() + sb1 * beta.H;
    const Matrix2d ddr = (Matrix2d::Identity() - dr * dr.transpose()) / r;
    const Matrix2d ddalpha =
        gamma.H / r - (gamma.g * dr.transpose() + dr * gamma.g.transpose()) / (r * r) +
        2 * gamma.v * dr * dr.transpose() / (r * r * r) - gamma.v * ddr / (r * r);
    const double sg2 = sg * (mu2 * mu2 / std::pow(alpha, 4) - 2 * mu2 / std::pow(alpha, 3));
    const Matrix2d Hg = sg2 * dalpha * dalpha.transpose() + sg1 * ddalpha;
    const double suu = -2 * b * b * one_minus_sb / (den * den * den);
    const double sbb2 = -2 * u * (u - 1) / (den * den * den);
    const double sub =
        (1 - 2 * b) / (den * den) - 2 * b * one_minus_sb * (u - 1) / (den * den * den);
    out.dd = suu * gg * gg.transpose() + sub * (gg * gb.transpose() + gb * gg.transpose()) +
             sbb2 * gb * gb.transpose() + su * Hg + sbb_ * Hb;
  }
  return out;
}

// §3.7: the deforming factor ν (homogeneous of degree −1 in w = y − c) to order O.
struct Factor {
  double nu = 0;
  Vector2d d = Vector2d::Zero();
  Matrix2d dd = Matrix2d::Zero();
};

template <DiffeoOrder O>
Factor factor_of(const Purge& pu, const Vector2d& w) {
  Factor out;
  if (pu.kind == Purge::Kind::kDiskRoot) {
    const double r = w.norm();
    out.nu = pu.radius / r;
    if constexpr (O != DiffeoOrder::kValue) out.d = -pu.radius * w / (r * r * r);
    if constexpr (O == DiffeoOrder::kHessian) {
      out.dd = 3 * pu.radius * w * w.transpose() / std::pow(r, 5) -
               pu.radius / (r * r * r) * Matrix2d::Identity();
    }
  } else {
    const Vector2d t = (pu.v1 - pu.v0).normalized();
    const Vector2d n(-t.y(), t.x());
    const double num = (pu.v0 - pu.center).dot(n);
    const double den = w.dot(n);
    out.nu = num / den;
    if constexpr (O != DiffeoOrder::kValue) out.d = -num / (den * den) * n;
    if constexpr (O == DiffeoOrder::kHessian)
      out.dd = 2 * num / (den * den * den) * n * n.transpose();
  }
  return out;
}

// §3.8: h_i(y) = y + f(y)(y − c), f = σ(ν − 1), composed onto `out` (h, Dh and D²h of the
// purges before it) by the chain rule, to order O.
template <DiffeoOrder O>
void compose(DiffeoEval& out, const Vector2d& w, const Switch& sw, const Factor& fa) {
  const double f = sw.sigma * (fa.nu - 1);
  if constexpr (O != DiffeoOrder::kValue) {
    const Vector2d df = (fa.nu - 1) * sw.d + sw.sigma * fa.d;
    const Matrix2d Ji = (1 + f) * Matrix2d::Identity() + w * df.transpose();
    if constexpr (O == DiffeoOrder::kHessian) {
      const Matrix2d ddf = (fa.nu - 1) * sw.dd + sw.d * fa.d.transpose() + fa.d * sw.d.transpose() +
                           sw.sigma * fa.dd;
      std::array<Matrix2d, 2> Hi;
      for (int k = 0; k < 2; ++k) {
        Hi[k] = w[k] * ddf;
        Hi[k].row(k) += df.transpose();
        Hi[k].col(k) += df;
      }
      // Chain rule: D²(h_i ∘ g)[k] = Jgᵀ Hi[k] Jg + Σ_a Ji(k, a) Hg[a].
      std::array<Matrix2d, 2> H;
      for (int k = 0; k < 2; ++k) {
        H[k] = out.J.transpose() * Hi[k] * out.J + Ji(k, 0) * out.H[0] + Ji(k, 1) * out.H[1];
      }
      out.H = H;
    }
    out.J = Ji * out.J;
  }
  out.h = out.h + f * w;
}

template <DiffeoOrder O>
DiffeoEval evaluate_to(const std::vector<Purge>& purges, const DiffeoParams& prm,
                       const PthRoot& root, const Point& x, std::size_t count) {
  DiffeoEval out;
  out.h = x;
  count = std::min(count, purges.size());
  for (std::size_t index = 0; index < count; ++index) {
    const Purge& pu = purges[index];
    const Point y = out.h;
    if (!pu.collar_box.contains(y)) continue;  // identity outside the collar (σ = 0)
    // The R-conjunction lies below each of its arguments (a + b − ‖(a, b)‖_p <= min(a, b)), so
    // β >= max_i of the half-plane values: at least ε there, and σ_β = 0 without evaluating it.
    if (beyond_collar(pu.beta_planes, y, prm.epsilon)) continue;
    // §3.5–3.6: β (negative inside the piece) and its switch.
    Scalar2 beta = r_conjunction<O>(pu.beta_planes, y, root);
    beta.v = -beta.v;
    beta.g = -beta.g;
    beta.H = -beta.H;
    if (beta.v >= prm.epsilon) continue;
    Switch sw;
    if (beta.v <= kBoundarySnap) {
      sw.sigma = 1;  // on or inside the piece: fully purged (its interior is not freespace)
    } else {
      const Scalar2 gamma = r_conjunction<O>(pu.gamma_planes, y, root);
      if (gamma.v <= 0) continue;
      sw = switch_of<O>(pu, y, beta, gamma, prm);
    }
    const Vector2d w = y - pu.center;
    compose<O>(out, w, sw, factor_of<O>(pu, w));
  }
  return out;
}

}  // namespace

DiffeoEval Diffeomorphism::evaluate(const Point& x, std::size_t count, DiffeoOrder order) const {
  // A default-constructed Diffeomorphism (no purges) has no table yet.
  const PthRoot& root = root_ ? *root_ : PthRoot::of(params_.p);
  switch (order) {
    case DiffeoOrder::kValue:
      return evaluate_to<DiffeoOrder::kValue>(purges_, params_, root, x, count);
    case DiffeoOrder::kJacobian:
      return evaluate_to<DiffeoOrder::kJacobian>(purges_, params_, root, x, count);
    case DiffeoOrder::kHessian:
      break;
  }
  return evaluate_to<DiffeoOrder::kHessian>(purges_, params_, root, x, count);
}

}  // namespace rearm::reactive
