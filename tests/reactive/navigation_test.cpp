#include "reactive/navigation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/convex.h"
#include "reactive/kinematics.h"
#include "reactive/local_freespace.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

using Eigen::Matrix2d;
using geometry::Disk;
using geometry::Polygon;

constexpr double kPi = std::numbers::pi;

// An analytic nonlinear diffeomorphism of the plane, derivatives by hand:
//   h1 = x1 + a1 sin(b1 x2) + c1 sin(x1 + x2)
//   h2 = x2 + a2 sin(b2 x1) + c2 cos(x1 − x2)
// ‖Dh − I‖ is small enough that det Dh >= 0.7 everywhere.
struct WavyMap {
  double a1 = 0.2, b1 = 0.8, c1 = 0.1, a2 = 0.15, b2 = 0.9, c2 = 0.1;

  DiffeoEval operator()(const Point& x) const {
    const double s = x.x() + x.y();
    const double d = x.x() - x.y();
    DiffeoEval e;
    e.h = Point(x.x() + a1 * std::sin(b1 * x.y()) + c1 * std::sin(s),
                x.y() + a2 * std::sin(b2 * x.x()) + c2 * std::cos(d));
    e.J << 1 + c1 * std::cos(s), a1 * b1 * std::cos(b1 * x.y()) + c1 * std::cos(s),
        a2 * b2 * std::cos(b2 * x.x()) - c2 * std::sin(d), 1 + c2 * std::sin(d);
    e.H[0] << -c1 * std::sin(s), -c1 * std::sin(s), -c1 * std::sin(s),
        -a1 * b1 * b1 * std::sin(b1 * x.y()) - c1 * std::sin(s);
    e.H[1] << -a2 * b2 * b2 * std::sin(b2 * x.x()) - c2 * std::cos(d), c2 * std::cos(d),
        c2 * std::cos(d), -c2 * std::cos(d);
    return e;
  }
};

ModelSpace square_world(double half) {
  ModelSpace m;
  m.boundary =
      Polygon{{Point(-half, -half), Point(half, -half), Point(half, half), Point(-half, half)}};
  return m;
}

double clearance(const ModelSpace& m, const Point& y) {
  double c = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = m.boundary.size(); i < n; ++i) {
    const Point& a = m.boundary.vertices[i];
    const Point& b = m.boundary.vertices[(i + 1) % n];
    const Point t = b - a;
    c = std::min(c, (t.x() * (y - a).y() - t.y() * (y - a).x()) / t.norm());
  }
  for (const Disk& d : m.disks) c = std::min(c, (y - d.center).norm() - d.radius);
  return c;
}

// Disks in a square, pairwise gaps >= gap and >= gap from the walls (the separation the
// Arslan–Koditschek guarantee assumes).
ModelSpace random_disk_world(Rng& rng, double half, int count, double gap) {
  ModelSpace m = square_world(half);
  for (int tries = 0; static_cast<int>(m.disks.size()) < count && tries < 1000; ++tries) {
    const Disk d{Point(rng.uniform(-half, half), rng.uniform(-half, half)), rng.uniform(0.3, 1.2)};
    bool ok = clearance(m, d.center) >= d.radius + gap;
    for (const Disk& o : m.disks) {
      ok = ok && (d.center - o.center).norm() >= d.radius + o.radius + gap;
    }
    if (ok) m.disks.push_back(d);
  }
  return m;
}

Point random_free(Rng& rng, const ModelSpace& m, double half, double margin) {
  for (;;) {
    const Point y(rng.uniform(-half, half), rng.uniform(-half, half));
    if (clearance(m, y) > margin) return y;
  }
}

TEST(WavyMap, DerivativesMatchFiniteDifferences) {
  const WavyMap h;
  Rng rng(1);
  constexpr double kStep = 1e-6;
  for (int c = 0; c < 100; ++c) {
    const Point x(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const DiffeoEval e = h(x);
    EXPECT_GT(e.J.determinant(), 0.7);
    for (int j = 0; j < 2; ++j) {
      const Point dx = kStep * Point::Unit(j);
      const DiffeoEval ep = h(x + dx);
      const DiffeoEval em = h(x - dx);
      const Point dh = (ep.h - em.h) / (2 * kStep);
      const Matrix2d dJ = (ep.J - em.J) / (2 * kStep);
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(e.J(k, j), dh(k), 1e-8);
        for (int i = 0; i < 2; ++i) EXPECT_NEAR(e.H[k](i, j), dJ(k, i), 1e-8);
      }
    }
  }
}

