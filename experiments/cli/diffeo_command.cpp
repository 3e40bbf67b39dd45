// rearm diffeo SCENE.yaml --out DIR [--seed N] [--starts N] [--robot unicycle|holonomic]
//              [--no-plot]
// Builds the mapped space and the diffeomorphism h of a static, fully known scene
// (docs/reactive.md §2–3), writes everything needed to draw them to DIR/diffeo.json, and
// plots it with experiments/plot/diffeo.py.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/rng.h"
#include "geometry/distance.h"
#include "python_plot.h"
#include "reactive/diffeomorphism.h"
#include "reactive/kinematics.h"
#include "reactive/mapped_space.h"
#include "reactive/navigation.h"
#include "reactive/reactive_controller.h"
#include "scene_file.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;
using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

constexpr const char* kUsage =
    "usage: rearm diffeo SCENE.yaml --out DIR [--seed N] [--starts N]\n"
    "                    [--robot unicycle|holonomic] [--no-plot]\n\n"
    "Builds the mapped space and the purging diffeomorphism h (docs/reactive.md §2-3) of the\n"
    "static scene SCENE.yaml (format: experiments/scenes/README.md), with every obstacle\n"
    "known, and integrates the closed loop from the scene's start to its goal (and from N\n"
    "random free starts drawn with --seed, default 1). Writes DIR/diffeo.json: the semantic,\n"
    "mapped and model spaces, every purge (piece, collar, centre, kind, parent), a grid of\n"
    "freespace lines with their images under h, and the paths in mapped and model\n"
    "coordinates. Then runs experiments/plot/diffeo.py, which draws DIR/semantic.png,\n"
    "DIR/mapped.png, DIR/model.png and DIR/path.png (skipped with a warning when python3 or\n"
    "matplotlib is missing; set REARM_PYTHON to choose the interpreter).\n\n"
    "  --robot     unicycle (differential drive, default) or holonomic (fully actuated)\n"
    "  --starts N  extra closed-loop runs from random free starts (default 0)\n"
    "  --no-plot   write the JSON only\n\n"
    "Exit codes: 0 every path reached the goal, 1 a path failed (the JSON is still written),\n"
    "2 bad usage or a bad scene.\n";

// Closed-loop integration (docs/reactive.md §6).
constexpr double kMaxTime = 400;         // s of simulated time per path
constexpr double kGoalTolerance = 0.05;  // m
constexpr int kRecordEvery = 5;          // steps between recorded path points
// Random starts: at least this far (m) from every boundary of the freespace.
constexpr double kStartClearance = 0.2;
constexpr int kStartDraws = 100000;
// The drawing grid: lines per longer side of F_e, samples per grid cell along a line.
constexpr int kGridLines = 40;
constexpr int kSamplesPerCell = 8;
// Samples along each familiar component's boundary (its image lands on ∂(model disk)).
constexpr double kBoundarySpacing = 0.02;  // m

// ---- JSON output (numbers with 17 significant digits would bloat the grid; 9 is plenty
// for drawing). Non-finite numbers are written as null and counted.
class Json {
 public:
  std::string str() const { return out_.str(); }
  int non_finite() const { return non_finite_; }

