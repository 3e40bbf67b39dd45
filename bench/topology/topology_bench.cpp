// The topology check's speed (docs/executive.md "Benchmarks
// required"): check_topology swept over the number of movable objects (1, 2, 4, 8, 16, 32)
// × familiar obstacles (0, 4, 16, 64), plus the target point of docs/executive.md (10 objects × 20
// obstacles, ≤ 1 ms), for the robot alone (radius 0.2) and carrying an object (the pair,
// radius 0.2 + 0.3; the carried object left out); each without and with a TopologyCache.
//
// Scene (seeded): a square room of 2.5 m grid cells, side ceil(sqrt(objects + obstacles + 2))
// cells (at least 4), so every shape has its own cell; each familiar obstacle a rotated
// rectangle or a star polygon of extent ≤ 1.2 m, each object a disk of radius 0.3, jittered
// in its cell. The robot starts in the bottom-left cell. kVariants variants of each scene share
// the familiar obstacles and move the objects, x and x* within their cells (variant 0 is the
// scene of the earlier single-input benchmark); the calls cycle through them. Two targets:
//  - FarCorner: x* in the top-right cell (usually reachable: steps 1–2 only);
//  - InsideObject: x* at the centre of the object farthest from x, so every call runs all
//    four steps (blocked by objects, the graph search included).
// Modes:
//  - BM_Topology<target>: check_topology(in), no cache: every call computes bound − ∪fixed
//    (the cold cost, and what the executive pays after the map of familiar obstacles changed);
//  - BM_Topology<target>Cached: check_topology(in, cache) with one cache warmed on variant 0:
//    the familiar obstacles unchanged, the objects, x and x* changing (the executive's loop);
//  - BM_MakeInput / BM_MakeInputCached (10 × 20 only): make_input, which the executive calls
//    whenever an object moves, without and with the cache (warm: only the objects change);
//  - BM_TopologyTickCached (10 × 20 only): make_input(…, cache) + check_topology(…, cache),
//    a whole re-check after objects moved, warm.
// Counters: objects, obstacles, carrying, verdict (variant 0: 0 reachable, 1 objects, 2 fixed),
// reachable / by_objects / by_fixed (verdicts over the variants), blocking (|B_M|, variant
// 0), components (|F_list|, variant 0).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "core/rng.h"
#include "geometry/convex.h"
#include "support/geometry_oracle.h"
#include "topology/topology_check.h"
#include "topology/topology_scenes.h"

