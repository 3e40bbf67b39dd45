// rearm baseline SCENARIO.yaml: one trial of an OMPL rearrangement baseline: plan
// (mRS, BiRRT over arrangements, or the replanning variant), validate, execute in Box2D, write
// metrics.json (the keys of `rearm run` plus planning_time_s, subqueries, nodes), the
// trajectory, the figure and the animation.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "baselines/run_baseline.h"
#include "command.h"
#include "core/file_io.h"
#include "options.h"
#include "python_plot.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kFooter =
    "Solves the scenario's rearrangement (every release(M,l) of its task: M ends inside l;\n"
    "a move(l): the robot ends in l) with a sampling-based baseline on OMPL's RRTConnect:\n"
    "  mrs     B1, depth-first search over move orders (monotone instances; a non-monotone\n"
    "          one is reported infeasible)\n"
    "  birrt   B2, bidirectional RRT over object arrangements (non-monotone instances)\n"
    "  replan  B2 on the map seen so far, replanning when the sensor reveals an obstacle\n"
    "          that invalidates the plan\n"
    "  buffer  TRLB-style: the order of goals that keeps the fewest objects in buffers at\n"
    "          once, blockers parked at buffer spots chosen lazily (non-monotone instances)\n"
    "mrs, birrt and buffer get the full map offline. The plan is checked by an independent "
    "validator\n"
    "and executed in the same Box2D world as `rearm run`. Writes DIR/metrics.json (the keys of\n"
    "`rearm run` plus planning_time_s, subqueries, nodes, ...), DIR/trajectory.json, and the\n"
    "figure and animation (experiments/plot/run.py). DIR defaults to out/<scenario>-<method>.\n"
    "--queries: a budget that, unlike the time limit, binds the same on any machine.\n"
    "Exit: 0 when the plan was executed with every goal reached, 1 when the method failed\n"
    "(infeasible, unsolved, timeout, execution failure), 2 for bad usage or input.";

// The command line of `rearm baseline`, parsed.
struct BaselineArgs {
  std::string path, out_dir, method;
  baselines::BaselineOptions options;
  std::uint64_t queries = 0;
  int stride = kDefaultStride;
  bool no_execute = false, no_plot = false, no_animation = false;
};

void print_summary(const scenario::Scenario& s, const baselines::BaselineRecord& r) {
  std::printf("%s (%s): %s (%s)\n", s.name.c_str(), baselines::to_string(r.method),
              r.status.c_str(), r.reason.c_str());
  std::printf(
      "  planning %.3f s (%ld motion queries, %ld nodes, %d replans), %zu moves; executed: %s, "
      "%d collisions, %.1f s simulated\n",
      r.planning_time_s, r.subqueries, r.nodes, r.replans, r.plan.moves.size(),
      r.executed ? "yes" : "no", r.execution.collisions, r.execution.sim_time);
}

int run(BaselineArgs a) {
  baselines::BaselineOptions& o = a.options;
  o.method = baselines::method_from_string(a.method);
  o.query_limit = static_cast<long>(a.queries);
  o.execute = !a.no_execute;
  const scenario::Scenario s = scenario::load_scenario(a.path);
  if (a.out_dir.empty())
    a.out_dir = (fs::path("out") / (s.name + "-" + baselines::to_string(o.method))).string();

  const baselines::BaselineRecord r = baselines::run_baseline(s, o);
  const fs::path metrics = fs::path(a.out_dir) / "metrics.json";
  const fs::path trajectory = fs::path(a.out_dir) / "trajectory.json";
  write_file_atomically(metrics.string(), baselines::baseline_metrics_json(s, r));
  write_file_atomically(trajectory.string(), baselines::baseline_trajectory_json(s, r, a.stride));
  print_summary(s, r);
  std::printf("wrote %s and %s\n", metrics.string().c_str(), trajectory.string().c_str());
  if (!a.no_plot && r.executed && !draw_run("baseline", trajectory, a.out_dir, !a.no_animation)) {
    return kExitFailure;
  }
  return r.status == "completed" ? kExitOk : kExitFailure;
}

}  // namespace

Command add_baseline(CLI::App& program) {
  CLI::App* c = program.add_subcommand(
      "baseline",
      "plan and execute a scenario with an OMPL rearrangement baseline (mRS, BiRRT, buffer, fmRS)");
  c->footer(kFooter);
  auto a = std::make_shared<BaselineArgs>();
  add_scenario_file(*c, a->path);
  c->add_option(
       "--method", a->method,
       "B1 (mrs), B2 (birrt), B2 replanning (replan), buffer, fmrs, birrt-fmrs or buffer-strict")
      ->required()
      ->check(CLI::IsMember(
          {"mrs", "birrt", "replan", "buffer", "fmrs", "birrt-fmrs", "buffer-strict"}));
  c->add_option("--time-limit", a->options.time_limit, "planning time budget (s, default 10)")
      ->check(finite_check())
      ->check(positive_check())
      ->type_name("S");
  add_seed(*c, a->options.seed, "seeds every sampler and planner (default 0)");
  c->add_option("--queries", a->queries, "motion queries of the trial (default 0: no limit)")
      ->check(count_check())
      ->type_name("K");
  add_out_dir(*c, a->out_dir, "default out/<scenario>-<method>");
  add_stride(*c, a->stride);
  c->add_flag("--no-execute", a->no_execute, "plan and validate only");
  add_plot_flags(*c, a->no_plot, a->no_animation);
  return {c, [a] { return run(*a); }};
}

}  // namespace rearm::cli
