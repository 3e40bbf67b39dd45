// The localized exact Booleans of the topology check (topology/freespace.h) against one global
// Boolean (geometry::subtract / geometry::intersect, a single CGAL overlay of everything) over
// seeded random scenes in which shapes touch, overlap, cross the workspace boundary and enclose
// islands: the same components with the same areas, and no area in either difference. Plus the
// cases the windows must handle by hand: a loop vertex exactly on a window's side, a fixed
// region with a hole, overlapping bound regions, everything isolated, nothing at all.
#include "topology/freespace.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "geometry/boolean.h"
#include "geometry/convex.h"
#include "geometry/dilation.h"
#include "support/scale.h"
#include "topology/topology_check.h"
#include "topology/topology_scenes.h"

namespace rearm::topology {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;
using geometry::Region;
using geometry::RegionSet;
using test_scenes::rect;

// Area left over between two roundings of one exact set (m²): rounding moves a vertex by
// ~1e-15 m in a 10 m scene, so slivers stay far below this.
constexpr double kAreaTolerance = 1e-8;

std::vector<double> areas(const RegionSet& s) {
  std::vector<double> out;
  for (const Region& r : s) out.push_back(r.area());
  std::sort(out.begin(), out.end());
  return out;
}

// Two roundings of the same exact set: as many regions, the same areas and hole counts, and
// the same answer to "inside?" at random points (a point within rounding distance, ~1e-15 m,
// of a boundary is drawn with probability ~1e-14; a wrong piece shows at many points). No
// Boolean of the two: their difference is made of slivers that geometry::subtract cannot
// round.
void expect_same_set(const RegionSet& got, const RegionSet& want, const std::string& what,
                     Rng& rng) {
  ASSERT_EQ(got.size(), want.size()) << what;
  const std::vector<double> a = areas(got), b = areas(want);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], kAreaTolerance) << what;
  std::vector<std::size_t> ha, hb;
  for (const Region& r : got) ha.push_back(r.holes.size());
  for (const Region& r : want) hb.push_back(r.holes.size());
  std::sort(ha.begin(), ha.end());
  std::sort(hb.begin(), hb.end());
  EXPECT_EQ(ha, hb) << what;
  if (want.empty()) return;
  Eigen::AlignedBox2d box;
  for (const Region& r : want) {
    for (const Point& v : r.outer.vertices) box.extend(v);
  }
  for (int k = 0; k < 300; ++k) {
    const Point p(rng.uniform(box.min().x(), box.max().x()),
                  rng.uniform(box.min().y(), box.max().y()));
    ASSERT_EQ(geometry::contains(got, p), geometry::contains(want, p))
        << what << " at " << p.transpose();
  }
}

RegionSet flatten(const std::vector<RegionSet>& sets) {
  RegionSet out;
  for (const RegionSet& s : sets) out.insert(out.end(), s.begin(), s.end());
  return out;
}

RegionSet regions_of(const std::vector<Polygon>& polygons) {
  RegionSet out;
  for (const Polygon& p : polygons) out.push_back(Region{p, {}});
  return out;
}

