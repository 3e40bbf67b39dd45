// rearm compare: rearm against the OMPL rearrangement baselines on seeded random instances
// (issue 7's comparison run): object counts × goal classes × repetitions, one CSV row per
// (method, instance) appended as it finishes, then a table and a plot of planning time against
// the number of objects (experiments/plot/compare.py).
//
// Rows are flushed one by one and a run resumes: rows already in the CSV (same method, class,
// objects, repetition and instance seed) are not run again, so an interruption loses no
// finished trial. Every instance's seed is derived from (base seed, class, objects,
// repetition), so rows do not depend on the thread count or the order trials finish in.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "baselines/run_baseline.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/rng.h"
#include "experiment/run_scenario.h"
#include "python_plot.h"
#include "scenario/random_instance.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: rearm compare [--objects A-B] [--seeds K] [--classes random,cyclic]\n"
    "                     [--methods rearm,mrs,birrt] [--density D] [--time-limit S]\n"
    "                     [--unknown-shapes round|polygon] [--seed N] [--threads T]\n"
    "                     [--out DIR] [--no-plot]\n\n"
    "Runs every method on K random instances (scenario::random_instance) per object count in\n"
    "A..B and goal class (random goals; cyclic: each goal occupied by the next object), in the\n"
    "Box2D world. rearm discovers the obstacles with its sensor; mrs (B1) and birrt (B2) get the\n"
    "full map and S seconds of planning time; replan is B2 replanning on discovery.\n"
    "Unknown obstacles are ellipses (round: strongly convex, as the paper assumes) or\n"
    "rectangles and random hulls (polygon: flat faces, outside the paper's assumption).\n"
    "Appends one row per trial to DIR/comparison.csv as it finishes (a rerun skips the rows\n"
    "already there), then writes DIR/comparison.md (table) and DIR/planning_time.png; every\n"
    "instance is kept as DIR/instances/<name>.yaml (rerun it with rearm run / baseline).\n"
    "Defaults: --objects 1-6 --seeds 10 --classes random,cyclic --methods rearm,mrs,birrt\n"
    "--density 0.1 --time-limit 10 --unknown-shapes round --seed 0 --threads 2\n"
    "--out out/comparison\n";

constexpr const char* kHeader =
    "method,class,objects,density,unknown_shapes,achieved_density,rep,instance_seed,success,"
    "status,planning_time_s,wall_time_s,sim_time_s,robot_path_m,object_path_m,actions,fix_mode_entries,replans,collisions,"
    "min_clearance,subqueries,nodes,goals_reached,host,revision";

struct Trial {
  std::string method;
  scenario::GoalClass goal_class;
  int objects;
  int rep;
  std::uint64_t instance_seed;
  bool first_method = false;
};

// The unknown_shapes column (InstanceSpec::round_unknown).
const char* shapes_name(bool round_unknown) { return round_unknown ? "round" : "polygon"; }

// What identifies a row for resuming: the CSV's first seven fields but achieved_density.
std::string row_key(const std::string& method, const std::string& goal_class,
                    const std::string& objects, const std::string& density,
                    const std::string& shapes, const std::string& rep, const std::string& seed) {
  return method + "," + goal_class + "," + objects + "," + density + "," + shapes + "," + rep +
         "," + seed;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) out.push_back(item);
  return out;
}

