#include "python_plot.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>

namespace rearm::cli {

namespace fs = std::filesystem;

// The most snapshot panels a figure holds (a panel per action is already unreadable).
constexpr int kMaxSnapshots = 24;

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

std::string find_python(const std::vector<std::string>& modules) {
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("REARM_PYTHON"); env && *env) candidates.push_back(env);
  candidates.push_back("python3");
  candidates.push_back("/usr/bin/python3");
  std::string imports;
  for (const std::string& m : modules) imports += "import " + m + "; ";
  for (const std::string& py : candidates) {
    const std::string cmd = shell_quote(py) + " -c " + shell_quote(imports) + " > /dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return py;
  }
  return "";
}

fs::path plot_script(const std::string& name) {
  if (const char* dir = std::getenv("REARM_PLOT_DIR"); dir && *dir) return fs::path(dir) / name;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path bin = ec ? fs::current_path(ec) : exe.parent_path();
  return bin.parent_path() / "share" / "rearm" / "plot" / name;
}

PlotOutcome run_plot(const std::string& command, const std::string& script,
                     const std::vector<std::string>& modules,
                     const std::vector<std::string>& args) {
  const std::string py = find_python(modules);
  const fs::path path = plot_script(script);
  if (py.empty()) {
    std::string names;
    for (const std::string& m : modules) names += (names.empty() ? "" : " and ") + m;
    std::fprintf(stderr, "rearm %s: warning: no python3 with %s found; %s did not run\n",
                 command.c_str(), names.c_str(), script.c_str());
    return PlotOutcome::kSkipped;
  }
  if (!fs::exists(path)) {
    std::fprintf(stderr,
                 "rearm %s: warning: plotting script %s not found (set REARM_PLOT_DIR to the "
                 "folder of the scripts)\n",
                 command.c_str(), path.string().c_str());
    return PlotOutcome::kSkipped;
  }
  std::string cmd = shell_quote(py) + " " + shell_quote(path.string());
  for (const std::string& a : args) cmd += " " + shell_quote(a);
  if (std::system(cmd.c_str()) != 0) {
    std::fprintf(stderr, "rearm %s: plotting failed: %s\n", command.c_str(), cmd.c_str());
    return PlotOutcome::kFailed;
  }
  return PlotOutcome::kDrawn;
}

bool draw_run(const std::string& command, const fs::path& trajectory, const std::string& out_dir,
              bool animation, const FigureStyle& style) {
  std::vector<std::string> args{trajectory.string(), out_dir, "--format=" + style.format,
                                "--snapshots=" + std::to_string(style.snapshots)};
  if (!animation) args.push_back("--no-animation");
  return run_plot(command, "run.py", {"matplotlib", "PIL"}, args) != PlotOutcome::kFailed;
}

void add_figure_flags(CLI::App& command, FigureStyle& style) {
  command
      .add_option("--snapshots", style.snapshots,
                  "draw K successive panels of the run, cut at action ends (default 1)")
      ->check(CLI::Range(1, kMaxSnapshots))
      ->type_name("K");
  command.add_option("--format", style.format, "the figure's file format (default png)")
      ->check(CLI::IsMember({"png", "pdf", "svg"}));
}

}  // namespace rearm::cli