NavParams unlimited() {
  NavParams p;
  p.v_max = 1e9;
  p.omega_max = 1e9;
  return p;
}

// The model-space target of the fully actuated law, from the parts tested elsewhere.
Point model_field(const ModelSpace& m, const Point& y, const Point& goal, const NavParams& p) {
  const Polygon lf = local_freespace(m, y, p.sensor_range, p.sensing_sides);
  return p.k * (geometry::project_onto_convex(lf, goal) - y);
}

TEST(FullyActuated, PulledBackFieldSatisfiesDhXdotEqualsU) {
  Rng rng(2);
  const WavyMap h;
  NavParams p = unlimited();
  p.k = 1.7;
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const ModelSpace m = random_disk_world(rng, 8, 6, 0.5);
    const Point goal = random_free(rng, m, 8, 0.1);
    DiffeoEval at;
    for (;;) {  // x with h(x) free
      at = h(Point(rng.uniform(-7, 7), rng.uniform(-7, 7)));
      if (clearance(m, at.h) > 1e-3) break;
    }
    const Point u = model_field(m, at.h, goal, p);
    const Point xdot = fully_actuated_velocity(m, at, goal, p);
    EXPECT_NEAR((at.J * xdot - u).norm(), 0.0, 1e-12 * (1 + u.norm())) << "case " << c;
    // Linear map h(x) = A x + b with A positive definite.
    DiffeoEval lin;
    const double s = rng.uniform(-0.5, 0.5);
    lin.J << rng.uniform(0.5, 2), s, s, rng.uniform(0.5, 2);
    lin.h = at.h;  // the same model point; only Dh changes
    const Point xl = fully_actuated_velocity(m, lin, goal, p);
    EXPECT_NEAR((lin.J * xl - u).norm(), 0.0, 1e-12 * (1 + u.norm()));
    // Saturation keeps the direction and caps the norm.
    NavParams slow = p;
    slow.v_max = 0.05;
    const Point xs = fully_actuated_velocity(m, at, goal, slow);
    EXPECT_LE(xs.norm(), slow.v_max * (1 + 1e-12));
    if (xdot.norm() > slow.v_max) {
      EXPECT_NEAR((xs - xdot * (slow.v_max / xdot.norm())).norm(), 0.0, 1e-12);
    } else {
      EXPECT_EQ(xs, xdot);
    }
  }
}

TEST(FullyActuated, ClosedLoopReachesGoalWithoutCollision) {
  Rng rng(3);
  NavParams p;
  const std::size_t worlds = test_support::scaled(12, 3);
  int reached = 0;
  int runs = 0;
  NavScratch scratch;
  for (std::size_t w = 0; w < worlds; ++w) {
    const ModelSpace m = random_disk_world(rng, 8, 8, 0.6);
    const Point goal = random_free(rng, m, 8, 0.3);
    for (int s = 0; s < 5; ++s, ++runs) {
      Point x = random_free(rng, m, 8, 0.05);
      double min_clear = clearance(m, x);
      bool done = false;
      for (int step = 0; step < 40000 && !done; ++step) {
        DiffeoEval at;  // identity diffeomorphism
        at.h = x;
        const Point v = fully_actuated_velocity(m, at, goal, p, scratch);
        ASSERT_TRUE(v.allFinite());
        ASSERT_LE(v.norm(), p.v_max * (1 + 1e-12));
        x = holonomic_step(x, v, kDefaultStep);
        min_clear = std::min(min_clear, clearance(m, x));
        ASSERT_GT(min_clear, 0.0) << "collision, world " << w << " start " << s;
        done = (x - goal).norm() < 1e-3;
      }
      EXPECT_TRUE(done) << "world " << w << " start " << s << " stopped at " << x.transpose();
      reached += done;
    }
  }
  EXPECT_EQ(reached, runs);
}

// ξ(x, ψ) = atan2(Dh(x) [cos ψ, sin ψ]).
double xi_of(const WavyMap& h, const Pose& q) {
  const Point e = h(q.x).J * Point(std::cos(q.psi), std::sin(q.psi));
  return std::atan2(e.y(), e.x());
}

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