std::string fmt(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

// The revision that produced the rows: git's short hash, "+dirty" when the tree outside
// results/ has uncommitted changes, "unknown" outside a checkout.
std::string revision() {
  auto first_line = [](const char* cmd) {
    std::string out;
    if (std::FILE* p = popen(cmd, "r")) {
      char buf[256];
      while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
      pclose(p);
    }
    return out.substr(0, out.find('\n'));
  };
  std::string rev = first_line("git rev-parse --short HEAD 2>/dev/null");
  if (rev.empty()) return "unknown";
  if (!first_line("git status --porcelain -- . ':!results' 2>/dev/null").empty()) rev += "+dirty";
  return rev;
}

std::string host_name() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// Every object with a goal region ends inside it (exact point location).
bool goals_reached(const scenario::Scenario& s, const std::vector<geometry::Point>& end) {
  const auto p = baselines::problem_from_scenario(s);
  return end.size() == p.object_count() && p.goals_reached(end);
}

std::string run_trial(const Trial& t, double density, bool round_unknown, double time_limit,
                      const std::string& host, const fs::path& instances) {
  static const std::string rev = revision();  // once per process
  scenario::InstanceSpec spec;
  spec.objects = t.objects;
  spec.obstacle_density = density;
  spec.goal_class = t.goal_class;
  spec.seed = t.instance_seed;
  spec.round_unknown = round_unknown;
  const scenario::Scenario s = scenario::random_instance(spec);
  // The instance as a scenario file, so any row can be rerun with `rearm run` or
  // `rearm baseline` (written by the first method of the list only).
  if (t.first_method)
    write_file_atomically((instances / (s.name + ".yaml")).string(), scenario::to_yaml(s));
  std::ostringstream row;
  double area = 0;
  for (const auto& f : s.familiar) area += f.polygon.area();
  for (const auto& u : s.unknown) area += u.polygon.area();
  row << t.method << ',' << scenario::to_string(t.goal_class) << ',' << t.objects << ','
      << fmt(density) << ',' << shapes_name(round_unknown) << ','
      << fmt(area / s.workspace.area()) << ',' << t.rep << ','
      << t.instance_seed << ',';
  if (t.method == "rearm") {
    experiment::RunOptions o;
    o.seed = t.instance_seed;
    o.record = false;
    const experiment::RunRecord r = experiment::run_scenario(s, o);
    const auto& x = r.result;
    const bool reached = goals_reached(s, r.objects_end);
    const bool success =
        x.status == executive::TaskStatus::kCompleted && reached && x.collisions == 0;
    row << (success ? 1 : 0) << ',' << executive::to_string(x.status) << ','
        << fmt(x.controller_time) << ',' << fmt(x.wall_time) << ',' << fmt(x.sim_time) << ','
        << fmt(x.robot_path_length) << ',' << fmt(x.object_path_length) << ',' << x.actions.size()
        << ',' << x.fix_mode_entries << ",0," << x.collisions << ',' << fmt(x.min_clearance)
        << ",0,0," << (reached ? 1 : 0);
  } else {
    baselines::BaselineOptions o;
    o.method = baselines::method_from_string(t.method);
    o.time_limit = time_limit;
    o.seed = t.instance_seed;
    o.record = false;
    const baselines::BaselineRecord r = baselines::run_baseline(s, o);
    const auto& e = r.execution;
    const bool reached = r.executed && e.goals_reached;
    const bool success = r.status == "completed" && e.collisions == 0;
    row << (success ? 1 : 0) << ',' << r.status << ',' << fmt(r.planning_time_s) << ','
        << fmt(r.wall_time_s) << ',' << fmt(e.sim_time) << ',' << fmt(e.robot_path_length) << ','
        << fmt(e.object_path_length) << ',' << 2 * e.moves_done << ",0," << r.replans << ','
        << e.collisions << ',' << fmt(r.executed ? e.min_clearance : 0.0) << ',' << r.subqueries
        << ',' << r.nodes << ',' << (reached ? 1 : 0);
  }
  row << ',' << host << ',' << rev;
  return row.str();
}

}  // namespace

