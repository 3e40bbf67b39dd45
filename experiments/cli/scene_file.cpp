#include "scene_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/distance.h"

namespace rearm::cli {
namespace {

using geometry::Point;
using geometry::Polygon;

// A parsed flow value with the line it starts on.
struct Value {
  enum class Kind { kNumber, kList, kMap };
  Kind kind = Kind::kNumber;
  int line = 0;
  double number = 0;
  std::vector<Value> items;                           // kList
  std::vector<std::pair<std::string, Value>> fields;  // kMap, in file order
};

class Parser {
 public:
  Parser(const std::string& text, const std::string& name) : text_(text), name_(name) {
    // Comments run from '#' to the end of the line (the format has no strings).
    bool comment = false;
    for (char& c : text_) {
      if (c == '\n') {
        comment = false;
      } else if (c == '#' || comment) {
        comment = true;
        c = ' ';
      }
    }
  }

  // The top-level mapping, keys in file order.
  std::vector<std::pair<std::string, Value>> parse_document() {
    std::vector<std::pair<std::string, Value>> out;
    for (;;) {
      skip_blank_lines();
      if (eof()) break;
      if (text_[pos_] == ' ' || text_[pos_] == '\t') {
        fail(pos_, "unexpected indentation (top-level keys start in column 1)");
      }
      const std::size_t key_pos = pos_;
      const std::string key = identifier("a top-level key");
      skip_spaces();
      expect(':', "after the key '" + key + "'");
      skip_spaces();
      Value v;
      if (at_line_end()) {
        v = block_list(key, line_at(key_pos));
      } else {
        v = flow_value();
        end_of_line();
      }
      for (const auto& [k, _] : out) {
        if (k == key) fail(key_pos, "duplicate key '" + key + "'");
      }
      out.emplace_back(key, std::move(v));
    }
    return out;
  }

