// rearm run SCENARIO.yaml: one run of a scenario in the Box2D world, with its metrics,
// figure and animation.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "experiment/run_scenario.h"
#include "python_plot.h"
#include "scenario/scenario_io.h"

namespace rearm::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: rearm run SCENARIO.yaml [--out DIR] [--seed N] [--plant box2d|kinematic]\n"
    "                 [--stride N] [--variant paper|robust] [--checked] [--no-plot]\n"
    "                 [--no-animation] [--spaces]\n\n"
    "Runs the scenario's LTL task: mission controller, interface layer (LTL and Fix modes),\n"
    "topology check and reactive controller, in a Box2D world (or on the kinematic plant).\n"
    "Writes DIR/metrics.json (status, collisions, times, actions, path lengths, ...),\n"
    "DIR/trajectory.json, the figure DIR/run.png and the animation DIR/run.gif (drawn by\n"
    "experiments/plot/run.py with python3, matplotlib and pillow; skipped with a warning\n"
    "when they are missing). DIR defaults to out/<scenario name>.\n"
    "  --seed N        recorded in the metrics (a fixed scenario draws no random number)\n"
    "  --stride N      steps between trajectory samples (default 10)\n"
    "  --checked       check the closed loop's invariants on every tick (finite commands, no\n"
    "                  overlap beyond Box2D's slop, det Dh > 0, the law's model point in the\n"
    "                  model freespace); a violation is an internal error (exit 1) naming it\n"
    "  --spaces        also record the mapped and model spaces of every diffeomorphism build\n"
    "                  and the law's model point (trajectory.json) and draw DIR/spaces.gif:\n"
    "                  the semantic, mapped and model spaces side by side, as the paper's video\n"
    "  --variant V     override the scenario's controller variant: paper (the paper's\n"
    "                  choices only) or robust (every extension; experiments/sweeps/README.md)\n"
    "Exit: 0 when the task completed, 1 when it ended infeasible, stuck or by timeout,\n"
    "2 for bad usage or an invalid scenario.\n";

// The command line of `rearm run`, parsed.
struct RunArgs {
  std::string path, out_dir, variant;
  experiment::RunOptions options;
  int stride = 10;
  bool plot = true, animation = true, help = false;
};

RunArgs parse_run_args(const std::vector<std::string>& args) {
  RunArgs r;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      r.help = true;
      return r;
    } else if (a == "--out") {
      r.out_dir = option_value(args, i);
    } else if (a == "--seed") {
      r.options.seed = parse_count(a, option_value(args, i));
    } else if (a == "--stride") {
      const std::uint64_t s = parse_count(a, option_value(args, i));
      if (s < 1 || s > 100000) throw Error("--stride must be in [1, 100000]");
      r.stride = static_cast<int>(s);
    } else if (a == "--plant") {
      const std::string& v = option_value(args, i);
      if (v == "box2d") {
        r.options.plant = experiment::PlantKind::kBox2d;
      } else if (v == "kinematic") {
        r.options.plant = experiment::PlantKind::kKinematic;
      } else {
        throw Error("--plant expects box2d or kinematic, got '" + v + "'");
      }
    } else if (a == "--variant") {
      r.variant = option_value(args, i);
      if (r.variant != "paper" && r.variant != "robust") {
        throw Error("--variant expects paper or robust, got '" + r.variant + "'");
      }
    } else if (a == "--checked") {
      r.options.checked = true;
    } else if (a == "--no-plot") {
      r.plot = false;
    } else if (a == "--no-animation") {
      r.animation = false;
    } else if (a == "--spaces") {
      r.options.spaces = true;
    } else if (a.rfind("--", 0) == 0) {
      throw Error("unknown option " + a + "\n" + kUsage);
    } else if (r.path.empty()) {
      r.path = a;
    } else {
      throw Error("one scenario file expected, got also '" + a + "'");
    }
  }
  if (r.path.empty()) throw Error(std::string("missing SCENARIO.yaml\n") + kUsage);
  return r;
}

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

// Draws the figure (and the animation) with experiments/plot/run.py; false when the script ran
// and failed (a missing python or script is a warning only).
bool draw(const fs::path& trajectory, const std::string& out_dir, bool animation) {
  std::vector<std::string> args{trajectory.string(), out_dir};
  if (!animation) args.push_back("--no-animation");
  return run_plot("run", "run.py", {"matplotlib", "PIL"}, args) != PlotOutcome::kFailed;
}

}  // namespace

int run_run(const std::vector<std::string>& args) {
  RunArgs a = parse_run_args(args);
  if (a.help) {
    std::printf("%s", kUsage);
    return kExitOk;
  }
  scenario::Scenario s = scenario::load_scenario(a.path);
  if (!a.variant.empty()) scenario::set_variant(s.controller, a.variant);
  if (a.out_dir.empty()) a.out_dir = (fs::path("out") / s.name).string();

  const experiment::RunRecord r = experiment::run_scenario(s, a.options);
  const fs::path metrics = fs::path(a.out_dir) / "metrics.json";
  const fs::path trajectory = fs::path(a.out_dir) / "trajectory.json";
  write_file_atomically(metrics.string(), experiment::metrics_json(s, r));
  write_file_atomically(trajectory.string(), experiment::trajectory_json(s, r, a.stride));
  print_summary(s, r);
  std::printf("wrote %s and %s\n", metrics.string().c_str(), trajectory.string().c_str());
  if (a.plot && !draw(trajectory, a.out_dir, a.animation)) return kExitFailure;
  return r.result.status == executive::TaskStatus::kCompleted ? kExitOk : kExitFailure;
}

}  // namespace rearm::cli
