// The guide path of the robust variant (executive/guide_path.h) against exact geometry: every
// point of every leg lies in the region (geometry::contains, exact predicates, sampled every
// millimetre), the length is bounded below by the true shortest path (computed by hand for
// each scene: a taut string around the corners) and above by a small factor of it, and points
// in different components or outside the region get no path.
#include "executive/guide_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "geometry/polygon.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using geometry::Point;
using geometry::Polygon;
using geometry::Region;

using test_support::rect;

// Every sampled point of the polyline from → path is in the region; returns its length.
double check_inside(const Region& r, const Point& from, const std::vector<Point>& path) {
  double length = 0;
  Point a = from;
  for (const Point& b : path) {
    const double l = (b - a).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(l / 1e-3)));
    for (int k = 0; k <= n; ++k) {
      const Point q = a + (b - a) * (double(k) / n);
      EXPECT_TRUE(geometry::contains(r, q)) << "leg point (" << q.x() << ", " << q.y() << ")";
    }
    length += l;
    a = b;
  }
  return length;
}

TEST(GuidePath, GoesAroundAWallNearTheShortestLength) {
  const Region r{rect(0, 0, 10, 10), {rect(4, 1, 6, 9)}};
  const Point from(2, 5), to(8, 5);
  const auto path = guide_path(r, from, to, GuideParams{});
  ASSERT_TRUE(path.has_value());
  EXPECT_EQ(path->back(), to);
  // Taut string over a corner pair of the wall: 2·√(2² + 4²) + 2.
  const double shortest = 2 * std::sqrt(20.0) + 2;
  const double length = check_inside(r, from, *path);
  EXPECT_GE(length, shortest - 1e-9);
  EXPECT_LE(length, 1.1 * shortest);
  EXPECT_GE(path->size(), 3u);  // at least the two corners before x*
}

// Shortcuts keep the raster path's clearance (up to GuideParams::comfort): around the wall's
// corners the legs stay at least comfort less two cells from it, where a taut string would
// graze the corners.
TEST(GuidePath, ShortcutsKeepTheirDistanceFromCorners) {
  const Polygon wall = rect(4, 1, 6, 9);
  const Region r{rect(0, 0, 10, 10), {wall}};
  const Region wall_only{rect(-1, -1, 11, 11), {wall}};
  const GuideParams p;
  const Point from(2, 5), to(8, 5);
  const auto path = guide_path(r, from, to, p);
  ASSERT_TRUE(path.has_value());
  Point a = from;
  for (const Point& b : *path) {
    EXPECT_TRUE(segment_clear(wall_only, a, b, p.comfort - 2 * p.resolution))
        << "leg to (" << b.x() << ", " << b.y() << ")";
    a = b;
  }
}

TEST(GuidePath, ThreadsANarrowPassageWhenItIsTheOnlyWay) {
  // Two walls from the outer boundary's bottom and top leave a gap 0.12 m wide at y = 5.
  const Polygon outer{{Point(0, 0), Point(4, 0), Point(4, 4.94), Point(6, 4.94), Point(6, 0),
                       Point(10, 0), Point(10, 10), Point(6, 10), Point(6, 5.06), Point(4, 5.06),
                       Point(4, 10), Point(0, 10)}};
  const Region r{outer, {}};
  const Point from(2, 5), to(8, 5);
  const auto path = guide_path(r, from, to, GuideParams{});
  ASSERT_TRUE(path.has_value());
  const double length = check_inside(r, from, *path);
  EXPECT_GE(length, 6 - 1e-9);
  EXPECT_LE(length, 6.5);
}

