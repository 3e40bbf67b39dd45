#include "geometry/convex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/boolean.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"

namespace rearm::geometry {
namespace {

using test_support::boundary_distance;
using test_support::ray_cast_inside;

constexpr double kPi = std::numbers::pi;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// A random convex polygon built without convex_hull: sorted random angles on an ellipse (a
// convex curve), then rotated and shifted. n >= 3 distinct angles give a strictly convex CCW
// polygon.
Polygon random_convex(Rng& rng, int n, const Point& c, double scale) {
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0, 2 * kPi));
  std::sort(angles.begin(), angles.end());
  const double ax = scale * rng.uniform(0.5, 1.5);
  const double ay = scale * rng.uniform(0.5, 1.5);
  const double rot = rng.uniform(0, 2 * kPi);
  return test_support::ellipse_polygon(angles, ax, ay, rot, c);
}

// Independent signed distance of q outside the edge a→b of a CCW polygon (> 0 outside).
double outside(const Point& a, const Point& b, const Point& q) {
  return -cross(b - a, q - a) / (b - a).norm();
}

double max_outside(const Polygon& p, const Point& q) {
  double m = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    m = std::max(m, outside(p.vertices[i], p.vertices[(i + 1) % n], q));
  }
  return m;
}

// The half-plane {normal·q <= offset} as a big CCW quadrilateral (for the exact Booleans).
Polygon half_plane_box(const HalfPlane& h, const Point& near, double size) {
  const Point n = h.normal.normalized();
  const Point t(-n.y(), n.x());
  const Point foot = near - (h.value(near) / h.normal.norm()) * n;  // on the line
  const Point a = foot - size * t;
  const Point b = foot + size * t;
  return Polygon{{a, a - size * n, b - size * n, b}};
}

double exact_area(const RegionSet& s) { return total_area(s); }

TEST(Convex, LeftOfIsTheInsideOfACcwEdge) {
  const HalfPlane h = left_of(Point(0, 0), Point(1, 0));
  EXPECT_LT(h.value(Point(0.5, 1)), 0);
  EXPECT_GT(h.value(Point(0.5, -1)), 0);
  EXPECT_NEAR(h.value(Point(7, 0)), 0, 1e-15);
}

TEST(Convex, ClipMatchesExactIntersection) {
  Rng rng(101);
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(10)), Point(0, 0), 2);
    const double a = rng.uniform(0, 2 * kPi);
    const Point normal = rng.uniform(0.2, 3) * Point(std::cos(a), std::sin(a));
    const Point through(rng.uniform(-2, 2), rng.uniform(-2, 2));
    const HalfPlane h{normal, normal.dot(through)};
    const Polygon r = clip(p, h);
    const double truth = exact_area(intersect(to_set(p), to_set(half_plane_box(h, through, 50))));
    EXPECT_NEAR(r.size() >= 3 ? r.area() : 0.0, truth, 1e-9) << "case " << c;
    for (const Point& v : r.vertices) {
      EXPECT_LE(h.value(v) / h.normal.norm(), 1e-12);
      EXPECT_LE(max_outside(p, v), 1e-12);
    }
    if (truth > 1e-6) {
      EXPECT_GT(r.signed_area(), 0);
      EXPECT_TRUE(r.is_convex());
    }
  }
}

TEST(Convex, ClipKeepsOrDropsWholePolygons) {
  const Polygon sq{{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}};
  EXPECT_EQ(clip(sq, HalfPlane{Point(1, 0), 5}).vertices, sq.vertices);
  EXPECT_EQ(clip(sq, HalfPlane{Point(1, 0), -5}).size(), 0u);
  const Polygon half = clip(sq, HalfPlane{Point(1, 0), 0.5});
  EXPECT_NEAR(half.area(), 0.5, 1e-15);
}