  [[noreturn]] void fail_line(int line, const std::string& what) const {
    throw Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

 private:
  bool eof() const { return pos_ >= text_.size(); }

  int line_at(std::size_t pos) const {
    return 1 + static_cast<int>(
                   std::count(text_.begin(), text_.begin() + std::min(pos, text_.size()), '\n'));
  }

  [[noreturn]] void fail(std::size_t pos, const std::string& what) const {
    fail_line(line_at(pos), what);
  }

  void skip_spaces() {
    while (!eof() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
  }

  void skip_whitespace() {
    while (!eof() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  bool at_line_end() const { return eof() || text_[pos_] == '\n'; }

  // Skips lines holding only whitespace; leaves pos_ at the start of the next other line.
  void skip_blank_lines() {
    for (;;) {
      std::size_t p = pos_;
      while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\r')) ++p;
      if (p < text_.size() && text_[p] == '\n') {
        pos_ = p + 1;
      } else if (p >= text_.size()) {
        pos_ = p;
        return;
      } else {
        return;
      }
    }
  }

  void end_of_line() {
    skip_spaces();
    if (!at_line_end()) fail(pos_, "unexpected text after the value");
    if (!eof()) ++pos_;
  }

  void expect(char c, const std::string& where) {
    if (eof() || text_[pos_] != c) {
      fail(pos_, std::string("expected '") + c + "' " + where +
                     (eof() ? std::string(", found the end of the file")
                            : ", found '" + std::string(1, text_[pos_]) + "'"));
    }
    ++pos_;
  }

  std::string identifier(const char* what) {
    const std::size_t start = pos_;
    while (!eof() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
      ++pos_;
    }
    if (start == pos_ || std::isdigit(static_cast<unsigned char>(text_[start]))) {
      fail(start, std::string("expected ") + what);
    }
    return text_.substr(start, pos_ - start);
  }

  // "- value" lines indented under a key with no value on its own line.
  Value block_list(const std::string& key, int key_line) {
    Value list;
    list.kind = Value::Kind::kList;
    list.line = key_line;
    if (!eof()) ++pos_;  // the key's newline
    for (;;) {
      skip_blank_lines();
      if (eof()) break;
      const std::size_t line_start = pos_;
      skip_spaces();
      if (text_[pos_] != '-') {
        if (pos_ == line_start) break;  // the next top-level key
        fail(pos_, "expected '- <value>' (an item of the list '" + key + "')");
      }
      ++pos_;
      if (eof() || (text_[pos_] != ' ' && text_[pos_] != '\t')) {
        fail(pos_, "expected a space after '-'");
      }
      skip_spaces();
      list.items.push_back(flow_value());
      end_of_line();
    }
    if (list.items.empty()) {
      fail_line(key_line, "the key '" + key + "' has no value (write [] for an empty list)");
    }
    return list;
  }

  Value flow_value() {
    skip_whitespace();
    if (eof()) fail(pos_, "expected a value, found the end of the file");
    Value v;
    v.line = line_at(pos_);
    const char c = text_[pos_];
    if (c == '[') {
      v.kind = Value::Kind::kList;
      ++pos_;
      skip_whitespace();
      if (!eof() && text_[pos_] == ']') {
        ++pos_;
        return v;
      }
      for (;;) {
        v.items.push_back(flow_value());
        skip_whitespace();
        if (eof()) fail_line(v.line, "unterminated list (no closing ']')");
        if (text_[pos_] == ',') {
          ++pos_;
        } else if (text_[pos_] == ']') {
          ++pos_;
          return v;
        } else {
          fail(pos_, std::string("expected ',' or ']' in a list, found '") + text_[pos_] + "'");
        }
      }
    }
    if (c == '{') {
      v.kind = Value::Kind::kMap;
      ++pos_;
      skip_whitespace();
      if (!eof() && text_[pos_] == '}') {
        ++pos_;
        return v;
      }
      for (;;) {
        skip_whitespace();
        const std::size_t key_pos = pos_;
        const std::string key = identifier("a key");
        for (const auto& [k, _] : v.fields) {
          if (k == key) fail(key_pos, "duplicate key '" + key + "'");
        }
        skip_spaces();
        expect(':', "after the key '" + key + "'");
        v.fields.emplace_back(key, flow_value());
        skip_whitespace();
        if (eof()) fail_line(v.line, "unterminated map (no closing '}')");
        if (text_[pos_] == ',') {
          ++pos_;
        } else if (text_[pos_] == '}') {
          ++pos_;
          return v;
        } else {
          fail(pos_, std::string("expected ',' or '}' in a map, found '") + text_[pos_] + "'");
        }
      }
    }
    // A number: everything up to a delimiter.
    const std::size_t start = pos_;
    while (!eof() && !std::isspace(static_cast<unsigned char>(text_[pos_])) && text_[pos_] != ',' &&
           text_[pos_] != ']' && text_[pos_] != '}' && text_[pos_] != '[' && text_[pos_] != '{' &&
           text_[pos_] != ':') {
      ++pos_;
    }
    const std::string token = text_.substr(start, pos_ - start);
    if (token.empty()) fail(start, std::string("expected a value, found '") + c + "'");
    std::string lower = token;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos) {
      fail(start, "non-finite number '" + token + "'");
    }
    char* end = nullptr;
    v.number = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size()) fail(start, "invalid number '" + token + "'");
    if (!std::isfinite(v.number)) fail(start, "non-finite number '" + token + "' (overflow)");
    return v;
  }

  std::string text_;
  std::string name_;
  std::size_t pos_ = 0;
};

// Schema checks on parsed values.
class Schema {
 public:
  explicit Schema(const Parser& p) : p_(p) {}

  [[noreturn]] void fail(const Value& v, const std::string& what) const {
    p_.fail_line(v.line, what);
  }

  double number(const Value& v, const std::string& what) const {
    if (v.kind != Value::Kind::kNumber) fail(v, what + " must be a number");
    return v.number;
  }

  double positive(const Value& v, const std::string& what) const {
    const double x = number(v, what);
    if (!(x > 0)) fail(v, what + " must be > 0, got " + std::to_string(x));
    return x;
  }

  Point point(const Value& v, const std::string& what) const {
    if (v.kind != Value::Kind::kList || v.items.size() != 2) {
      fail(v, what + " must be a point [x, y]");
    }
    return {number(v.items[0], what + " x"), number(v.items[1], what + " y")};
  }

  Polygon polygon(const Value& v, const std::string& what) const {
    if (v.kind != Value::Kind::kList) fail(v, what + " must be a list of points [[x, y], ...]");
    if (v.items.size() < 3) {
      fail(v, what + " needs at least 3 vertices, got " + std::to_string(v.items.size()));
    }
    Polygon p;
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      p.vertices.push_back(point(v.items[i], what + " vertex " + std::to_string(i + 1)));
    }
    try {
      return geometry::validated(p, what.c_str());
    } catch (const Error& e) {
      fail(v, e.what());
    }
  }

  const std::vector<Value>& list(const Value& v, const std::string& what) const {
    if (v.kind != Value::Kind::kList) fail(v, what + " must be a list");
    return v.items;
  }

  // The fields of a map, checked against the allowed keys; required ones must be present.
  const std::vector<std::pair<std::string, Value>>& map(
      const Value& v, const std::string& what, const std::vector<std::string>& allowed,
      const std::vector<std::string>& required) const {
    if (v.kind != Value::Kind::kMap) fail(v, what + " must be a map {key: value, ...}");
    for (const auto& [k, field] : v.fields) {
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
        fail(field,
             "unknown key '" + k + "' in " + what + " (expected one of: " + join(allowed) + ")");
      }
    }
    for (const std::string& k : required) {
      if (!find(v.fields, k)) fail(v, what + " is missing the key '" + k + "'");
    }
    return v.fields;
  }

