// Tests of docs/reactive.md §5 for the diffeomorphism, each against independent truth: finite
// differences, exact geometry of the model space, the determinant on a grid.
#include "reactive/diffeomorphism.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/distance.h"
#include "reactive/mapped_space.h"
#include "support/reactive_scenes.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

using test_support::random_free_point;
using test_support::random_scene;
using test_support::ReactiveScene;
using test_support::scaled;
using test_support::SceneOptions;
using test_support::to_semantic_input;

// Fourth-order central differences are taken at steps kFdFirstStep·2^-k, k < kFdSteps; the
// oracle keeps the step where two successive estimates agree best (its own error estimate,
// made without looking at the analytic derivatives): near sharp corners, where D²h reaches
// 10³ m⁻¹, no single fixed step is both above round-off and below truncation error.
constexpr double kFdFirstStep = 1e-3;
constexpr int kFdSteps = 12;
// Max relative error of Dh and D²h against differences.
constexpr double kMaxRelativeError = 1e-5;

struct Built {
  ReactiveScene scene;
  MappedSpace mapped;
  Diffeomorphism diffeo;
};

bool d_is_identity(const Diffeomorphism& d, const Point& x) { return d.map(x) == x; }

// The i-th scene of the property tests: square or L-shaped rooms, wide and tight margins
// (collars cut by neighbours), walls attached to the boundary, unknown and movable obstacles.
Built scene(int i) {
  Rng rng = Rng::derive(2024, static_cast<std::uint64_t>(i));
  SceneOptions o;
  o.familiar = 3 + i % 3;
  o.unknown = 2;
  o.movable = i % 2;
  o.margin = (i % 4 == 0) ? 2.0 : (i % 4 == 1 ? 0.6 : 0.3);
  o.boundary_touching = i % 3;
  o.workspace_shape =
      (i % 5 == 4) ? test_support::WorkspaceShape::kLRoom : test_support::WorkspaceShape::kSquare;
  ReactiveScene s = random_scene(rng, o);
  // The robot's start: the goal's freespace component is the one that matters.
  MappedSpace m = build_mapped_space(to_semantic_input(s), s.robot_radius, s.goal);
  Diffeomorphism d = Diffeomorphism::build(m);
  return Built{std::move(s), std::move(m), std::move(d)};
}

double frobenius(const std::array<Eigen::Matrix2d, 2>& H) {
  return std::sqrt(H[0].squaredNorm() + H[1].squaredNorm());
}

// Fourth-order central differences of h (→ Dh) and of Dh (→ D²h) at x with step s.
void differences(const Diffeomorphism& d, const Point& x, double step, Eigen::Matrix2d* J,
                 std::array<Eigen::Matrix2d, 2>* H) {
  for (int a = 0; a < 2; ++a) {
    Point s = Point::Zero();
    s[a] = step;
    const DiffeoEval p1 = d.evaluate(x + s), m1 = d.evaluate(x - s);
    const DiffeoEval p2 = d.evaluate(x + 2 * s), m2 = d.evaluate(x - 2 * s);
    J->col(a) = (8 * (p1.h - m1.h) - (p2.h - m2.h)) / (12 * step);
    for (int k = 0; k < 2; ++k) {
      (*H)[k].col(a) =
          ((8 * (p1.J.row(k) - m1.J.row(k)) - (p2.J.row(k) - m2.J.row(k))) / (12 * step))
              .transpose();
    }
  }
}