TEST(Convex, IntersectConvexMatchesExactIntersection) {
  Rng rng(202);
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const Polygon a = random_convex(rng, 3 + static_cast<int>(rng.index(9)), Point(0, 0), 1.5);
    const Polygon b = random_convex(rng, 3 + static_cast<int>(rng.index(9)),
                                    Point(rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5)), 1.5);
    const Polygon r = intersect_convex(a, b);
    const double truth = exact_area(intersect(to_set(a), to_set(b)));
    EXPECT_NEAR(r.size() >= 3 ? r.area() : 0.0, truth, 1e-9) << "case " << c;
    for (const Point& v : r.vertices) {
      EXPECT_LE(max_outside(a, v), 1e-9);
      EXPECT_LE(max_outside(b, v), 1e-9);
    }
  }
}

TEST(Convex, ContainsMatchesRayCasting) {
  Rng rng(303);
  for (std::size_t c = 0, n = test_support::scaled(100, 10); c < n; ++c) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(10)), Point(0, 0), 1);
    for (int k = 0; k < 200; ++k) {
      const Point q(rng.uniform(-2, 2), rng.uniform(-2, 2));
      if (boundary_distance(p, q) < 1e-9) continue;
      EXPECT_EQ(convex_contains(p, q), ray_cast_inside(p, q));
      // A tolerance widens the polygon by that distance.
      EXPECT_EQ(convex_contains(p, q, 0.1), max_outside(p, q) <= 0.1 || ray_cast_inside(p, q));
    }
  }
  EXPECT_FALSE(convex_contains(Polygon{}, Point(0, 0)));
}

TEST(Convex, ProjectionMatchesBruteForce) {
  Rng rng(404);
  constexpr int kPerEdge = 2000;
  for (std::size_t c = 0, n = test_support::scaled(100, 10); c < n; ++c) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 1);
    for (int k = 0; k < 20; ++k) {
      const Point q(rng.uniform(-3, 3), rng.uniform(-3, 3));
      const Point pr = project_onto_convex(p, q);
      if (ray_cast_inside(p, q) && boundary_distance(p, q) > 1e-9) {
        EXPECT_EQ(pr, q);
        continue;
      }
      // Brute force: the closest of dense boundary samples.
      double best = std::numeric_limits<double>::infinity();
      double spacing = 0;
      for (std::size_t i = 0, m = p.size(); i < m; ++i) {
        const Point& a = p.vertices[i];
        const Point& b = p.vertices[(i + 1) % m];
        spacing = std::max(spacing, (b - a).norm() / kPerEdge);
        for (int s = 0; s <= kPerEdge; ++s) {
          best = std::min(best, (a + (b - a) * (double(s) / kPerEdge) - q).norm());
        }
      }
      EXPECT_LE((pr - q).norm(), best + 1e-12);
      EXPECT_GE((pr - q).norm(), best - spacing);
      EXPECT_LE(max_outside(p, pr), 1e-12);
      // Variational inequality of the projection onto a convex set: (q − p)·(z − p) <= 0.
      for (const Point& z : p.vertices) EXPECT_LE((q - pr).dot(z - pr), 1e-12);
    }
  }
  EXPECT_THROW(project_onto_convex(Polygon{}, Point(0, 0)), Error);
}

