// The reactive layer's speed on the scene of docs/reactive.md §7
// ("Speed to beat"): 20 × 20 m, K familiar non-convex obstacles (test_support::benchmark_scene),
// radius 0.2, DiffeoParams{} (p = 20, ε = 1, μ1 = 1, μ2 = 0.05), K = 1, 2, 5, 10, 15, 20:
// - BM_MappedSpace: build_mapped_space (exact CGAL Booleans);
// - BM_DiffeoConstruction: Diffeomorphism::build, the "tree construction" of §7;
// - BM_DiffeoEvaluate: one evaluate(x) (h, Dh, D²h), cycling over 256 seeded free points, half
//   of them within ε of an obstacle (its collar), half uniform over the freespace;
// - BM_HolonomicCommand / BM_UnicycleCommand: one full command at the same points (evaluate,
//   local freespace, law), the "one full command" of §7;
// - BM_ReactiveRebuild: ReactiveController::rebuild (mapped space, diffeo, goal image), paid on
//   every map change: the map alternates between K and K − 1 localized obstacles.
// Counters: K, pieces (purges = convex pieces), components (purged obstacles) and, for the
// per-point benchmarks, active = mean number of purges that are not the identity at a point.
// The sensor update is bench/perception/sensor_bench.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/rng.h"
#include "geometry/distance.h"
#include "reactive/diffeomorphism.h"
#include "reactive/kinematics.h"
#include "reactive/mapped_space.h"
#include "reactive/navigation.h"
#include "reactive/reactive_controller.h"
#include "support/reactive_scenes.h"

namespace {

using rearm::Rng;
using rearm::geometry::Point;
using rearm::geometry::Polygon;
using rearm::reactive::DiffeoEval;
using rearm::reactive::Diffeomorphism;
using rearm::reactive::DiffeoParams;
using rearm::reactive::MappedSpace;
using rearm::reactive::NavParams;
using rearm::reactive::Pose;
using rearm::reactive::ReactiveController;
using rearm::reactive::SemanticInput;

constexpr std::uint64_t kSceneSeed = 42;
constexpr double kRobotRadius = 0.2;  // m (the §7 scene's dilation)
const Point kStart{0.8, 0.8};         // a free corner of every §7 scene
constexpr std::uint64_t kPointSeed = 7;
constexpr int kPoints = 256;              // query points per scene
constexpr int kCandidates = 4 * kPoints;  // drawn; the first kPoints that command cleanly kept
constexpr double kPointClearance = 0.05;  // m from every boundary
constexpr double kMinTime = 0.3;          // s per benchmark (36 of them, whole run < 60 s)

// Smallest distance from x to any boundary of the mapped space's freespace and obstacles.
double clearance(const rearm::reactive::MappedSpace& m, const Point& x) {
  double d = rearm::geometry::nearest_on_boundary(m.freespace.outer, x).distance;
  for (const Polygon& h : m.freespace.holes) {
    d = std::min(d, rearm::geometry::nearest_on_boundary(h, x).distance);
  }
  for (const auto& c : m.familiar) {
    d = std::min(d, rearm::geometry::nearest_on_boundary(c.polygon, x).distance);
  }
  for (const Polygon& u : m.unknown)
    d = std::min(d, rearm::geometry::nearest_on_boundary(u, x).distance);
  return d;
}

// Query points of the freespace F_k at least `min_clearance` from every boundary: even draws
// uniform over F_k, odd draws within `near` of a random familiar component (inside its collar
// when near = ε). Rejection sampling; throws std::runtime_error when a draw keeps failing.
std::vector<Point> query_points(const rearm::reactive::MappedSpace& m, int count,
                                std::uint64_t seed, double min_clearance, double near) {
  Rng rng(seed);
  Eigen::AlignedBox2d box;
  for (const Point& v : m.freespace.outer.vertices) box.extend(v);
  std::vector<Point> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const bool near_obstacle = i % 2 == 1 && !m.familiar.empty();
    Eigen::AlignedBox2d draw_box = box;
    const Polygon* target = nullptr;
    int attempt = 0;
    for (;; ++attempt) {
      if (attempt == 100000) throw std::runtime_error("query_points: no free point found");
      if (near_obstacle && (attempt % 64 == 0)) {  // pick a component, now and then another
        target = &m.familiar[rng.index(m.familiar.size())].polygon;
        draw_box.setEmpty();
        for (const Point& v : target->vertices) draw_box.extend(v);
        draw_box.min().array() -= near;
        draw_box.max().array() += near;
      }
      const Point x(rng.uniform(draw_box.min().x(), draw_box.max().x()),
                    rng.uniform(draw_box.min().y(), draw_box.max().y()));
      if (!rearm::reactive::in_freespace(m, x) || clearance(m, x) < min_clearance) continue;
      if (target != nullptr && rearm::geometry::distance(*target, x) > near) continue;
      out.push_back(x);
      break;
    }
  }
  return out;
}

