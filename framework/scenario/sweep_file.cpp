// Sweep files (sweep_file.h; format reference experiments/sweeps/README.md).
#include "scenario/sweep_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/switches.h"
#include "scenario/yaml_internal.h"

namespace rearm::scenario {
namespace {

using detail::Fields;
using detail::Reader;

constexpr double kMaxSide = kMaxSweepSide;
constexpr double kMinSide = 0.5;  // m: below this no robot fits
constexpr double kMaxFootprint = kMaxFootprintDensity;
constexpr double kMaxPassageMarginInFile = 2;  // m (random_instance.h, InstanceSpec)

std::string num(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return ec == std::errc() ? std::string(buf, end) : "?";
}

std::uint64_t unsigned64(Reader& r, const YAML::Node& n, const std::string& path) {
  const std::string& text = r.numeric_text(n, path, "a non-negative integer");
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    r.fail(path, "expected a non-negative integer below 2^64, got " + detail::quoted(text));
  }
  return value;
}

double in_range(Reader& r, const YAML::Node& n, const std::string& path, double lo, double hi,
                bool open_lo = false) {
  const double x = r.number(n, path);
  if (x < lo || x > hi || (open_lo && x == lo)) {
    r.fail(path, "must be in " + std::string(open_lo ? "(" : "[") + num(lo) + ", " + num(hi) +
                     "], got " + num(x));
  }
  return x;
}

int int_in_range(Reader& r, const YAML::Node& n, const std::string& path, int lo, int hi) {
  const int x = r.integer(n, path);
  if (x < lo || x > hi) {
    r.fail(path, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "], got " + std::to_string(x));
  }
  return x;
}

// A list (or one scalar, as a list of one) of values read by `item`, non-empty, no repeats.
template <class T, class ItemFn>
std::vector<T> list_of(Reader& r, const YAML::Node& n, const std::string& path, ItemFn item) {
  std::vector<std::pair<YAML::Node, std::string>> items;
  if (n.IsScalar()) {
    items.emplace_back(n, path);
  } else {
    items = r.items(n, path);
  }
  if (items.empty()) r.fail(path, "must list at least one value");
  std::vector<T> out;
  for (const auto& [node, p] : items) {
    T v = item(node, p);
    for (const T& seen : out) {
      if (seen == v) r.fail(p, "repeated value");
    }
    out.push_back(v);
  }
  return out;
}

WorkspaceRule read_workspace(Reader& r, const YAML::Node& n) {
  const Fields f(r, n, "workspace", {"side", "sides", "footprint_density", "min_side"});
  WorkspaceRule w;
  const int given =
      (f.find("side") ? 1 : 0) + (f.find("sides") ? 1 : 0) + (f.find("footprint_density") ? 1 : 0);
  if (given != 1) {
    r.fail("workspace", "give exactly one of side, sides and footprint_density");
  }
  if (const auto v = f.find("side")) {
    w.kind = WorkspaceRule::Kind::kSide;
    w.side = in_range(r, *v, "workspace.side", kMinSide, kMaxSide);
  } else if (const auto v = f.find("sides")) {
    w.kind = WorkspaceRule::Kind::kSidePerCount;
    for (const auto& [item, p] : r.items(*v, "workspace.sides")) {
      if (!item.IsSequence() || item.size() != 2) r.fail(p, "expected a pair [objects, side]");
      const int objects = int_in_range(r, item[0], p + "[0]", 1, kMaxInstanceObjects);
      if (w.per_count.count(objects)) r.fail(p, "repeated object count");
      w.per_count[objects] = in_range(r, item[1], p + "[1]", kMinSide, kMaxSide);
    }
    if (w.per_count.empty()) r.fail("workspace.sides", "must list at least one [objects, side]");
  } else {
    w.kind = WorkspaceRule::Kind::kFootprint;
    w.footprint_density = in_range(r, *f.find("footprint_density"), "workspace.footprint_density",
                                   0, kMaxFootprint, true);
    if (const auto v = f.find("min_side")) {
      w.min_side = in_range(r, *v, "workspace.min_side", 0, kMaxSide);
    }
  }
  if (w.kind != WorkspaceRule::Kind::kFootprint && f.find("min_side")) {
    r.fail("workspace.min_side", "only goes with footprint_density");
  }
  return w;
}

// `footprint_densities: [...]`: the footprint rule per value; `workspace` may then only give
// min_side.
void read_footprints(Reader& r, const YAML::Node& list, const std::optional<YAML::Node>& workspace,
                     SweepFile& s) {
  s.footprints = list_of<double>(r, list, "footprint_densities",
                                 [&](const YAML::Node& n, const std::string& p) {
                                   return in_range(r, n, p, 0, kMaxFootprint, true);
                                 });
  s.workspace.kind = WorkspaceRule::Kind::kFootprint;
  s.workspace.footprint_density = s.footprints.front();
  if (!workspace) return;
  const Fields w(r, *workspace, "workspace", {"side", "sides", "footprint_density", "min_side"});
  if (w.find("side") || w.find("sides") || w.find("footprint_density")) {
    r.fail("workspace", "with footprint_densities, workspace may only give min_side");
  }
  if (const auto v = w.find("min_side")) {
    s.workspace.min_side = in_range(r, *v, "workspace.min_side", 0, kMaxSide);
  }
}

void read_instance(Reader& r, const YAML::Node& n, InstanceSpec& spec) {
  const Fields f(r, n, "instance",
                 {"robot_radius", "object_radius", "region_side", "sensor_range", "passage_margin",
                  "max_obstacle_side", "max_attempts"});
  auto length = [&](const char* key, double& field) {
    if (const auto v = f.find(key)) field = in_range(r, *v, f.child(key), 0, 10, true);
  };
  length("robot_radius", spec.robot_radius);
  length("object_radius", spec.object_radius);
  length("region_side", spec.region_side);
  length("sensor_range", spec.sensor_range);
  if (const auto v = f.find("passage_margin")) {
    spec.passage_margin =
        in_range(r, *v, "instance.passage_margin", kMinPassageMargin, kMaxPassageMarginInFile);
  }
  if (const auto v = f.find("max_obstacle_side")) {
    spec.max_obstacle_side =
        in_range(r, *v, "instance.max_obstacle_side", kMinMaxObstacleSide, kMaxMaxObstacleSide);
  }
  if (const auto v = f.find("max_attempts")) {
    spec.max_attempts = int_in_range(r, *v, "instance.max_attempts", 1, 1'000'000);
  }
}

// "rearm-no*" stands for every switch's ablation method, in the registry's order
// (core/switches.h), so an ablation sweep covers a switch added later.
std::vector<std::string> expand_ablation_group(const std::vector<std::string>& named) {
  std::vector<std::string> out;
  for (const std::string& m : named) {
    if (m != kAblationGroup) {
      out.push_back(m);
      continue;
    }
    for (const SwitchInfo& w : kSwitches) out.push_back(ablation_method(w));
  }
  return out;
}

// A list of names read by `from_string` (a generator enum's inverse of to_string), its error
// reported at the entry's key.
template <class T, class FromString>
std::vector<T> names_of(Reader& r, const YAML::Node& node, const std::string& key,
                        FromString from_string) {
  return list_of<T>(r, node, key, [&](const YAML::Node& n, const std::string& p) {
    try {
      return from_string(r.text(n, p));
    } catch (const ScenarioError&) {
      throw;
    } catch (const Error& e) {
      r.fail(p, e.what());
    }
  });
}

void read_lists(Reader& r, const Fields& f, SweepFile& s) {
  const auto named = list_of<std::string>(r, f.require("methods"), "methods",
                                          [&](const YAML::Node& n, const std::string& p) {
                                            std::string m = r.text(n, p);
                                            if (m.empty()) r.fail(p, "empty method name");
                                            try {
                                              (void)method_entry(m);
                                            } catch (const Error& e) {
                                              r.fail(p, e.what());
                                            }
                                            return m;
                                          });
  s.methods = expand_ablation_group(named);
  s.classes = names_of<GoalClass>(r, f.require("classes"), "classes", goal_class_from_string);
  if (const auto v = f.find("goal_orders")) {
    s.goal_orders = names_of<GoalOrder>(r, *v, "goal_orders", goal_order_from_string);
  }
  s.objects = list_of<int>(r, f.require("objects"), "objects",
                           [&](const YAML::Node& n, const std::string& p) {
                             return int_in_range(r, n, p, 1, kMaxInstanceObjects);
                           });
  if (const auto v = f.find("scatter_moves")) {
    const int most =
        kMaxScatterMovesPerObject * *std::min_element(s.objects.begin(), s.objects.end());
    s.scatter_moves = list_of<int>(
        r, *v, "scatter_moves",
        [&](const YAML::Node& n, const std::string& p) { return int_in_range(r, n, p, 0, most); });
  }
  s.densities = list_of<double>(r, f.require("densities"), "densities",
                                [&](const YAML::Node& n, const std::string& p) {
                                  return in_range(r, n, p, 0, kMaxObstacleDensity);
                                });
  s.unknown_fractions = {0.5};
  if (const auto v = f.find("unknown_fraction")) {
    s.unknown_fractions = list_of<double>(
        r, *v, "unknown_fraction",
        [&](const YAML::Node& n, const std::string& p) { return in_range(r, n, p, 0, 1); });
  }
  s.round_unknown = {true};
  if (const auto v = f.find("unknown_shapes")) {
    s.round_unknown =
        list_of<bool>(r, *v, "unknown_shapes", [&](const YAML::Node& n, const std::string& p) {
          const std::string t = r.text(n, p);
          if (t != "round" && t != "polygon") {
            r.fail(p, "expected round or polygon, got '" + t + "'");
          }
          return t == "round";
        });
  }
}

SweepFile read_sweep(Reader& r, const YAML::Node& doc) {
  const Fields f(r, doc, "",
                 {"name", "description", "methods", "classes", "goal_orders", "objects",
                  "densities", "workspace", "footprint_densities", "unknown_fraction",
                  "unknown_shapes", "seeds", "scatter_moves", "time_limit", "query_limit",
                  "base_seed", "instance", "refused_cells", "role"});
  SweepFile s;
  s.source = r.source();
  s.name = r.text(f.require("name"), "name");
  if (s.name.empty() ||
      s.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRST"
                               "UVWXYZ0123456789_-.") != std::string::npos ||
      s.name[0] == '.' || s.name[0] == '-') {
    r.fail("name", "must be a file-name-safe word (letters, digits, _ - .), got '" + s.name + "'");
  }
  if (const auto v = f.find("description")) s.description = r.text(*v, "description");
  read_lists(r, f, s);
  if (const auto v = f.find("footprint_densities")) {
    read_footprints(r, *v, f.find("workspace"), s);
  } else {
    s.workspace = read_workspace(r, f.require("workspace"));
  }
  if (s.workspace.kind == WorkspaceRule::Kind::kSidePerCount) {
    for (int n : s.objects) {
      if (!s.workspace.per_count.count(n)) {
        r.fail("workspace.sides", "lists no side for " + std::to_string(n) + " objects");
      }
    }
  }
  if (const auto v = f.find("seeds")) s.seeds = int_in_range(r, *v, "seeds", 1, kMaxSweepSeeds);
  if (const auto v = f.find("time_limit")) {
    s.time_limit = in_range(r, *v, "time_limit", 0, kMaxTrialTimeLimit, true);
  }
  if (const auto v = f.find("query_limit")) {
    s.query_limit = int_in_range(r, *v, "query_limit", 0, kMaxQueryLimit);
  }
  if (const auto v = f.find("base_seed")) s.base_seed = unsigned64(r, *v, "base_seed");
  if (const auto v = f.find("instance")) read_instance(r, *v, s.instance);
  if (const auto v = f.find("role")) {
    s.role = r.text(*v, "role");
    if (s.role != "tuning" && s.role != "test") {
      r.fail("role", "expected tuning or test, got '" + s.role + "'");
    }
  }
  if (const auto v = f.find("refused_cells")) {
    const std::string t = r.text(*v, "refused_cells");
    if (t != "error" && t != "skip")
      r.fail("refused_cells", "expected error or skip, got '" + t + "'");
    s.skip_refused_cells = t == "skip";
  }
  if (s.workspace.kind == WorkspaceRule::Kind::kFootprint) {
    const std::string key =
        s.footprints.empty() ? "workspace.footprint_density" : "footprint_densities";
    for (const WorkspaceRule& w : s.workspaces()) {
      for (int n : s.objects) {
        const double side = w.side_for(n, s.instance.object_radius);
        if (!(side <= kMaxSide)) {
          r.fail(key, "footprint " + num(w.footprint_density) + " gives a side of " + num(side) +
                          " m for " + std::to_string(n) + " objects, more than " + num(kMaxSide) +
                          " m");
        }
      }
    }
  }
  if (s.trial_count() > kMaxSweepTrials) {
    r.fail("seeds", "the sweep has " + std::to_string(s.trial_count()) + " trials, more than " +
                        std::to_string(kMaxSweepTrials));
  }
  return s;
}

}  // namespace

