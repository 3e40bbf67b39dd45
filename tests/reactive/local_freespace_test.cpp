#include "reactive/local_freespace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/convex.h"
#include "support/scale.h"

namespace rearm::reactive {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Convex CCW polygon: sorted random angles on a circle of radius r around c.
Polygon random_convex(Rng& rng, int n, const Point& c, double r) {
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0, 2 * kPi));
  std::sort(angles.begin(), angles.end());
  Polygon p;
  for (double a : angles) p.vertices.push_back(c + r * Point(std::cos(a), std::sin(a)));
  return p;
}

// Independent nearest point on a polygon's boundary (plain loops).
Point nearest_boundary_point(const Polygon& p, const Point& y) {
  Point best = p.vertices.front();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const double t = std::clamp((y - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    const Point q = a + t * (b - a);
    if ((q - y).norm() < (best - y).norm()) best = q;
  }
  return best;
}

// Signed distance outside a CCW convex polygon's edge lines (max over edges; > 0 outside).
double max_outside(const Polygon& p, const Point& q) {
  double m = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    m = std::max(m, -cross(b - a, q - a) / (b - a).norm());
  }
  return m;
}

struct World {
  ModelSpace m;
  Point y;
  double range = 0;
};

// Every constraint of LF(y), computed here from its definition (reactive.md §4); all obstacles
// are included (the library may skip far ones). Returns the largest violation (> 0: outside).
double constraint_violation(const World& w, const Point& q, int sides) {
  const Point& y = w.y;
  double worst = -std::numeric_limits<double>::infinity();
  const auto bisector = [&](const Point& p) {
    const double d = (p - y).norm();
    worst = std::max(worst, (q - y).dot((p - y) / d) - d / 2);
  };
  for (const Disk& dk : w.m.disks) {
    bisector(dk.center + dk.radius * (y - dk.center).normalized());
  }
  for (const Polygon& c : w.m.convex) bisector(nearest_boundary_point(c, y));
  bisector(nearest_boundary_point(w.m.boundary, y));
  worst = std::max(worst, max_outside(w.m.boundary, q));
  // Inscribed regular polygon of B(y, R/2): apothem (R/2)cos(π/n) along each edge normal at
  // angle (2k + 1)π/n.
  const double apothem = 0.5 * w.range * std::cos(kPi / sides);
  for (int k = 0; k < sides; ++k) {
    const double a = (2 * k + 1) * kPi / sides;
    worst = std::max(worst, (q - y).dot(Point(std::cos(a), std::sin(a))) - apothem);
  }
  return worst;
}

bool free_point(const ModelSpace& m, const Point& y, double clearance) {
  if (max_outside(m.boundary, y) > -clearance) return false;
  for (const Disk& d : m.disks) {
    if ((y - d.center).norm() < d.radius + clearance) return false;
  }
  for (const Polygon& c : m.convex) {
    if (max_outside(c, y) < clearance) return false;
  }
  return true;
}

World random_world(Rng& rng) {
  World w;
  w.m.boundary = random_convex(rng, 5 + static_cast<int>(rng.index(6)), Point(0, 0), 6);
  const int disks = static_cast<int>(rng.index(8));
  for (int i = 0; i < disks; ++i) {
    w.m.disks.push_back({Point(rng.uniform(-4, 4), rng.uniform(-4, 4)), rng.uniform(0.2, 1.2)});
  }
  const int polys = static_cast<int>(rng.index(5));
  for (int i = 0; i < polys; ++i) {
    w.m.convex.push_back(random_convex(rng, 3 + static_cast<int>(rng.index(5)),
                                       Point(rng.uniform(-4, 4), rng.uniform(-4, 4)),
                                       rng.uniform(0.3, 1.2)));
  }
  w.range = rng.uniform(1.0, 8.0);
  do {
    w.y = Point(rng.uniform(-6, 6), rng.uniform(-6, 6));
  } while (!free_point(w.m, w.y, 1e-3));
  return w;
}

