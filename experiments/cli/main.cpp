#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"

namespace {

using rearm::cli::Command;

const Command kCommands[] = {
    {"translate", "translate an LTL formula into a Büchi automaton", &rearm::cli::run_translate},
    {"plan", "run the mission controller against a perfect executor", &rearm::cli::run_plan},
    {"diffeo", "build and plot the diffeomorphism of a static scene", &rearm::cli::run_diffeo},
    {"run", "run a scenario's task in the Box2D world (metrics, figure, animation)",
     &rearm::cli::run_run},
    {"baseline", "plan and execute a scenario with an OMPL rearrangement baseline (mRS, BiRRT)",
     &rearm::cli::run_baseline},
    {"sweep", "Monte Carlo sweeps of rearm and the baselines (run, merge, report)",
     &rearm::cli::run_sweep},
};

void print_help() {
  std::printf(
      "usage: rearm <command> [options]\n\n"
      "rearm reproduces the hybrid architecture of Vasilopoulos, Kantaros, Pappas and\n"
      "Koditschek, \"Reactive Planning for Mobile Manipulation Tasks in Unexplored Semantic\n"
      "Environments\" (ICRA 2021).\n\ncommands:\n");
  for (const Command& c : kCommands) std::printf("  %-12s %s\n", c.name, c.summary);
  std::printf("\n'rearm <command> --help' describes a command.\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help();
    return args.empty() ? rearm::cli::kExitUsage : rearm::cli::kExitOk;
  }
  for (const Command& c : kCommands) {
    if (args[0] == c.name) {
      try {
        return c.run(std::vector<std::string>(args.begin() + 1, args.end()));
      } catch (const rearm::BudgetExceeded& e) {
        std::fprintf(stderr, "rearm %s: %s\n", c.name, e.what());
        return rearm::cli::kExitFailure;
      } catch (const rearm::Error& e) {
        std::fprintf(stderr, "rearm %s: %s\n", c.name, e.what());
        return rearm::cli::kExitUsage;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "rearm %s: internal error: %s\n", c.name, e.what());
        return rearm::cli::kExitFailure;
      }
    }
  }
  std::fprintf(stderr, "rearm: unknown command '%s' (try 'rearm --help')\n", args[0].c_str());
  return rearm::cli::kExitUsage;
}
