// rearm baseline SCENARIO.yaml: one trial of an OMPL rearrangement baseline: plan
// (mRS, BiRRT over arrangements, or the replanning variant), validate, execute in Box2D, write
// metrics.json (the keys of `rearm run` plus planning_time_s, subqueries, nodes), the
// trajectory, the figure and the animation.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "baselines/run_baseline.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "python_plot.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {

std::uint64_t parse_count(const std::string& flag, const std::string& v) {
  if (v.empty() || v.size() > 19 || v.find_first_not_of("0123456789") != std::string::npos)
    throw Error(flag + " expects a non-negative integer, got '" + v + "'");
  return std::stoull(v);
}

double parse_number(const std::string& flag, const std::string& v) {
  if (v.empty() || v.find_first_not_of("0123456789.eE+-") != std::string::npos)
    throw Error(flag + " expects a decimal number, got '" + v + "'");
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end != v.c_str() + v.size() || errno != 0 || !std::isfinite(x))
    throw Error(flag + " expects a finite decimal number, got '" + v + "'");
  return x;
}

namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: rearm baseline SCENARIO.yaml --method mrs|birrt|replan [--time-limit S] [--seed N]\n"
    "                      [--queries K] [--out DIR] [--stride N] [--no-execute] [--no-plot]\n"
    "                      [--no-animation]\n\n"
    "Solves the scenario's rearrangement (every release(M,l) of its task: M ends inside l;\n"
    "a move(l): the robot ends in l) with a sampling-based baseline on OMPL's RRTConnect:\n"
    "  mrs     B1, depth-first search over move orders (monotone instances; a non-monotone\n"
    "          one is reported infeasible)\n"
    "  birrt   B2, bidirectional RRT over object arrangements (non-monotone instances)\n"
    "  replan  B2 on the map seen so far, replanning when the sensor reveals an obstacle\n"
    "          that invalidates the plan\n"
    "mrs and birrt get the full map offline. The plan is checked by an independent validator\n"
    "and executed in the same Box2D world as `rearm run`. Writes DIR/metrics.json (the keys of\n"
    "`rearm run` plus planning_time_s, subqueries, nodes, ...), DIR/trajectory.json, and the\n"
    "figure and animation (experiments/plot/run.py). DIR defaults to out/<scenario>-<method>.\n"
    "  --time-limit S  planning time budget of the trial (s, default 10)\n"
    "  --seed N        seeds every sampler and planner (default 0)\n"
    "  --queries K     motion queries for the trial, all replans together (default 0: no\n"
    "                  limit); a budget that, unlike the time limit, binds the same anywhere\n"
    "Exit: 0 when the plan was executed with every goal reached, 1 when the method failed\n"
    "(infeasible, unsolved, timeout, execution failure), 2 for bad usage or input.\n";

}  // namespace

int run_baseline(const std::vector<std::string>& args) {
  std::string path, out_dir;
  baselines::BaselineOptions o;
  bool have_method = false, plot = true, animation = true;
  int stride = 10;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return kExitOk;
    } else if (a == "--method") {
      o.method = baselines::method_from_string(option_value(args, i));
      have_method = true;
    } else if (a == "--queries") {
      o.query_limit = static_cast<long>(parse_count(a, option_value(args, i)));
    } else if (a == "--time-limit") {
      o.time_limit = parse_number(a, option_value(args, i));
      if (o.time_limit <= 0) throw Error("--time-limit must be positive");
    } else if (a == "--seed") {
      o.seed = parse_count(a, option_value(args, i));
    } else if (a == "--out") {
      out_dir = option_value(args, i);
    } else if (a == "--stride") {
      const std::uint64_t s = parse_count(a, option_value(args, i));
      if (s < 1 || s > 100000) throw Error("--stride must be in [1, 100000]");
      stride = static_cast<int>(s);
    } else if (a == "--no-execute") {
      o.execute = false;
    } else if (a == "--no-plot") {
      plot = false;
    } else if (a == "--no-animation") {
      animation = false;
    } else if (a.rfind("--", 0) == 0) {
      throw Error("unknown option " + a + "\n" + kUsage);
    } else if (path.empty()) {
      path = a;
    } else {
      throw Error("one scenario file expected, got also '" + a + "'");
    }
  }
  if (path.empty()) throw Error(std::string("missing SCENARIO.yaml\n") + kUsage);
  if (!have_method) throw Error(std::string("missing --method mrs|birrt|replan\n") + kUsage);
  const scenario::Scenario s = scenario::load_scenario(path);
  if (out_dir.empty())
    out_dir = (fs::path("out") / (s.name + "-" + baselines::to_string(o.method))).string();

  const baselines::BaselineRecord r = baselines::run_baseline(s, o);
  const fs::path metrics = fs::path(out_dir) / "metrics.json";
  const fs::path trajectory = fs::path(out_dir) / "trajectory.json";
  write_file_atomically(metrics.string(), baselines::baseline_metrics_json(s, r));
  write_file_atomically(trajectory.string(), baselines::baseline_trajectory_json(s, r, stride));
  std::printf("%s (%s): %s (%s)\n", s.name.c_str(), baselines::to_string(o.method),
              r.status.c_str(), r.reason.c_str());
  std::printf(
      "  planning %.3f s (%ld motion queries, %ld nodes, %d replans), %zu moves; executed: %s, "
      "%d collisions, %.1f s simulated\n",
      r.planning_time_s, r.subqueries, r.nodes, r.replans, r.plan.moves.size(),
      r.executed ? "yes" : "no", r.execution.collisions, r.execution.sim_time);
  std::printf("wrote %s and %s\n", metrics.string().c_str(), trajectory.string().c_str());
  if (plot && r.executed) {
    std::vector<std::string> plot_args{trajectory.string(), out_dir};
    if (!animation) plot_args.push_back("--no-animation");
    if (run_plot("baseline", "run.py", {"matplotlib", "PIL"}, plot_args) == PlotOutcome::kFailed) {
      return kExitFailure;
    }
  }
  return r.status == "completed" ? kExitOk : kExitFailure;
}

}  // namespace rearm::cli