// The components of bound − ∪fixed, of that minus the objects, and every step-4 clipping of the
// grown objects to a component, localized and global.
void check_scene(const RegionSet& bound, const RegionSet& fixed,
                 const std::vector<Polygon>& movable, const std::string& what) {
  Rng rng = Rng::derive(77, std::hash<std::string>{}(what));
  const detail::ExactFreespace fs(bound, fixed);
  expect_same_set(fs.components(), geometry::subtract(bound, fixed), what + ": bound - fixed", rng);
  RegionSet all = fixed;
  for (const Polygon& p : movable) all.push_back(Region{p, {}});
  expect_same_set(fs.subtract(movable), geometry::subtract(bound, all),
                  what + ": bound - fixed - movable", rng);
  std::vector<Polygon> grown;
  for (const Polygon& p : movable) grown.push_back(geometry::offset_convex(p, 1e-8));
  for (std::size_t k = 0; k < fs.components().size(); ++k) {
    const Region& c = fs.components()[k];
    const detail::Clusters clusters = detail::clip_union(grown, c);
    ASSERT_EQ(clusters.candidates.size(), clusters.regions.size());
    ASSERT_EQ(clusters.sole.size(), clusters.regions.size());
    const RegionSet want =
        grown.empty() ? RegionSet{} : geometry::intersect(regions_of(grown), {c});
    expect_same_set(clusters.regions, want, what + ": clusters in component " + std::to_string(k),
                    rng);
    // Every object touching a cluster is among its candidates.
    for (std::size_t j = 0; j < clusters.regions.size(); ++j) {
      for (std::size_t i = 0; i < grown.size(); ++i) {
        const bool listed = std::find(clusters.candidates[j].begin(), clusters.candidates[j].end(),
                                      i) != clusters.candidates[j].end();
        if (!listed) {
          EXPECT_FALSE(geometry::intersects({clusters.regions[j]}, {Region{movable[i], {}}}))
              << what << ": object " << i << " touches cluster " << j << " but is no candidate";
        }
      }
    }
  }
}

