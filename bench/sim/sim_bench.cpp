// One SimWorld::step (Box2D world step plus the exact clearance measurement) in a 20 × 20 m room
// with 10 obstacles (6 familiar, 4 of them non-convex or above 8 vertices, 4 unknown convex) and
// 3 objects, for a robot driving a circle of radius 1.5 m in free space:
// - `alone`: nothing held;
// - `carrying`: one object welded to the robot.
// Plus building the world (partition of the obstacles, Box2D bodies and fixtures).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "scenario/scenario.h"
#include "sim/sim_world.h"

namespace {

using rearm::geometry::Disk;
using rearm::geometry::Point;
using rearm::geometry::Polygon;
using rearm::scenario::Scenario;
using rearm::sim::SimWorld;

constexpr double kV = 0.3;
constexpr double kOmega = 0.2;  // circle radius kV / kOmega = 1.5 m around the origin

Polygon Rect(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

Polygon Regular(const Point& c, double r, int n, double phase = 0) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / n;
    p.vertices.push_back(c + r * Point(std::cos(a), std::sin(a)));
  }
  return p;
}

Polygon Star(const Point& c, double r_in, double r_out, int points) {
  Polygon p;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = std::numbers::pi * k / points;
    p.vertices.push_back(c + (k % 2 ? r_in : r_out) * Point(std::cos(a), std::sin(a)));
  }
  return p;
}

// The robot starts at (0, −1.5) heading east; with `carry`, object 0 sits 5 mm ahead of it.
Scenario Room(bool carry) {
  Scenario s;
  s.name = "bench";
  s.workspace = Rect(-10, -10, 10, 10);
  s.robot.radius = 0.2;
  s.robot.start = Point(0, -1.5);
  s.robot.heading = 0;
  s.familiar = {
      {"F0", Rect(5, 5, 7, 6)},
      {"F1", Polygon{{Point(-8, 4), Point(-5, 4), Point(-5, 5), Point(-7, 5), Point(-7, 8),
                      Point(-8, 8)}}},  // L
      {"F2", Polygon{{Point(-8, -9), Point(-4, -9), Point(-4, -6), Point(-5, -6), Point(-5, -8),
                      Point(-7, -8), Point(-7, -6), Point(-8, -6)}}},  // U
      {"F3", Rect(6, -8, 8, -4)},
      {"F4", Regular(Point(7, 0), 1.0, 20)},   // split into 8-vertex pieces
      {"F5", Star(Point(0, 7), 0.6, 1.5, 5)},  // non-convex
  };
  s.unknown = {
      {"U0", Regular(Point(-7, 0), 1.0, 6)},
      {"U1", Rect(3, -8, 4, -6)},
      {"U2", Regular(Point(0, -7), 0.8, 3, 0.5)},
      {"U3", Regular(Point(4, 8), 0.7, 5)},
  };
  const Disk ahead{Point(0.2 + 0.15 + 0.005, -1.5), 0.15};
  s.objects = {{"M0", carry ? ahead : Disk{Point(4, 0), 0.15}},
               {"M1", Disk{Point(0, 4), 0.25}},
               {"M2", Disk{Point(-4, -2), 0.2}}};
  return s;
}

void BM_Step(benchmark::State& state) {
  const bool carry = state.range(0) != 0;
  SimWorld w(Room(carry));
  if (carry && !w.grip(0)) {
    state.SkipWithError("grip failed");
    return;
  }
  for (auto _ : state) {
    w.step(kV, kOmega);
  }
  state.SetLabel(carry ? "carrying" : "alone");
  state.counters["collisions"] = w.collisions();
  state.counters["min_clearance"] = w.min_clearance();
}
BENCHMARK(BM_Step)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_Build(benchmark::State& state) {
  const Scenario s = Room(false);
  for (auto _ : state) {
    SimWorld w(s);
    benchmark::DoNotOptimize(w.object_count());
  }
}
BENCHMARK(BM_Build)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
