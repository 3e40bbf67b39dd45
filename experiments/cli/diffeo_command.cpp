// rearm diffeo SCENARIO.yaml --out DIR [--goal NAME|X,Y] [--seed N] [--starts N]
//              [--robot unicycle|holonomic] [--no-plot]
// Builds the mapped space and the diffeomorphism h of a scenario's scene with every obstacle
// known (docs/reactive.md §2–3), integrates the closed loop (reactive::run_closed_loop) from the
// robot's start, writes everything needed to draw them to DIR/diffeo.json, and plots it with
// experiments/plot/diffeo.py.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/rng.h"
#include "experiment/task_from_scenario.h"
#include "geometry/distance.h"
#include "options.h"
#include "python_plot.h"
#include "reactive/closed_loop.h"
#include "reactive/diffeomorphism.h"
#include "reactive/mapped_space.h"
#include "reactive/reactive_controller.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keys in the order written
using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

constexpr const char* kFooter =
    "Builds the mapped space and the purging diffeomorphism h (docs/reactive.md §2-3) of the\n"
    "scene of SCENARIO.yaml (format: experiments/scenarios/README.md) with every obstacle\n"
    "known (unknown obstacles as if fully seen, objects as disks), and integrates the closed\n"
    "loop from the robot's start to the goal (and from N random free starts drawn with\n"
    "--seed, default 1). Writes DIR/diffeo.json: the semantic, mapped and model spaces, every\n"
    "purge (piece, collar, centre, kind, parent), a grid of freespace lines with their images\n"
    "under h, and the paths in mapped and model coordinates. Then runs\n"
    "experiments/plot/diffeo.py, which draws DIR/semantic.png, DIR/mapped.png, DIR/model.png\n"
    "and DIR/path.png (skipped with a warning when python3 or matplotlib is missing; set\n"
    "REARM_PYTHON to choose the interpreter).\n"
    "--goal: default the first region with a point in the start's freespace component (of a\n"
    "region, the free point nearest its centroid, on a 5 cm grid).\n"
    "Exit codes: 0 every path reached the goal, 1 a path failed (the JSON is still written),\n"
    "2 bad usage or a bad scenario.";

// Closed-loop integration (docs/reactive.md §6).
constexpr double kMaxTime = 400;         // s of simulated time per path
constexpr double kGoalTolerance = 0.05;  // m
constexpr int kRecordEvery = 5;          // steps between recorded path points
// Random starts: at least this far (m) from every boundary of the freespace.
constexpr double kStartClearance = 0.2;
constexpr int kStartDraws = 100000;
constexpr int kMaxStarts = 1000;
// The drawing grid: lines per longer side of F_e, samples per grid cell along a line.
constexpr int kGridLines = 40;
constexpr int kSamplesPerCell = 8;
// Samples along each familiar component's boundary (its image lands on ∂(model disk)).
constexpr double kBoundarySpacing = 0.02;  // m
// m: the spacing of the points tried for a goal inside a region whose centroid is not free.
constexpr double kGoalGrid = 0.05;
// Significant digits of diffeo.json's numbers: drawing data, where 9 are plenty and keep the
// file small (round_numbers).
constexpr int kJsonDigits = 9;

// The command line, parsed.
struct DiffeoArgs {
  std::string scenario, out_dir, goal, robot_name = "unicycle";
  reactive::RobotModel robot = reactive::RobotModel::kUnicycle;
  std::uint64_t seed = 1;
  int starts = 0;
  bool no_plot = false;
};

// The static scene of a scenario, as the reactive layer sees it with every obstacle known.
struct Scene {
  std::string source;
  reactive::SemanticInput semantic;
  double radius = 0, sensor_range = 0, heading = 0;
  Point start = Point::Zero(), goal = Point::Zero();
  reactive::DiffeoParams params;
  reactive::NavParams nav;
};

Scene scene_of(const scenario::Scenario& s) {
  Scene c;
  c.source = s.source;
  c.semantic.workspace = s.workspace;
  for (const auto& f : s.familiar) c.semantic.familiar.push_back(f.polygon);
  for (const auto& u : s.unknown) c.semantic.unknown.push_back(u.polygon);
  for (const auto& o : s.objects) c.semantic.movable.push_back(o.disk);
  c.radius = s.robot.radius;
  c.sensor_range = s.robot.sensor_range;
  c.start = s.robot.start;
  c.heading = s.robot.heading;
  c.params = experiment::diffeo_params(s);
  c.nav = experiment::nav_params(s);
  return c;
}