// GuideParams::avoid: a wall across the room with a 0.4 m gap (clearance 0.2 m at its middle)
// on the straight line and a 3 m opening 4 m away. The plain path takes the gap; with avoid
// 0.3 m it goes round through the opening (longer than the taut string through it, computed by
// hand), every point of it farther than 0.3 m from the wall away from the endpoints; with the
// gap's cells near an endpoint (exempt) the gap is taken again.
TEST(GuidePath, AvoidGoesRoundAPassageNarrowerThanAsked) {
  // Room 12 x 12; wall x in [5.8, 6.2] from y = 0 to 5.8 and from 6.2 to 9 (gap y in (5.8, 6.2)),
  // opening y in (9, 12).
  const Region r{rect(0, 0, 12, 12), {rect(5.8, 0.01, 6.2, 5.8), rect(5.8, 6.2, 6.2, 9)}};
  const Point from(2, 6), to(10, 6);
  const auto plain = guide_path(r, from, to, GuideParams{});
  ASSERT_TRUE(plain.has_value());
  EXPECT_LE(check_inside(r, from, *plain), 8.5);  // through the gap: 8 m straight
  GuideParams wide;
  wide.avoid = 0.3;
  const auto round = guide_path(r, from, to, wide);
  ASSERT_TRUE(round.has_value());
  // Through the opening: at least the taut string over the wall's top corner (5.8, 9) and
  // (6.2, 9), i.e. 2·hypot(3.8, 3) + 0.4.
  EXPECT_GE(check_inside(r, from, *round), 2 * std::hypot(3.8, 3.0) + 0.4 - 1e-9);
  Point a = from;
  for (const Point& b : *round) {
    for (int k = 0; k <= 100; ++k) {
      const Point q = a + (b - a) * (k / 100.0);
      if ((q - from).norm() <= kAvoidExempt || (q - to).norm() <= kAvoidExempt) continue;
      EXPECT_FALSE(q.x() > 5.5 && q.x() < 6.5 && q.y() < 9) << q.x() << ", " << q.y();
    }
    a = b;
  }
  // Endpoints beside the gap: its cells are exempt, and the path goes through it.
  const auto near = guide_path(r, Point(5.5, 6), Point(6.5, 6), wide);
  ASSERT_TRUE(near.has_value());
  EXPECT_LE(check_inside(r, Point(5.5, 6), *near), 1.5);
  wide.avoid = -0.1;
  EXPECT_THROW(validate(wide), Error);
}

TEST(GuidePath, NoPathBetweenComponentsOrFromOutside) {
  // A closed room (the hole's ring) inside a ring-shaped region: the inside of the hole is not
  // in the region, and the region's two sides of a closed wall are one component, so use a
  // point inside the hole (outside the region) as the unreachable end.
  const Region r{rect(0, 0, 10, 10), {rect(3, 3, 7, 7)}};
  EXPECT_FALSE(guide_path(r, Point(1, 1), Point(5, 5), GuideParams{}).has_value());
  EXPECT_FALSE(guide_path(r, Point(5, 5), Point(1, 1), GuideParams{}).has_value());
  EXPECT_FALSE(guide_path(r, Point(-1, 1), Point(9, 9), GuideParams{}).has_value());
}

// Blocked convex polygons (what has been seen of unknown obstacles, RobustParams::memory) are
// kept out of like holes: against a triangle across the direct line, every sampled leg point is
// outside it (exact point location); the length is at least the taut string over its apex.
TEST(GuidePath, KeepsOutOfBlockedPolygonsUnlessTheyHoldAnEndpoint) {
  const Region r{rect(0, 0, 10, 10), {}};
  const Polygon tri{{{5, 0.5}, {5.5, 7}, {4.5, 7}}};  // counter-clockwise
  const Point from(2, 3), to(8, 3);
  const Polygon blocked[] = {tri};
  const auto path = guide_path(r, from, to, GuideParams{}, blocked);
  ASSERT_TRUE(path.has_value());
  Point a = from;
  double length = 0;
  for (const Point& b : *path) {
    for (int k = 0; k <= 1000; ++k) {
      const Point q = a + (b - a) * (k / 1000.0);
      EXPECT_FALSE(geometry::contains(tri, q)) << "(" << q.x() << ", " << q.y() << ")";
    }
    length += (b - a).norm();
    a = b;
  }
  // Over the apex (4.5, 7)–(5.5, 7), or under the base corner (5, 0.5): the shorter is over.
  const double under = 2 * std::sqrt(9.0 + 2.5 * 2.5);
  EXPECT_GE(
      length,
      std::min(under, (Point(4.5, 7) - from).norm() + 1 + (to - Point(5.5, 7)).norm()) - 1e-9);
  // The same region without the polygon: one straight leg.
  EXPECT_EQ(guide_path(r, from, to, GuideParams{})->size(), 1u);
  // A blocked polygon that holds the start is left out (the robot stands there).
  const auto inside = guide_path(r, Point(5, 3), to, GuideParams{}, blocked);
  ASSERT_TRUE(inside.has_value());
  EXPECT_EQ(inside->size(), 1u);
  // A wall of blocked polygons across the room separates the two sides.
  const Polygon wall{{{4.9, -1}, {5.1, -1}, {5.1, 11}, {4.9, 11}}};
  const Polygon walls[] = {wall};
  EXPECT_FALSE(guide_path(r, from, to, GuideParams{}, walls).has_value());
  const Polygon degenerate[] = {Polygon{{{1, 1}, {2, 2}}}};
  EXPECT_THROW(guide_path(r, from, to, GuideParams{}, degenerate), Error);
}