TEST(Freespace, LocalizedEqualsGlobalOverRandomScenes) {
  const std::size_t scenes = test_support::scaled(300);
  std::size_t objects = 0;
  for (std::uint64_t seed = 1; seed <= scenes; ++seed) {
    Rng rng = Rng::derive(20261123, seed);
    const test_scenes::Scene s = test_scenes::random_scene(rng);
    const TopologyInput in =
        make_input(s.workspace, s.familiar, s.objects, s.radius, {0, 0}, {0, 0});
    objects += in.movable.size();
    check_scene(in.bound, flatten(in.fixed), in.movable, "seed " + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
  std::printf("freespace: %zu scenes, %zu objects compared with the global Boolean\n", scenes,
              objects);
}

TEST(Freespace, DirectInputsWithHolesAndOverlappingBoundRegions) {
  // Two overlapping bound regions (united), one with a hole; a fixed ring (a region with a hole:
  // its inside is an island) both isolated and crossing the bound; objects inside the ring's
  // island, across the ring, and bridging the bound's hole.
  const RegionSet bound = {Region{rect(0, 0, 6, 6), {rect(2, 2, 3, 3)}},
                           Region{rect(5, 1, 10, 5), {}}};
  const Region ring{rect(6.5, 1.5, 8.5, 3.5), {rect(7, 2, 8, 3)}};
  const Region cut_ring{rect(-1, 4, 1.5, 7), {rect(-0.5, 4.5, 1, 6.5)}};
  const RegionSet fixed = {ring, cut_ring, Region{rect(4, 4, 4.5, 4.5), {}}};
  const std::vector<Polygon> movable = {
      geometry::disk_polygon(Disk{{7.5, 2.5}, 0.2}),   // in the ring's island
      geometry::disk_polygon(Disk{{6.5, 2.5}, 0.3}),   // across the ring
      geometry::disk_polygon(Disk{{2.5, 3.2}, 0.4}),   // across the bound's hole
      geometry::disk_polygon(Disk{{1.0, 1.0}, 0.3}),   // isolated
      geometry::disk_polygon(Disk{{9.9, 3.0}, 0.3})};  // across the bound's boundary
  check_scene(bound, fixed, movable, "direct");
  check_scene(bound, fixed, {}, "direct, no objects");
  check_scene(bound, {}, movable, "direct, no fixed");
}

TEST(Freespace, WindowSideThroughALoopVertex) {
  // The window around an object is its box grown by 1/16 of the box's larger side on each side
  // (freespace.cpp, kWindowMargin). Put wall vertices exactly on that first window's sides (and
  // corners): the splice must take a larger window and still match the global Boolean.
  const Polygon object = rect(4, 4, 5.6, 5);                     // a box-shaped "object", 1.6 × 1
  const double m = (1.0 / 16) * std::max(5.6 - 4.0, 5.0 - 4.0);  // as freespace.cpp computes it
  const double x0 = 4 - m, y0 = 4 - m, x1 = 5.6 + m, y1 = 5 + m;
  const RegionSet bound = {Region{rect(0, 0, 10, 10), {}}};
  const RegionSet fixed = {
      Region{Polygon{{{x0, 2}, {x0 + 0.5, 2}, {x0 + 0.5, 4.5}, {x0, 4.5}}}, {}},  // on the side
      Region{Polygon{{{x1, y1}, {x1 + 1, y1}, {x1 + 1, y1 + 1}}}, {}},            // at a corner
      Region{Polygon{{{4.6, y0 - 1}, {5.0, y0 - 1}, {4.8, y0}}}, {}},             // tip on it
      Region{rect(4.5, 4.9, 7, 5.05), {}}};                                       // crossing
  check_scene(bound, fixed, {object}, "window through vertices");
}

TEST(Freespace, PinchedLoopTakesThePlainOverlay) {
  // Two squares touching at a corner: bound − fixed has a hole whose one cycle passes through
  // that corner twice, which the windows do not splice; an object across it is subtracted in
  // one overlay instead. A triangle touching the bound's boundary at a vertex: CGAL returns it
  // as a hole touching the outer cycle, which the localization must not take for disjoint.
  const RegionSet bound = {Region{rect(0, 0, 10, 10), {}}};
  const RegionSet squares = {Region{rect(4, 4, 5, 5), {}}, Region{rect(5, 5, 6, 6), {}}};
  check_scene(bound, squares, {geometry::disk_polygon(Disk{{5.8, 4.5}, 0.5})}, "pinched hole");
  check_scene(bound, squares, {geometry::disk_polygon(Disk{{5.0, 5.0}, 0.2})}, "at the pinch");
  const RegionSet triangle = {Region{Polygon{{{5, 0}, {6, 2}, {4, 2}}}, {}}};
  check_scene(bound, triangle, {geometry::disk_polygon(Disk{{5, 1.8}, 0.5})}, "touching hole");
  check_scene(bound, triangle, {geometry::disk_polygon(Disk{{5, 0.2}, 0.3})}, "at the touch");
  check_scene(bound, triangle, {geometry::disk_polygon(Disk{{8, 8}, 0.3})}, "away");
  // Two bound squares touching at a corner: one outer cycle through it twice.
  const RegionSet bow = {Region{rect(0, 0, 5, 5), {}}, Region{rect(5, 5, 10, 10), {}}};
  check_scene(bow, {}, {geometry::disk_polygon(Disk{{4.8, 4.0}, 0.5})}, "pinched outer");
  check_scene(bow, {}, {geometry::disk_polygon(Disk{{5.0, 5.0}, 0.3})}, "at the outer pinch");
}

TEST(Freespace, IsolatedObjectsNeedNoOverlay) {
  const RegionSet bound = {Region{rect(0, 0, 10, 10), {}}};
  const RegionSet fixed = {Region{rect(1, 1, 2, 2), {}}, Region{rect(7, 7, 8, 9), {}}};
  std::vector<Polygon> movable;
  for (int k = 0; k < 5; ++k) {
    movable.push_back(geometry::disk_polygon(Disk{{1.5 + 1.7 * k, 5}, 0.5}));
  }
  check_scene(bound, fixed, movable, "isolated");
  const detail::ExactFreespace fs(bound, fixed);
  const RegionSet f = fs.subtract(movable);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f.front().holes.size(), 7u);  // two fixed obstacles, five objects
  // An object wholly inside a fixed obstacle changes nothing.
  const RegionSet g = fs.subtract({rect(7.2, 7.2, 7.8, 8.8)});
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g.front().holes.size(), 2u);
}

}  // namespace
}  // namespace rearm::topology
