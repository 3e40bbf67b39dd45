// Property test of the topology check against independent truth:
// seeded random scenes in a 10 × 10 m room (walls with doors, rectangles and star polygons,
// disk objects, a random radius standing for the robot or a robot–object pair); the verdict
// must agree with a 4-connected flood fill on a 400 × 400 raster of the same dilated
// geometry, rasterized here with plain double scanlines and segment distances (and
// test_support's geometry oracle, which shares no code with framework/geometry).
//
// Skipping near contacts, by a sandwich: with δ = 1.5 cells, the pessimistic raster (a cell
// free iff its centre is free and more than δ from every boundary) can only under-connect and
// the optimistic one (a cell blocked iff its centre is inside an obstacle and more than δ
// from its boundary) can only over-connect the true freespace (a cell centre is within
// 0.71 cells of every point of its cell). When both give the same verdict, that verdict is
// the truth; otherwise the scene is within a cell or two of a touching contact (a corridor of
// critical width, x or x* at a boundary) and is counted and skipped.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <numbers>
#include <vector>

#include "core/rng.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"
#include "topology/topology_check.h"
#include "topology/topology_scenes.h"

namespace rearm::topology {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;
using geometry::Region;
using test_scenes::rect;
using test_scenes::rotated_rect;

constexpr double kRoomSize = 10.0;                   // m
constexpr int kCells = 400;                          // raster cells per side
constexpr double kCell = kRoomSize / kCells;         // 2.5 cm
constexpr double kMargin = 1.5 * kCell;              // δ of the sandwich
constexpr double kPointClearance = kMargin + kCell;  // x, x* drawn this far from boundaries

struct Scene {
  std::vector<Polygon> familiar;
  std::vector<Disk> objects;
  double radius = 0;
  std::vector<Point> doors;  // centres of the wall doors (objects like to sit there)
};

bool disk_hits_polygon(const Disk& d, const Polygon& p) {
  return test_support::ray_cast_inside(p, d.center) ||
         test_support::boundary_distance(p, d.center) < d.radius;
}

Scene random_scene(Rng& rng) {
  Scene s;
  s.radius = rng.uniform(0.15, 0.45);
  const int walls = static_cast<int>(rng.uniform_int(0, 3));
  for (int w = 0; w < walls; ++w) {
    const bool horizontal = rng.bernoulli(0.5);
    const double at = rng.uniform(2.0, 8.0);
    const double thick = rng.uniform(0.1, 0.4);
    const double door = rng.uniform(1.5, 8.5);
    const double width = rng.uniform(0.3, 2.2);
    const double lo = door - width / 2, hi = door + width / 2;
    if (horizontal) {
      s.familiar.push_back(rect(0, at - thick / 2, lo, at + thick / 2));
      s.familiar.push_back(rect(hi, at - thick / 2, kRoomSize, at + thick / 2));
      s.doors.emplace_back(door, at);
    } else {
      s.familiar.push_back(rect(at - thick / 2, 0, at + thick / 2, lo));
      s.familiar.push_back(rect(at - thick / 2, hi, at + thick / 2, kRoomSize));
      s.doors.emplace_back(at, door);
    }
  }
  const int blocks = static_cast<int>(rng.uniform_int(0, 5));
  for (int b = 0; b < blocks; ++b) {
    const Point c(rng.uniform(1, 9), rng.uniform(1, 9));
    if (rng.bernoulli(0.5)) {
      s.familiar.push_back(rotated_rect(c, rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0),
                                        rng.uniform(0, std::numbers::pi)));
    } else {
      s.familiar.push_back(
          test_support::random_star(rng, static_cast<int>(rng.uniform_int(5, 9)), 0.3, 1.2, c));
    }
  }
  const int objects = static_cast<int>(rng.uniform_int(0, 8));
  for (int k = 0; k < objects; ++k) {
    for (int attempt = 0; attempt < 20; ++attempt) {
      Disk d;
      d.radius = rng.uniform(0.2, 0.6);
      if (!s.doors.empty() && rng.bernoulli(0.7)) {
        const Point& door = s.doors[rng.index(s.doors.size())];
        d.center = door + Point(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
      } else {
        d.center = Point(rng.uniform(0.5, 9.5), rng.uniform(0.5, 9.5));
      }
      bool ok = true;
      for (const Polygon& p : s.familiar) ok = ok && !disk_hits_polygon(d, p);
      for (const Disk& o : s.objects) {
        ok = ok && (o.center - d.center).norm() >= o.radius + d.radius;
      }
      if (ok) {
        s.objects.push_back(d);
        break;
      }
    }
  }
  return s;
}

// --- The independent raster. ---

// Per cell: centre inside some obstacle of the layer; within δ of some boundary; inside some
// obstacle and more than δ from its boundary.
struct Layer {
  std::vector<std::uint8_t> inside, near, deep;
  Layer() : inside(kCells * kCells, 0), near(kCells * kCells, 0), deep(kCells * kCells, 0) {}
};

Point centre(int i, int j) { return Point((i + 0.5) * kCell, (j + 0.5) * kCell); }

bool region_inside(const Region& r, const Point& p) {
  if (!test_support::ray_cast_inside(r.outer, p)) return false;
  for (const Polygon& h : r.holes) {
    if (test_support::ray_cast_inside(h, p)) return false;
  }
  return true;
}

double region_distance(const Region& r, const Point& p) {
  double d = test_support::boundary_distance(r.outer, p);
  for (const Polygon& h : r.holes) d = std::min(d, test_support::boundary_distance(h, p));
  return d;
}

int cell_of(double c) { return std::clamp(static_cast<int>(std::floor(c / kCell)), 0, kCells - 1); }

// Rasterizes one obstacle region (outer minus holes): centre inside by an even-odd scanline
// per row, "near" by segment distances in each edge's δ-box.
void add_region(Layer& layer, const Region& r) {
  std::vector<std::pair<Point, Point>> edges;
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const Point& v : r.outer.vertices) {
    x0 = std::min(x0, v.x());
    y0 = std::min(y0, v.y());
    x1 = std::max(x1, v.x());
    y1 = std::max(y1, v.y());
  }
  auto add_loop = [&edges](const Polygon& p) {
    for (std::size_t i = 0, n = p.size(); i < n; ++i) {
      edges.emplace_back(p.vertices[i], p.vertices[(i + 1) % n]);
    }
  };
  add_loop(r.outer);
  for (const Polygon& h : r.holes) add_loop(h);
  const int i0 = cell_of(x0 - kMargin), i1 = cell_of(x1 + kMargin);
  const int j0 = cell_of(y0 - kMargin), j1 = cell_of(y1 + kMargin);
  const int w = i1 - i0 + 1, h = j1 - j0 + 1;
  std::vector<std::uint8_t> in(static_cast<std::size_t>(w * h), 0), close(in.size(), 0);
  std::vector<double> xs;
  for (int j = j0; j <= j1; ++j) {
    const double y = (j + 0.5) * kCell;
    xs.clear();
    for (const auto& [a, b] : edges) {
      if ((a.y() > y) != (b.y() > y)) {
        xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      for (int i = std::max(i0, cell_of(xs[k]) - 1); i <= std::min(i1, cell_of(xs[k + 1]) + 1);
           ++i) {
        const double x = (i + 0.5) * kCell;
        if (x >= xs[k] && x < xs[k + 1]) in[(i - i0) * h + (j - j0)] = 1;
      }
    }
  }
  for (const auto& [a, b] : edges) {
    for (int i = cell_of(std::min(a.x(), b.x()) - kMargin);
         i <= cell_of(std::max(a.x(), b.x()) + kMargin); ++i) {
      for (int j = cell_of(std::min(a.y(), b.y()) - kMargin);
           j <= cell_of(std::max(a.y(), b.y()) + kMargin); ++j) {
        if (i < i0 || i > i1 || j < j0 || j > j1) continue;
        std::uint8_t& c = close[(i - i0) * h + (j - j0)];
        if (!c && test_support::segment_distance(a, b, centre(i, j)) <= kMargin) c = 1;
      }
    }
  }
  for (int i = i0; i <= i1; ++i) {
    for (int j = j0; j <= j1; ++j) {
      const int local = (i - i0) * h + (j - j0), k = i * kCells + j;
      layer.inside[k] |= in[local];
      layer.near[k] |= close[local];
      layer.deep[k] |= in[local] && !close[local];
    }
  }
}

// 4-connected flood fill over free cells from the cell of `from`; is the cell of `to` reached?
bool flood(const std::vector<std::uint8_t>& free, const Point& from, const Point& to) {
  const auto index = [](const Point& p) {
    const int i = std::clamp(static_cast<int>(std::floor(p.x() / kCell)), 0, kCells - 1);
    const int j = std::clamp(static_cast<int>(std::floor(p.y() / kCell)), 0, kCells - 1);
    return i * kCells + j;
  };
  const int start = index(from), goal = index(to);
  if (!free[start] || !free[goal]) return false;
  std::vector<std::uint8_t> seen(free.size(), 0);
  std::deque<int> queue{start};
  seen[start] = 1;
  while (!queue.empty()) {
    const int k = queue.front();
    queue.pop_front();
    if (k == goal) return true;
    const int i = k / kCells, j = k % kCells;
    const int next[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[0] >= kCells || n[1] < 0 || n[1] >= kCells) continue;
      const int m = n[0] * kCells + n[1];
      if (free[m] && !seen[m]) {
        seen[m] = 1;
        queue.push_back(m);
      }
    }
  }
  return false;
}