  void num(double v) {
    if (!std::isfinite(v)) {
      ++non_finite_;
      out_ << "null";
      return;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    out_ << buf;
  }
  void point(const Point& p) {
    out_ << '[';
    num(p.x());
    out_ << ',';
    num(p.y());
    out_ << ']';
  }
  void polygon(const Polygon& p) {
    out_ << '[';
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i) out_ << ',';
      point(p.vertices[i]);
    }
    out_ << ']';
  }
  void polygons(const std::vector<Polygon>& ps) {
    out_ << '[';
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (i) out_ << ",\n";
      polygon(ps[i]);
    }
    out_ << ']';
  }
  void disk(const Disk& d) {
    out_ << "{\"center\":";
    point(d.center);
    out_ << ",\"radius\":";
    num(d.radius);
    out_ << '}';
  }
  void disks(const std::vector<Disk>& ds) {
    out_ << '[';
    for (std::size_t i = 0; i < ds.size(); ++i) {
      if (i) out_ << ',';
      disk(ds[i]);
    }
    out_ << ']';
  }
  void points(const std::vector<Point>& ps) {
    out_ << '[';
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (i) out_ << ',';
      point(ps[i]);
    }
    out_ << ']';
  }
  void str(const std::string& s) {
    out_ << '"';
    for (char c : s) {
      if (c == '"' || c == '\\') {
        out_ << '\\' << c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ << buf;
      } else {
        out_ << c;
      }
    }
    out_ << '"';
  }
  void key(const char* k) { out_ << '"' << k << "\":"; }
  std::ostringstream& raw() { return out_; }

 private:
  std::ostringstream out_;
  int non_finite_ = 0;
};

enum class Robot { kUnicycle, kHolonomic };

struct PathRun {
  Point start;
  double heading = 0;
  std::string status;  // reached | timeout | error: ... | collision
  double time = 0;
  std::vector<Point> mapped;
  std::vector<double> headings;
  std::vector<Point> model;
};

// One closed-loop run with the navigation law of docs/reactive.md §4, integrated by the
// exact zero-order-hold steps of reactive/kinematics.h.
PathRun integrate(const SceneFile& scene, const Point& start, double heading, Robot robot) {
  PathRun run;
  run.start = start;
  run.heading = heading;
  const Point& goal = scene.goal;
  reactive::NavParams np;
  np.sensing_range = scene.sensing_range;
  // The reactive controller (the mapped space and diffeomorphism of the scene, seen from this
  // start), so the path gets its discrete-time safety filter too.
  reactive::ReactiveController controller(scene.params, np);
  controller.rebuild(scene.semantic, scene.radius, start, goal);
  const reactive::MappedSpace& m = controller.mapped();
  const reactive::Diffeomorphism& h = controller.diffeo();
  reactive::Pose pose{start, heading};
  const double dt = reactive::kDefaultStep;
  const int steps = static_cast<int>(kMaxTime / dt);
  auto record = [&]() {
    run.mapped.push_back(pose.x);
    run.headings.push_back(pose.psi);
    run.model.push_back(h.map(pose.x));
  };
  run.status = "timeout";
  for (int k = 0; k <= steps; ++k) {
    if (k % kRecordEvery == 0) record();
    if ((pose.x - goal).norm() <= kGoalTolerance) {
      if (k % kRecordEvery != 0) record();
      run.status = "reached";
      break;
    }
    if (k == steps) break;
    try {
      if (robot == Robot::kUnicycle) {
        pose = reactive::unicycle_step(pose, controller.unicycle(pose, dt), dt);
      } else {
        pose.x = reactive::holonomic_step(pose.x, controller.holonomic(pose.x, dt), dt);
      }
    } catch (const Error& err) {
      if (k % kRecordEvery != 0) record();
      run.status = std::string("error: ") + err.what();
      break;
    }
    run.time = (k + 1) * dt;
    if (!reactive::in_freespace(m, pose.x)) {
      record();
      run.status = "collision";
      break;
    }
  }
  return run;
}

double freespace_clearance(const reactive::MappedSpace& m, const Point& x) {
  double d = geometry::nearest_on_boundary(m.freespace.outer, x).distance;
  for (const Polygon& hole : m.freespace.holes) {
    d = std::min(d, geometry::nearest_on_boundary(hole, x).distance);
  }
  return d;
}

