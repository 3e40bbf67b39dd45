// The kinematic plant against hand-computed geometry: clearances, contact onsets, the
// gripper's reach and the rigid motion of a held object.
#include "executive/kinematic_plant.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using test_support::rect;

perception::World room() {
  perception::World w;
  w.workspace = rect(0, 0, 10, 6);
  w.familiar = {{"P1", rect(3, 0, 4, 2)}};
  w.unknown = {{"C1", rect(7, 4, 8, 5)}};
  w.movable = {{"M1", geometry::Disk{Point(2.5, 4.0), 0.25}}};
  return w;
}

TEST(KinematicPlant, ClearanceIsTheNearestSurface) {
  // Robot r = 0.2 at (2.5, 1): wall P1 at 0.5, the workspace bottom at 1, M1 at 3 - 0.25.
  KinematicPlant a(room(), 0.2, {Point(2.5, 1), 0});
  EXPECT_NEAR(a.clearance(), 0.5 - 0.2, 1e-12);
  // Near the unknown obstacle's corner (7, 4): distance sqrt(0.3² + 0.4²) = 0.5.
  KinematicPlant b(room(), 0.2, {Point(6.7, 3.6), 0});
  EXPECT_NEAR(b.clearance(), 0.5 - 0.2, 1e-12);
  // Near the object: centre distance 0.6, so 0.6 - 0.25 - 0.2.
  KinematicPlant c(room(), 0.2, {Point(2.5, 3.4), 0});
  EXPECT_NEAR(c.clearance(), 0.15, 1e-12);
  // Overlapping a wall: negative, and counted from the start.
  KinematicPlant d(room(), 0.2, {Point(3.1, 1), 0});
  EXPECT_NEAR(d.clearance(), -0.1 - 0.2, 1e-12);
}

TEST(KinematicPlant, CollisionsCountContactOnsets) {
  KinematicPlant p(room(), 0.2, {Point(2.0, 1.0), 0});
  // Drive east into P1 (face x = 3): contact when x > 2.8.
  for (int k = 0; k < 150; ++k) p.step({0.5, 0}, 0.01);  // to x = 2.75
  EXPECT_EQ(p.collisions(), 0);
  EXPECT_NEAR(p.clearance(), 0.05, 1e-9);
  for (int k = 0; k < 20; ++k) p.step({0.5, 0}, 0.01);  // to x = 2.85, still in contact
  EXPECT_EQ(p.collisions(), 1);
  EXPECT_LT(p.clearance(), 0);
  for (int k = 0; k < 40; ++k) p.step({-0.5, 0}, 0.01);  // back to 2.65
  EXPECT_EQ(p.collisions(), 1);
  for (int k = 0; k < 40; ++k) p.step({0.5, 0}, 0.01);  // in again
  EXPECT_EQ(p.collisions(), 2);
}

TEST(KinematicPlant, GripperReachAndCone) {
  // Object M1 at (2.5, 4), radius 0.25; robot r = 0.2 facing it from the south.
  const double half_pi = std::acos(0.0);
  KinematicPlant near(room(), 0.2, {Point(2.5, 4.0 - 0.45 - 0.005), half_pi});
  EXPECT_TRUE(near.grip(0));
  EXPECT_EQ(near.held(), std::optional<std::size_t>(0));
  KinematicPlant far(room(), 0.2, {Point(2.5, 4.0 - 0.45 - 0.05), half_pi});
  EXPECT_FALSE(far.grip(0));
  KinematicPlant sideways(room(), 0.2, {Point(2.5, 4.0 - 0.45 - 0.005), 0.0});
  EXPECT_FALSE(sideways.grip(0));
  EXPECT_THROW(near.grip(3), Error);
}

TEST(KinematicPlant, HeldObjectMovesRigidly) {
  const double half_pi = std::acos(0.0);
  const Pose start{Point(2.5, 4.0 - 0.455), half_pi};
  KinematicPlant p(room(), 0.2, start);
  ASSERT_TRUE(p.grip(0));
  // Turn on an arc for 2 s: the object stays 0.455 m ahead on the heading.
  for (int k = 0; k < 200; ++k) p.step({0.2, 0.3}, 0.01);
  const Pose q = p.pose();
  const Point expected = q.x + 0.455 * Point(std::cos(q.psi), std::sin(q.psi));
  EXPECT_NEAR((p.object_center(0) - expected).norm(), 0, 1e-12);
  EXPECT_NEAR(q.psi, half_pi + 0.6, 1e-12);
  p.release();
  const Point dropped = p.object_center(0);
  p.step({-0.2, 0}, 0.01);
  EXPECT_EQ(p.object_center(0), dropped);
}

TEST(KinematicPlant, HeldObjectCollisionsCount) {
  // Carry M1 east toward the unknown obstacle C1 ([7, 8] × [4, 5]): the object, not the robot,
  // touches first.
  perception::World w = room();
  w.movable[0].disk.center = Point(5.0, 4.5);
  KinematicPlant p(w, 0.2, {Point(5.0 - 0.455, 4.5), 0});
  ASSERT_TRUE(p.grip(0));
  for (int k = 0; k < 400 && p.collisions() == 0; ++k) p.step({0.5, 0}, 0.01);
  EXPECT_EQ(p.collisions(), 1);
  EXPECT_NEAR(p.object_center(0).x(), 7.0 - 0.25, 0.006);
}

TEST(KinematicPlant, BadInput) {
  EXPECT_THROW(KinematicPlant(room(), 0, {}), Error);
  EXPECT_THROW(KinematicPlant(room(), 0.2, {Point(std::nan(""), 1), 0}), Error);
  perception::World bad = room();
  bad.movable[0].disk.radius = -1;
  EXPECT_THROW(KinematicPlant(bad, 0.2, {Point(1, 1), 0}), Error);
  KinematicPlant p(room(), 0.2, {Point(1, 1), 0});
  EXPECT_THROW(p.object_center(5), Error);
  EXPECT_THROW(p.step({std::nan(""), 0}, 0.01), Error);
}

}  // namespace
}  // namespace rearm::executive