int run_compare(const std::vector<std::string>& args) {
  int lo = 1, hi = 6, seeds = 10, threads = 2;
  std::vector<std::string> classes = {"random", "cyclic"}, methods = {"rearm", "mrs", "birrt"};
  double density = 0.1, time_limit = 10;
  std::uint64_t base_seed = 0;
  std::string out_dir = "out/comparison";
  bool plot = true;
  bool round_unknown = true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return kExitOk;
    } else if (a == "--objects") {
      const auto parts = split(option_value(args, i), '-');
      if (parts.empty() || parts.size() > 2) throw Error("--objects expects N or A-B");
      lo = static_cast<int>(parse_count(a, parts[0]));
      hi = parts.size() == 2 ? static_cast<int>(parse_count(a, parts[1])) : lo;
      if (lo < 1 || hi < lo || hi > 12) throw Error("--objects: need 1 <= A <= B <= 12");
    } else if (a == "--seeds") {
      seeds = static_cast<int>(parse_count(a, option_value(args, i)));
      if (seeds < 1 || seeds > 10000) throw Error("--seeds must be in [1, 10000]");
    } else if (a == "--classes") {
      classes = split(option_value(args, i), ',');
      for (const auto& c : classes) scenario::goal_class_from_string(c);
    } else if (a == "--methods") {
      methods = split(option_value(args, i), ',');
      for (const auto& m : methods)
        if (m != "rearm") baselines::method_from_string(m);
    } else if (a == "--density") {
      density = parse_number(a, option_value(args, i));
    } else if (a == "--time-limit") {
      time_limit = parse_number(a, option_value(args, i));
      if (time_limit <= 0) throw Error("--time-limit must be positive");
    } else if (a == "--seed") {
      base_seed = parse_count(a, option_value(args, i));
    } else if (a == "--threads") {
      threads = static_cast<int>(parse_count(a, option_value(args, i)));
      if (threads < 1 || threads > 256) throw Error("--threads must be in [1, 256]");
    } else if (a == "--out") {
      out_dir = option_value(args, i);
    } else if (a == "--unknown-shapes") {
      const std::string shapes = option_value(args, i);
      if (shapes != "round" && shapes != "polygon")
        throw Error("--unknown-shapes expects round or polygon, got '" + shapes + "'");
      round_unknown = shapes == "round";
    } else if (a == "--no-plot") {
      plot = false;
    } else {
      throw Error("unknown argument " + a + "\n" + kUsage);
    }
  }
  if (classes.empty() || methods.empty()) throw Error("--classes and --methods need a value");

  std::vector<Trial> trials;
  for (const auto& c : classes) {
    const scenario::GoalClass gc = scenario::goal_class_from_string(c);
    for (int n = lo; n <= hi; ++n)
      for (int k = 0; k < seeds; ++k) {
        const std::uint64_t stream = (static_cast<std::uint64_t>(gc) << 48) |
                                     (static_cast<std::uint64_t>(n) << 32) |
                                     static_cast<std::uint64_t>(k);
        const std::uint64_t seed = Rng::derive(base_seed, stream).next() >> 1;
        for (const auto& m : methods) trials.push_back({m, gc, n, k, seed, m == methods.front()});
      }
  }
  const fs::path instances = fs::path(out_dir) / "instances";
  fs::create_directories(instances);
  const fs::path csv = fs::path(out_dir) / "comparison.csv";
  std::set<std::string> done;
  if (fs::exists(csv)) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    if (line != kHeader)
      throw Error(csv.string() + ": not a comparison file of this version (header differs)");
    while (std::getline(in, line)) {
      const auto f = split(line, ',');
      if (f.size() < 8) continue;  // a row cut by an interruption: run again
      done.insert(row_key(f[0], f[1], f[2], f[3], f[4], f[6], f[7]));
    }
  }
  bool ends_mid_line = false;
  if (fs::exists(csv) && fs::file_size(csv) > 0) {
    std::ifstream in(csv, std::ios::binary);
    in.seekg(-1, std::ios::end);
    ends_mid_line = in.get() != '\n';
  }
  std::FILE* out = std::fopen(csv.string().c_str(), "a");
  if (out == nullptr) throw Error("cannot open " + csv.string() + " for appending");
  if (ends_mid_line) std::fputc('\n', out);  // a row cut by an interruption stays alone
  if (done.empty() && std::ftell(out) == 0) {
    std::fprintf(out, "%s\n", kHeader);
    std::fflush(out);
  }
  std::vector<Trial> todo;
  auto key = [&](const Trial& t) {
    return row_key(t.method, scenario::to_string(t.goal_class), std::to_string(t.objects),
                   fmt(density), shapes_name(round_unknown), std::to_string(t.rep), std::to_string(t.instance_seed));
  };
  for (const auto& t : trials)
    if (!done.count(key(t))) todo.push_back(t);
  std::printf("compare: %zu trials, %zu already in %s, %zu to run on %d threads\n", trials.size(),
              trials.size() - todo.size(), csv.string().c_str(), todo.size(), threads);
  const std::string host = host_name();
  std::mutex mu;
  std::atomic<std::size_t> next{0};
  std::string error;
  auto worker = [&] {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= todo.size()) return;
      std::string row;
      try {
        row = run_trial(todo[k], density, round_unknown, time_limit, host, instances);
      } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(mu);
        error = key(todo[k]) + ": " + e.what();
        next = todo.size();
        return;
      }
      const std::lock_guard<std::mutex> lock(mu);
      std::fprintf(out, "%s\n", row.c_str());
      std::fflush(out);
      fsync(fileno(out));
      std::printf("  [%zu/%zu] %s\n", k + 1, todo.size(), row.c_str());
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  std::fclose(out);
  if (!error.empty()) throw Error("compare: trial " + error);

  if (plot) {
    const std::string py = find_python({"matplotlib"});
    const fs::path script = plot_script("compare.py");
    if (py.empty() || !fs::exists(script)) {
      std::fprintf(stderr,
                   "rearm compare: warning: no python3 with matplotlib (or no "
                   "experiments/plot/compare.py); table and plot not written\n");
      return kExitOk;
    }
    const std::string cmd = shell_quote(py) + " " + shell_quote(script.string()) + " " +
                            shell_quote(csv.string()) + " " + shell_quote(out_dir);
    if (std::system(cmd.c_str()) != 0) {
      std::fprintf(stderr, "rearm compare: plotting failed: %s\n", cmd.c_str());
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace rearm::cli