TEST(Convex, LineIntervalMatchesExactChord) {
  Rng rng(505);
  for (std::size_t c = 0, n = test_support::scaled(500, 50); c < n; ++c) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 1);
    const Point o(rng.uniform(-2, 2), rng.uniform(-2, 2));
    const double a = rng.uniform(0, 2 * kPi);
    const Point d = rng.uniform(0.1, 2) * Point(std::cos(a), std::sin(a));
    const auto iv = line_interval(p, o, d);
    // Independent: the line misses a convex polygon iff all vertices lie strictly on one side.
    int left = 0;
    int right = 0;
    for (const Point& v : p.vertices) {
      const double s = cross(d, v - o);
      left += s > 1e-12;
      right += s < -1e-12;
    }
    const bool misses = left == static_cast<int>(p.size()) || right == static_cast<int>(p.size());
    if (misses) {
      EXPECT_FALSE(iv.has_value()) << "case " << c;
      continue;
    }
    ASSERT_TRUE(iv.has_value()) << "case " << c;
    EXPECT_LE(iv->lo, iv->hi);
    const double scale = d.norm();
    EXPECT_NEAR(boundary_distance(p, o + iv->lo * d), 0.0, 1e-9);
    EXPECT_NEAR(boundary_distance(p, o + iv->hi * d), 0.0, 1e-9);
    EXPECT_GT(max_outside(p, o + (iv->lo - 1e-3 / scale) * d), 0.0);
    EXPECT_GT(max_outside(p, o + (iv->hi + 1e-3 / scale) * d), 0.0);
    if (iv->hi - iv->lo > 1e-6) {
      EXPECT_LE(max_outside(p, o + 0.5 * (iv->lo + iv->hi) * d), 1e-12);
    }
    // ray_exit: defined exactly when o is inside.
    const auto exit = ray_exit(p, o, d);
    if (ray_cast_inside(p, o) && boundary_distance(p, o) > 1e-9) {
      ASSERT_TRUE(exit.has_value());
      EXPECT_NEAR(*exit, iv->hi, 1e-12);
      EXPECT_GE(*exit, 0.0);
    } else if (!ray_cast_inside(p, o) && boundary_distance(p, o) > 1e-9) {
      EXPECT_FALSE(exit.has_value());
    }
  }
}

TEST(Convex, LineIntervalParallelToAnEdge) {
  const Polygon sq{{Point(0, 0), Point(2, 0), Point(2, 1), Point(0, 1)}};
  const auto iv = line_interval(sq, Point(-1, 0.5), Point(1, 0));
  ASSERT_TRUE(iv.has_value());
  EXPECT_DOUBLE_EQ(iv->lo, 1.0);
  EXPECT_DOUBLE_EQ(iv->hi, 3.0);
  EXPECT_FALSE(line_interval(sq, Point(-1, 1.5), Point(1, 0)).has_value());
}

// Brute-force hull edges of points in general position: (a, b) with every other point strictly
// on the left.
int brute_hull_edges(const std::vector<Point>& pts, const Polygon& hull) {
  int edges = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (i == j) continue;
      bool all_left = true;
      for (std::size_t k = 0; k < pts.size() && all_left; ++k) {
        if (k != i && k != j) all_left = cross(pts[j] - pts[i], pts[k] - pts[i]) > 0;
      }
      if (!all_left) continue;
      ++edges;
      // (pts[i], pts[j]) must be a consecutive pair of the hull.
      bool found = false;
      for (std::size_t h = 0, m = hull.size(); h < m; ++h) {
        found |= hull.vertices[h] == pts[i] && hull.vertices[(h + 1) % m] == pts[j];
      }
      EXPECT_TRUE(found);
    }
  }
  return edges;
}

TEST(Convex, HullMatchesBruteForce) {
  Rng rng(606);
  for (std::size_t c = 0, n = test_support::scaled(200, 20); c < n; ++c) {
    std::vector<Point> pts;
    const int m = 3 + static_cast<int>(rng.index(30));
    for (int i = 0; i < m; ++i) pts.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1));
    const Polygon hull = convex_hull(pts);
    ASSERT_GE(hull.size(), 3u);
    EXPECT_GT(hull.signed_area(), 0);
    EXPECT_TRUE(hull.is_convex());
    for (const Point& v : hull.vertices) {
      EXPECT_NE(std::find(pts.begin(), pts.end(), v), pts.end());
    }
    for (const Point& q : pts) EXPECT_LE(max_outside(hull, q), 1e-12);
    EXPECT_EQ(brute_hull_edges(pts, hull), static_cast<int>(hull.size())) << "case " << c;
  }
}

TEST(Convex, HullDropsDuplicatesAndCollinearPoints) {
  const std::vector<Point> pts{Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1),
                               Point(2, 2), Point(1, 2), Point(0, 2), Point(0, 1),
                               Point(1, 1), Point(2, 2), Point(0, 0)};
  const Polygon hull = convex_hull(pts);
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_NEAR(hull.area(), 4.0, 1e-15);
  EXPECT_GT(hull.signed_area(), 0);
  const Polygon line = convex_hull({Point(0, 0), Point(1, 1), Point(2, 2)});
  EXPECT_LT(line.size(), 3u);
}