TEST(LocalFreespace, SatisfiesEveryConstraintAndContainsY) {
  Rng rng(31);
  for (std::size_t c = 0, n = test_support::scaled(500, 50); c < n; ++c) {
    const World w = random_world(rng);
    const Polygon lf = local_freespace(w.m, w.y, w.range);
    ASSERT_GE(lf.size(), 3u) << "case " << c;
    EXPECT_GT(lf.signed_area(), 0);
    for (const Point& v : lf.vertices) {
      EXPECT_LE(constraint_violation(w, v, kSensingPolygonSides), kTol) << "case " << c;
      EXPECT_LE((v - w.y).norm(), 0.5 * w.range + kTol);  // ⊆ B(y, R/2)
      EXPECT_LE(max_outside(w.m.boundary, v), kTol);      // ⊆ F_e
    }
    EXPECT_LT(max_outside(lf, w.y), 0.0) << "y in the interior of LF, case " << c;
  }
}

TEST(LocalFreespace, ContainsNoObstaclePoint) {
  Rng rng(32);
  for (std::size_t c = 0, n = test_support::scaled(200, 20); c < n; ++c) {
    const World w = random_world(rng);
    const Polygon lf = local_freespace(w.m, w.y, w.range);
    // Dense samples of each disk (boundary and interior) and of each convex obstacle.
    for (const Disk& d : w.m.disks) {
      for (int i = 0; i < 64; ++i) {
        for (double s : {0.25, 0.5, 0.75, 1.0}) {
          const double a = 2 * kPi * i / 64;
          const Point q = d.center + s * d.radius * Point(std::cos(a), std::sin(a));
          EXPECT_GT(max_outside(lf, q), 0.0) << "case " << c;
        }
      }
    }
    for (const Polygon& o : w.m.convex) {
      const Point ctr = o.centroid();
      for (std::size_t i = 0; i < o.size(); ++i) {
        const Point& a = o.vertices[i];
        const Point& b = o.vertices[(i + 1) % o.size()];
        for (int k = 0; k < 20; ++k) {
          const Point e = a + (b - a) * (k / 20.0);
          for (double s : {0.0, 0.5, 1.0}) {
            EXPECT_GT(max_outside(lf, e + s * (ctr - e)), 0.0) << "case " << c;
          }
        }
      }
    }
  }
}

TEST(LocalFreespace, MatchesBruteForceGrid) {
  Rng rng(33);
  for (std::size_t c = 0, n = test_support::scaled(60, 6); c < n; ++c) {
    const World w = random_world(rng);
    const Polygon lf = local_freespace(w.m, w.y, w.range);
    const double half = 0.5 * w.range;
    constexpr int kGrid = 80;
    int inside = 0;
    for (int i = 0; i <= kGrid; ++i) {
      for (int j = 0; j <= kGrid; ++j) {
        const Point q = w.y + half * Point(2.0 * i / kGrid - 1, 2.0 * j / kGrid - 1);
        const double viol = constraint_violation(w, q, kSensingPolygonSides);
        if (std::abs(viol) < 1e-7) continue;  // on a constraint line: either verdict is fine
        const bool truth = viol < 0;
        EXPECT_EQ(geometry::convex_contains(lf, q, 1e-12), truth)
            << "case " << c << " q = " << q.transpose();
        inside += truth;
      }
    }
    EXPECT_GT(inside, 0);
  }
}

TEST(LocalFreespace, ScratchVersionMatchesAndFarObstaclesAreSkipped) {
  Rng rng(34);
  Polygon out;
  Polygon scratch;
  for (std::size_t c = 0, n = test_support::scaled(100, 10); c < n; ++c) {
    World w = random_world(rng);
    const Polygon a = local_freespace(w.m, w.y, w.range);
    local_freespace(w.m, w.y, w.range, out, scratch);
    EXPECT_EQ(a.vertices, out.vertices);
    // A disk farther than R cannot change LF.
    const Point dir(std::cos(c * 0.7), std::sin(c * 0.7));
    w.m.disks.push_back({w.y + (w.range + 1.5) * dir, 1.0});
    EXPECT_EQ(local_freespace(w.m, w.y, w.range).vertices, a.vertices);
  }
}

TEST(LocalFreespace, OpenWorldIsTheSensingPolygon) {
  ModelSpace m;
  m.boundary = Polygon{{Point(-100, -100), Point(100, -100), Point(100, 100), Point(-100, 100)}};
  const Polygon lf = local_freespace(m, Point(1, 2), 4.0, 8);
  ASSERT_EQ(lf.size(), 8u);
  EXPECT_NEAR(lf.area(), 0.5 * 8 * 4.0 * std::sin(2 * kPi / 8), 1e-12);
  for (const Point& v : lf.vertices) EXPECT_NEAR((v - Point(1, 2)).norm(), 2.0, 1e-12);
}