// Everything a benchmark of scene K needs, built once per K (outside the timings).
struct Setup {
  SemanticInput input;
  Point goal = Point::Zero();
  MappedSpace mapped;
  std::unique_ptr<Diffeomorphism> diffeo;
  std::unique_ptr<ReactiveController> controller;
  std::vector<Point> points;
  std::vector<double> headings;
  double active = 0;  // mean number of non-identity purges at the points
};

// Purge i acts at x when composing it changes h or Dh.
int active_purges(const Diffeomorphism& d, const Point& x) {
  int n = 0;
  DiffeoEval before = d.evaluate(x, 0);
  for (std::size_t i = 0; i < d.purges().size(); ++i) {
    const DiffeoEval after = d.evaluate(x, i + 1);
    if (after.h != before.h || after.J != before.J) ++n;
    before = after;
  }
  return n;
}

std::unique_ptr<Setup> make_setup(int K) {
  auto s = std::make_unique<Setup>();
  const rearm::test_support::ReactiveScene scene =
      rearm::test_support::benchmark_scene(K, kSceneSeed);
  s->input = rearm::test_support::to_semantic_input(scene);
  s->goal = scene.goal;
  s->mapped = rearm::reactive::build_mapped_space(s->input, kRobotRadius, kStart);
  s->diffeo = std::make_unique<Diffeomorphism>(Diffeomorphism::build(s->mapped));
  s->controller = std::make_unique<ReactiveController>(DiffeoParams{}, NavParams{});
  s->controller->rebuild(s->input, kRobotRadius, kStart, s->goal);
  const std::vector<Point> candidates =
      query_points(s->mapped, kCandidates, kPointSeed, kPointClearance, DiffeoParams{}.epsilon);
  Rng rng(kPointSeed + 1);
  long active = 0;
  for (const Point& x : candidates) {
    if (static_cast<int>(s->points.size()) == kPoints) break;
    const double psi = rng.uniform(-std::numbers::pi, std::numbers::pi);
    try {  // a point next to a sharp corner may have a singular Dh: not a query point
      s->controller->holonomic(x);
      s->controller->unicycle(Pose{x, psi});
    } catch (const std::exception&) {
      continue;
    }
    s->points.push_back(x);
    s->headings.push_back(psi);
    active += active_purges(*s->diffeo, x);
  }
  s->active = s->points.empty() ? 0 : static_cast<double>(active) / s->points.size();
  return s;
}

// Built on first use; a failed build is reported as the benchmark's error.
const Setup* setup_for(benchmark::State& state, int K) {
  static std::map<int, std::unique_ptr<Setup>> cache;
  static std::map<int, std::string> failures;
  if (auto it = cache.find(K); it != cache.end()) return it->second.get();
  if (auto it = failures.find(K); it != failures.end()) {
    state.SkipWithError(it->second.c_str());
    return nullptr;
  }
  try {
    auto s = make_setup(K);
    if (static_cast<int>(s->points.size()) < kPoints) {
      throw std::runtime_error("only " + std::to_string(s->points.size()) + " query points");
    }
    return cache.emplace(K, std::move(s)).first->second.get();
  } catch (const std::exception& e) {
    failures[K] = std::string("setup K=") + std::to_string(K) + ": " + e.what();
    state.SkipWithError(failures[K].c_str());
    return nullptr;
  }
}