TEST(Convex, RegularPolygonInscribedAndCircumscribed) {
  const Disk d{Point(1, -2), 0.7};
  for (int n : {3, 4, 7, 32}) {
    const Polygon in = regular_polygon(d, n, false);
    const Polygon out = regular_polygon(d, n, true);
    ASSERT_EQ(in.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(out.size(), static_cast<std::size_t>(n));
    EXPECT_GT(in.signed_area(), 0);
    EXPECT_TRUE(out.is_convex());
    for (const Point& v : in.vertices) EXPECT_NEAR((v - d.center).norm(), d.radius, 1e-12);
    // Circumscribed: every edge is tangent (centre at distance r from each edge line).
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_NEAR(-outside(out.vertices[i], out.vertices[(i + 1) % out.size()], d.center), d.radius,
                  1e-12);
    }
    EXPECT_NEAR(in.area(), 0.5 * n * d.radius * d.radius * std::sin(2 * kPi / n), 1e-12);
  }
  EXPECT_THROW(regular_polygon(d, 2, false), Error);
  EXPECT_THROW(regular_polygon(Disk{Point(0, 0), 0}, 5, false), Error);
}

TEST(Convex, RemoveCollinearKeepsTheArea) {
  Rng rng(707);
  for (std::size_t c = 0, n = test_support::scaled(200, 20); c < n; ++c) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 1);
    Polygon noisy;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Point& a = p.vertices[i];
      const Point& b = p.vertices[(i + 1) % p.size()];
      noisy.vertices.push_back(a);
      if (rng.bernoulli(0.3)) noisy.vertices.push_back(a);              // repeated vertex
      if (rng.bernoulli(0.5)) noisy.vertices.push_back(0.5 * (a + b));  // exactly collinear-ish
    }
    const Polygon r = remove_collinear(noisy, 1e-9);
    EXPECT_EQ(r.size(), p.size()) << "case " << c;
    EXPECT_NEAR(r.area(), p.area(), 1e-12);
    EXPECT_GT(r.signed_area(), 0);
    for (const Point& v : r.vertices) {
      EXPECT_NE(std::find(p.vertices.begin(), p.vertices.end(), v), p.vertices.end());
    }
  }
}

TEST(Convex, OverlapMatchesExactIntersection) {
  Rng rng(808);
  int overlaps = 0;
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const Polygon a = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 1);
    const Polygon b = random_convex(rng, 3 + static_cast<int>(rng.index(8)),
                                    Point(rng.uniform(-3, 3), rng.uniform(-3, 3)), 1);
    const double area = exact_area(intersect(to_set(a), to_set(b)));
    if (area > 0 && area < 1e-9) continue;  // too close to call for a tolerance test
    EXPECT_EQ(convex_overlap(a, b), area > 0) << "case " << c;
    overlaps += area > 0;
  }
  EXPECT_GT(overlaps, 0);
  // Touching along an edge or at a vertex is not overlap.
  const Polygon s1{{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}};
  const Polygon s2{{Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1)}};
  const Polygon s3{{Point(1, 1), Point(2, 1), Point(2, 2), Point(1, 2)}};
  EXPECT_FALSE(convex_overlap(s1, s2));
  EXPECT_FALSE(convex_overlap(s1, s3));
}