  static const Value* find(const std::vector<std::pair<std::string, Value>>& fields,
                           const std::string& key) {
    for (const auto& [k, v] : fields) {
      if (k == key) return &v;
    }
    return nullptr;
  }

  static std::string join(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
  }

 private:
  const Parser& p_;
};

std::string show(const Point& x) {
  std::ostringstream s;
  s << "(" << x.x() << ", " << x.y() << ")";
  return s.str();
}

// A start or goal must be in the workspace and at least the robot radius from everything.
void check_free(const SceneFile& s, const Parser& parser, const Point& x, const char* what) {
  const auto& in = s.semantic;
  if (!geometry::contains(in.workspace, x) ||
      geometry::nearest_on_boundary(in.workspace, x).distance < s.radius) {
    parser.fail_line(s.robot_line, std::string("robot ") + what + " " + show(x) +
                                       " is outside the workspace or closer than the robot "
                                       "radius to its boundary");
  }
  auto polygon_check = [&](const std::vector<Polygon>& ps, const std::vector<int>& lines,
                           const char* kind) {
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (geometry::distance(ps[i], x) < s.radius) {
        parser.fail_line(
            s.robot_line,
            std::string("robot ") + what + " " + show(x) + " is " +
                (geometry::contains(ps[i], x) ? "inside" : "within the robot radius of") + " " +
                kind + " obstacle " + std::to_string(i + 1) + " (line " + std::to_string(lines[i]) +
                ")");
      }
    }
  };
  polygon_check(in.familiar, s.familiar_lines, "familiar");
  polygon_check(in.unknown, s.unknown_lines, "unknown");
  for (std::size_t i = 0; i < in.movable.size(); ++i) {
    if ((x - in.movable[i].center).norm() < in.movable[i].radius + s.radius) {
      parser.fail_line(s.robot_line, std::string("robot ") + what + " " + show(x) +
                                         " is inside (or within the robot radius of) movable "
                                         "object " +
                                         std::to_string(i + 1) + " (line " +
                                         std::to_string(s.movable_lines[i]) + ")");
    }
  }
}

}  // namespace