void annotate(benchmark::State& state, const Setup& s, int K, bool per_point) {
  const auto pieces = s.diffeo->purges().size();
  state.counters["K"] = K;
  state.counters["pieces"] = static_cast<double>(pieces);
  state.counters["components"] = static_cast<double>(s.mapped.familiar.size());
  std::string label = std::to_string(s.mapped.familiar.size()) + " components, " +
                      std::to_string(pieces) + " pieces";
  if (per_point) {
    state.counters["active"] = s.active;
    label += ", " + std::to_string(s.points.size()) + " points";
  }
  state.SetLabel(label);
}

void BM_MappedSpace(benchmark::State& state) {
  const int K = static_cast<int>(state.range(0));
  const Setup* s = setup_for(state, K);
  if (s == nullptr) return;
  for (auto _ : state) {
    MappedSpace m = rearm::reactive::build_mapped_space(s->input, kRobotRadius, kStart);
    benchmark::DoNotOptimize(m);
  }
  annotate(state, *s, K, false);
}

void BM_DiffeoConstruction(benchmark::State& state) {
  const int K = static_cast<int>(state.range(0));
  const Setup* s = setup_for(state, K);
  if (s == nullptr) return;
  for (auto _ : state) {
    Diffeomorphism d = Diffeomorphism::build(s->mapped);
    benchmark::DoNotOptimize(d);
  }
  annotate(state, *s, K, false);
}

// Times `call(i)` for i cycling over the setup's query points.
template <typename Call>
void cycle_points(benchmark::State& state, Call&& call) {
  const int K = static_cast<int>(state.range(0));
  const Setup* s = setup_for(state, K);
  if (s == nullptr) return;
  std::size_t i = 0;
  for (auto _ : state) {
    auto r = call(*s, i);
    benchmark::DoNotOptimize(r);
    i = (i + 1) % s->points.size();
  }
  annotate(state, *s, K, true);
}

void BM_DiffeoEvaluate(benchmark::State& state) {
  cycle_points(state,
               [](const Setup& s, std::size_t i) { return s.diffeo->evaluate(s.points[i]); });
}

// h and Dh only (the unicycle guard's candidate steps, the pair's and holonomic law's points).
void BM_DiffeoEvaluateJacobian(benchmark::State& state) {
  cycle_points(state, [](const Setup& s, std::size_t i) {
    return s.diffeo->evaluate(s.points[i], rearm::reactive::DiffeoOrder::kJacobian);
  });
}

void BM_HolonomicCommand(benchmark::State& state) {
  cycle_points(state,
               [](const Setup& s, std::size_t i) { return s.controller->holonomic(s.points[i]); });
}

void BM_UnicycleCommand(benchmark::State& state) {
  cycle_points(state, [](const Setup& s, std::size_t i) {
    return s.controller->unicycle(Pose{s.points[i], s.headings[i]});
  });
}

void BM_ReactiveRebuild(benchmark::State& state) {
  const int K = static_cast<int>(state.range(0));
  const Setup* s = setup_for(state, K);
  if (s == nullptr) return;
  ReactiveController c(DiffeoParams{}, NavParams{});
  // The map alternates between the scene and the scene before its last familiar obstacle was
  // localized, so that every rebuild follows a map change and runs the whole construction (the
  // controller reuses its mapped space for an unchanged map), with warm caches.
  SemanticInput before = s->input;
  before.familiar.pop_back();
  bool full = true;
  for (auto _ : state) {
    c.rebuild(full ? s->input : before, kRobotRadius, kStart, s->goal);
    benchmark::DoNotOptimize(c.model_goal());
    full = !full;
  }
  annotate(state, *s, K, false);
}

void Sweep(benchmark::internal::Benchmark* b) {
  for (int K : {1, 2, 5, 10, 15, 20}) b->Arg(K);
  b->ArgName("K")->MinTime(kMinTime);
}

}  // namespace

BENCHMARK(BM_MappedSpace)->Apply(Sweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiffeoConstruction)->Apply(Sweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiffeoEvaluate)->Apply(Sweep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DiffeoEvaluateJacobian)->Apply(Sweep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HolonomicCommand)->Apply(Sweep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UnicycleCommand)->Apply(Sweep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReactiveRebuild)->Apply(Sweep)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
