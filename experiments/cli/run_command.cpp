// rearm run SCENARIO.yaml: one run of a scenario in the Box2D world, with its metrics,
// figure and animation.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "experiment/run_scenario.h"
#include "options.h"
#include "python_plot.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFooter =
    "Runs the scenario's LTL task: mission controller, interface layer (LTL and Fix modes),\n"
    "topology check and reactive controller, in a Box2D world (or on the kinematic plant).\n"
    "Writes DIR/metrics.json (status, collisions, times, actions, path lengths, ...),\n"
    "DIR/trajectory.json, the figure DIR/run.png and the animation DIR/run.gif (drawn by\n"
    "experiments/plot/run.py with python3, matplotlib and pillow; skipped with a warning\n"
    "when they are missing). DIR defaults to out/<scenario name>. The figure has axes in\n"
    "metres, the robot's end pose and sensor range, carried stretches drawn solid and every\n"
    "action numbered where it ended (Fix-mode actions in red squares), listed in\n"
    "DIR/run_figure.json; --snapshots K cuts the run at action ends into K panels (the\n"
    "paper's Figs. 3-5), --format png|pdf|svg chooses the file (run.pdf, run.svg).\n"
    "--checked: check the closed loop's invariants on every tick (finite commands, no overlap\n"
    "beyond Box2D's slop, det Dh > 0, the law's model point in the model freespace); a\n"
    "violation is an internal error (exit 1) naming it.\n"
    "--spaces: also record the mapped and model spaces of every diffeomorphism build and the\n"
    "law's model point (trajectory.json) and draw DIR/spaces.gif: the semantic, mapped and\n"
    "model spaces side by side, as the paper's video.\n"
    "--variant: paper (the paper's choices only) or robust (every extension;\n"
    "experiments/sweeps/README.md).\n"
    "Exit: 0 when the task completed, 1 when it ended infeasible, stuck or by timeout,\n"
    "2 for bad usage or an invalid scenario.";

// The command line of `rearm run`, parsed.
struct RunArgs {
  std::string path, out_dir, variant, plant = "box2d";
  experiment::RunOptions options;
  int stride = kDefaultStride;
  bool no_plot = false, no_animation = false;
  FigureStyle style;
};

void print_summary(const scenario::Scenario& s, const experiment::RunRecord& r) {
  const executive::TaskResult& t = r.result;
  std::printf("%s: %s (%s)\n", s.name.c_str(), executive::to_string(t.status), t.reason.c_str());
  std::printf(
      "  %.2f s simulated in %.2f s wall (%.0fx real time), %d collisions, min clearance %.4f "
      "m, %d Fix mode entries, %zu actions\n",
      t.sim_time, t.wall_time, r.real_time_factor(), t.collisions, t.min_clearance,
      t.fix_mode_entries, t.actions.size());
  if (s.controller.variant != "robust") return;
  std::printf(
      "  recoveries (%s variant): %d guide paths, %d back-ups, %d singular switches, "
      "%d convex fallbacks, %d restores, %d early releases, %d withdrawals, %d release "
      "points, %d early docks, %d turns toward the goal, %d narrow passages cleared, %d "
      "ways cleared beside unknown obstacles, %d drops in a pocket, %d drop points chosen "
      "again\n",
      s.controller.variant.c_str(), t.recoveries.guides, t.recoveries.back_outs,
      t.recoveries.singular, t.recoveries.fallbacks, t.recoveries.restores,
      t.recoveries.early_releases, t.recoveries.withdrawals, t.recoveries.release_points,
      t.recoveries.early_docks, t.recoveries.faces, t.recoveries.narrows,
      t.recoveries.fragment_fixes, t.recoveries.pocket_drops, t.recoveries.redrops);
}

int run(RunArgs a) {
  scenario::Scenario s = scenario::load_scenario(a.path);
  if (!a.variant.empty()) scenario::set_variant(s.controller, a.variant);
  if (a.out_dir.empty()) a.out_dir = (fs::path("out") / s.name).string();
  a.options.plant =
      a.plant == "kinematic" ? experiment::PlantKind::kKinematic : experiment::PlantKind::kBox2d;

  const experiment::RunRecord r = experiment::run_scenario(s, a.options);
  const fs::path metrics = fs::path(a.out_dir) / "metrics.json";
  const fs::path trajectory = fs::path(a.out_dir) / "trajectory.json";
  write_file_atomically(metrics.string(), experiment::metrics_json(s, r));
  write_file_atomically(trajectory.string(), experiment::trajectory_json(s, r, a.stride));
  print_summary(s, r);
  std::printf("wrote %s and %s\n", metrics.string().c_str(), trajectory.string().c_str());
  if (!a.no_plot && !draw_run("run", trajectory, a.out_dir, !a.no_animation, a.style)) {
    return kExitFailure;
  }
  return r.result.status == executive::TaskStatus::kCompleted ? kExitOk : kExitFailure;
}

}  // namespace

Command add_run(CLI::App& program) {
  CLI::App* c = program.add_subcommand(
      "run", "run a scenario's task in the Box2D world (metrics, figure, animation)");
  c->footer(kFooter);
  auto a = std::make_shared<RunArgs>();
  add_scenario_file(*c, a->path);
  add_out_dir(*c, a->out_dir, "default out/<scenario name>");
  add_seed(*c, a->options.seed, "recorded in the metrics (a fixed scenario draws none)");
  c->add_option("--plant", a->plant, "box2d (default) or kinematic")
      ->check(CLI::IsMember({"box2d", "kinematic"}));
  add_stride(*c, a->stride);
  c->add_option("--variant", a->variant, "override the scenario's controller variant")
      ->check(CLI::IsMember({"paper", "robust"}));
  c->add_flag("--checked", a->options.checked, "check the closed loop's invariants every tick");
  add_plot_flags(*c, a->no_plot, a->no_animation);
  add_figure_flags(*c, a->style);
  c->add_flag("--spaces", a->options.spaces, "record and draw the mapped and model spaces");
  return {c, [a] { return run(*a); }};
}

}  // namespace rearm::cli