// Step-controlled differences: separately for Dh and D²h, the estimate whose change from the
// previous (twice larger) step is smallest.
void finite_differences(const Diffeomorphism& d, const Point& x, Eigen::Matrix2d* J,
                        std::array<Eigen::Matrix2d, 2>* H) {
  Eigen::Matrix2d prev_j = Eigen::Matrix2d::Zero();
  std::array<Eigen::Matrix2d, 2> prev_h{Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
  double best_j = std::numeric_limits<double>::infinity();
  double best_h = best_j;
  for (int k = 0; k < kFdSteps; ++k) {
    Eigen::Matrix2d j = Eigen::Matrix2d::Zero();
    std::array<Eigen::Matrix2d, 2> h{Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
    differences(d, x, kFdFirstStep * std::ldexp(1.0, -k), &j, &h);
    if (k > 0) {
      const double cj = (j - prev_j).norm();
      const double ch =
          std::sqrt((h[0] - prev_h[0]).squaredNorm() + (h[1] - prev_h[1]).squaredNorm());
      if (cj < best_j) {
        best_j = cj;
        *J = j;
      }
      if (ch < best_h) {
        best_h = ch;
        *H = h;
      }
    }
    prev_j = j;
    prev_h = h;
  }
}

// Distance from x to the boundary of the mapped freespace F_k (outer boundary and holes).
double freespace_clearance(const MappedSpace& m, const Point& x) {
  double c = geometry::nearest_on_boundary(m.freespace.outer, x).distance;
  for (const Polygon& h : m.freespace.holes) {
    c = std::min(c, geometry::nearest_on_boundary(h, x).distance);
  }
  return c;
}

TEST(Diffeomorphism, DerivativesMatchFiniteDifferences) {
  const int scenes = static_cast<int>(scaled(60, 3));
  const int points = 24;
  double worst_j = 0, worst_h = 0;
  int checked = 0, deformed = 0;
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    Rng rng = Rng::derive(99, static_cast<std::uint64_t>(i));
    for (int k = 0; k < points; ++k) {
      // Half the points near obstacles (inside collars), half anywhere in the freespace.
      Point x = random_free_point(rng, b.mapped, 1e-3);
      if (k % 2 == 0) {
        for (int t = 0; t < 200 && d_is_identity(b.diffeo, x); ++t) {
          x = random_free_point(rng, b.mapped, 1e-3);
        }
      }
      const DiffeoEval e = b.diffeo.evaluate(x);
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      std::array<Eigen::Matrix2d, 2> H{Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
      finite_differences(b.diffeo, x, &J, &H);
      const double ej = (J - e.J).norm() / e.J.norm();
      std::array<Eigen::Matrix2d, 2> diff{H[0] - e.H[0], H[1] - e.H[1]};
      // D²h is 0 away from collars; relative to max(‖D²h‖, 1 m⁻¹).
      const double eh = frobenius(diff) / std::max(frobenius(e.H), 1.0);
      EXPECT_LT(ej, kMaxRelativeError) << "scene " << i << " x " << x.transpose();
      EXPECT_LT(eh, kMaxRelativeError) << "scene " << i << " x " << x.transpose();
      worst_j = std::max(worst_j, ej);
      worst_h = std::max(worst_h, eh);
      deformed += (e.h - x).norm() > 0;
      ++checked;
    }
  }
  RecordProperty("points", checked);
  std::printf(
      "finite differences: %d points (%d deformed) over %d scenes, max rel. error Dh %.2e, "
      "D2h %.2e\n",
      checked, deformed, scenes, worst_j, worst_h);
  EXPECT_GT(deformed, checked / 3);
}

// The value-only and Jacobian-only evaluations (the safety filter's) compute h and Dh with the
// same operations as the full one, which the finite differences above check: bit for bit equal.
TEST(Diffeomorphism, LowerOrdersGiveTheSameValueAndJacobian) {
  const int scenes = static_cast<int>(scaled(30, 3));
  int deformed = 0;
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    Rng rng = Rng::derive(7, static_cast<std::uint64_t>(i));
    for (int k = 0; k < 24; ++k) {
      Point x = random_free_point(rng, b.mapped, 1e-3);
      for (int t = 0; t < 200 && d_is_identity(b.diffeo, x); ++t) {
        x = random_free_point(rng, b.mapped, 1e-3);  // a point in a collar
      }
      const DiffeoEval full = b.diffeo.evaluate(x);
      const DiffeoEval first = b.diffeo.evaluate(x, DiffeoOrder::kJacobian);
      const DiffeoEval value = b.diffeo.evaluate(x, DiffeoOrder::kValue);
      EXPECT_EQ(value.h, full.h) << "scene " << i << " x " << x.transpose();
      EXPECT_EQ(b.diffeo.map(x), full.h);
      EXPECT_EQ(first.h, full.h);
      EXPECT_EQ(first.J, full.J);
      EXPECT_EQ(value.J, Eigen::Matrix2d::Identity());  // not computed: the default
      EXPECT_EQ(first.H[0], Eigen::Matrix2d::Zero());
      deformed += full.h != x;
    }
  }
  EXPECT_GT(deformed, scenes * 12);
}

TEST(Diffeomorphism, DeterminantPositiveOnFreespaceGrid) {
  const int scenes = static_cast<int>(scaled(50, 2));
  const double spacing = test_support::test_scale() < 1 ? 0.5 : 0.1;
  long cells = 0;
  double min_det = std::numeric_limits<double>::infinity();
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    Eigen::AlignedBox2d box;
    for (const Point& v : b.mapped.enclosing.vertices) box.extend(v);
    for (double x = box.min().x() + spacing / 2; x < box.max().x(); x += spacing) {
      for (double y = box.min().y() + spacing / 2; y < box.max().y(); y += spacing) {
        const Point p(x, y);
        // Interior points of F_k (h is a diffeomorphism of the open freespace).
        if (!in_freespace(b.mapped, p) || freespace_clearance(b.mapped, p) < 1e-6) continue;
        const DiffeoEval e = b.diffeo.evaluate(p);
        ASSERT_TRUE(e.J.allFinite()) << "scene " << i << " at " << p.transpose();
        const double det = e.J.determinant();
        EXPECT_GT(det, 0) << "scene " << i << " at " << p.transpose();
        min_det = std::min(min_det, det);
        ++cells;
      }
    }
  }
  std::printf("det Dh > 0 on %ld grid points over %d scenes, min %.3e\n", cells, scenes, min_det);
  EXPECT_GT(cells, 1000);
}

