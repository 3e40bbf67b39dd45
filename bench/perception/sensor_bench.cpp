// Perception per control tick (paper §II, docs/reactive.md §2): SemanticMap::update in a
// 20 x 20 m room with K familiar non-convex obstacles (K = 1..20) and 4 unknown convex ones,
// sensor range 3 m, for a robot
// - `moving`: driving a closed loop, 2 cm per tick; the visible fragments change at every tick
//   while an unknown obstacle is in sight, which is about half the loop (counter `changed` =
//   fraction of ticks that bumped the version);
// - `jitter`: standing still up to 1e-9 m of rounding, which recomputes everything and finds
//   no change;
// - `still`: at exactly the same position (the update's shortcut).
// Plus the two sensor primitives: a fragment (32-gon clip) and a familiar visibility test.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/rng.h"
#include "perception/semantic_map.h"
#include "perception/sensor.h"

namespace {

using rearm::Rng;
using rearm::perception::Disk;
using rearm::perception::Point;
using rearm::perception::Polygon;
using rearm::perception::SemanticMap;
using rearm::perception::Sensor;
using rearm::perception::World;

constexpr double kRange = 3.0;

Polygon Star(Rng& rng, int n, double r_min, double r_max, const Point& c) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * (k + rng.uniform(0.1, 0.9)) / n;
    p.vertices.push_back(c + rng.uniform(r_min, r_max) * Point(std::cos(a), std::sin(a)));
  }
  return p;
}

std::string Name(const char* prefix, int i) {
  std::string s = prefix;
  s += std::to_string(i);
  return s;
}

// K familiar stars (10 vertices) and 4 unknown convex 8-gons scattered over the room.
World Room(int k) {
  Rng rng(42);
  World w;
  w.workspace = Polygon{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}};
  for (int i = 0; i < k; ++i) {
    const Point c(rng.uniform(-8.5, 8.5), rng.uniform(-8.5, 8.5));
    w.familiar.push_back({Name("F", i), Star(rng, 10, 0.4, 1.2, c)});
  }
  for (int i = 0; i < 4; ++i) {
    const double a = std::numbers::pi / 2 * i;
    const Point c = 5.5 * Point(std::cos(a), std::sin(a));
    w.unknown.push_back({Name("U", i), Star(rng, 8, 1.0, 1.0, c)});  // on a circle: convex
  }
  w.movable.push_back({"M1", Disk{Point(0, 0), 0.3}});
  w.movable.push_back({"M2", Disk{Point(1, 1), 0.3}});
  return w;
}

// The robot's loop: a circle of radius 5 m through the unknown obstacles' neighbourhood.
Point OnLoop(long tick) {
  const double a = 0.02 / 5 * static_cast<double>(tick);
  return 5 * Point(std::cos(a), std::sin(a)) + Point(0.3, 0.3);
}

void BM_UpdateMoving(benchmark::State& state) {
  SemanticMap map(Room(static_cast<int>(state.range(0))), Sensor({.range = kRange}));
  long tick = 0;
  long changed = 0;
  for (auto _ : state) {
    changed += map.update(OnLoop(tick++));
    benchmark::DoNotOptimize(map.version());
  }
  state.counters["changed"] = static_cast<double>(changed) / static_cast<double>(tick);
  state.counters["visible"] = static_cast<double>(map.unknown().size());
}
BENCHMARK(BM_UpdateMoving)->Arg(1)->Arg(5)->Arg(10)->Arg(20);

void BM_UpdateJitter(benchmark::State& state) {
  SemanticMap map(Room(static_cast<int>(state.range(0))), Sensor({.range = kRange}));
  const Point x = OnLoop(0);
  map.update(x);
  long tick = 0;
  long changed = 0;
  for (auto _ : state) {
    const double e = (tick++ % 2 == 0) ? 1e-9 : -1e-9;
    changed += map.update(x + Point(e, e));
  }
  state.counters["changed"] = static_cast<double>(changed) / static_cast<double>(tick);
  state.counters["visible"] = static_cast<double>(map.unknown().size());
}
BENCHMARK(BM_UpdateJitter)->Arg(1)->Arg(5)->Arg(10)->Arg(20);

void BM_UpdateStill(benchmark::State& state) {
  SemanticMap map(Room(static_cast<int>(state.range(0))), Sensor({.range = kRange}));
  const Point x = OnLoop(0);
  map.update(x);
  for (auto _ : state) benchmark::DoNotOptimize(map.update(x));
}
BENCHMARK(BM_UpdateStill)->Arg(1)->Arg(20);

void BM_Fragment(benchmark::State& state) {
  const Sensor sensor({.range = kRange});
  Rng rng(3);
  const Polygon obstacle = Star(rng, 8, 1.5, 1.5, Point(2.5, 0));
  std::vector<Point> out, scratch;
  for (auto _ : state) {
    sensor.fragment(obstacle, Point(0, 0.1), out, scratch);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["vertices"] = static_cast<double>(out.size());
}
BENCHMARK(BM_Fragment);

void BM_SeesFamiliar(benchmark::State& state) {
  const Sensor sensor({.range = kRange});
  Rng rng(5);
  const Polygon p = Star(rng, 10, 0.4, 1.2, Point(4.5, 0));
  bool seen = false;
  for (auto _ : state) {
    seen = sensor.sees(p, Point(0, 0));
    benchmark::DoNotOptimize(seen);
  }
  state.counters["seen"] = seen;
}
BENCHMARK(BM_SeesFamiliar);

}  // namespace

BENCHMARK_MAIN();