Point random_start(Rng& rng, const reactive::MappedSpace& m) {
  Eigen::Vector2d lo = m.freespace.outer.vertices[0], hi = lo;
  for (const Point& v : m.freespace.outer.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (int i = 0; i < kStartDraws; ++i) {
    const Point x(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
    if (reactive::in_freespace(m, x) && freespace_clearance(m, x) >= kStartClearance) return x;
  }
  throw BudgetExceeded("no free start found in " + std::to_string(kStartDraws) + " draws");
}

// Lines of the freespace (horizontal and vertical, through F_e's bounding box) cut into the
// runs of samples that lie in F_k, each with its image under h.
void write_grid(Json& j, const reactive::MappedSpace& m, const reactive::Diffeomorphism& h) {
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
        } else if (!run.empty()) {
          if (run.size() > 1) runs.push_back(std::move(run));
          run.clear();
        }
      }
      if (run.size() > 1) runs.push_back(std::move(run));
    }
  }
  j.raw() << '[';
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (i) j.raw() << ",\n";
    std::vector<Point> images;
    images.reserve(runs[i].size());
    for (const Point& x : runs[i]) images.push_back(h.map(x));
    j.raw() << "{\"mapped\":";
    j.points(runs[i]);
    j.raw() << ",\"model\":";
    j.points(images);
    j.raw() << '}';
  }
  j.raw() << ']';
}

// Each familiar component's boundary, densely sampled, and its image (on ∂F_e or a model
// disk's circle when h is right).
void write_boundary_images(Json& j, const reactive::MappedSpace& m,
                           const reactive::Diffeomorphism& h) {
  j.raw() << '[';
  for (std::size_t c = 0; c < m.familiar.size(); ++c) {
    const Polygon& p = m.familiar[c].polygon;
    std::vector<Point> xs, ys;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Point a = p.vertices[i], b = p.vertices[(i + 1) % p.size()];
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kBoundarySpacing)));
      for (int k = 0; k < n; ++k) {
        const Point x = a + (b - a) * (static_cast<double>(k) / n);
        xs.push_back(x);
        ys.push_back(h.map(x));
      }
    }
    if (c) j.raw() << ",\n";
    j.raw() << "{\"component\":" << c << ",\"mapped\":";
    j.points(xs);
    j.raw() << ",\"model\":";
    j.points(ys);
    j.raw() << '}';
  }
  j.raw() << ']';
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

}  // namespace