SceneFile parse_scene(const std::string& text, const std::string& name) {
  Parser parser(text, name);
  const auto doc = parser.parse_document();
  const Schema schema(parser);
  SceneFile s;
  s.name = name;
  const std::vector<std::string> top = {"workspace", "robot",   "familiar",
                                        "unknown",   "movable", "params"};
  for (const auto& [k, v] : doc) {
    if (std::find(top.begin(), top.end(), k) == top.end()) {
      schema.fail(v, "unknown key '" + k + "' (expected one of: " + Schema::join(top) + ")");
    }
  }
  for (const char* required : {"workspace", "robot"}) {
    if (!Schema::find(doc, required)) {
      parser.fail_line(1, std::string("missing the required key '") + required + "'");
    }
  }

  const Value& ws = *Schema::find(doc, "workspace");
  s.semantic.workspace = schema.polygon(ws, "workspace");
  s.workspace_line = ws.line;

  const Value& robot = *Schema::find(doc, "robot");
  s.robot_line = robot.line;
  const auto& rf =
      schema.map(robot, "robot", {"radius", "sensing_range", "start", "heading", "goal"},
                 {"radius", "start", "goal"});
  s.radius = schema.positive(*Schema::find(rf, "radius"), "robot radius");
  if (const Value* v = Schema::find(rf, "sensing_range")) {
    s.sensing_range = schema.positive(*v, "robot sensing_range");
  }
  s.start = schema.point(*Schema::find(rf, "start"), "robot start");
  if (const Value* v = Schema::find(rf, "heading")) s.heading = schema.number(*v, "robot heading");
  s.goal = schema.point(*Schema::find(rf, "goal"), "robot goal");

  if (const Value* v = Schema::find(doc, "familiar")) {
    const auto& items = schema.list(*v, "familiar");
    for (std::size_t i = 0; i < items.size(); ++i) {
      s.semantic.familiar.push_back(
          schema.polygon(items[i], "familiar obstacle " + std::to_string(i + 1)));
      s.familiar_lines.push_back(items[i].line);
    }
  }
  if (const Value* v = Schema::find(doc, "unknown")) {
    const auto& items = schema.list(*v, "unknown");
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string what = "unknown obstacle " + std::to_string(i + 1);
      const Polygon p = schema.polygon(items[i], what);
      if (!geometry::remove_collinear(p).is_convex())
        schema.fail(items[i], what + " is not convex");
      s.semantic.unknown.push_back(p);
      s.unknown_lines.push_back(items[i].line);
    }
  }
  if (const Value* v = Schema::find(doc, "movable")) {
    const auto& items = schema.list(*v, "movable");
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string what = "movable object " + std::to_string(i + 1);
      const auto& f = schema.map(items[i], what, {"center", "radius"}, {"center", "radius"});
      s.semantic.movable.push_back(
          geometry::Disk{schema.point(*Schema::find(f, "center"), what + " center"),
                         schema.positive(*Schema::find(f, "radius"), what + " radius")});
      s.movable_lines.push_back(items[i].line);
    }
  }
  if (const Value* v = Schema::find(doc, "params")) {
    const auto& f = schema.map(*v, "params",
                               {"epsilon", "mu1", "mu2", "p", "root_radius_fraction",
                                "boundary_center_offset", "sliver_area"},
                               {});
    auto& p = s.params;
    if (const Value* x = Schema::find(f, "epsilon")) p.epsilon = schema.number(*x, "epsilon");
    if (const Value* x = Schema::find(f, "mu1")) p.mu1 = schema.number(*x, "mu1");
    if (const Value* x = Schema::find(f, "mu2")) p.mu2 = schema.number(*x, "mu2");
    if (const Value* x = Schema::find(f, "root_radius_fraction")) {
      p.root_radius_fraction = schema.number(*x, "root_radius_fraction");
    }
    if (const Value* x = Schema::find(f, "boundary_center_offset")) {
      p.boundary_center_offset = schema.number(*x, "boundary_center_offset");
    }
    if (const Value* x = Schema::find(f, "sliver_area")) {
      p.sliver_area = schema.number(*x, "sliver_area");
    }
    if (const Value* x = Schema::find(f, "p")) {
      const double d = schema.number(*x, "p");
      if (d != std::floor(d) || std::abs(d) > 1e6) schema.fail(*x, "p must be an even integer");
      p.p = static_cast<int>(d);
    }
    try {
      reactive::validate(p);
    } catch (const Error& e) {
      schema.fail(*v, e.what());
    }
  }

  check_free(s, parser, s.start, "start");
  check_free(s, parser, s.goal, "goal");
  return s;
}

SceneFile read_scene_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

}  // namespace rearm::cli
