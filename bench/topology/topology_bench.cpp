// The topology check's speed (issue 5, acceptance 4; docs/executive.md "Benchmarks
// required"): check_topology swept over the number of movable objects (1, 2, 4, 8, 16, 32)
// × familiar obstacles (0, 4, 16, 64), plus the target point of issue 5 (10 objects × 20
// obstacles, ≤ 1 ms), for the robot alone (radius 0.2) and carrying an object (the pair,
// radius 0.2 + 0.3; the carried object left out).
//
// Scene (seeded): a square room of 2.5 m grid cells, side ceil(sqrt(objects + obstacles + 2))
// cells (at least 4), so every shape has its own cell; each familiar obstacle a rotated
// rectangle or a star polygon of extent ≤ 1.2 m, each object a disk of radius 0.3, jittered
// in its cell. The robot starts in the bottom-left cell. Two targets:
//  - BM_TopologyFarCorner: x* in the top-right cell (usually reachable: step 1–2 only);
//  - BM_TopologyInsideObject: x* at the centre of the object farthest from x, so every call
//    runs all four steps (blocked by objects, the graph search included).
// Counters: objects, obstacles, carrying, verdict (0 reachable, 1 objects, 2 fixed), blocking
// (|B_M|), components (|F_list|).
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

namespace {

using rearm::Rng;
using rearm::geometry::Disk;
using rearm::geometry::Point;
using rearm::geometry::Polygon;
using rearm::topology::TopologyInput;

constexpr std::uint64_t kSeed = 42;
constexpr double kCellSize = 2.5;      // m
constexpr double kRobotRadius = 0.2;   // m
constexpr double kObjectRadius = 0.3;  // m (also the carried object's)
constexpr double kMinTime = 0.2;       // s per benchmark

Polygon rotated_rect(const Point& c, double w, double h, double angle) {
  const Eigen::Rotation2Dd rot(angle);
  Polygon p;
  for (const Point& v :
       {Point(-w / 2, -h / 2), Point(w / 2, -h / 2), Point(w / 2, h / 2), Point(-w / 2, h / 2)}) {
    p.vertices.push_back(c + rot * v);
  }
  return p;
}

TopologyInput scene(int objects, int obstacles, bool carrying, bool target_in_object) {
  Rng rng(kSeed + 1000 * static_cast<std::uint64_t>(objects) +
          static_cast<std::uint64_t>(obstacles));
  const int side = std::max(4, static_cast<int>(std::ceil(std::sqrt(objects + obstacles + 2.0))));
  const double size = side * kCellSize;
  const Polygon room{{{0, 0}, {size, 0}, {size, size}, {0, size}}};
  // Cells, shuffled; the first (bottom-left) and last (top-right) are kept for x and x*.
  std::vector<int> cells;
  for (int c = 1; c < side * side - 1; ++c) cells.push_back(c);
  for (std::size_t i = cells.size(); i > 1; --i) std::swap(cells[i - 1], cells[rng.index(i)]);
  auto cell_centre = [&](int c) {
    return Point((c % side + 0.5) * kCellSize + rng.uniform(-0.3, 0.3),
                 (c / side + 0.5) * kCellSize + rng.uniform(-0.3, 0.3));
  };
  std::size_t next = 0;
  std::vector<Polygon> familiar;
  for (int k = 0; k < obstacles; ++k) {
    const Point c = cell_centre(cells[next++]);
    if (rng.bernoulli(0.5)) {
      familiar.push_back(rotated_rect(c, rng.uniform(0.4, 1.2), rng.uniform(0.2, 0.8),
                                      rng.uniform(0, std::numbers::pi)));
    } else {
      familiar.push_back(rearm::test_support::random_star(
          rng, static_cast<int>(rng.uniform_int(5, 9)), 0.25, 0.6, c));
    }
  }
  const Point x(0.5 * kCellSize, 0.5 * kCellSize);
  std::vector<Disk> disks;
  if (carrying) disks.push_back(Disk{x, kObjectRadius});  // in the gripper, left out
  for (int k = 0; k < objects; ++k)
    disks.push_back(Disk{cell_centre(cells[next++]), kObjectRadius});
  Point target(size - 0.5 * kCellSize, size - 0.5 * kCellSize);
  if (target_in_object) {
    double far = -1;
    for (std::size_t k = carrying ? 1 : 0; k < disks.size(); ++k) {
      if ((disks[k].center - x).norm() > far) {
        far = (disks[k].center - x).norm();
        target = disks[k].center;
      }
    }
  }
  const double radius = carrying ? kRobotRadius + kObjectRadius : kRobotRadius;
  return rearm::topology::make_input(room, familiar, disks, radius, x, target,
                                     carrying ? std::optional<std::size_t>(0) : std::nullopt);
}

void run(benchmark::State& state, bool target_in_object) {
  const int objects = static_cast<int>(state.range(0));
  const int obstacles = static_cast<int>(state.range(1));
  const bool carrying = state.range(2) != 0;
  const TopologyInput in = scene(objects, obstacles, carrying, target_in_object);
  rearm::topology::TopologyResult last;
  for (auto _ : state) {
    last = rearm::topology::check_topology(in);
    benchmark::DoNotOptimize(last);
  }
  state.counters["objects"] = objects;
  state.counters["obstacles"] = obstacles;
  state.counters["carrying"] = carrying;
  state.counters["verdict"] = static_cast<double>(last.verdict);
  state.counters["blocking"] = static_cast<double>(last.blocking.size());
  state.counters["components"] = static_cast<double>(last.components.size());
}

void BM_TopologyFarCorner(benchmark::State& state) { run(state, false); }
void BM_TopologyInsideObject(benchmark::State& state) { run(state, true); }

void sweep(benchmark::internal::Benchmark* b) {
  b->ArgNames({"objects", "obstacles", "carrying"});
  for (int carrying : {0, 1}) {
    for (int obstacles : {0, 4, 16, 64}) {
      for (int objects : {1, 2, 4, 8, 16, 32}) b->Args({objects, obstacles, carrying});
    }
    b->Args({10, 20, carrying});  // the target point of issue 5
  }
  b->Unit(benchmark::kMicrosecond)->MinTime(kMinTime);
}

BENCHMARK(BM_TopologyFarCorner)->Apply(sweep);
BENCHMARK(BM_TopologyInsideObject)->Apply(sweep);

}  // namespace

BENCHMARK_MAIN();
