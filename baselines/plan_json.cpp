#include "baselines/plan_json.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/error.h"
#include "experiment/json_internal.h"

namespace rearm::baselines {
namespace {

using experiment::json::Json;
using experiment::json::point;

Json path(const std::vector<Point>& p) {
  Json a = Json::array();
  for (const Point& x : p) a.push_back(point(x));
  return a;
}

// Reads one plan file; every failure names the file and the field.
class Reader {
 public:
  Reader(const std::vector<std::string>& names, const std::string& source)
      : names_(names), source_(source) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw Error(source_ + ": " + (field.empty() ? "" : field + ": ") + what);
  }

  const Json& field(const Json& j, const std::string& key, const std::string& where) const {
    if (!j.is_object()) fail(where, "expected an object");
    const auto it = j.find(key);
    if (it == j.end()) fail(where, "missing field '" + key + "'");
    return *it;
  }

  double number(const Json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number");
    const double x = j.get<double>();
    if (!std::isfinite(x)) fail(where, "not a finite number");
    return x;
  }

  Point xy(const Json& j, const std::string& where) const {
    if (!j.is_array() || j.size() != 2) fail(where, "expected [x, y]");
    return Point(number(j[0], where + "[0]"), number(j[1], where + "[1]"));
  }

  std::vector<Point> points(const Json& j, const std::string& where) const {
    if (!j.is_array()) fail(where, "expected a list of [x, y]");
    std::vector<Point> out;
    for (std::size_t i = 0; i < j.size(); ++i)
      out.push_back(xy(j[i], where + "[" + std::to_string(i) + "]"));
    return out;
  }

  std::size_t object(const Json& j, const std::string& where) const {
    if (!j.is_string()) fail(where, "expected an object name");
    const std::string n = j.get<std::string>();
    const auto it = std::find(names_.begin(), names_.end(), n);
    if (it == names_.end()) fail(where, "unknown object '" + n + "'");
    return static_cast<std::size_t>(it - names_.begin());
  }

  ObjectMove move(const Json& j, const std::string& w) const {
    ObjectMove m;
    m.object = object(field(j, "object", w), w + ".object");
    const Json& held = field(j, "held_at_start", w);
    if (!held.is_boolean()) fail(w + ".held_at_start", "expected true or false");
    m.held_at_start = held.get<bool>();
    m.from = xy(field(j, "from", w), w + ".from");
    m.to = xy(field(j, "to", w), w + ".to");
    m.transit = points(field(j, "transit", w), w + ".transit");
    m.grasp_heading = number(field(j, "grasp_heading", w), w + ".grasp_heading");
    m.transfer = points(field(j, "transfer", w), w + ".transfer");
    m.release_heading = number(field(j, "release_heading", w), w + ".release_heading");
    return m;
  }

  Plan plan(const Json& doc) const {
    const Json& format = field(doc, "format", "");
    if (!format.is_string() || format.get<std::string>() != "rearm-plan")
      fail("format", "expected \"rearm-plan\"");
    const Json& version = field(doc, "version", "");
    if (!version.is_number_integer() || version.get<long long>() != kPlanFormatVersion)
      fail("version", "expected " + std::to_string(kPlanFormatVersion));
    Plan p;
    const Json& moves = field(doc, "moves", "");
    if (!moves.is_array()) fail("moves", "expected a list");
    for (std::size_t i = 0; i < moves.size(); ++i)
      p.moves.push_back(move(moves[i], "moves[" + std::to_string(i) + "]"));
    p.final_transit = points(field(doc, "final_transit", ""), "final_transit");
    p.final_arrangement = points(field(doc, "final_arrangement", ""), "final_arrangement");
    return p;
  }

 private:
  const std::vector<std::string>& names_;
  const std::string& source_;
};

}  // namespace

std::string plan_to_json(const Plan& plan, const std::vector<std::string>& object_names) {
  Json moves = Json::array();
  for (const ObjectMove& m : plan.moves) {
    if (m.object >= object_names.size())
      throw Error("plan_to_json: object index " + std::to_string(m.object) + " out of range");
    moves.push_back({{"object", object_names[m.object]},
                     {"held_at_start", m.held_at_start},
                     {"from", point(m.from)},
                     {"to", point(m.to)},
                     {"transit", path(m.transit)},
                     {"grasp_heading", m.grasp_heading},
                     {"transfer", path(m.transfer)},
                     {"release_heading", m.release_heading}});
  }
  const Json doc = {{"format", "rearm-plan"},
                    {"version", kPlanFormatVersion},
                    {"moves", moves},
                    {"final_transit", path(plan.final_transit)},
                    {"final_arrangement", path(plan.final_arrangement)}};
  return experiment::json::text(doc);
}

Plan plan_from_json(const std::string& text, const std::vector<std::string>& object_names,
                    const std::string& source) {
  const Json doc = Json::parse(text, nullptr, false);
  if (doc.is_discarded()) throw Error(source + ": not valid JSON");
  return Reader(object_names, source).plan(doc);
}

}  // namespace rearm::baselines
