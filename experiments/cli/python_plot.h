// Running the matplotlib scripts of experiments/plot from the command line. The scripts live
// beside the program as an installation lays them out: <prefix>/bin/rearm and
// <prefix>/share/rearm/plot/*.py; the build tree mirrors that layout (build/bin/rearm,
// build/share/rearm/plot, copied at build time), so a relocated or installed rearm finds them
// from any working directory.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rearm::cli {

// s quoted for /bin/sh.
std::string shell_quote(const std::string& s);

// The first python3 that imports every module of `modules`: $REARM_PYTHON, else python3 on
// PATH, else /usr/bin/python3 (Debian's, with python3-matplotlib and python3-pil from
// scripts/setup.sh); "" when none does.
std::string find_python(const std::vector<std::string>& modules);

// The plotting script `name`: $REARM_PLOT_DIR/name when that variable is set, else
// <directory of the running executable>/../share/rearm/plot/name.
std::filesystem::path plot_script(const std::string& name);

enum class PlotOutcome { kDrawn, kSkipped, kFailed };

// Runs plotting script `script` on `args` with the first python3 that imports `modules`.
// kSkipped, with a warning "rearm <command>: warning: ..." on stderr naming what is missing,
// when there is no such python or no such script; kFailed, naming the command line, when the
// script exits non-zero.
PlotOutcome run_plot(const std::string& command, const std::string& script,
                     const std::vector<std::string>& modules, const std::vector<std::string>& args);

// How run.py draws the figure: its file format and the number of snapshot panels.
struct FigureStyle {
  std::string format = "png";  // png, pdf or svg
  int snapshots = 1;
};

// The figure DIR/run.FORMAT (with DIR/run_figure.json) and, unless !animation, the animation
// DIR/run.gif of a trajectory.json (experiments/plot/run.py, for `rearm run` and `rearm
// baseline`); false when the script ran and failed (a missing python or script is a warning
// only).
bool draw_run(const std::string& command, const std::filesystem::path& trajectory,
              const std::string& out_dir, bool animation, const FigureStyle& style = {});
// --snapshots K and --format png|pdf|svg of the commands that draw run.png.
void add_figure_flags(CLI::App& command, FigureStyle& style);

}  // namespace rearm::cli