TEST(Convex, SeparatingHalfPlaneSeparates) {
  Rng rng(909);
  int separated = 0;
  for (std::size_t c = 0, n = test_support::scaled(300, 30); c < n; ++c) {
    const Polygon a = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 1);
    const Polygon b = random_convex(rng, 3 + static_cast<int>(rng.index(8)),
                                    Point(rng.uniform(-4, 4), rng.uniform(-4, 4)), 1);
    const double area = exact_area(intersect(to_set(a), to_set(b)));
    if (area > 0 && area < 1e-9) continue;
    const auto h = separating_half_plane(a, b);
    if (area > 0) {
      EXPECT_FALSE(h.has_value()) << "case " << c;
      continue;
    }
    ASSERT_TRUE(h.has_value()) << "case " << c;
    ++separated;
    const double len = h->normal.norm();
    ASSERT_GT(len, 0);
    for (const Point& v : a.vertices) EXPECT_LE(h->value(v) / len, 1e-9);
    for (const Point& v : b.vertices) EXPECT_GE(h->value(v) / len, -1e-9);
    // Dense samples of both interiors (independent of the vertices test).
    for (int k = 0; k < 50; ++k) {
      const Point qa = a.vertices[rng.index(a.size())] * 0.7 + a.centroid() * 0.3;
      const Point qb = b.vertices[rng.index(b.size())] * 0.7 + b.centroid() * 0.3;
      EXPECT_LT(h->value(qa), 0);
      EXPECT_GT(h->value(qb), 0);
    }
  }
  EXPECT_GT(separated, 0);
  // Touching squares: the shared edge's line separates them.
  const Polygon s1{{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}};
  const Polygon s2{{Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1)}};
  const auto h = separating_half_plane(s1, s2);
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(h->value(Point(1, 0.5)), 0.0, 1e-15);
  EXPECT_LT(h->value(Point(0.5, 0.5)), 0);
  EXPECT_GT(h->value(Point(1.5, 0.5)), 0);
}

std::vector<Polygon> remove_flat(const std::vector<Polygon>& pieces) {
  std::vector<Polygon> out;
  for (const Polygon& q : pieces) out.push_back(remove_collinear(q));
  return out;
}

// Reflex vertices of a counter-clockwise polygon (exact doubles: any negative turn).
int reflex_count(const Polygon& p) {
  int r = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[(i + n - 1) % n];
    const Point& b = p.vertices[i];
    const Point& c = p.vertices[(i + 1) % n];
    r += cross(b - a, c - b) < -1e-12 * (b - a).norm() * (c - b).norm();
  }
  return r;
}

// Offsets contain the d-dilation (points at distance d of the boundary, outside, are inside
// the offset) and reach at most d / cos(φ/2) (miter) or about miter_limit·d (bevel).
TEST(Convex, OffsetContainsTheDilationAndStaysClose) {
  Rng rng(17);
  for (int trial = 0; trial < static_cast<int>(test_support::scaled(300, 20)); ++trial) {
    const Polygon p = random_convex(rng, 3 + static_cast<int>(rng.index(8)), Point(0, 0), 2.0);
    const double d = rng.uniform(0.05, 1.0);
    for (const double limit : {1.0, 2.0}) {
      const Polygon o = offset_convex(p, d, limit);
      ASSERT_TRUE(remove_collinear(o).is_convex()) << "trial " << trial;
      for (int k = 0; k < 400; ++k) {
        const double a = 2 * kPi * k / 400;
        // The farthest point of the polygon in direction a, pushed out by d (on the boundary
        // of the round dilation).
        const Point u(std::cos(a), std::sin(a));
        Point far = p.vertices.front();
        for (const Point& v : p.vertices) {
          if (v.dot(u) > far.dot(u)) far = v;
        }
        EXPECT_TRUE(convex_contains(o, far + d * (1 - 1e-9) * u, 1e-9)) << "trial " << trial;
      }
      for (const Point& v : o.vertices) {
        // Every offset vertex lies within limit·d·sqrt(2) of the polygon (a bevel corner).
        EXPECT_LE(boundary_distance(p, v), limit * d * std::sqrt(2.0) + 1e-9);
      }
    }
  }
}

// Triangulation: n − 2 counter-clockwise triangles of the polygon's vertices that tile it.
TEST(Convex, TriangulationTilesTheStar) {
  Rng rng(23);
  for (int trial = 0; trial < static_cast<int>(test_support::scaled(200, 10)); ++trial) {
    const Polygon p = remove_collinear(
        test_support::random_star(rng, 5 + static_cast<int>(rng.index(20)), 1.0, 3.0));
    const std::vector<Polygon> t = triangulate(p).or_throw();
    ASSERT_EQ(t.size(), p.size() - 2);
    double area = 0;
    for (const Polygon& tri : t) {
      ASSERT_EQ(tri.size(), 3u);
      EXPECT_GT(tri.signed_area(), 0);
      EXPECT_TRUE(ray_cast_inside(p, tri.centroid()));
      for (const Point& v : tri.vertices) {
        EXPECT_NE(std::find(p.vertices.begin(), p.vertices.end(), v), p.vertices.end());
      }
      area += tri.area();
    }
    EXPECT_NEAR(area, p.area(), 1e-9 * p.area());
    for (std::size_t i = 0; i < t.size(); ++i) {
      for (std::size_t j = i + 1; j < t.size(); ++j) EXPECT_FALSE(convex_overlap(t[i], t[j], 1e-9));
    }
  }
}

