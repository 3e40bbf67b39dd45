// The value checks the commands share (CLI11 validators), so a bad value gets the same message
// from every command: "--flag: expects ..., got '...'". Included by experiments/cli/*.cpp only.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "geometry/polygon.h"

namespace rearm::cli {

// A non-negative integer in decimal digits, at most 19 of them (so it fits std::uint64_t).
// CLI11's own conversion would wrap "-3" to 2^64 - 3 and saturate an overflow.
const CLI::Validator& count_check();
// A finite decimal number: no nan, inf, hexadecimal or overflow (CLI11 converts all four).
const CLI::Validator& finite_check();
// A number > 0 (after finite_check).
const CLI::Validator& positive_check();

// The required positional SCENARIO.yaml of run, baseline and diffeo.
void add_scenario_file(CLI::App& command, std::string& path);
// --out DIR; `what` says where it goes by default (or that it is required).
CLI::Option* add_out_dir(CLI::App& command, std::string& dir, const std::string& what);
// --seed N (count_check).
CLI::Option* add_seed(CLI::App& command, std::uint64_t& seed, const std::string& what);
// --stride N in [1, kMaxStride]: steps between trajectory samples (default 10).
inline constexpr int kDefaultStride = 10;
inline constexpr int kMaxStride = 100000;
void add_stride(CLI::App& command, int& stride);
// --no-plot and --no-animation of the commands that draw run.png and run.gif.
void add_plot_flags(CLI::App& command, bool& no_plot, bool& no_animation);

// A finite decimal number, or rearm::Error naming flag (for values inside a larger option,
// such as diffeo's --goal X,Y).
double parse_number(const std::string& flag, const std::string& v);
// "X,Y" as a finite point (parse_number's checks, naming flag), or nullopt when the text is not
// two comma-separated fields (a name, for the options that take a region's name or a point).
std::optional<geometry::Point> parse_point(const std::string& flag, const std::string& text);

}  // namespace rearm::cli