Verdict verdict_of(bool reach_with_objects, bool reach_without_objects) {
  if (reach_with_objects) return Verdict::kReachable;
  return reach_without_objects ? Verdict::kBlockedByObjects : Verdict::kBlockedByFixed;
}

struct Raster {
  Layer outside_bound, fixed, movable;

  explicit Raster(const TopologyInput& in) {
    // The complement of the bound: every cell starts "inside" it, the bound's regions carve it.
    Layer bound;
    for (const Region& r : in.bound) add_region(bound, r);
    for (int k = 0; k < kCells * kCells; ++k) {
      outside_bound.inside[k] = !bound.inside[k];
      outside_bound.near[k] = bound.near[k];
      outside_bound.deep[k] = !bound.inside[k] && !bound.near[k];
    }
    for (const auto& set : in.fixed) {
      for (const Region& r : set) add_region(fixed, r);
    }
    for (const Polygon& p : in.movable) add_region(movable, Region{p, {}});
  }

  // pessimistic: blocked iff inside or near; optimistic: blocked iff deep.
  std::vector<std::uint8_t> free_cells(bool pessimistic, bool objects_block) const {
    std::vector<std::uint8_t> free(kCells * kCells, 1);
    for (int k = 0; k < kCells * kCells; ++k) {
      for (const Layer* l : {&outside_bound, &fixed, &movable}) {
        if (l == &movable && !objects_block) continue;
        const bool blocked = pessimistic ? (l->inside[k] || l->near[k]) : l->deep[k];
        if (blocked) free[k] = 0;
      }
    }
    return free;
  }