namespace {

using rearm::Rng;
using rearm::geometry::Disk;
using rearm::geometry::Point;
using rearm::geometry::Polygon;
using rearm::topology::TopologyCache;
using rearm::topology::TopologyInput;
using rearm::topology::test_scenes::rotated_rect;

constexpr std::uint64_t kSeed = 42;
constexpr double kCellSize = 2.5;      // m
constexpr double kRobotRadius = 0.2;   // m
constexpr double kObjectRadius = 0.3;  // m (also the carried object's)
constexpr double kJitter = 0.3;        // m, of a shape, x or x* in its cell
constexpr double kMinTime = 0.2;       // s per benchmark
constexpr int kVariants = 8;

// One scene's fixed part and the cells of its objects.
struct Layout {
  int side = 0;
  Polygon room;
  std::vector<Polygon> familiar;
  std::vector<Point> object_cells;  // cell centres
  std::vector<Disk> objects;        // variant 0
};

Point cell_centre(int side, int c) {
  return Point((c % side + 0.5) * kCellSize, (c / side + 0.5) * kCellSize);
}

Layout layout(int objects, int obstacles) {
  Rng rng(kSeed + 1000 * static_cast<std::uint64_t>(objects) +
          static_cast<std::uint64_t>(obstacles));
  Layout l;
  l.side = std::max(4, static_cast<int>(std::ceil(std::sqrt(objects + obstacles + 2.0))));
  const double size = l.side * kCellSize;
  l.room = Polygon{{{0, 0}, {size, 0}, {size, size}, {0, size}}};
  // Cells, shuffled; the first (bottom-left) and last (top-right) are kept for x and x*.
  std::vector<int> cells;
  for (int c = 1; c < l.side * l.side - 1; ++c) cells.push_back(c);
  for (std::size_t i = cells.size(); i > 1; --i) std::swap(cells[i - 1], cells[rng.index(i)]);
  // As the earlier benchmark drew them (variant 0 is its scene).
  auto jittered = [&](int c) {
    const int side = l.side;
    return Point((c % side + 0.5) * kCellSize + rng.uniform(-kJitter, kJitter),
                 (c / side + 0.5) * kCellSize + rng.uniform(-kJitter, kJitter));
  };
  std::size_t next = 0;
  for (int k = 0; k < obstacles; ++k) {
    const Point c = jittered(cells[next++]);
    if (rng.bernoulli(0.5)) {
      l.familiar.push_back(rotated_rect(c, rng.uniform(0.4, 1.2), rng.uniform(0.2, 0.8),
                                        rng.uniform(0, std::numbers::pi)));
    } else {
      l.familiar.push_back(rearm::test_support::random_star(
          rng, static_cast<int>(rng.uniform_int(5, 9)), 0.25, 0.6, c));
    }
  }
  for (int k = 0; k < objects; ++k) {
    const int c = cells[next++];
    l.object_cells.push_back(cell_centre(l.side, c));
    l.objects.push_back(Disk{jittered(c), kObjectRadius});
  }
  return l;
}

// The inputs of variant v (0: the layout's objects, x and x* at their cell centres).
TopologyInput variant(const Layout& l, int v, bool carrying, bool target_in_object,
                      TopologyCache* cache) {
  Rng rng = Rng::derive(kSeed, static_cast<std::uint64_t>(v));
  auto jitter = [&]() {
    if (v == 0) return Point(0, 0);
    const double dx = rng.uniform(-kJitter, kJitter);
    const double dy = rng.uniform(-kJitter, kJitter);
    return Point(dx, dy);
  };
  std::vector<Disk> objects = l.objects;
  if (v != 0) {
    for (std::size_t k = 0; k < objects.size(); ++k)
      objects[k].center = l.object_cells[k] + jitter();
  }
  const Point x = cell_centre(l.side, 0) + jitter();
  Point target = cell_centre(l.side, l.side * l.side - 1) + jitter();
  std::vector<Disk> disks;
  if (carrying) disks.push_back(Disk{x, kObjectRadius});  // in the gripper, left out
  disks.insert(disks.end(), objects.begin(), objects.end());
  if (target_in_object) {
    double far = -1;
    for (const Disk& d : objects) {
      if ((d.center - x).norm() > far) {
        far = (d.center - x).norm();
        target = d.center;
      }
    }
  }
  const double radius = carrying ? kRobotRadius + kObjectRadius : kRobotRadius;
  const std::optional<std::size_t> carried =
      carrying ? std::optional<std::size_t>(0) : std::nullopt;
  if (cache != nullptr) {
    return rearm::topology::make_input(l.room, l.familiar, disks, radius, x, target, carried,
                                       *cache);
  }
  return rearm::topology::make_input(l.room, l.familiar, disks, radius, x, target, carried);
}

void counters(benchmark::State& state, const std::vector<TopologyInput>& inputs) {
  int verdicts[3] = {0, 0, 0};
  rearm::topology::TopologyResult first;
  for (std::size_t v = 0; v < inputs.size(); ++v) {
    const rearm::topology::TopologyResult r = rearm::topology::check_topology(inputs[v]);
    ++verdicts[static_cast<int>(r.verdict)];
    if (v == 0) first = r;
  }
  state.counters["objects"] = static_cast<double>(state.range(0));
  state.counters["obstacles"] = static_cast<double>(state.range(1));
  state.counters["carrying"] = static_cast<double>(state.range(2));
  state.counters["verdict"] = static_cast<double>(first.verdict);
  state.counters["reachable"] = verdicts[0];
  state.counters["by_objects"] = verdicts[1];
  state.counters["by_fixed"] = verdicts[2];
  state.counters["blocking"] = static_cast<double>(first.blocking.size());
  state.counters["components"] = static_cast<double>(first.components.size());
}

void run(benchmark::State& state, bool target_in_object, bool cached) {
  const int objects = static_cast<int>(state.range(0));
  const int obstacles = static_cast<int>(state.range(1));
  const bool carrying = state.range(2) != 0;
  const Layout l = layout(objects, obstacles);
  TopologyCache cache;
  std::vector<TopologyInput> inputs;
  for (int v = 0; v < kVariants; ++v) {
    inputs.push_back(variant(l, v, carrying, target_in_object, cached ? &cache : nullptr));
  }
  if (cached) rearm::topology::check_topology(inputs.front(), cache);  // warm
  std::size_t i = 0;
  for (auto _ : state) {
    const TopologyInput& in = inputs[i++ % inputs.size()];
    if (cached) {
      benchmark::DoNotOptimize(rearm::topology::check_topology(in, cache));
    } else {
      benchmark::DoNotOptimize(rearm::topology::check_topology(in));
    }
  }
  counters(state, inputs);
}

void BM_TopologyFarCorner(benchmark::State& state) { run(state, false, false); }
void BM_TopologyInsideObject(benchmark::State& state) { run(state, true, false); }
void BM_TopologyFarCornerCached(benchmark::State& state) { run(state, false, true); }
void BM_TopologyInsideObjectCached(benchmark::State& state) { run(state, true, true); }

// make_input alone, and a whole warm re-check (make_input + check_topology), variants cycling.
void make_input_run(benchmark::State& state, bool cached, bool check) {
  const bool carrying = state.range(2) != 0;
  const Layout l = layout(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  TopologyCache cache;
  std::vector<TopologyInput> inputs;
  for (int v = 0; v < kVariants; ++v) inputs.push_back(variant(l, v, carrying, false, nullptr));
  if (cached) rearm::topology::check_topology(variant(l, 0, carrying, false, &cache), cache);
  int v = 0;
  for (auto _ : state) {
    const TopologyInput in =
        variant(l, v++ % kVariants, carrying, false, cached ? &cache : nullptr);
    if (check) benchmark::DoNotOptimize(rearm::topology::check_topology(in, cache));
    benchmark::DoNotOptimize(in);
  }
  counters(state, inputs);
}

void BM_MakeInput(benchmark::State& state) { make_input_run(state, false, false); }
void BM_MakeInputCached(benchmark::State& state) { make_input_run(state, true, false); }
void BM_TopologyTickCached(benchmark::State& state) { make_input_run(state, true, true); }

void sweep(benchmark::internal::Benchmark* b) {
  b->ArgNames({"objects", "obstacles", "carrying"});
  for (int carrying : {0, 1}) {
    for (int obstacles : {0, 4, 16, 64}) {
      for (int objects : {1, 2, 4, 8, 16, 32}) b->Args({objects, obstacles, carrying});
    }
    b->Args({10, 20, carrying});  // the target point (10 objects x 20 obstacles)
  }
  b->Unit(benchmark::kMicrosecond)->MinTime(kMinTime);
}

void target_point(benchmark::internal::Benchmark* b) {
  b->ArgNames({"objects", "obstacles", "carrying"});
  for (int carrying : {0, 1}) b->Args({10, 20, carrying});
  b->Unit(benchmark::kMicrosecond)->MinTime(kMinTime);
}

BENCHMARK(BM_TopologyFarCorner)->Apply(sweep);
BENCHMARK(BM_TopologyInsideObject)->Apply(sweep);
BENCHMARK(BM_TopologyFarCornerCached)->Apply(sweep);
BENCHMARK(BM_TopologyInsideObjectCached)->Apply(sweep);
BENCHMARK(BM_MakeInput)->Apply(target_point);
BENCHMARK(BM_MakeInputCached)->Apply(target_point);
BENCHMARK(BM_TopologyTickCached)->Apply(target_point);

}  // namespace

BENCHMARK_MAIN();