TEST(Unicycle, HeadingRateFormulaMatchesFiniteDifferences) {
  // ξ̇ = ω det(Dh)/‖e‖² + v (e × D²h[t, t])/‖e‖², by central differences along the exact
  // unicycle motion (forward with (v, ω), backward with (−v, −ω)).
  Rng rng(4);
  const WavyMap h;
  constexpr double kDt = 1e-6;
  for (int c = 0; c < 200; ++c) {
    const Pose q{Point(rng.uniform(-5, 5), rng.uniform(-5, 5)), rng.uniform(-kPi, kPi)};
    const Twist u{rng.uniform(-1, 1), rng.uniform(-2, 2)};
    const Pose fwd = unicycle_step(q, u, kDt);
    const Pose bwd = unicycle_step(q, Twist{-u.v, -u.omega}, kDt);
    const double fd = std::remainder(xi_of(h, fwd) - xi_of(h, bwd), 2 * kPi) / (2 * kDt);
    const DiffeoEval e = h(q.x);
    const Point t(std::cos(q.psi), std::sin(q.psi));
    const Point ev = e.J * t;
    const Point beta(t.dot(e.H[0] * t), t.dot(e.H[1] * t));
    const double formula = (u.omega * e.J.determinant() + u.v * cross(ev, beta)) / ev.squaredNorm();
    EXPECT_NEAR(formula, fd, 1e-6) << "case " << c;
  }
}

TEST(Unicycle, CommandRealizesTheModelSpaceTargets) {
  // With the command applied, the model point moves as ẏ = k_v t_V e_ξ and its heading turns
  // as ξ̇ = k_ω t_W (reactive.md §4), checked by finite differences of h and ξ.
  Rng rng(5);
  const WavyMap h;
  NavParams p = unlimited();
  p.k_v = 0.7;
  p.k_omega = 1.3;
  constexpr double kDt = 1e-6;
  for (std::size_t c = 0, n = test_support::scaled(200, 20); c < n; ++c) {
    const ModelSpace m = random_disk_world(rng, 8, 6, 0.5);
    const Point goal = random_free(rng, m, 8, 0.1);
    Pose q;
    DiffeoEval at;
    for (;;) {
      q = Pose{Point(rng.uniform(-7, 7), rng.uniform(-7, 7)), rng.uniform(-kPi, kPi)};
      at = h(q.x);
      if (clearance(m, at.h) > 1e-2) break;
    }
    const Twist u = unicycle_command(m, at, q.psi, goal, p);
    ASSERT_TRUE(std::isfinite(u.v) && std::isfinite(u.omega));
    // Targets, recomputed here.
    const Polygon lf = local_freespace(m, at.h, p.sensor_range);
    const Point e = at.J * Point(std::cos(q.psi), std::sin(q.psi));
    const Point ex = e.normalized();
    const auto chord = geometry::line_interval(lf, at.h, ex);
    ASSERT_TRUE(chord.has_value());
    const double t_v = std::clamp((goal - at.h).dot(ex), chord->lo, chord->hi);
    const Point pga = geometry::project_onto_convex(lf, goal) - at.h;
    // Arslan–Koditschek's angular error: atan of the ratio (the nearer direction of the line).
    const double t_w = ex.dot(pga) != 0 ? std::atan(cross(ex, pga) / ex.dot(pga))
                                        : std::copysign(kPi / 2, cross(ex, pga));

    const Pose fwd = unicycle_step(q, u, kDt);
    const Pose bwd = unicycle_step(q, Twist{-u.v, -u.omega}, kDt);
    const Point ydot = (h(fwd.x).h - h(bwd.x).h) / (2 * kDt);
    const double xidot = std::remainder(xi_of(h, fwd) - xi_of(h, bwd), 2 * kPi) / (2 * kDt);
    EXPECT_NEAR((ydot - p.k_v * t_v * ex).norm(), 0.0, 1e-6) << "case " << c;
    EXPECT_NEAR(xidot, p.k_omega * t_w, 1e-5 * (1 + std::abs(u.omega))) << "case " << c;

    // Limits: the gains are reduced, never negated: v has the sign of t_V and |v| <= v_max; the
    // resulting ξ̇ = k t_W for some k in [0, k_ω] (the same sign as the unlimited turn), checked
    // by finite differences of the heading image like the unlimited case above.
    NavParams lim = p;
    lim.v_max = 0.1;
    lim.omega_max = 0.2;
    const Twist ul = unicycle_command(m, at, q.psi, goal, lim);
    EXPECT_LE(std::abs(ul.v), lim.v_max * (1 + 1e-12));
    EXPECT_LE(std::abs(ul.omega), lim.omega_max * (1 + 1e-12));
    EXPECT_GE(ul.v * t_v, 0.0);
    const Pose lf_fwd = unicycle_step(q, ul, kDt);
    const Pose lf_bwd = unicycle_step(q, Twist{-ul.v, -ul.omega}, kDt);
    const double xidot_l = std::remainder(xi_of(h, lf_fwd) - xi_of(h, lf_bwd), 2 * kPi) / (2 * kDt);
    EXPECT_GE(xidot_l * t_w, -1e-6) << "case " << c;
    EXPECT_LE(std::abs(xidot_l), p.k_omega * std::abs(t_w) + 1e-5) << "case " << c;
  }
}