  Verdict verdict(bool pessimistic, const Point& x, const Point& target) const {
    return verdict_of(flood(free_cells(pessimistic, true), x, target),
                      flood(free_cells(pessimistic, false), x, target));
  }
};

// Inside the bound, outside every fixed obstacle (and every object unless allowed), and at
// least kPointClearance from every boundary it must avoid.
bool good_point(const TopologyInput& in, const Point& p, bool allow_in_object) {
  bool in_bound = false;
  for (const Region& r : in.bound) {
    in_bound = in_bound || region_inside(r, p);
    if (region_distance(r, p) < kPointClearance) return false;
  }
  if (!in_bound) return false;
  for (const auto& set : in.fixed) {
    for (const Region& r : set) {
      if (region_inside(r, p) || region_distance(r, p) < kPointClearance) return false;
    }
  }
  for (const Polygon& m : in.movable) {
    const bool inside = test_support::ray_cast_inside(m, p);
    if ((inside && !allow_in_object) || test_support::boundary_distance(m, p) < kPointClearance) {
      return false;
    }
  }
  return true;
}

bool draw_point(Rng& rng, const TopologyInput& in, bool allow_in_object, Point& out) {
  for (int attempt = 0; attempt < 500; ++attempt) {
    const Point p(rng.uniform(0, kRoomSize), rng.uniform(0, kRoomSize));
    if (good_point(in, p, allow_in_object)) {
      out = p;
      return true;
    }
  }
  return false;
}