// The point of region r in the start's freespace component nearest its centroid, on a grid of
// kGoalGrid (the centroid itself when free), or nullopt when none is.
std::optional<Point> free_point(const Polygon& r, const reactive::MappedSpace& m) {
  const Point c = r.centroid();
  if (reactive::in_freespace(m, c)) return c;
  Eigen::Vector2d lo = r.vertices[0], hi = lo;
  for (const Point& v : r.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  std::optional<Point> best;
  for (double x = lo.x(); x <= hi.x(); x += kGoalGrid) {
    for (double y = lo.y(); y <= hi.y(); y += kGoalGrid) {
      const Point q(x, y);
      if (!geometry::contains(r, q) || !reactive::in_freespace(m, q)) continue;
      if (!best || (q - c).norm() < (*best - c).norm()) best = q;
    }
  }
  return best;
}

// The goal of --goal (a region's name or X,Y), or the first region with a free point.
Point goal_of(const scenario::Scenario& s, const std::string& arg, const reactive::MappedSpace& m) {
  for (const auto& r : s.regions) {
    if (!arg.empty() && r.name != arg) continue;
    if (const auto p = free_point(r.polygon, m)) return *p;
    if (!arg.empty()) throw Error("--goal: no point of region " + arg + " is free");
  }
  if (arg.empty()) {
    throw Error(
        "no region has a point in the robot's freespace component; give the goal "
        "with --goal X,Y");
  }
  if (const auto p = parse_point("--goal", arg)) return *p;
  throw Error("--goal: '" + arg + "' is neither a region of the scenario nor a point X,Y");
}

// The signed clearance of x in the mapped freespace (negative outside).
double freespace_clearance(const reactive::MappedSpace& m, const Point& x) {
  double d = geometry::nearest_on_boundary(m.freespace.outer, x).distance;
  for (const Polygon& hole : m.freespace.holes) {
    d = std::min(d, geometry::nearest_on_boundary(hole, x).distance);
  }
  return reactive::in_freespace(m, x) ? d : -d;
}

struct PathRun {
  reactive::Pose start;
  std::string status;  // reached | timeout | collision | error: ...
  double time = 0;
  std::vector<reactive::Pose> poses;  // every kRecordEvery-th step and the last
  std::vector<Point> model;           // h of each recorded position
};

// One run of the closed loop (reactive::run_closed_loop) in the static scene, its own
// controller built from this start.
PathRun integrate(const Scene& scene, const reactive::Pose& start, reactive::RobotModel robot) {
  reactive::ReactiveController controller(scene.params, scene.nav);
  bool sensed = false;
  const auto sense = [&](const reactive::Pose&) -> std::optional<reactive::SemanticInput> {
    if (sensed) return std::nullopt;
    sensed = true;
    return scene.semantic;
  };
  const auto clearance = [&](const reactive::Pose& p) {
    return freespace_clearance(controller.mapped(), p.x);
  };
  reactive::ClosedLoopOptions o;
  o.model = robot;
  o.max_time = kMaxTime;
  o.goal_tolerance = kGoalTolerance;
  o.radius = scene.radius;
  const reactive::ClosedLoopResult r =
      reactive::run_closed_loop(controller, start, scene.goal, sense, clearance, o);
  PathRun run{start, "", r.time, {}, {}};
  run.status = r.status == reactive::ClosedLoopResult::Status::kReached   ? "reached"
               : r.status == reactive::ClosedLoopResult::Status::kTimeout ? "timeout"
                                                                          : "error: " + r.message;
  if (r.min_clearance < 0) run.status = "collision";
  for (std::size_t k = 0; k < r.path.size(); ++k) {
    if (k % kRecordEvery != 0 && k + 1 != r.path.size()) continue;
    run.poses.push_back(r.path[k]);
    run.model.push_back(controller.diffeo().map(r.path[k].x));
  }
  return run;
}

Point random_start(Rng& rng, const reactive::MappedSpace& m) {
  Eigen::Vector2d lo = m.freespace.outer.vertices[0], hi = lo;
  for (const Point& v : m.freespace.outer.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (int i = 0; i < kStartDraws; ++i) {
    const Point x(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
    if (freespace_clearance(m, x) >= kStartClearance) return x;
  }
  throw BudgetExceeded("no free start found in " + std::to_string(kStartDraws) + " draws");
}

// ---- diffeo.json (experiments/plot/diffeo.py reads it) ----
Json put(const Point& p) { return {p.x(), p.y()}; }

Json put(const std::vector<Point>& ps) {
  Json a = Json::array();
  for (const Point& p : ps) a.push_back(put(p));
  return a;
}

Json put(const Polygon& p) { return put(p.vertices); }

Json put(const std::vector<Polygon>& ps) {
  Json a = Json::array();
  for (const Polygon& p : ps) a.push_back(put(p));
  return a;
}

Json put(const std::vector<Disk>& ds) {
  Json a = Json::array();
  for (const Disk& d : ds) a.push_back({{"center", put(d.center)}, {"radius", d.radius}});
  return a;
}

// v rounded to `digits` significant digits (correctly rounded, like printf's "%.*g"): nlohmann
// then writes the shortest text that reads back as that double, at most `digits` digits.
// Non-finite numbers pass through (written as null).
double round_significant(double v, int digits) {
  if (!std::isfinite(v)) return v;
  char buf[32];
  const auto [end, ec] =
      std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
  double r = v;
  if (ec == std::errc()) std::from_chars(buf, end, r);
  return r;
}

// Every floating-point number of j rounded to `digits` significant digits, in place.
void round_numbers(Json& j, int digits) {
  if (j.is_number_float()) {
    j = round_significant(j.get<double>(), digits);
  } else if (j.is_structured()) {
    for (Json& child : j) round_numbers(child, digits);
  }
}

// Lines of the freespace (horizontal and vertical, through F_e's bounding box) cut into the
// runs of samples that lie in F_k.
std::vector<std::vector<Point>> grid_runs(const reactive::MappedSpace& m) {
  Eigen::Vector2d lo = m.enclosing.vertices[0], hi = lo;
  for (const Point& v : m.enclosing.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double spacing = std::max(hi.x() - lo.x(), hi.y() - lo.y()) / kGridLines;
  const double step = spacing / kSamplesPerCell;
  std::vector<std::vector<Point>> runs;
  for (int axis = 0; axis < 2; ++axis) {
    const int other = 1 - axis;
    const int lines = static_cast<int>(std::floor((hi[other] - lo[other]) / spacing));
    const int samples = static_cast<int>(std::ceil((hi[axis] - lo[axis]) / step));
    for (int l = 1; l <= lines; ++l) {
      std::vector<Point> run;
      for (int s = 0; s <= samples; ++s) {
        Point x;
        x[other] = lo[other] + l * spacing;
        x[axis] = std::min(hi[axis], lo[axis] + s * step);
        if (reactive::in_freespace(m, x)) {
          run.push_back(x);
        } else {
          if (run.size() > 1) runs.push_back(run);
          run.clear();
        }
      }
      if (run.size() > 1) runs.push_back(run);
    }
  }
  return runs;
}

// Mapped points and their images under h, as {"mapped": [...], "model": [...]}.
Json images(const std::vector<Point>& xs, const reactive::Diffeomorphism& h) {
  std::vector<Point> ys;
  ys.reserve(xs.size());
  for (const Point& x : xs) ys.push_back(h.map(x));
  return {{"mapped", put(xs)}, {"model", put(ys)}};
}

Json put_grid(const reactive::MappedSpace& m, const reactive::Diffeomorphism& h) {
  Json a = Json::array();
  for (const auto& run : grid_runs(m)) a.push_back(images(run, h));
  return a;
}

// Each familiar component's boundary, densely sampled, and its image (on ∂F_e or a model
// disk's circle when h is right).
Json put_boundary_images(const reactive::MappedSpace& m, const reactive::Diffeomorphism& h) {
  Json a = Json::array();
  for (std::size_t c = 0; c < m.familiar.size(); ++c) {
    const Polygon& p = m.familiar[c].polygon;
    std::vector<Point> xs;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Point u = p.vertices[i], v = p.vertices[(i + 1) % p.size()];
      const int n = std::max(1, static_cast<int>(std::ceil((v - u).norm() / kBoundarySpacing)));
      for (int k = 0; k < n; ++k) xs.push_back(u + (v - u) * (static_cast<double>(k) / n));
    }
    Json entry = {{"component", c}};
    entry.update(images(xs, h));
    a.push_back(std::move(entry));
  }
  return a;
}

// "scene", "seed", "robot", "params" and "semantic", the first keys of the document.
Json put_header(const DiffeoArgs& a, const Scene& s, const reactive::DiffeoParams& p) {
  const char* model = a.robot == reactive::RobotModel::kUnicycle ? "unicycle" : "holonomic";
  return {{"scene", a.scenario},
          {"seed", a.seed},
          {"robot",
           {{"model", model},
            {"radius", s.radius},
            {"sensor_range", s.sensor_range},
            {"start", put(s.start)},
            {"heading", s.heading},
            {"goal", put(s.goal)}}},
          {"params", {{"p", p.p}, {"epsilon", p.epsilon}, {"mu1", p.mu1}, {"mu2", p.mu2}}},
          {"semantic",
           {{"workspace", put(s.semantic.workspace)},
            {"familiar", put(s.semantic.familiar)},
            {"unknown", put(s.semantic.unknown)},
            {"movable", put(s.semantic.movable)}}}};
}

Json put_mapped(const reactive::MappedSpace& m) {
  Json familiar = Json::array();
  for (const reactive::FamiliarComponent& c : m.familiar) {
    familiar.push_back(
        {{"polygon", put(c.polygon)},
         {"lid", c.lid ? put(std::vector<Point>{c.lid->first, c.lid->second}) : Json()}});
  }
  return {{"radius", m.radius},
          {"enclosing", put(m.enclosing)},
          {"freespace", {{"outer", put(m.freespace.outer)}, {"holes", put(m.freespace.holes)}}},
          {"familiar", familiar},
          {"unknown", put(m.unknown)},
          {"movable", put(m.movable)}};
}

const char* kind_name(reactive::Purge::Kind k) {
  switch (k) {
    case reactive::Purge::Kind::kChild:
      return "child";
    case reactive::Purge::Kind::kDiskRoot:
      return "disk_root";
    case reactive::Purge::Kind::kBoundaryRoot:
      return "boundary_root";
  }
  return "?";
}

Json put_purges(const reactive::Diffeomorphism& h) {
  Json a = Json::array();
  for (std::size_t i = 0; i < h.purges().size(); ++i) {
    const reactive::Purge& p = h.purges()[i];
    a.push_back({{"index", i},
                 {"kind", kind_name(p.kind)},
                 {"component", p.component},
                 {"parent", p.parent},
                 {"depth", p.depth},
                 {"piece", put(p.piece)},
                 {"collar", put(p.collar)},
                 {"center", put(p.center)},
                 {"v0", put(p.v0)},
                 {"v1", put(p.v1)},
                 {"radius", p.radius},
                 {"epsilon", p.epsilon}});
  }
  return a;
}

Json put_model(const Scene& s, const reactive::Diffeomorphism& h) {
  return {{"boundary", put(h.model().boundary)},
          {"disks", put(h.model().disks)},
          {"convex", put(h.model().convex)},
          {"start", put(h.map(s.start))},
          {"goal", put(h.map(s.goal))}};
}

Json put_paths(const std::vector<PathRun>& runs) {
  Json a = Json::array();
  for (const PathRun& r : runs) {
    std::vector<Point> xs;
    Json headings = Json::array();
    for (const reactive::Pose& p : r.poses) {
      xs.push_back(p.x);
      headings.push_back(p.psi);
    }
    a.push_back({{"start", put(r.start.x)},
                 {"heading", r.start.psi},
                 {"status", r.status},
                 {"time", r.time},
                 {"headings", headings},
                 {"mapped", put(xs)},
                 {"model", put(r.model)}});
  }
  return a;
}

// The whole of diffeo.json, compact (drawing data), numbers to kJsonDigits digits.
std::string diffeo_json(const DiffeoArgs& a, const Scene& s, const reactive::MappedSpace& m,
                        const reactive::Diffeomorphism& h, const std::vector<PathRun>& runs) {
  Json j = put_header(a, s, h.params());
  j["mapped"] = put_mapped(m);
  j["purges"] = put_purges(h);
  j["model"] = put_model(s, h);
  j["grid"] = put_grid(m, h);
  j["boundary_images"] = put_boundary_images(m, h);
  j["paths"] = put_paths(runs);
  round_numbers(j, kJsonDigits);
  return j.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n";
}

void report(const reactive::MappedSpace& m, const reactive::Diffeomorphism& h,
            const std::vector<PathRun>& runs, int reached) {
  std::printf("mapped space: %zu familiar components, %zu unknown, %zu movable\n",
              m.familiar.size(), m.unknown.size(), m.movable.size());
  std::printf("purges: %zu\n", h.purges().size());
  std::printf("paths: %d/%zu reached the goal\n", reached, runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].status == "reached") continue;
    std::printf("  path %zu from (%g, %g): %s\n", i, runs[i].start.x.x(), runs[i].start.x.y(),
                runs[i].status.c_str());
  }
}

int diffeo(DiffeoArgs a) {
  a.robot = a.robot_name == "holonomic" ? reactive::RobotModel::kHolonomic
                                        : reactive::RobotModel::kUnicycle;
  const scenario::Scenario sc = scenario::load_scenario(a.scenario);
  Scene scene = scene_of(sc);
  reactive::MappedSpace m;
  reactive::Diffeomorphism h;
  try {
    reactive::validate(scene.params);
    m = reactive::build_mapped_space(scene.semantic, scene.radius, scene.start);
    scene.goal = goal_of(sc, a.goal, m);
    if (!reactive::in_freespace(m, scene.goal)) {
      throw Error("the goal is not in the robot's freespace component");
    }
    h = reactive::Diffeomorphism::build(m, scene.params);
  } catch (const BudgetExceeded&) {
    throw;
  } catch (const Error& e) {
    throw Error(a.scenario + ": " + e.what());
  }

  std::vector<PathRun> runs{integrate(scene, {scene.start, scene.heading}, a.robot)};
  Rng rng(a.seed);
  for (int i = 0; i < a.starts; ++i) {
    const Point s = random_start(rng, m);
    const double psi = rng.uniform(-std::numbers::pi, std::numbers::pi);
    runs.push_back(integrate(scene, {s, psi}, a.robot));
  }
  int reached = 0;
  for (const PathRun& r : runs) reached += r.status == "reached";

  const fs::path json_path = fs::path(a.out_dir) / "diffeo.json";
  write_file_atomically(json_path.string(), diffeo_json(a, scene, m, h, runs));
  report(m, h, runs, reached);
  std::printf("wrote %s\n", json_path.string().c_str());
  if (!a.no_plot) {
    const PlotOutcome drawn =
        run_plot("diffeo", "diffeo.py", {"matplotlib"}, {json_path.string(), a.out_dir});
    if (drawn == PlotOutcome::kFailed) return kExitFailure;
    if (drawn == PlotOutcome::kDrawn) {
      std::printf("wrote %s/{semantic,mapped,model,path}.png\n", a.out_dir.c_str());
    }
  }
  return reached == static_cast<int>(runs.size()) ? kExitOk : kExitFailure;
}

}  // namespace

Command add_diffeo(CLI::App& program) {
  CLI::App* c =
      program.add_subcommand("diffeo", "build and plot the diffeomorphism of a static scene");
  c->footer(kFooter);
  auto a = std::make_shared<DiffeoArgs>();
  add_scenario_file(*c, a->scenario);
  add_out_dir(*c, a->out_dir, "required")->required();
  c->add_option("--goal", a->goal, "a region's name or a point X,Y")->type_name("NAME|X,Y");
  add_seed(*c, a->seed, "seeds the random starts (default 1)");
  c->add_option("--starts", a->starts, "extra closed-loop runs from random free starts")
      ->check(count_check())
      ->check(CLI::Range(0, kMaxStarts))
      ->type_name("N");
  c->add_option("--robot", a->robot_name, "unicycle (differential drive, default) or holonomic")
      ->check(CLI::IsMember({"unicycle", "holonomic"}));
  c->add_flag("--no-plot", a->no_plot, "write the JSON only");
  return {c, [a] { return diffeo(*a); }};
}

}  // namespace rearm::cli