int run_diffeo(const std::vector<std::string>& args) {
  std::string scene_path, out_dir;
  std::uint64_t seed = 1;
  int starts = 0;
  Robot robot = Robot::kUnicycle;
  bool plot = true;
  auto integer = [](const std::string& flag, const std::string& v, std::uint64_t max) {
    if (v.empty() || v.size() > 18 || v.find_first_not_of("0123456789") != std::string::npos) {
      throw Error(flag + " expects a non-negative integer, got '" + v + "'");
    }
    const std::uint64_t n = std::stoull(v);
    if (n > max) throw Error(flag + " must be at most " + std::to_string(max));
    return n;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& { return option_value(args, i); };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    } else if (a == "--out") {
      out_dir = value();
    } else if (a == "--seed") {
      seed = integer(a, value(), std::numeric_limits<std::int64_t>::max());
    } else if (a == "--starts") {
      starts = static_cast<int>(integer(a, value(), 1000));
    } else if (a == "--robot") {
      const std::string& v = value();
      if (v == "unicycle") {
        robot = Robot::kUnicycle;
      } else if (v == "holonomic") {
        robot = Robot::kHolonomic;
      } else {
        throw Error("--robot expects unicycle or holonomic, got '" + v + "'");
      }
    } else if (a == "--no-plot") {
      plot = false;
    } else if (a.rfind("--", 0) == 0 || !scene_path.empty()) {
      throw Error("unknown argument '" + a + "'\n" + kUsage);
    } else {
      scene_path = a;
    }
  }
  if (scene_path.empty()) throw Error(std::string("missing SCENE.yaml\n") + kUsage);
  if (out_dir.empty()) throw Error(std::string("missing --out DIR\n") + kUsage);

  const SceneFile scene = read_scene_file(scene_path);
  reactive::MappedSpace m;
  try {
    m = reactive::build_mapped_space(scene.semantic, scene.radius, scene.start);
  } catch (const Error& e) {
    throw Error(scene_path + ": " + e.what());
  }
  if (!reactive::in_freespace(m, scene.goal)) {
    throw Error(scene_path + ":" + std::to_string(scene.robot_line) +
                ": the goal is not in the robot's freespace component");
  }
  reactive::Diffeomorphism h;
  try {
    h = reactive::Diffeomorphism::build(m, scene.params);
  } catch (const Error& e) {
    throw Error(scene_path + ": the diffeomorphism cannot be built: " + e.what());
  }

  // Closed-loop runs: the scene's start, then the random ones.
  std::vector<PathRun> runs;
  runs.push_back(integrate(scene, scene.start, scene.heading, robot));
  Rng rng(seed);
  for (int i = 0; i < starts; ++i) {
    const Point s = random_start(rng, m);
    const double psi = rng.uniform(-std::numbers::pi, std::numbers::pi);
    runs.push_back(integrate(scene, s, psi, robot));
  }

  Json j;
  auto& o = j.raw();
  o << "{\n";
  j.key("scene");
  j.str(scene_path);
  o << ",\n";
  j.key("seed");
  o << seed << ",\n";
  j.key("robot");
  o << "{\"model\":\"" << (robot == Robot::kUnicycle ? "unicycle" : "holonomic")
    << "\",\"radius\":";
  j.num(scene.radius);
  o << ",\"sensing_range\":";
  j.num(scene.sensing_range);
  o << ",\"start\":";
  j.point(scene.start);
  o << ",\"heading\":";
  j.num(scene.heading);
  o << ",\"goal\":";
  j.point(scene.goal);
  o << "},\n";
  const auto& prm = h.params();
  j.key("params");
  o << "{\"p\":" << prm.p << ",\"epsilon\":";
  j.num(prm.epsilon);
  o << ",\"mu1\":";
  j.num(prm.mu1);
  o << ",\"mu2\":";
  j.num(prm.mu2);
  o << "},\n";

  j.key("semantic");
  o << "{\"workspace\":";
  j.polygon(scene.semantic.workspace);
  o << ",\n\"familiar\":";
  j.polygons(scene.semantic.familiar);
  o << ",\n\"unknown\":";
  j.polygons(scene.semantic.unknown);
  o << ",\n\"movable\":";
  j.disks(scene.semantic.movable);
  o << "},\n";

  j.key("mapped");
  o << "{\"radius\":";
  j.num(m.radius);
  o << ",\n\"enclosing\":";
  j.polygon(m.enclosing);
  o << ",\n\"freespace\":{\"outer\":";
  j.polygon(m.freespace.outer);
  o << ",\"holes\":";
  j.polygons(m.freespace.holes);
  o << "},\n\"familiar\":[";
  for (std::size_t i = 0; i < m.familiar.size(); ++i) {
    if (i) o << ",\n";
    o << "{\"polygon\":";
    j.polygon(m.familiar[i].polygon);
    o << ",\"lid\":";
    if (m.familiar[i].lid) {
      j.points({m.familiar[i].lid->first, m.familiar[i].lid->second});
    } else {
      o << "null";
    }
    o << '}';
  }
  o << "],\n\"unknown\":";
  j.polygons(m.unknown);
  o << ",\n\"movable\":";
  j.disks(m.movable);
  o << "},\n";

  j.key("purges");
  o << '[';
  for (std::size_t i = 0; i < h.purges().size(); ++i) {
    const reactive::Purge& p = h.purges()[i];
    if (i) o << ",\n";
    o << "{\"index\":" << i << ",\"kind\":\"" << kind_name(p.kind)
      << "\",\"component\":" << p.component << ",\"parent\":" << p.parent
      << ",\"depth\":" << p.depth << ",\"piece\":";
    j.polygon(p.piece);
    o << ",\"collar\":";
    j.polygon(p.collar);
    o << ",\"center\":";
    j.point(p.center);
    o << ",\"v0\":";
    j.point(p.v0);
    o << ",\"v1\":";
    j.point(p.v1);
    o << ",\"radius\":";
    j.num(p.radius);
    o << ",\"epsilon\":";
    j.num(p.epsilon);
    o << '}';
  }
  o << "],\n";

  j.key("model");
  o << "{\"boundary\":";
  j.polygon(h.model().boundary);
  o << ",\n\"disks\":";
  j.disks(h.model().disks);
  o << ",\n\"convex\":";
  j.polygons(h.model().convex);
  o << ",\n\"start\":";
  j.point(h.map(scene.start));
  o << ",\"goal\":";
  j.point(h.map(scene.goal));
  o << "},\n";

  j.key("grid");
  write_grid(j, m, h);
  o << ",\n";
  j.key("boundary_images");
  write_boundary_images(j, m, h);
  o << ",\n";

  j.key("paths");
  o << '[';
  int reached = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PathRun& r = runs[i];
    reached += r.status == "reached";
    if (i) o << ",\n";
    o << "{\"start\":";
    j.point(r.start);
    o << ",\"heading\":";
    j.num(r.heading);
    o << ",\"status\":";
    j.str(r.status);
    o << ",\"time\":";
    j.num(r.time);
    o << ",\"mapped\":";
    j.points(r.mapped);
    o << ",\"headings\":[";
    for (std::size_t k = 0; k < r.headings.size(); ++k) {
      if (k) o << ',';
      j.num(r.headings[k]);
    }
    o << "],\"model\":";
    j.points(r.model);
    o << '}';
  }
  o << "]\n}\n";

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw Error("cannot create the output folder '" + out_dir + "': " + ec.message());
  const fs::path json_path = fs::path(out_dir) / "diffeo.json";
  {
    std::ofstream f(json_path, std::ios::binary);
    f << j.str();
    if (!f) throw Error("cannot write '" + json_path.string() + "'");
  }
  std::printf("mapped space: %zu familiar components, %zu unknown, %zu movable\n",
              m.familiar.size(), m.unknown.size(), m.movable.size());
  std::printf("purges: %zu\n", h.purges().size());
  std::printf("paths: %d/%zu reached the goal\n", reached, runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].status != "reached") {
      std::printf("  path %zu from (%g, %g): %s\n", i, runs[i].start.x(), runs[i].start.y(),
                  runs[i].status.c_str());
    }
  }
  if (j.non_finite() > 0) {
    std::fprintf(stderr, "rearm diffeo: warning: %d non-finite numbers written as null\n",
                 j.non_finite());
  }
  std::printf("wrote %s\n", json_path.string().c_str());

  if (plot) {
    const std::string py = find_python({"matplotlib"});
    const fs::path script = plot_script("diffeo.py");
    if (py.empty()) {
      std::fprintf(stderr,
                   "rearm diffeo: warning: no python3 with matplotlib found; the plots were "
                   "not drawn (the JSON is written)\n");
    } else if (!fs::exists(script)) {
      std::fprintf(stderr, "rearm diffeo: warning: plotting script %s not found\n",
                   script.string().c_str());
    } else {
      const std::string cmd = shell_quote(py) + " " + shell_quote(script.string()) + " " +
                              shell_quote(json_path.string()) + " " + shell_quote(out_dir);
      if (std::system(cmd.c_str()) != 0) {
        std::fprintf(stderr, "rearm diffeo: plotting failed: %s\n", cmd.c_str());
        return kExitFailure;
      }
      std::printf("wrote %s/{semantic,mapped,model,path}.png\n", out_dir.c_str());
    }
  }
  return reached == static_cast<int>(runs.size()) ? kExitOk : kExitFailure;
}

}  // namespace rearm::cli
