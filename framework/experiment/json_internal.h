// INTERNAL to the result files (experiment/run_scenario.cpp, baselines/run_baseline.cpp): the
// JSON pieces both write. Included by .cpp files only: it brings in nlohmann-json.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/run_scenario.h"
#include "geometry/polygon.h"

namespace rearm::experiment::json {

// Objects keep their keys in insertion order (the order the files have always had); nlohmann
// writes non-finite numbers as null and every double in its shortest form that reads back
// exactly, so identical runs write identical bytes.
using Json = nlohmann::ordered_json;
inline constexpr int kIndent = 2;  // metrics.json is for people: two spaces per level

// The document's text ending in a newline; invalid UTF-8 in a name becomes U+FFFD.
inline std::string text(const Json& j, int indent = -1) {
  return j.dump(indent, ' ', false, Json::error_handler_t::replace) + "\n";
}

inline Json point(const geometry::Point& p) { return {p.x(), p.y()}; }

inline Json polygon(const geometry::Polygon& p) {
  Json a = Json::array();
  for (const auto& v : p.vertices) a.push_back(point(v));
  return a;
}

// "min_clearance_by_kind" of a metrics.json (kClearanceKinds, in file order).
inline Json clearance_by_kind(const geometry::ClearanceByKind& c) {
  Json j = Json::object();
  for (const ClearanceKind& k : kClearanceKinds) j[k.name] = c.*k.value;
  return j;
}

// {name, polygon} of each familiar obstacle, unknown obstacle or region.
template <typename Named>
Json named_polygons(const std::vector<Named>& items) {
  Json a = Json::array();
  for (const Named& x : items) a.push_back({{"name", x.name}, {"polygon", polygon(x.polygon)}});
  return a;
}

}  // namespace rearm::experiment::json
