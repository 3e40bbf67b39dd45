#include "experiment/known_obstacles.h"

#include "experiment/task_from_scenario.h"
#include "perception/sensor.h"

namespace rearm::experiment {

KnownObstacles::KnownObstacles(const scenario::Scenario& s)
    : map_(world_of(s), perception::Sensor(perception::SensorParams{s.robot.sensor_range}),
           perception::ChangeTolerances{s.controller.fragment_tolerance,
                                        perception::ChangeTolerances{}.object_move}) {}

std::vector<geometry::Polygon> KnownObstacles::polygons() const {
  std::vector<geometry::Polygon> out = map_.familiar();
  out.insert(out.end(), map_.unknown().begin(), map_.unknown().end());
  return out;
}

}  // namespace rearm::experiment
