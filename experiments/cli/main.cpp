// rearm: the program. Registers the subcommands on one CLI11 application and maps outcomes to
// exit codes: CLI11's parse errors and rearm::Error (bad usage or input) exit 2,
// rearm::BudgetExceeded and other failures of the work exit 1.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/suggest.h"
#include "experiment/provenance.h"
#include "options.h"

namespace {

using rearm::cli::Command;

constexpr const char* kDescription =
    "rearm reproduces the hybrid architecture of Vasilopoulos, Kantaros, Pappas and\n"
    "Koditschek, \"Reactive Planning for Mobile Manipulation Tasks in Unexplored Semantic\n"
    "Environments\" (ICRA 2021).";

std::string version_text() {
  return std::string("rearm ") + REARM_VERSION + " (revision " +
         rearm::experiment::build_revision() + ")";
}

// The command whose options were being parsed (the first one selected), or nullptr.
const Command* selected(const std::vector<Command>& commands) {
  for (const Command& c : commands) {
    if (c.app->parsed()) return &c;
  }
  return nullptr;
}

// "rearm", "rearm <command>" or "rearm <command> <subcommand>", for messages.
std::string who(const Command* c) {
  if (c == nullptr) return "rearm";
  std::string name = "rearm " + c->app->get_name();
  for (std::vector<CLI::App*> sub = c->app->get_subcommands(); !sub.empty();
       sub = sub.front()->get_subcommands()) {
    name += " " + sub.front()->get_name();
  }
  return name;
}

int usage_error(const Command* c, const std::string& message) {
  std::fprintf(stderr, "%s: %s\n(try '%s --help')\n", who(c).c_str(), message.c_str(),
               who(c).c_str());
  return rearm::cli::kExitUsage;
}

// Runs the parsed command; exceptions become messages and exit codes.
int execute(const Command& c) {
  try {
    return c.run();
  } catch (const rearm::BudgetExceeded& e) {
    std::fprintf(stderr, "%s: %s\n", who(&c).c_str(), e.what());
    return rearm::cli::kExitFailure;
  } catch (const rearm::Error& e) {
    std::fprintf(stderr, "%s: %s\n", who(&c).c_str(), e.what());
    return rearm::cli::kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", who(&c).c_str(), e.what());
    return rearm::cli::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App program{kDescription, "rearm"};
  program.set_version_flag("--version", version_text(), "Print the version and exit");
  program.require_subcommand(1, 1);
  program.footer("'rearm <command> --help' describes a command.");
  const std::vector<Command> commands{
      rearm::cli::add_translate(program), rearm::cli::add_plan(program),
      rearm::cli::add_diffeo(program),    rearm::cli::add_run(program),
      rearm::cli::add_baseline(program),  rearm::cli::add_sweep(program),
      rearm::cli::add_topology(program)};
  if (argc < 2) {
    std::fputs(program.help().c_str(), stdout);
    return rearm::cli::kExitUsage;
  }
  const std::string first = argv[1];
  bool known = first.rfind('-', 0) == 0;
  std::vector<std::string> names;
  for (const Command& c : commands) {
    known = known || c.app->get_name() == first;
    names.push_back(c.app->get_name());
  }
  if (!known) {
    return usage_error(nullptr,
                       "unknown command '" + first + "'" + rearm::did_you_mean(first, names));
  }
  try {
    program.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return program.exit(e);
    return usage_error(selected(commands), e.what());
  }
  const Command* c = selected(commands);
  return c == nullptr ? usage_error(nullptr, "a command is required") : execute(*c);
}