// Distance from y to the boundary of a convex polygon's edge lines (0 on ∂F_e).
double distance_to_boundary(const Polygon& convex, const Point& y) {
  return geometry::nearest_on_boundary(convex, y).distance;
}

TEST(Diffeomorphism, ObstacleBoundariesMapOntoModelDisksOrWorkspaceBoundary) {
  const int scenes = static_cast<int>(scaled(50, 2));
  double worst = 0;
  int free_components = 0, pockets = 0;
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    for (std::size_t ci = 0; ci < b.mapped.familiar.size(); ++ci) {
      const FamiliarComponent& comp = b.mapped.familiar[ci];
      const Purge* root = nullptr;
      for (const Purge& p : b.diffeo.purges()) {
        if (p.component == static_cast<int>(ci) && p.parent < 0) root = &p;
      }
      ASSERT_NE(root, nullptr);
      (comp.lid ? pockets : free_components)++;
      if (!comp.lid) {
        // The model disk lies inside the obstacle it replaces.
        ASSERT_TRUE(geometry::contains(comp.polygon, root->center));
        EXPECT_LE(root->radius, geometry::nearest_on_boundary(comp.polygon, root->center).distance);
      }
      const Polygon& P = comp.polygon;
      for (std::size_t e = 0; e < P.size(); ++e) {
        const Point a = P.vertices[e], c = P.vertices[(e + 1) % P.size()];
        for (int k = 0; k <= 50; ++k) {
          const Point x = a + (c - a) * (k / 50.0);
          const Point y = b.diffeo.map(x);
          const double err = comp.lid ? distance_to_boundary(b.mapped.enclosing, y)
                                      : std::abs((y - root->center).norm() - root->radius);
          EXPECT_LT(err, 1e-9) << "scene " << i << " component " << ci << " at " << x.transpose();
          worst = std::max(worst, err);
        }
      }
    }
  }
  std::printf(
      "boundaries: %d free components onto disks, %d pockets onto the boundary, max "
      "error %.2e m\n",
      free_components, pockets, worst);
  EXPECT_GT(free_components, 0);
  EXPECT_GT(pockets, 0);
}