// Decomposition by reflex extensions: convex, interior-disjoint pieces of the polygon's area;
// an orthogonal polygon falls apart into rectangles.
TEST(Convex, ExtensionDecompositionTilesWithConvexPieces) {
  Rng rng(29);
  for (int trial = 0; trial < static_cast<int>(test_support::scaled(200, 10)); ++trial) {
    const Polygon p = remove_collinear(
        test_support::random_star(rng, 5 + static_cast<int>(rng.index(15)), 1.0, 3.0));
    const std::vector<Polygon> pieces = decompose_by_extensions(p).or_throw();
    double area = 0;
    for (const Polygon& q : pieces) {
      EXPECT_EQ(reflex_count(q), 0) << "trial " << trial;
      EXPECT_GT(q.signed_area(), 0);
      EXPECT_TRUE(ray_cast_inside(p, q.centroid())) << "trial " << trial;
      area += q.area();
    }
    EXPECT_NEAR(area, p.area(), 1e-9 * p.area()) << "trial " << trial;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      for (std::size_t j = i + 1; j < pieces.size(); ++j) {
        EXPECT_FALSE(convex_overlap(pieces[i], pieces[j], 1e-9)) << "trial " << trial;
      }
    }
  }
  // A plus sign: 12 vertices, 4 reflex; every piece an axis-aligned rectangle.
  const Polygon cross_shape{{Point(1, 0), Point(2, 0), Point(2, 1), Point(3, 1), Point(3, 2),
                             Point(2, 2), Point(2, 3), Point(1, 3), Point(1, 2), Point(0, 2),
                             Point(0, 1), Point(1, 1)}};
  const std::vector<Polygon> pieces = decompose_by_extensions(cross_shape).or_throw();
  double area = 0;
  for (const Polygon& q : remove_flat(pieces)) {
    ASSERT_EQ(q.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      const Point e = q.vertices[(i + 1) % 4] - q.vertices[i];
      EXPECT_TRUE(e.x() == 0 || e.y() == 0);
    }
    area += q.area();
  }
  EXPECT_DOUBLE_EQ(area, 5.0);
}

// The failures are values the caller acts on (the diffeomorphism tries its next candidate):
// a clockwise square has no ear (every corner is reflex for the counter-clockwise walk), the plus
// sign needs 3 pieces (the bar and two arms).
TEST(Convex, DecompositionFailuresAreValues) {
  const Polygon clockwise{{Point(0, 0), Point(0, 1), Point(1, 1), Point(1, 0)}};
  const Outcome<std::vector<Polygon>> t = triangulate(clockwise);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.reason().find("no ear"), std::string::npos) << t.reason();
  const Polygon cross_shape{{Point(1, 0), Point(2, 0), Point(2, 1), Point(3, 1), Point(3, 2),
                             Point(2, 2), Point(2, 3), Point(1, 3), Point(1, 2), Point(0, 2),
                             Point(0, 1), Point(1, 1)}};
  const Outcome<std::vector<Polygon>> few = decompose_by_extensions(cross_shape, 2);
  ASSERT_FALSE(few.ok());
  EXPECT_NE(few.reason().find("more than 2 pieces"), std::string::npos) << few.reason();
  EXPECT_THROW((void)decompose_by_extensions(cross_shape, 2).or_throw(), Error);
  EXPECT_TRUE(decompose_by_extensions(cross_shape).ok());
}

}  // namespace
}  // namespace rearm::geometry
