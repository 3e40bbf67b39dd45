// What the robot's sensor has revealed of a scenario's obstacles, for methods that replan on
// discovery (the baselines' replanning variant): perception::SemanticMap with the scenario's
// sensor range and fragment tolerance, read as polygons: the familiar obstacles localized so far
// whole, and the visible fragments of the unknown ones.
#pragma once

#include <vector>

#include "geometry/polygon.h"
#include "perception/semantic_map.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

class KnownObstacles {
 public:
  explicit KnownObstacles(const scenario::Scenario& s);

  // Reads the sensor at the robot's centre; true when what is known changed.
  bool update(const geometry::Point& robot) { return map_.update(robot); }

  // The familiar obstacles localized so far, then the visible unknown fragments.
  std::vector<geometry::Polygon> polygons() const;

 private:
  perception::SemanticMap map_;
};

}  // namespace rearm::experiment
