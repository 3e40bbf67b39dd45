// Internal to the scenario module (yaml-cpp stays inside that module): the strict
// YAML reading shared by the scenario files (scenario_io.cpp) and the sweep files
// (sweep_file.cpp). Every scalar is interpreted here rather than through yaml-cpp's converters,
// so that numbers are read exactly the same way everywhere: a plain (unquoted) YAML scalar in
// decimal notation, parsed by std::from_chars (locale-independent, correctly rounded), with
// every spelling of NaN and infinity rejected. Every mapping is read against the list of its
// allowed keys, so an unknown (misspelt) or repeated key is an error instead of being ignored
// (yaml-cpp 0.7 keeps both entries of a repeated key). Each key path (`objects[1].radius`) is
// remembered with its line, so that an error found later also names the line in the file.
//
// Include only from the scenario module's .cpp files.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/suggest.h"
#include "geometry/polygon.h"
#include "scenario/scenario_io.h"

namespace rearm::scenario::detail {

// The key of errors about the document as a whole (empty, not a mapping, several documents).
inline const char* const kDocumentKey = "<document>";
// Longest excerpt of a scalar quoted in an error message.
constexpr std::size_t kMaxQuoted = 40;

inline const char* const kFloatTag = "tag:yaml.org,2002:float";
inline const char* const kIntTag = "tag:yaml.org,2002:int";

inline std::string quoted(const std::string& text) {
  if (text.size() <= kMaxQuoted) return "'" + text + "'";
  return "'" + text.substr(0, kMaxQuoted) + "...'";
}

// The shortest decimal that reads back to x.
inline std::string quoted_number(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(x);
}

// What a node is, for "expected X, got Y" messages.
inline std::string describe(const YAML::Node& n) {
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

inline bool is_nonfinite_spelling(std::string text) {
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

  // true or false (YAML's other spellings, yes/no/on/off, are refused: one way to say it).
  bool flag(const YAML::Node& n, const std::string& path) const {
    if (n.IsScalar() && n.Tag() != "!" && (n.Scalar() == "true" || n.Scalar() == "false")) {
      return n.Scalar() == "true";
    }
    fail(path, "expected true or false, got " + describe(n));
    return false;
  }

  geometry::Point point(const YAML::Node& n, const std::string& path) {
    if (!n.IsSequence() || n.size() != 2) {
      fail(path, "expected a point [x, y], got " + describe(n));
    }
    const geometry::Point p(number(n[0], path + "[0]"), number(n[1], path + "[1]"));
    if (!(std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate)) {
      fail(path, "coordinates must lie within ±" + quoted_number(kMaxCoordinate) + " m, got (" +
                     quoted_number(p.x()) + ", " + quoted_number(p.y()) + ")");
    }
    return p;
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
  Fields(Reader& reader, const YAML::Node& node, std::string path, std::vector<const char*> allowed)
      : reader_(reader), path_(std::move(path)), allowed_(std::move(allowed)) {
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
                                std::to_string(line) + ")" +
                                did_you_mean(name, {allowed_.begin(), allowed_.end()}));
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

// The one YAML document of `text` (none or several are errors); syntax errors name their line
// and column. `kind` ("scenario", "sweep") and `required` (its required keys, in words) make
// the messages.
YAML::Node single_document(const std::string& text, const std::string& source, const char* kind,
                           const char* required);

// The text of the file at `path`; throws ScenarioError(path, "file", reason).
std::string read_text_file(const std::string& path, const char* what);

}  // namespace rearm::scenario::detail
