// rearm diffeo SCENARIO.yaml --out DIR [--goal NAME|X,Y] [--seed N] [--starts N]
//              [--robot unicycle|holonomic] [--no-plot]
// Builds the mapped space and the diffeomorphism h of a scenario's scene with every obstacle
// known (docs/reactive.md §2–3), integrates the closed loop (reactive::run_closed_loop) from the
// robot's start, writes everything needed to draw them to DIR/diffeo.json, and plots it with
// experiments/plot/diffeo.py.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/rng.h"
#include "experiment/json_writer.h"
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
using experiment::JsonWriter;
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
// Significant digits of diffeo.json's numbers: drawing data, where 9 are plenty.
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

// "X,Y" as a finite point, or nullopt when the text is not two numbers.
std::optional<Point> point_of(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    return std::nullopt;
  }
  return Point(parse_number("--goal", text.substr(0, comma)),
               parse_number("--goal", text.substr(comma + 1)));
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
  if (const auto p = point_of(arg)) return *p;
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
void put(JsonWriter& j, const Point& p) { j.begin_array().value(p.x()).value(p.y()).end_array(); }

void put(JsonWriter& j, const std::vector<Point>& ps) {
  j.begin_array();
  for (const Point& p : ps) put(j, p);
  j.end_array();
}

void put(JsonWriter& j, const Polygon& p) { put(j, p.vertices); }

void put(JsonWriter& j, const std::vector<Polygon>& ps) {
  j.begin_array();
  for (const Polygon& p : ps) put(j, p);
  j.end_array();
}

void put(JsonWriter& j, const std::vector<Disk>& ds) {
  j.begin_array();
  for (const Disk& d : ds) {
    j.begin_object().key("center");
    put(j, d.center);
    j.key("radius").value(d.radius).end_object();
  }
  j.end_array();
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
void put_images(JsonWriter& j, const std::vector<Point>& xs, const reactive::Diffeomorphism& h) {
  std::vector<Point> ys;
  ys.reserve(xs.size());
  for (const Point& x : xs) ys.push_back(h.map(x));
  j.key("mapped");
  put(j, xs);
  j.key("model");
  put(j, ys);
}

void put_grid(JsonWriter& j, const reactive::MappedSpace& m, const reactive::Diffeomorphism& h) {
  j.key("grid").begin_array();
  for (const auto& run : grid_runs(m)) {
    j.begin_object();
    put_images(j, run, h);
    j.end_object();
  }
  j.end_array();
}

// Each familiar component's boundary, densely sampled, and its image (on ∂F_e or a model
// disk's circle when h is right).
void put_boundary_images(JsonWriter& j, const reactive::MappedSpace& m,
                         const reactive::Diffeomorphism& h) {
  j.key("boundary_images").begin_array();
  for (std::size_t c = 0; c < m.familiar.size(); ++c) {
    const Polygon& p = m.familiar[c].polygon;
    std::vector<Point> xs;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Point a = p.vertices[i], b = p.vertices[(i + 1) % p.size()];
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kBoundarySpacing)));
      for (int k = 0; k < n; ++k) xs.push_back(a + (b - a) * (static_cast<double>(k) / n));
    }
    j.begin_object().key("component").value(static_cast<std::int64_t>(c));
    put_images(j, xs, h);
    j.end_object();
  }
  j.end_array();
}

void put_header(JsonWriter& j, const DiffeoArgs& a, const Scene& s,
                const reactive::DiffeoParams& p) {
  j.key("scene").value(a.scenario).key("seed").value(a.seed);
  j.key("robot").begin_object();
  j.key("model").value(a.robot == reactive::RobotModel::kUnicycle ? "unicycle" : "holonomic");
  j.key("radius").value(s.radius).key("sensor_range").value(s.sensor_range).key("start");
  put(j, s.start);
  j.key("heading").value(s.heading).key("goal");
  put(j, s.goal);
  j.end_object();
  j.key("params").begin_object().key("p").value(p.p).key("epsilon").value(p.epsilon);
  j.key("mu1").value(p.mu1).key("mu2").value(p.mu2).end_object();
  j.key("semantic").begin_object().key("workspace");
  put(j, s.semantic.workspace);
  j.key("familiar");
  put(j, s.semantic.familiar);
  j.key("unknown");
  put(j, s.semantic.unknown);
  j.key("movable");
  put(j, s.semantic.movable);
  j.end_object();
}