TEST(Unicycle, ClosedLoopReachesGoalWithinLimits) {
  Rng rng(6);
  NavParams p;
  constexpr double kGoalTol = 0.05;
  const std::size_t worlds = test_support::scaled(10, 3);
  int reached = 0;
  int runs = 0;
  NavScratch scratch;
  for (std::size_t w = 0; w < worlds; ++w) {
    const ModelSpace m = random_disk_world(rng, 8, 8, 0.6);
    const Point goal = random_free(rng, m, 8, 0.3);
    for (int s = 0; s < 5; ++s, ++runs) {
      Pose pose{random_free(rng, m, 8, 0.05), rng.uniform(-kPi, kPi)};
      bool done = false;
      for (int step = 0; step < 60000 && !done; ++step) {
        DiffeoEval at;
        at.h = pose.x;
        const Twist u = unicycle_command(m, at, pose.psi, goal, p, scratch);
        ASSERT_TRUE(std::isfinite(u.v) && std::isfinite(u.omega));
        ASSERT_LE(std::abs(u.v), p.v_max * (1 + 1e-12));
        ASSERT_LE(std::abs(u.omega), p.omega_max * (1 + 1e-12));
        pose = unicycle_step(pose, u, kDefaultStep);
        ASSERT_GT(clearance(m, pose.x), 0.0) << "collision, world " << w << " start " << s;
        done = (pose.x - goal).norm() < kGoalTol;
      }
      EXPECT_TRUE(done) << "world " << w << " start " << s << " stopped at " << pose.x.transpose();
      reached += done;
    }
  }
  EXPECT_EQ(reached, runs);
}

TEST(Unicycle, AtTheGoalTheCommandIsZeroNotNan) {
  const ModelSpace m = square_world(5);
  DiffeoEval at;
  at.h = Point(1, 1);
  const Twist u = unicycle_command(m, at, 0.4, Point(1, 1), NavParams{});
  EXPECT_EQ(u.v, 0.0);
  EXPECT_EQ(u.omega, 0.0);
  EXPECT_EQ(fully_actuated_velocity(m, at, Point(1, 1), NavParams{}), Point(0, 0));
}

Matrix2d pair_t(double psi, double rho) {
  Matrix2d t;
  t << std::cos(psi), -rho * std::sin(psi), std::sin(psi), rho * std::cos(psi);
  return t;
}

TEST(Pair, CommandInvertsThePairKinematics) {
  Rng rng(7);
  const WavyMap h;
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const ModelSpace m = random_disk_world(rng, 8, 6, 0.5);
    const Point goal = random_free(rng, m, 8, 0.1);
    const double rho = rng.uniform(0.1, 0.6);
    Pose q;
    Point xc;
    DiffeoEval at;
    for (;;) {
      q = Pose{Point(rng.uniform(-7, 7), rng.uniform(-7, 7)), rng.uniform(-kPi, kPi)};
      xc = pair_center(q.x, q.psi, rho);
      at = h(xc);
      if (clearance(m, at.h) > 1e-3) break;
    }
    EXPECT_NEAR((xc - q.x).norm(), rho, 1e-12);
    EXPECT_NEAR((xc - q.x).normalized().dot(Point(std::cos(q.psi), std::sin(q.psi))), 1.0, 1e-12);
    const NavParams p = unlimited();
    const Point uc = at.J.inverse() * model_field(m, at.h, goal, p);
    const Twist u = pair_command(m, at, q.psi, rho, goal, p);
    EXPECT_NEAR((pair_t(q.psi, rho) * Eigen::Vector2d(u.v, u.omega) - uc).norm(), 0.0,
                1e-12 * (1 + uc.norm()))
        << "case " << c;
    // The pair centre moves along u_c over a tiny exact step.
    constexpr double kDt = 1e-7;
    const Pose next = unicycle_step(q, u, kDt);
    const Point moved = (pair_center(next.x, next.psi, rho) - xc) / kDt;
    EXPECT_NEAR((moved - uc).norm(), 0.0, 1e-5 * (1 + uc.norm()));
    // Limits by one common factor.
    NavParams lim;
    lim.v_max = 0.05;
    lim.omega_max = 0.1;
    const Twist ul = pair_command(m, at, q.psi, rho, goal, lim);
    EXPECT_LE(std::abs(ul.v), lim.v_max * (1 + 1e-12));
    EXPECT_LE(std::abs(ul.omega), lim.omega_max * (1 + 1e-12));
    EXPECT_NEAR(ul.v * u.omega - ul.omega * u.v, 0.0, 1e-9 * (1 + std::abs(u.v * u.omega)));
    EXPECT_GE(ul.v * u.v + ul.omega * u.omega, 0.0);
  }
}

