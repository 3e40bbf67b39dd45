// How far the semantic map's news lies from the robot: what the map marks as obstacle now
// that it did not when the reactive controller last rebuilt its diffeomorphism. The robust
// variant's deferred rebuild (RobustParams::defer, docs/executive.md "Deferred rebuilds")
// rebuilds only once that news comes within a margin of the robot's disk.
#pragma once

#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "perception/semantic_map.h"

namespace rearm::executive {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

// What the map held at a rebuild, by name (familiar obstacles are localized once and kept).
struct MapSnapshot {
  std::vector<std::string> familiar_ids;
  std::vector<std::string> unknown_ids;
  std::vector<Polygon> unknown;  // the visible convex fragments
  std::vector<std::string> movable_ids;
  std::vector<Disk> movable;

  static MapSnapshot of(const perception::SemanticMap& map);
};

// Distance (m, doubles) from x to the closure of what `now` marks as obstacle beyond `then`:
// familiar obstacles localized since, the new part of each unknown fragment (its polygon now
// minus its polygon then; both convex), and movable objects that appeared or moved (their
// disks now). What the map no longer holds (a fragment that shrank or left the sensor's
// range, an object's old place) does not count: a diffeomorphism built with it is the more
// conservative. +infinity when nothing is new. Rounding makes the value uncertain by about
// 1e-12 m, far below any margin it is compared with.
double news_distance(const MapSnapshot& then, const perception::SemanticMap& now, const Point& x);

}  // namespace rearm::executive
