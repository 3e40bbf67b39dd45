// Scenario files (experiments/scenarios/README.md): reading YAML strictly (yaml_internal.h: the
// reading rules shared with the sweep files) and writing it back.
#include "scenario/scenario_io.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "scenario/yaml_internal.h"

namespace rearm::scenario {

ScenarioError::ScenarioError(const std::string& source, const std::string& key,
                             const std::string& reason)
    : Error(source + ": " + key + ": " + reason), source_(source), key_(key), reason_(reason) {}

namespace {

using detail::Fields;
using detail::kDocumentKey;
using detail::Reader;

void read_robot(Reader& r, const YAML::Node& n, Robot& robot) {
  const Fields f(r, n, "robot",
                 {"radius", "start", "heading", "v_max", "omega_max", "sensor_range"});
  robot.radius = r.number(f.require("radius"), f.child("radius"));
  robot.start = r.point(f.require("start"), f.child("start"));
  if (auto v = f.find("heading")) robot.heading = r.number(*v, f.child("heading"));
  if (auto v = f.find("v_max")) robot.v_max = r.number(*v, f.child("v_max"));
  if (auto v = f.find("omega_max")) robot.omega_max = r.number(*v, f.child("omega_max"));
  if (auto v = f.find("sensor_range")) robot.sensor_range = r.number(*v, f.child("sensor_range"));
}

std::vector<NamedPolygon> read_named_polygons(Reader& r, const YAML::Node& n,
                                              const std::string& path) {
  std::vector<NamedPolygon> out;
  for (const auto& [item, item_path] : r.items(n, path)) {
    const Fields f(r, item, item_path, {"name", "polygon"});
    NamedPolygon np;
    np.name = r.text(f.require("name"), f.child("name"));
    np.polygon = r.polygon(f.require("polygon"), f.child("polygon"));
    out.push_back(std::move(np));
  }
  return out;
}

std::vector<Object> read_objects(Reader& r, const YAML::Node& n) {
  std::vector<Object> out;
  for (const auto& [item, item_path] : r.items(n, "objects")) {
    const Fields f(r, item, item_path, {"name", "center", "radius"});
    Object o;
    o.name = r.text(f.require("name"), f.child("name"));
    o.disk.center = r.point(f.require("center"), f.child("center"));
    o.disk.radius = r.number(f.require("radius"), f.child("radius"));
    out.push_back(std::move(o));
  }
  return out;
}

void read_controller(Reader& r, const YAML::Node& n, Controller& c) {
  // The robust switches' keys come from the registry (core/switches.h).
  std::vector<const char*> allowed = {"p",
                                      "epsilon",
                                      "mu1",
                                      "mu2",
                                      "k_v",
                                      "k_omega",
                                      "goal_tolerance",
                                      "fragment_tolerance",
                                      "scan_spacing",
                                      "variant"};
  for (const SwitchInfo& s : kSwitches) allowed.push_back(s.key);
  allowed.push_back("rebuild_margin");
  const Fields f(r, n, "controller", std::move(allowed));
  struct Field {
    const char* key;
    double* value;
  };
  if (auto v = f.find("p")) c.p = r.integer(*v, f.child("p"));
  const Field fields[] = {{"epsilon", &c.epsilon},
                          {"mu1", &c.mu1},
                          {"mu2", &c.mu2},
                          {"k_v", &c.k_v},
                          {"k_omega", &c.k_omega},
                          {"goal_tolerance", &c.goal_tolerance},
                          {"fragment_tolerance", &c.fragment_tolerance},
                          {"scan_spacing", &c.scan_spacing},
                          {"rebuild_margin", &c.rebuild_margin}};
  for (const auto& [key, value] : fields) {
    if (auto v = f.find(key)) *value = r.number(*v, f.child(key));
  }
  if (auto v = f.find("variant")) {
    c.variant = r.text(*v, f.child("variant"));
    if (c.variant != "robust" && c.variant != "paper") {
      r.fail(f.child("variant"), "expected robust or paper, got '" + c.variant + "'");
    }
  }
  set_variant(c, c.variant);
  for (std::size_t i = 0; i < kSwitchCount; ++i) {
    const char* key = kSwitches[i].key;
    if (auto v = f.find(key)) {
      c.switches.set(i, r.flag(*v, f.child(key)));
      if (c.variant == "paper" && c.switches.on(i)) {
        r.fail(f.child(key), "the paper variant runs no extension (use variant: robust)");
      }
    }
  }
}

void read_simulation(Reader& r, const YAML::Node& n, Simulation& s) {
  const Fields f(
      r, n, "simulation",
      {"dt", "time_budget", "velocity_iterations", "position_iterations", "max_actions"});
  if (auto v = f.find("dt")) s.dt = r.number(*v, f.child("dt"));
  if (auto v = f.find("time_budget")) s.time_budget = r.number(*v, f.child("time_budget"));
  if (auto v = f.find("velocity_iterations")) {
    s.velocity_iterations = r.integer(*v, f.child("velocity_iterations"));
  }
  if (auto v = f.find("position_iterations")) {
    s.position_iterations = r.integer(*v, f.child("position_iterations"));
  }
  if (auto v = f.find("max_actions")) s.max_actions = r.integer(*v, f.child("max_actions"));
}

Scenario read_scenario(Reader& r, const YAML::Node& doc) {
  const Fields f(r, doc, "",
                 {"name", "description", "workspace", "robot", "regions", "objects", "familiar",
                  "unknown", "task", "initial_predicate", "controller", "simulation"});
  Scenario s;
  s.source = r.source();
  s.name = r.text(f.require("name"), "name");
  if (auto v = f.find("description")) s.description = r.text(*v, "description");
  s.workspace = r.polygon(f.require("workspace"), "workspace");
  read_robot(r, f.require("robot"), s.robot);
  if (auto v = f.find("regions")) s.regions = read_named_polygons(r, *v, "regions");
  if (auto v = f.find("objects")) s.objects = read_objects(r, *v);
  if (auto v = f.find("familiar")) s.familiar = read_named_polygons(r, *v, "familiar");
  if (auto v = f.find("unknown")) s.unknown = read_named_polygons(r, *v, "unknown");
  s.task = r.text(f.require("task"), "task");
  if (auto v = f.find("initial_predicate")) {
    s.initial_predicate = r.text(*v, "initial_predicate");
  }
  if (auto v = f.find("controller")) read_controller(r, *v, s.controller);
  if (auto v = f.find("simulation")) read_simulation(r, *v, s.simulation);
  return s;
}

// ---- writing ----

// The shortest decimal that reads back to the same double (std::to_chars; at most 17
// significant digits).
std::string num(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

// A YAML double-quoted scalar: backslash, quote and control characters escaped; other bytes
// (UTF-8 included) as they are.
std::string yaml_string(const std::string& text) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string flow_point(const geometry::Point& p) {
  return "[" + num(p.x()) + ", " + num(p.y()) + "]";
}

std::string flow_polygon(const geometry::Polygon& p) {
  std::string out = "[";
  for (std::size_t i = 0; i < p.size(); ++i) out += (i ? ", " : "") + flow_point(p.vertices[i]);
  return out + "]";
}

void write_named(std::ostream& out, const char* key, const std::vector<NamedPolygon>& list) {
  out << key << ":";
  if (list.empty()) {
    out << " []\n";
    return;
  }
  out << "\n";
  for (const NamedPolygon& np : list) {
    out << "  - {name: " << yaml_string(np.name) << ", polygon: " << flow_polygon(np.polygon)
        << "}\n";
  }
}

}  // namespace

Scenario parse_scenario(const std::string& yaml, const std::string& source) {
  Reader reader(source);
  const YAML::Node doc =
      detail::single_document(yaml, source, "scenario", "name, workspace, robot and task");
  Scenario s;
  try {
    s = read_scenario(reader, doc);
  } catch (const ScenarioError&) {
    throw;
  } catch (const YAML::Exception& e) {
    // Not expected from a loaded tree (every access above is checked); reported, not hidden.
    throw ScenarioError(source, kDocumentKey, std::string("YAML error: ") + e.what());
  }
  try {
    validate(s);
  } catch (const ScenarioError& e) {
    throw ScenarioError(e.source(), e.key(), e.reason() + reader.line_suffix(e.key()));
  }
  return s;
}

Scenario load_scenario(const std::string& path) {
  return parse_scenario(detail::read_text_file(path, "the scenario"), path);
}

std::string to_yaml(const Scenario& s) {
  std::ostringstream out;
  out << "name: " << yaml_string(s.name) << "\n";
  out << "description: " << yaml_string(s.description) << "\n";
  out << "workspace: " << flow_polygon(s.workspace) << "\n";
  const Robot& r = s.robot;
  out << "robot: {radius: " << num(r.radius) << ", start: " << flow_point(r.start)
      << ", heading: " << num(r.heading) << ", v_max: " << num(r.v_max)
      << ", omega_max: " << num(r.omega_max) << ", sensor_range: " << num(r.sensor_range) << "}\n";
  write_named(out, "regions", s.regions);
  out << "objects:";
  if (s.objects.empty()) out << " []";
  out << "\n";
  for (const Object& o : s.objects) {
    out << "  - {name: " << yaml_string(o.name) << ", center: " << flow_point(o.disk.center)
        << ", radius: " << num(o.disk.radius) << "}\n";
  }
  write_named(out, "familiar", s.familiar);
  write_named(out, "unknown", s.unknown);
  out << "task: " << yaml_string(s.task) << "\n";
  if (!s.initial_predicate.empty()) {
    out << "initial_predicate: " << yaml_string(s.initial_predicate) << "\n";
  }
  const Controller& c = s.controller;
  out << "controller: {p: " << c.p << ", epsilon: " << num(c.epsilon) << ", mu1: " << num(c.mu1)
      << ", mu2: " << num(c.mu2) << ", k_v: " << num(c.k_v) << ", k_omega: " << num(c.k_omega)
      << ", goal_tolerance: " << num(c.goal_tolerance)
      << ", fragment_tolerance: " << num(c.fragment_tolerance)
      << ", scan_spacing: " << num(c.scan_spacing) << ", rebuild_margin: " << num(c.rebuild_margin)
      << ", variant: " << c.variant;
  if (c.variant == "robust") {
    for (std::size_t i = 0; i < kSwitchCount; ++i) {
      out << ", " << kSwitches[i].key << ": " << (c.switches.on(i) ? "true" : "false");
    }
  }
  out << "}\n";
  const Simulation& m = s.simulation;
  out << "simulation: {dt: " << num(m.dt) << ", time_budget: " << num(m.time_budget)
      << ", velocity_iterations: " << m.velocity_iterations
      << ", position_iterations: " << m.position_iterations << ", max_actions: " << m.max_actions
      << "}\n";
  return out.str();
}

}  // namespace rearm::scenario