TEST(Navigation, LimitCommonScalesBoth) {
  const Twist a = limit_common(Twist{2.0, 0.5}, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(a.v, 1.0);
  EXPECT_DOUBLE_EQ(a.omega, 0.25);
  const Twist b = limit_common(Twist{-0.5, -4.0}, 1.0, 2.0);
  EXPECT_DOUBLE_EQ(b.v, -0.25);
  EXPECT_DOUBLE_EQ(b.omega, -2.0);
  const Twist c = limit_common(Twist{0.3, 0.2}, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(c.v, 0.3);
  EXPECT_DOUBLE_EQ(c.omega, 0.2);
}

TEST(Navigation, RejectsBadInput) {
  const ModelSpace m = square_world(5);
  DiffeoEval at;
  at.h = Point(0, 0);
  const NavParams p;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DiffeoEval singular = at;
  singular.J = Matrix2d::Zero();
  EXPECT_THROW(fully_actuated_velocity(m, singular, Point(1, 1), p), Error);
  EXPECT_THROW(unicycle_command(m, singular, 0, Point(1, 1), p), Error);
  EXPECT_THROW(pair_command(m, singular, 0, 0.2, Point(1, 1), p), Error);
  singular.J << 1, 2, 2, 4;  // rank one
  EXPECT_THROW(unicycle_command(m, singular, 0, Point(1, 1), p), Error);
  DiffeoEval bad = at;
  bad.H[1](0, 1) = nan;
  EXPECT_THROW(unicycle_command(m, bad, 0, Point(1, 1), p), Error);
  bad = at;
  bad.h = Point(nan, 0);
  EXPECT_THROW(fully_actuated_velocity(m, bad, Point(1, 1), p), Error);
  EXPECT_THROW(fully_actuated_velocity(m, at, Point(nan, 1), p), Error);
  EXPECT_THROW(unicycle_command(m, at, nan, Point(1, 1), p), Error);
  EXPECT_THROW(pair_command(m, at, 0, 0.0, Point(1, 1), p), Error);
  EXPECT_THROW(pair_command(m, at, 0, -0.1, Point(1, 1), p), Error);
  EXPECT_THROW(pair_center(Point(0, 0), nan, 0.1), Error);
  DiffeoEval outside = at;
  outside.h = Point(6, 0);
  EXPECT_THROW(unicycle_command(m, outside, 0, Point(1, 1), p), Error);
  for (auto field : {&NavParams::k, &NavParams::k_v, &NavParams::k_omega, &NavParams::v_max,
                     &NavParams::omega_max, &NavParams::sensor_range}) {
    NavParams q;
    q.*field = 0;
    EXPECT_THROW(validate(q), Error);
    q.*field = nan;
    EXPECT_THROW(validate(q), Error);
    EXPECT_THROW(fully_actuated_velocity(m, at, Point(1, 1), q), Error);
  }
  NavParams q;
  q.sensing_sides = 2;
  EXPECT_THROW(validate(q), Error);
  q = NavParams{};
  q.singular_tolerance = -1;
  EXPECT_THROW(validate(q), Error);
  EXPECT_NO_THROW(validate(NavParams{}));
}

}  // namespace
}  // namespace rearm::reactive
