// The `rearm` command line: one subcommand per source file, each registered here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"

namespace rearm::cli {

struct Command {
  const char* name;
  const char* summary;
  // Runs with the arguments after the subcommand name; returns the process exit code.
  int (*run)(const std::vector<std::string>& args);
};

int run_translate(const std::vector<std::string>& args);
int run_plan(const std::vector<std::string>& args);
int run_diffeo(const std::vector<std::string>& args);
int run_run(const std::vector<std::string>& args);
int run_baseline(const std::vector<std::string>& args);
int run_sweep(const std::vector<std::string>& args);

// Exit codes: 0 success, 1 a clean failure of the requested work (e.g. budget exceeded),
// 2 bad usage or bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// The value of the option args[i], advancing i past it; throws rearm::Error (a usage error)
// when the value is missing or is the next option ("--...").
// A non-negative integer option value (decimal digits only); throws rearm::Error naming flag.
std::uint64_t parse_count(const std::string& flag, const std::string& v);
// A finite decimal number; throws rearm::Error naming flag.
double parse_number(const std::string& flag, const std::string& v);

inline const std::string& option_value(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) {
    throw Error(args[i] + " expects a value");
  }
  return args[++i];
}

}  // namespace rearm::cli