void put_mapped(JsonWriter& j, const reactive::MappedSpace& m) {
  j.key("mapped").begin_object().key("radius").value(m.radius).key("enclosing");
  put(j, m.enclosing);
  j.key("freespace").begin_object().key("outer");
  put(j, m.freespace.outer);
  j.key("holes");
  put(j, m.freespace.holes);
  j.end_object().key("familiar").begin_array();
  for (const reactive::FamiliarComponent& c : m.familiar) {
    j.begin_object().key("polygon");
    put(j, c.polygon);
    j.key("lid");
    if (c.lid) {
      put(j, std::vector<Point>{c.lid->first, c.lid->second});
    } else {
      j.null();
    }
    j.end_object();
  }
  j.end_array().key("unknown");
  put(j, m.unknown);
  j.key("movable");
  put(j, m.movable);
  j.end_object();
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

void put_purges(JsonWriter& j, const reactive::Diffeomorphism& h) {
  j.key("purges").begin_array();
  for (std::size_t i = 0; i < h.purges().size(); ++i) {
    const reactive::Purge& p = h.purges()[i];
    j.begin_object().key("index").value(static_cast<std::int64_t>(i));
    j.key("kind").value(kind_name(p.kind));
    j.key("component").value(static_cast<std::int64_t>(p.component));
    j.key("parent").value(static_cast<std::int64_t>(p.parent));
    j.key("depth").value(static_cast<std::int64_t>(p.depth)).key("piece");
    put(j, p.piece);
    j.key("collar");
    put(j, p.collar);
    j.key("center");
    put(j, p.center);
    j.key("v0");
    put(j, p.v0);
    j.key("v1");
    put(j, p.v1);
    j.key("radius").value(p.radius).key("epsilon").value(p.epsilon).end_object();
  }
  j.end_array();
}

void put_model(JsonWriter& j, const Scene& s, const reactive::Diffeomorphism& h) {
  j.key("model").begin_object().key("boundary");
  put(j, h.model().boundary);
  j.key("disks");
  put(j, h.model().disks);
  j.key("convex");
  put(j, h.model().convex);
  j.key("start");
  put(j, h.map(s.start));
  j.key("goal");
  put(j, h.map(s.goal));
  j.end_object();
}

void put_paths(JsonWriter& j, const std::vector<PathRun>& runs) {
  j.key("paths").begin_array();
  for (const PathRun& r : runs) {
    j.begin_object().key("start");
    put(j, r.start.x);
    j.key("heading").value(r.start.psi).key("status").value(r.status);
    j.key("time").value(r.time);
    std::vector<Point> xs;
    j.key("headings").begin_array();
    for (const reactive::Pose& p : r.poses) {
      xs.push_back(p.x);
      j.value(p.psi);
    }
    j.end_array().key("mapped");
    put(j, xs);
    j.key("model");
    put(j, r.model);
    j.end_object();
  }
  j.end_array();
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

  JsonWriter j(false, kJsonDigits);
  j.begin_object();
  put_header(j, a, scene, h.params());
  put_mapped(j, m);
  put_purges(j, h);
  put_model(j, scene, h);
  put_grid(j, m, h);
  put_boundary_images(j, m, h);
  put_paths(j, runs);
  j.end_object();
  const fs::path json_path = fs::path(a.out_dir) / "diffeo.json";
  write_file_atomically(json_path.string(), j.str() + "\n");
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
