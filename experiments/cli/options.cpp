#include "options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace rearm::cli {
namespace {

constexpr std::size_t kMaxCountDigits = 19;  // 10^19 - 1 < 2^64

// True, with x the number, when v spells a finite decimal number.
bool finite_decimal(const std::string& v, double& x) {
  if (v.empty() || v.find_first_not_of("0123456789.eE+-") != std::string::npos) return false;
  errno = 0;
  char* end = nullptr;
  x = std::strtod(v.c_str(), &end);
  return end == v.c_str() + v.size() && errno == 0 && std::isfinite(x);
}

}  // namespace

const CLI::Validator& count_check() {
  static const CLI::Validator v(
      [](std::string& s) -> std::string {
        if (s.empty() || s.size() > kMaxCountDigits ||
            s.find_first_not_of("0123456789") != std::string::npos) {
          return "expects a non-negative integer, got '" + s + "'";
        }
        return {};
      },
      "");
  return v;
}

const CLI::Validator& finite_check() {
  static const CLI::Validator v(
      [](std::string& s) -> std::string {
        double x = 0;
        return finite_decimal(s, x) ? std::string()
                                    : "expects a finite decimal number, got '" + s + "'";
      },
      "");
  return v;
}

const CLI::Validator& positive_check() {
  static const CLI::Validator v(
      [](std::string& s) -> std::string {
        double x = 0;
        return finite_decimal(s, x) && x > 0 ? std::string() : "must be positive, got '" + s + "'";
      },
      "");
  return v;
}

void add_scenario_file(CLI::App& command, std::string& path) {
  command.add_option("SCENARIO", path, "the scenario file (experiments/scenarios/README.md)")
      ->required()
      ->type_name("SCENARIO.yaml");
}

CLI::Option* add_out_dir(CLI::App& command, std::string& dir, const std::string& what) {
  return command.add_option("--out", dir, "output folder (" + what + ")")->type_name("DIR");
}

CLI::Option* add_seed(CLI::App& command, std::uint64_t& seed, const std::string& what) {
  return command.add_option("--seed", seed, what)->check(count_check())->type_name("N");
}

void add_stride(CLI::App& command, int& stride) {
  command.add_option("--stride", stride, "steps between trajectory samples (default 10)")
      ->check(count_check())
      ->check(CLI::Range(1, kMaxStride))
      ->type_name("N");
}

void add_plot_flags(CLI::App& command, bool& no_plot, bool& no_animation) {
  command.add_flag("--no-plot", no_plot, "write the JSON files only");
  command.add_flag("--no-animation", no_animation, "draw run.png but not run.gif");
}

double parse_number(const std::string& flag, const std::string& v) {
  double x = 0;
  if (!finite_decimal(v, x))
    throw Error(flag + " expects a finite decimal number, got '" + v + "'");
  return x;
}

std::optional<geometry::Point> parse_point(const std::string& flag, const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    return std::nullopt;
  }
  return geometry::Point(parse_number(flag, text.substr(0, comma)),
                         parse_number(flag, text.substr(comma + 1)));
}

}  // namespace rearm::cli