TEST(LocalFreespace, HalfwayToASingleDisk) {
  ModelSpace m;
  m.boundary = Polygon{{Point(-100, -100), Point(100, -100), Point(100, 100), Point(-100, 100)}};
  m.disks.push_back({Point(3, 0), 1.0});  // nearest point (2, 0), d = 2: the cut is x <= 1
  const Polygon lf = local_freespace(m, Point(0, 0), 10.0);
  double max_x = -1;
  for (const Point& v : lf.vertices) max_x = std::max(max_x, v.x());
  EXPECT_NEAR(max_x, 1.0, 1e-12);
}

TEST(LocalFreespace, ProjectionMatchesBruteForce) {
  Rng rng(35);
  for (std::size_t c = 0, n = test_support::scaled(100, 10); c < n; ++c) {
    const World w = random_world(rng);
    const Polygon lf = local_freespace(w.m, w.y, w.range);
    for (int k = 0; k < 10; ++k) {
      const Point q(rng.uniform(-8, 8), rng.uniform(-8, 8));
      const Point p = geometry::project_onto_convex(lf, q);
      EXPECT_LE(max_outside(lf, p), 1e-12);
      // Brute force: nearest of dense samples of LF (boundary, plus interior fans from y).
      double best = std::numeric_limits<double>::infinity();
      double spacing = 0;
      constexpr int kPerEdge = 1000;
      for (std::size_t i = 0; i < lf.size(); ++i) {
        const Point& a = lf.vertices[i];
        const Point& b = lf.vertices[(i + 1) % lf.size()];
        spacing = std::max(spacing, (b - a).norm() / kPerEdge);
        for (int s = 0; s <= kPerEdge; ++s) {
          const Point e = a + (b - a) * (double(s) / kPerEdge);
          for (double f : {1.0, 0.75, 0.5, 0.25, 0.0}) {
            best = std::min(best, (w.y + f * (e - w.y) - q).norm());
          }
        }
      }
      if (max_outside(lf, q) <= 0) {
        EXPECT_EQ(p, q);
      } else {
        EXPECT_LE((p - q).norm(), best + 1e-12);
        EXPECT_GE((p - q).norm(), best - spacing);
      }
    }
  }
}

TEST(LocalFreespace, RejectsPointsOutsideTheFreespace) {
  ModelSpace m;
  m.boundary = Polygon{{Point(-5, -5), Point(5, -5), Point(5, 5), Point(-5, 5)}};
  m.disks.push_back({Point(1, 1), 0.5});
  m.convex.push_back(Polygon{{Point(-3, -3), Point(-2, -3), Point(-2, -2)}});
  EXPECT_THROW(local_freespace(m, Point(1.2, 1.1), 3), Error);    // inside the disk
  EXPECT_THROW(local_freespace(m, Point(1.5, 1.0), 3), Error);    // on the disk
  EXPECT_THROW(local_freespace(m, Point(-2.2, -2.8), 3), Error);  // inside the polygon
  EXPECT_THROW(local_freespace(m, Point(-2.5, -3.0), 3), Error);  // on the polygon
  EXPECT_THROW(local_freespace(m, Point(6, 0), 3), Error);        // outside the boundary
  EXPECT_THROW(local_freespace(m, Point(5, 0), 3), Error);        // on the boundary
  EXPECT_THROW(local_freespace(m, Point(0, std::numeric_limits<double>::quiet_NaN()), 3), Error);
  EXPECT_THROW(local_freespace(m, Point(0, 0), 0), Error);
  EXPECT_THROW(local_freespace(m, Point(0, 0), std::numeric_limits<double>::infinity()), Error);
  EXPECT_THROW(local_freespace(m, Point(0, 0), 3, 2), Error);
  EXPECT_NO_THROW(local_freespace(m, Point(0, 0), 3));
  ModelSpace empty;
  EXPECT_THROW(local_freespace(empty, Point(0, 0), 3), Error);
}

}  // namespace
}  // namespace rearm::reactive
