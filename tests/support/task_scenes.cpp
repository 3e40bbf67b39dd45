#include "support/task_scenes.h"

#include "ltl/parser.h"

namespace rearm::test_support {

using geometry::Point;
using geometry::Polygon;

Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

perception::SemanticMap sensed_map(const perception::World& w, const Point& robot, double range) {
  perception::SemanticMap m(w, perception::Sensor(perception::SensorParams{range}));
  m.update(robot);
  return m;
}

namespace {

executive::TaskSpec base(const Polygon& workspace) {
  executive::TaskSpec t;
  t.world.workspace = workspace;
  t.sensor.range = 3.0;
  t.map_tolerances.fragment = 0.1;
  t.executive.robot_radius = 0.2;
  return t;
}

}  // namespace

executive::TaskSpec fig3_task() {
  executive::TaskSpec t = base(rect(0, 0, 10, 6));
  t.world.familiar = {{"P1", rect(4.7, 0, 5.3, 2.5)}, {"P2", rect(4.7, 3.5, 5.3, 6)}};
  t.world.movable = {{"M1", geometry::Disk{Point(5.0, 3.0), 0.25}}};
  t.regions = {{"l1", rect(8, 2.5, 9, 3.5)}};
  t.formula = ltl::parse("<>move(l1)");
  return t;
}
reactive::Pose fig3_start() { return {Point(1.5, 3.0), 0.0}; }

executive::TaskSpec fig4_task() {
  executive::TaskSpec t = base(rect(0, 0, 12, 8));
  // Lower wall: an L (the vertical bar and an arm to the east); upper wall: a bar with an arm.
  const Polygon lower{{Point(6.0, 0), Point(6.6, 0), Point(6.6, 3.0), Point(8.0, 3.0),
                       Point(8.0, 3.6), Point(6.0, 3.6)}};
  const Polygon upper{{Point(6.0, 4.6), Point(6.6, 4.6), Point(6.6, 6.5), Point(7.5, 6.5),
                       Point(7.5, 7.1), Point(6.6, 7.1), Point(6.6, 8.0), Point(6.0, 8.0)}};
  t.world.familiar = {{"P1", lower}, {"P2", upper}};
  t.world.unknown = {
      {"C1", Polygon{{Point(3.0, 3.6), Point(3.9, 3.5), Point(4.2, 4.3), Point(3.4, 4.7)}}},
      {"C2", Polygon{{Point(9.0, 4.4), Point(9.8, 4.6), Point(9.2, 5.2)}}}};
  t.world.movable = {{"M1", geometry::Disk{Point(6.3, 4.1), 0.25}}};
  t.regions = {{"l1", rect(9.5, 1.0, 10.5, 2.0)},
               {"l2", rect(9.5, 6.0, 10.5, 7.0)},
               {"l3", rect(1.0, 6.0, 2.0, 7.0)}};
  t.formula = ltl::parse("<>(move(l1) && <>(move(l2) && <>(grasp(M1) && <>release(M1,l3))))");
  return t;
}
reactive::Pose fig4_start() { return {Point(1.5, 1.5), 0.0}; }

executive::TaskSpec walled_in_task() {
  executive::TaskSpec t = base(rect(0, 0, 12, 6));
  t.world.familiar = {{"P1", Polygon{{Point(9.0, 0), Point(9.3, 0), Point(9.3, 2.7),
                                      Point(12.0, 2.7), Point(12.0, 3.0), Point(9.0, 3.0)}}}};
  t.regions = {{"l1", rect(10.2, 0.8, 11.2, 1.8)}};
  t.formula = ltl::parse("<>move(l1)");
  return t;
}
reactive::Pose walled_in_start() { return {Point(2.0, 4.5), 0.0}; }

executive::TaskSpec swap_task() {
  executive::TaskSpec t = base(rect(0, 0, 10, 8));
  t.world.familiar = {{"P1", rect(4.5, 3.0, 5.5, 5.0)}};
  t.world.movable = {{"M1", geometry::Disk{Point(2.0, 2.0), 0.25}},
                     {"M2", geometry::Disk{Point(8.0, 6.0), 0.25}}};
  t.regions = {{"l1", rect(1.4, 1.4, 2.6, 2.6)}, {"l2", rect(7.4, 5.4, 8.6, 6.6)}};
  t.formula =
      ltl::parse("<>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && <>release(M2,l1))))");
  return t;
}
reactive::Pose swap_start() { return {Point(4.0, 1.0), 0.0}; }

}  // namespace rearm::test_support
