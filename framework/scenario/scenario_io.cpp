// Scenario files (experiments/scenarios/README.md): reading YAML strictly and writing it back.
//
// yaml-cpp builds the node tree; every scalar is then interpreted here rather than through
// yaml-cpp's converters, so that numbers are read exactly the same way everywhere: a plain
// (unquoted) YAML scalar in decimal notation, parsed by std::from_chars (locale-independent,
// correctly rounded), with every spelling of NaN and infinity rejected. Every mapping is read
// against the list of its allowed keys, so an unknown (misspelt) or repeated key is an error
// instead of being ignored (yaml-cpp 0.7 keeps both entries of a repeated key).
//
// Each key path (`objects[1].radius`) is remembered with its line, so that an error found
// later by validate() also names the line in the file.
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

namespace rearm::scenario {

ScenarioError::ScenarioError(const std::string& source, const std::string& key,
                             const std::string& reason)
    : Error(source + ": " + key + ": " + reason), source_(source), key_(key), reason_(reason) {}

namespace {

// The key of errors about the document as a whole (empty, not a mapping, several documents).
const char* const kDocumentKey = "<document>";
// Longest excerpt of a scalar quoted in an error message.
constexpr std::size_t kMaxQuoted = 40;

const char* const kFloatTag = "tag:yaml.org,2002:float";
const char* const kIntTag = "tag:yaml.org,2002:int";

std::string quoted(const std::string& text) {
  if (text.size() <= kMaxQuoted) return "'" + text + "'";
  return "'" + text.substr(0, kMaxQuoted) + "...'";
}

// What a node is, for "expected X, got Y" messages.
std::string describe(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Null:
      return "an empty value (null)";
    case YAML::NodeType::Sequence:
      return "a list of " + std::to_string(n.size()) + (n.size() == 1 ? " item" : " items");
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Scalar:
      if (n.Tag() == "!") return "the quoted string " + quoted(n.Scalar());
      return quoted(n.Scalar());
    default:
      return "nothing";
  }
}

bool is_nonfinite_spelling(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.erase(0, 1);
  if (!text.empty() && text[0] == '.') text.erase(0, 1);
  return text == "nan" || text == "inf" || text == "infinity";
}

// The reader of one document: the source's name, and the line (1-based) of every key path.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  void remember(const std::string& path, const YAML::Mark& mark) {
    if (!mark.is_null()) lines_.emplace(path, mark.line + 1);
  }

  // " (line N)" for the path, or for its closest enclosing path that has a line; "" if none.
  std::string line_suffix(std::string path) const {
    while (!path.empty()) {
      if (const auto it = lines_.find(path); it != lines_.end()) {
        return " (line " + std::to_string(it->second) + ")";
      }
      const std::size_t cut = path.find_last_of(".[");
      if (cut == std::string::npos) break;
      path.erase(cut);
    }
    return "";
  }

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw ScenarioError(source_, path, reason + line_suffix(path));
  }

  // A scalar of the node, checked to be a plain scalar that may denote a number.
  const std::string& numeric_text(const YAML::Node& n, const std::string& path,
                                  const char* expected) const {
    if (!n.IsScalar()) fail(path, std::string("expected ") + expected + ", got " + describe(n));
    const std::string& tag = n.Tag();
    if (tag != "?" && tag != kFloatTag && tag != kIntTag) {
      fail(path, std::string("expected ") + expected + ", got " +
                     (tag == "!" ? describe(n) : "a value tagged " + tag));
    }
    return n.Scalar();
  }

  double number(const YAML::Node& n, const std::string& path) const {
    const std::string& text = numeric_text(n, path, "a number");
    if (is_nonfinite_spelling(text)) fail(path, "must be a finite number, got " + quoted(text));
    const char* first = text.data();
    const char* last = text.data() + text.size();
    // YAML allows a leading '+', std::from_chars does not.
    if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
    double value = 0;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range) {
      fail(path, "must be a finite number representable as a double, got " + quoted(text));
    }
    if (ec != std::errc() || end != last) fail(path, "expected a number, got " + quoted(text));
    if (!std::isfinite(value)) fail(path, "must be a finite number, got " + quoted(text));
    return value;
  }

  int integer(const YAML::Node& n, const std::string& path) const {
    const std::string& text = numeric_text(n, path, "an integer");
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
    long long value = 0;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc() && end == last) {
      if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
        fail(path, "integer out of range, got " + quoted(text));
      }
      return static_cast<int>(value);
    }
    if (ec == std::errc::result_out_of_range) {
      fail(path, "integer out of range, got " + quoted(text));
    }
    fail(path, "expected an integer, got " + quoted(text));
  }

  std::string text(const YAML::Node& n, const std::string& path) const {
    if (!n.IsScalar()) fail(path, "expected a string, got " + describe(n));
    return n.Scalar();
  }

  geometry::Point point(const YAML::Node& n, const std::string& path) {
    if (!n.IsSequence() || n.size() != 2) {
      fail(path, "expected a point [x, y], got " + describe(n));
    }
    return geometry::Point(number(n[0], path + "[0]"), number(n[1], path + "[1]"));
  }

  // A polygon given as a list of [x, y] vertices in either orientation, returned
  // counter-clockwise (geometry::validated).
  geometry::Polygon polygon(const YAML::Node& n, const std::string& path) {
    if (!n.IsSequence()) {
      fail(path, "expected a polygon (a list of [x, y] vertices), got " + describe(n));
    }
    geometry::Polygon p;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::string vertex = path + "[" + std::to_string(i) + "]";
      remember(vertex, n[i].Mark());
      p.vertices.push_back(point(n[i], vertex));
    }
    try {
      return geometry::validated(p, path.c_str());
    } catch (const Error& e) {
      std::string reason = e.what();
      const std::string prefix = path + ": ";
      if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
      fail(path, reason);
    }
  }

  // The items of a list, each with its path `key[i]`.
  std::vector<std::pair<YAML::Node, std::string>> items(const YAML::Node& n,
                                                        const std::string& path) {
    if (!n.IsSequence()) fail(path, "expected a list, got " + describe(n));
    std::vector<std::pair<YAML::Node, std::string>> out;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::string item = path + "[" + std::to_string(i) + "]";
      remember(item, n[i].Mark());
      out.emplace_back(n[i], item);
    }
    return out;
  }

 private:
  std::string source_;
  std::map<std::string, int> lines_;
};

