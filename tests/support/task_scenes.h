// Hand-built task scenes of the paper's Section VI for the kinematic end-to-end tests (no
// Box2D): coordinates chosen to match the figures' descriptions (docs/experiments.md).
#pragma once

#include <string>

#include "executive/task_runner.h"

namespace rearm::test_support {

geometry::Polygon rect(double x0, double y0, double x1, double y1);
// The semantic map of world `w` after one sensor update (range `range`) at `robot`.
perception::SemanticMap sensed_map(const perception::World& w, const geometry::Point& robot,
                                   double range = 20);

// Fig. 3: two rectangular familiar obstacles leave one 1 m passage in a wall across a 10 × 6 m
// room; a movable object of radius 0.25 m sits in it; region l1 lies beyond the wall. Task
// <>move(l1).
executive::TaskSpec fig3_task();
// Fig. 4: a wall of two familiar non-convex obstacles with a doorway the object M1 blocks,
// unknown convex obstacles on both sides, regions l1, l2 beyond the wall and l3 at the start
// side. Task <>(move(l1) && <>(move(l2) && <>(grasp(M1) && <>release(M1,l3)))).
executive::TaskSpec fig4_task();
// A region walled in by a familiar L-shaped obstacle and the workspace corner. Task
// <>move(l1).
executive::TaskSpec walled_in_task();
// Two objects each sitting in the other's goal region (the cyclic case of Fig. 5, two objects):
// <>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && <>release(M2,l1)))).
executive::TaskSpec swap_task();

reactive::Pose fig3_start();
reactive::Pose fig4_start();
reactive::Pose walled_in_start();
reactive::Pose swap_start();

}  // namespace rearm::test_support