TEST(GuidePath, ASegmentInSightIsOneLeg) {
  const Region r{rect(0, 0, 10, 10), {rect(4, 6, 6, 9)}};
  const auto path = guide_path(r, Point(1, 2), Point(9, 2), GuideParams{});
  ASSERT_TRUE(path.has_value());
  ASSERT_EQ(path->size(), 1u);
  EXPECT_EQ(path->front(), Point(9, 2));
}

TEST(GuidePath, SegmentClearMeasuresTheDistanceToTheBoundary) {
  const Region r{rect(0, 0, 10, 10), {rect(4, 4, 6, 6)}};
  // The segment y = 3.9 passes 0.1 m below the hole.
  EXPECT_TRUE(segment_clear(r, Point(1, 3.9), Point(9, 3.9), 0.09));
  EXPECT_FALSE(segment_clear(r, Point(1, 3.9), Point(9, 3.9), 0.11));
  EXPECT_FALSE(segment_clear(r, Point(1, 5), Point(9, 5), 0));  // through the hole
}

// Distance from q to the boundary of the rectangle [0, w] × [0, h] (q inside): the exact truth
// for the drop-point searches below.
double inset(const Point& q, double w, double h) {
  return std::min({q.x(), q.y(), w - q.x(), h - q.y()});
}

// A corridor 4 m wide: no point is 3 m clear, so the search falls to the next level (1.5 m),
// whose nearest point from (1, 1) is the corner (1.5, 1.5) of the 1.5 m inset, a walk of
// √2 · 0.5 m; a level is preferred to any nearer point of a lower level.
TEST(DropPoint, TheFirstLevelThatHasAPointThenTheNearest) {
  const Region r{rect(0, 0, 10, 4), {}};
  const GuideParams p;
  const double cell = p.resolution;
  const std::vector<double> levels{3.0, 1.5, 1.0};
  const auto any = [](const Point&, std::size_t) { return true; };
  const auto q = nearest_clear_point(r, Point(1, 1), levels, any, p);
  ASSERT_TRUE(q.has_value());
  EXPECT_EQ(q->level, 1u);
  EXPECT_GE(inset(q->point, 10, 4), 1.5 - cell);
  EXPECT_LE((q->point - Point(1.5, 1.5)).norm(), 2 * cell);
  // accept refuses level 1 west of x = 5: level 1's nearest east of it beats level 2's points,
  // which lie nearer.
  const auto east = [](const Point& x, std::size_t k) { return k != 1 || x.x() >= 5; };
  const auto e = nearest_clear_point(r, Point(1, 1), levels, east, p);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->level, 1u);
  EXPECT_GE(e->point.x(), 5);
  EXPECT_LE(e->point.x(), 5 + 2 * cell);
  EXPECT_GE(inset(e->point, 10, 4), 1.5 - cell);
  // None refused everywhere, or a start outside the region: nullopt.
  const auto none = [](const Point&, std::size_t) { return false; };
  EXPECT_FALSE(nearest_clear_point(r, Point(1, 1), levels, none, p).has_value());
  EXPECT_FALSE(nearest_clear_point(r, Point(-1, 1), levels, any, p).has_value());
  const std::vector<double> bad{std::nan("")};
  EXPECT_THROW(nearest_clear_point(r, Point(1, 1), bad, any, p), Error);
}

// The clearest point of the corridor is on its midline (2 m from both walls), the nearest such
// point from (1, 1) at x = 2; with points west of x = 7 refused, at x = 7.
TEST(DropPoint, TheClearestReachablePointTheNearestOfEquals) {
  const Region r{rect(0, 0, 10, 4), {}};
  const GuideParams p;
  const double cell = p.resolution;
  const auto q = clearest_point(
      r, Point(1, 1), [](const Point&) { return true; }, p);
  ASSERT_TRUE(q.has_value());
  EXPECT_GE(inset(*q, 10, 4), 2 - cell);
  EXPECT_LE((*q - Point(2, 2)).norm(), 2 * cell);
  const auto e = clearest_point(
      r, Point(1, 1), [](const Point& x) { return x.x() >= 7; }, p);
  ASSERT_TRUE(e.has_value());
  EXPECT_GE(inset(*e, 10, 4), 2 - cell);
  EXPECT_LE((*e - Point(7, 2)).norm(), 2 * cell);
}

TEST(GuidePath, RejectsBadParametersAndPoints) {
  const Region r{rect(0, 0, 10, 10), {}};
  GuideParams p;
  p.resolution = -1;
  EXPECT_THROW(guide_path(r, Point(1, 1), Point(2, 2), p), Error);
  p = GuideParams{};
  p.comfort = std::nan("");
  EXPECT_THROW(validate(p), Error);
  EXPECT_THROW(guide_path(r, Point(1, std::nan("")), Point(2, 2), GuideParams{}), Error);
}

}  // namespace
}  // namespace rearm::executive