// A YAML mapping read against its allowed keys: an unknown, repeated or non-scalar key is an
// error; required keys are checked when asked for.
class Fields {
 public:
  Fields(Reader& reader, const YAML::Node& node, std::string path,
         std::initializer_list<const char*> allowed)
      : reader_(reader), path_(std::move(path)), allowed_(allowed) {
    if (!node.IsMap()) {
      reader_.fail(path_.empty() ? kDocumentKey : path_,
                   "expected a mapping with keys " + allowed_list() + ", got " + describe(node));
    }
    std::map<std::string, int> first_line;
    for (auto it = node.begin(); it != node.end(); ++it) {
      // By value: yaml-cpp's iterator hands out a temporary pair.
      const YAML::Node key = it->first;
      const int line = key.Mark().line + 1;
      if (!key.IsScalar()) {
        const std::string where = path_.empty() ? std::string(kDocumentKey) : path_;
        reader_.fail(where, "keys must be plain words, got " + describe(key) +
                                " as a key at line " + std::to_string(line));
      }
      const std::string name = key.Scalar();
      const std::string full = child(name);
      if (std::find_if(allowed_.begin(), allowed_.end(),
                       [&](const char* a) { return name == a; }) == allowed_.end()) {
        throw ScenarioError(reader_.source(), full,
                            "unknown key (allowed here: " + allowed_list() + ") (line " +
                                std::to_string(line) + ")");
      }
      if (const auto seen = first_line.find(name); seen != first_line.end()) {
        throw ScenarioError(reader_.source(), full,
                            "repeated key (first at line " + std::to_string(seen->second) +
                                ") (line " + std::to_string(line) + ")");
      }
      first_line.emplace(name, line);
      reader_.remember(full, key.Mark());
      values_.emplace(name, it->second);
    }
    reader_.remember(path_, node.Mark());
  }

  std::string child(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  std::optional<YAML::Node> find(const char* key) const {
    if (const auto it = values_.find(key); it != values_.end()) return it->second;
    return std::nullopt;
  }

  YAML::Node require(const char* key) const {
    if (auto v = find(key)) return *v;
    reader_.fail(child(key), "required key is missing");
  }

 private:
  std::string allowed_list() const {
    std::string out;
    for (const char* a : allowed_) out += (out.empty() ? "" : ", ") + std::string(a);
    return out;
  }

  Reader& reader_;
  std::string path_;
  std::vector<const char*> allowed_;
  std::map<std::string, YAML::Node> values_;
};

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
  const Fields f(
      r, n, "controller",
      {"p", "epsilon", "mu1", "mu2", "k_v", "k_omega", "goal_tolerance", "fragment_tolerance"});
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
                          {"fragment_tolerance", &c.fragment_tolerance}};
  for (const auto& [key, value] : fields) {
    if (auto v = f.find(key)) *value = r.number(*v, f.child(key));
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
                  "unknown", "task", "controller", "simulation"});
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
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(yaml);
  } catch (const YAML::Exception& e) {
    if (e.mark.is_null()) throw ScenarioError(source, kDocumentKey, "malformed YAML: " + e.msg);
    throw ScenarioError(
        source,
        "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1),
        "malformed YAML: " + e.msg);
  }
  if (docs.empty()) {
    throw ScenarioError(source, kDocumentKey,
                        "the document is empty (a scenario needs at least name, workspace, robot "
                        "and task)");
  }
  if (docs.size() > 1) {
    throw ScenarioError(source, kDocumentKey,
                        "more than one YAML document (one scenario per file; the second starts at "
                        "line " +
                            std::to_string(docs[1].Mark().line + 1) + ")");
  }
  Scenario s;
  try {
    s = read_scenario(reader, docs.front());
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
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path, "file", "cannot read the scenario: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ScenarioError(path, "file",
                        std::string("cannot read the scenario: ") + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw ScenarioError(path, "file",
                        std::string("cannot read the scenario: ") + std::strerror(errno));
  }
  return parse_scenario(text.str(), path);
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
  const Controller& c = s.controller;
  out << "controller: {p: " << c.p << ", epsilon: " << num(c.epsilon) << ", mu1: " << num(c.mu1)
      << ", mu2: " << num(c.mu2) << ", k_v: " << num(c.k_v) << ", k_omega: " << num(c.k_omega)
      << ", goal_tolerance: " << num(c.goal_tolerance)
      << ", fragment_tolerance: " << num(c.fragment_tolerance) << "}\n";
  const Simulation& m = s.simulation;
  out << "simulation: {dt: " << num(m.dt) << ", time_budget: " << num(m.time_budget)
      << ", velocity_iterations: " << m.velocity_iterations
      << ", position_iterations: " << m.position_iterations << ", max_actions: " << m.max_actions
      << "}\n";
  return out.str();
}

}  // namespace rearm::scenario