TEST(TopologyProperty, VerdictAgreesWithRasterFloodFill) {
  const std::size_t wanted = test_support::scaled(500);
  const std::size_t max_scenes = 4 * wanted;
  const Polygon room = rect(0, 0, kRoomSize, kRoomSize);
  std::size_t compared = 0, near_contact = 0, no_point = 0, disagreements = 0, scenes = 0;
  std::size_t by_verdict[3] = {0, 0, 0};
  std::size_t removal_checked = 0;
  for (std::uint64_t seed = 1; compared < wanted && scenes < max_scenes; ++seed, ++scenes) {
    Rng rng = Rng::derive(20240501, seed);
    const Scene s = random_scene(rng);
    TopologyInput in = make_input(room, s.familiar, s.objects, s.radius, {0, 0}, {0, 0});
    Point x, target;
    if (!draw_point(rng, in, false, x) || !draw_point(rng, in, rng.bernoulli(0.2), target)) {
      ++no_point;
      continue;
    }
    in.x = x;
    in.target = target;
    const Raster raster(in);
    const Verdict low = raster.verdict(true, x, target);
    const Verdict high = raster.verdict(false, x, target);
    if (low != high) {
      ++near_contact;
      continue;
    }
    ++compared;
    const TopologyResult t = check_topology(in);
    ++by_verdict[static_cast<int>(high)];
    if (t.verdict != high) {
      ++disagreements;
      ADD_FAILURE() << "seed " << seed << ": check says " << to_string(t.verdict)
                    << ", raster says " << to_string(high) << "; x = " << x.transpose()
                    << ", x* = " << target.transpose() << ", radius " << s.radius << "; "
                    << t.reason;
      continue;
    }
    EXPECT_EQ(t.blocking.empty(), t.verdict != Verdict::kBlockedByObjects) << "seed " << seed;
    EXPECT_EQ(geometry::contains(t.enclosing, target) || t.verdict != Verdict::kReachable, true)
        << "seed " << seed;
    // Removing the stack B_M from the scene opens the way to x*.
    if (t.verdict == Verdict::kBlockedByObjects) {
      TopologyInput cleared = in;
      cleared.movable.clear();
      cleared.movable_ids.clear();
      for (std::size_t k = 0; k < in.movable.size(); ++k) {
        if (std::find(t.blocking.begin(), t.blocking.end(), in.movable_ids[k]) ==
            t.blocking.end()) {
          cleared.movable.push_back(in.movable[k]);
          cleared.movable_ids.push_back(in.movable_ids[k]);
        }
      }
      EXPECT_EQ(check_topology(cleared).verdict, Verdict::kReachable)
          << "seed " << seed << ": removing B_M does not free x*; " << t.reason;
      ++removal_checked;
    }
  }
  std::printf(
      "topology property: %zu scenes drawn, %zu compared (%zu reachable, %zu blocked by "
      "objects, %zu blocked by fixed), %zu skipped near a contact, %zu without a clear x/x*, "
      "%zu disagreements; B_M removal checked on %zu\n",
      scenes, compared, by_verdict[0], by_verdict[1], by_verdict[2], near_contact, no_point,
      disagreements, removal_checked);
  EXPECT_EQ(disagreements, 0u);
  EXPECT_GE(compared, wanted);
  if (test_support::test_scale() >= 1) {
    EXPECT_GE(compared, 500u);
    // Every verdict is exercised.
    for (std::size_t n : by_verdict) EXPECT_GE(n, 25u);
  }
}

}  // namespace
}  // namespace rearm::topology