double WorkspaceRule::side_for(int objects, double rho) const {
  switch (kind) {
    case Kind::kSide:
      return side;
    case Kind::kSidePerCount: {
      const auto it = per_count.find(objects);
      if (it == per_count.end()) {
        throw Error("workspace rule: no side for " + std::to_string(objects) + " objects");
      }
      return it->second;
    }
    case Kind::kFootprint:
      return std::max(min_side,
                      std::sqrt(objects * std::numbers::pi * rho * rho / footprint_density));
  }
  return side;
}

std::string WorkspaceRule::describe() const {
  switch (kind) {
    case Kind::kSide:
      return "side " + num(side);
    case Kind::kSidePerCount:
      return "sides per N";
    case Kind::kFootprint:
      return "footprint " + num(footprint_density) +
             (min_side > 0 ? " (>= " + num(min_side) + " m)" : "");
  }
  return "";
}

std::vector<WorkspaceRule> SweepFile::workspaces() const {
  if (footprints.empty()) return {workspace};
  std::vector<WorkspaceRule> out;
  for (const double f : footprints) {
    WorkspaceRule w = workspace;
    w.footprint_density = f;
    out.push_back(w);
  }
  return out;
}

std::vector<int> SweepFile::scatter_moves_of(GoalClass c) const {
  return c == GoalClass::kConstructive ? scatter_moves : std::vector<int>{0};
}