TEST(Diffeomorphism, IdentityOutsideCollarsAndFreespaceMapsIntoModelFreespace) {
  const int scenes = static_cast<int>(scaled(50, 2));
  int far = 0, mapped = 0;
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    const DiffeoParams& prm = b.diffeo.params();
    // Every collar lies within miter-limit·ε of its augmented piece, whose centre is within
    // the boundary-centre offset of the component: beyond that reach h must be the identity.
    const double reach = 2 * prm.epsilon + prm.boundary_center_offset;
    Rng rng = Rng::derive(7, static_cast<std::uint64_t>(i));
    const ModelSpace& model = b.diffeo.model();
    for (int k = 0; k < 200; ++k) {
      const Point x = random_free_point(rng, b.mapped, 1e-3);
      double dist = std::numeric_limits<double>::infinity();
      for (const FamiliarComponent& c : b.mapped.familiar) {
        dist = std::min(dist, geometry::distance(c.polygon, x));
      }
      const DiffeoEval e = b.diffeo.evaluate(x);
      if (dist > reach) {
        ++far;
        EXPECT_EQ(e.h, x);
        EXPECT_EQ(e.J, Eigen::Matrix2d::Identity());
        EXPECT_EQ(frobenius(e.H), 0.0);
      }
      // h(x) lies in the model freespace: inside F_e, outside every model disk and every
      // unknown obstacle.
      ++mapped;
      EXPECT_TRUE(geometry::contains(model.boundary, e.h)) << "scene " << i;
      for (const Disk& disk : model.disks) {
        EXPECT_GT((e.h - disk.center).norm(), disk.radius)
            << "scene " << i << " x " << x.transpose();
      }
      for (const Polygon& u : model.convex) {
        EXPECT_GT(geometry::distance(u, e.h), 0) << "scene " << i;
      }
    }
  }
  std::printf("identity checked at %d far points; %d images in the model freespace\n", far, mapped);
  EXPECT_GT(far, 100);
}

// The decomposition cache changes no result: the same scenes built with a shared cache (twice:
// the second time every component from it, then with a changed radius beside it) give the same
// purges and, at random free points, the same h, Dh and D²h bit for bit as a build without one.
TEST(Diffeomorphism, DecompositionCacheGivesTheSameMap) {
  DecompositionCache cache;
  const int scenes = static_cast<int>(scaled(12, 2));
  for (int i = 0; i < scenes; ++i) {
    const Built b = scene(i);
    for (int twice = 0; twice < 2; ++twice) {
      const Diffeomorphism cached = Diffeomorphism::build(b.mapped, {}, cache);
      ASSERT_EQ(cached.purges().size(), b.diffeo.purges().size()) << i;
      for (std::size_t k = 0; k < cached.purges().size(); ++k) {
        EXPECT_EQ(cached.purges()[k].center, b.diffeo.purges()[k].center) << i;
        EXPECT_EQ(cached.purges()[k].piece.vertices, b.diffeo.purges()[k].piece.vertices) << i;
      }
      Rng rng = Rng::derive(77, static_cast<std::uint64_t>(i));
      for (int k = 0; k < 20; ++k) {
        const Point x = random_free_point(rng, b.mapped, 1e-3);
        const DiffeoEval e = cached.evaluate(x), f = b.diffeo.evaluate(x);
        EXPECT_EQ(e.h, f.h) << i;
        EXPECT_EQ(e.J, f.J) << i;
        EXPECT_EQ(e.H[0], f.H[0]) << i;
        EXPECT_EQ(e.H[1], f.H[1]) << i;
      }
    }
  }
  EXPECT_GT(cache.size(), 0u);
  EXPECT_LE(cache.size(), kDecompositionCacheEntries);
}

}  // namespace
}  // namespace rearm::reactive
