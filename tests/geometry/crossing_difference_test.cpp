// geometry::internal::crossing_difference (one polygon minus a union of polygons, traced along
// the boundaries' crossings) against CGAL's own Boolean difference, exactly: the symmetric
// difference of the two results is empty, and they have the same pieces and holes. Random
// stars and rectangles over random materials (some with constructed, non-double vertices),
// rings of rectangles that enclose islands, a material inside a cutter, and the degenerate
// inputs it must hand back (nullopt) to CGAL's overlay.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <numbers>
#include <vector>

#include "core/rng.h"
#include "geometry/cgal_internal.h"
#include "support/geometry_oracle.h"

namespace rearm::geometry::internal {
namespace {

using PolygonSet = CGAL::Polygon_set_2<Kernel>;

CPolygon star(Rng& rng, const Point& c, double r_min, double r_max) {
  const int n = 3 + static_cast<int>(rng.index(10));
  return to_cgal(test_support::random_star(rng, n, r_min, r_max, c));
}

CPolygon rect(double x0, double y0, double x1, double y1) {
  return to_cgal(Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
}

CPolygon rotated_rect(const Point& c, double w, double h, double angle) {
  Polygon p;
  for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    const Point d(sx * w / 2, sy * h / 2);
    p.vertices.emplace_back(c.x() + std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                            c.y() + std::sin(angle) * d.x() + std::cos(angle) * d.y());
  }
  return to_cgal(p);
}

// A polygon of doubles scaled by k (the crossing points are built in integers scaled by the
// inputs' smallest binary exponent: small and large coordinates too).
CPolygon scaled(const CPolygon& p, double k) {
  CPolygon out;
  for (const CPoint& v : p.vertices())
    out.push_back(CPoint(CGAL::to_double(v.x()) * k, CGAL::to_double(v.y()) * k));
  return out;
}

// CGAL's difference: the material minus the union of the cutters.
std::vector<CPolygonWithHoles> reference(const CPolygon& material,
                                         const std::vector<CPolygonWithHoles>& cutters) {
  PolygonSet s(material);
  PolygonSet u;
  u.join(cutters.begin(), cutters.end());
  s.difference(u);
  std::vector<CPolygonWithHoles> out;
  s.polygons_with_holes(std::back_inserter(out));
  return out;
}

std::size_t holes(const std::vector<CPolygonWithHoles>& ps) {
  std::size_t n = 0;
  for (const CPolygonWithHoles& p : ps) n += p.number_of_holes();
  return n;
}

// Traced and checked against CGAL; false when crossing_difference declined.
bool check(const CPolygon& material, const std::vector<CPolygonWithHoles>& cutters) {
  const auto traced = crossing_difference(material, cutters);
  if (!traced) return false;
  const std::vector<CPolygonWithHoles> want = reference(material, cutters);
  EXPECT_EQ(traced->size(), want.size());
  EXPECT_EQ(holes(*traced), holes(want));
  for (const CPolygonWithHoles& p : *traced) {
    EXPECT_TRUE(p.outer_boundary().is_simple());
    EXPECT_EQ(p.outer_boundary().orientation(), CGAL::COUNTERCLOCKWISE);
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
      EXPECT_EQ(h->orientation(), CGAL::CLOCKWISE);
    }
  }
  PolygonSet a;
  a.join(traced->begin(), traced->end());
  PolygonSet b;
  b.join(want.begin(), want.end());
  a.symmetric_difference(b);
  EXPECT_TRUE(a.is_empty()) << "the traced difference differs from CGAL's";
  return true;
}

TEST(CrossingDifference, MatchesCgalOnRandomStarsAndRectangles) {
  Rng rng(20261205);
  int traced = 0, declined = 0;
  for (int trial = 0; trial < 300; ++trial) {
    CPolygon material;
    if (trial % 3 == 0) {
      material = star(rng, Point(0, 0), 1.0, 3.0);
    } else {
      material = rotated_rect(Point(0, 0), rng.uniform(2, 6), rng.uniform(2, 6),
                              rng.uniform(0, std::numbers::pi));
    }
    const double scale = trial % 4 == 1 ? 1e-5 : trial % 4 == 3 ? 3e4 : 1;
    material = scaled(material, scale);
    if (trial % 5 == 0) {  // constructed vertices: midpoints (not doubles) replace every other
      CPolygon m;
      for (std::size_t i = 0; i < material.size(); ++i) {
        m.push_back(material.vertex(i));
        m.push_back(CGAL::midpoint(material.vertex(i), material.vertex((i + 1) % material.size())));
      }
      material = m;
    }
    std::vector<CPolygonWithHoles> cutters;
    const int k = 1 + static_cast<int>(rng.index(8));
    for (int c = 0; c < k; ++c) {
      const Point at(rng.uniform(-3.5, 3.5), rng.uniform(-3.5, 3.5));
      const CPolygon shape = rng.bernoulli(0.5)
                                 ? star(rng, at, 0.2, 1.5)
                                 : rotated_rect(at, rng.uniform(0.2, 3), rng.uniform(0.2, 3),
                                                rng.uniform(0, std::numbers::pi));
      cutters.emplace_back(scaled(shape, scale));
    }
    if (check(material, cutters)) {
      ++traced;
    } else {
      ++declined;
    }
    ASSERT_FALSE(HasFailure()) << "trial " << trial;
  }
  EXPECT_GT(traced, 270);  // random doubles are in general position nearly always
  EXPECT_LT(declined, 30);
}

TEST(CrossingDifference, RingsEncloseIslandsAndHolesGoToTheInnermostPiece) {
  const CPolygon material = rect(0, 0, 10, 10);
  // A ring of four overlapping bars (their corners off each other's edges): the frame outside
  // it with one hole, and the island inside it.
  std::vector<CPolygonWithHoles> cutters{CPolygonWithHoles(rect(1.05, 1.02, 8.93, 1.71)),
                                         CPolygonWithHoles(rect(8.1, 0.95, 8.95, 8.97)),
                                         CPolygonWithHoles(rect(0.98, 8.2, 8.91, 8.9)),
                                         CPolygonWithHoles(rect(1.0, 0.97, 1.8, 8.93))};
  ASSERT_TRUE(check(material, cutters));
  const auto one = crossing_difference(material, cutters);
  EXPECT_EQ(one->size(), 2u);
  EXPECT_EQ(holes(*one), 1u);
  // A second ring on the island, and a star on its island: three pieces, each with one hole
  // (the inner ring's outer boundary belongs to the middle piece, not the frame).
  const std::vector<CPolygonWithHoles> inner{CPolygonWithHoles(rect(3.02, 2.97, 6.99, 3.71)),
                                             CPolygonWithHoles(rect(6.31, 2.93, 7.04, 7.03)),
                                             CPolygonWithHoles(rect(2.96, 6.33, 7.01, 7.06)),
                                             CPolygonWithHoles(rect(2.98, 3.01, 3.67, 6.98))};
  cutters.insert(cutters.end(), inner.begin(), inner.end());
  Rng rng(3);
  cutters.emplace_back(star(rng, Point(5, 5), 0.3, 0.8));
  ASSERT_TRUE(check(material, cutters));
  const auto two = crossing_difference(material, cutters);
  EXPECT_EQ(two->size(), 3u);
  for (const CPolygonWithHoles& p : *two) EXPECT_EQ(p.number_of_holes(), 1u);
}

TEST(CrossingDifference, ACutterAroundTheMaterialLeavesNothing) {
  const CPolygon material = rect(0, 0, 1, 1);
  const std::vector<CPolygonWithHoles> cutters{CPolygonWithHoles(rect(-1, -1, 2, 2))};
  const auto out = crossing_difference(material, cutters);
  ASSERT_TRUE(out);
  EXPECT_TRUE(out->empty());
  EXPECT_TRUE(reference(material, cutters).empty());
}

TEST(CrossingDifference, DegenerateInputsGoBackToTheOverlay) {
  const CPolygon material = rect(0, 0, 4, 4);
  // A cutter vertex on the material's boundary, a shared vertex, a collinear overlap.
  for (const CPolygon& c : {rect(1, -1, 2, 0), rect(4, 4, 5, 5), rect(1, 3, 2, 4)}) {
    SCOPED_TRACE(c.vertex(0).x());
    const std::vector<CPolygonWithHoles> cutters{CPolygonWithHoles(c)};
    EXPECT_FALSE(crossing_difference(material, cutters));
  }
  // Two cutters' edges crossing the material's top edge at one point, (2, 4).
  const std::vector<CPolygonWithHoles> three{
      CPolygonWithHoles(to_cgal(Polygon{{{1, 3}, {3, 5}, {0, 6}}})),
      CPolygonWithHoles(to_cgal(Polygon{{{3, 3}, {4, 6}, {1, 5}}}))};
  EXPECT_FALSE(crossing_difference(material, three));
  // A cutter with a hole, and a clockwise material.
  CPolygonWithHoles holed(rect(1, 1, 3, 3));
  CPolygon h = rect(1.5, 1.5, 2.5, 2.5);
  h.reverse_orientation();
  holed.add_hole(h);
  EXPECT_FALSE(crossing_difference(material, {holed}));
  CPolygon cw = material;
  cw.reverse_orientation();
  EXPECT_FALSE(crossing_difference(cw, {CPolygonWithHoles(rect(1, 1, 2, 2))}));
}

}  // namespace
}  // namespace rearm::geometry::internal