std::size_t SweepFile::trial_count(
    const std::function<bool(const std::string& method)>& follows_order) const {
  std::size_t per_instance = 0;  // trials per geometry, over its goal orders
  for (const std::string& m : methods) {
    const bool follows = !follows_order || follows_order(method_entry(m).method);
    per_instance += follows ? goal_orders.size() : 1;
  }
  std::size_t class_cells = 0;
  for (const GoalClass c : classes) class_cells += scatter_moves_of(c).size();
  return class_cells * objects.size() * std::max<std::size_t>(1, footprints.size()) *
         densities.size() * unknown_fractions.size() * round_unknown.size() *
         static_cast<std::size_t>(seeds) * per_instance;
}

SweepFile parse_sweep_file(const std::string& yaml, const std::string& source) {
  Reader reader(source);
  const YAML::Node doc = detail::single_document(
      yaml, source, "sweep", "name, methods, classes, objects, densities and workspace");
  try {
    return read_sweep(reader, doc);
  } catch (const ScenarioError&) {
    throw;
  } catch (const YAML::Exception& e) {
    throw ScenarioError(source, detail::kDocumentKey, std::string("YAML error: ") + e.what());
  }
}

SweepFile load_sweep_file(const std::string& path) {
  return parse_sweep_file(detail::read_text_file(path, "the sweep"), path);
}

MethodEntry method_entry(const std::string& entry) {
  const std::size_t at = entry.find('@');
  MethodEntry out{entry.substr(0, at), std::nullopt};
  if (out.method.empty()) throw Error("method entry '" + entry + "' names no method");
  if (at == std::string::npos) return out;
  const std::string budget = entry.substr(at + 1);
  long k = 0;
  const auto [end, ec] = std::from_chars(budget.data(), budget.data() + budget.size(), k);
  if (ec != std::errc() || end != budget.data() + budget.size() || k < 1 || k > kMaxQueryLimit) {
    throw Error("method entry '" + entry + "': the budget after '@' must be an integer in [1, " +
                std::to_string(kMaxQueryLimit) + "] motion queries");
  }
  out.query_limit = k;
  return out;
}

}  // namespace rearm::scenario
