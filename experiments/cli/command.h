// The `rearm` command line: one subcommand per source file, each registered on the program's
// CLI11 application by its add_* function (main.cpp), with the shared value checks of
// options.h, so every command has the same --help, --version and error style.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace rearm::cli {

// Exit codes: 0 success, 1 a clean failure of the requested work (e.g. budget exceeded),
// 2 bad usage or bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// A registered subcommand: its CLI11 application (its options bound to the runner's state) and
// the runner that does the work once the command line is parsed; returns the exit code.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_translate(CLI::App& program);
Command add_plan(CLI::App& program);
Command add_diffeo(CLI::App& program);
Command add_run(CLI::App& program);
Command add_baseline(CLI::App& program);
Command add_sweep(CLI::App& program);
Command add_topology(CLI::App& program);

}  // namespace rearm::cli
