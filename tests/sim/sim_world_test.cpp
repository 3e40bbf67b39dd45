// The Box2D world against independent truth: unicycle kinematics in free space (x + v·T,
// ψ + ω·T), hand-computed clearances, point-in-polygon after driving into walls and obstacles,
// the rigid-body offset of a held object, and bit-identical repeated runs.
#include "sim/sim_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/polygon.h"
#include "sim/sim_config.h"

namespace rearm::sim {
namespace {

using geometry::Point;
using geometry::Polygon;

// Free motion is tracked in double (sim_world.cpp); what remains is the float command (v·cos ψ
// rounded to float, Box2D's step 0.01f), ~1e-7 relative.
constexpr double kFreeTol = 1e-6;
// Box2D stores object positions as float: one rounding at coordinates up to 10 m is up to
// 4.8e-7 m per coordinate.
constexpr double kFloatTol = 1e-6;
// A body pressed against a shape rests up to Box2D's b2_linearSlop (5 mm) inside it; twice that
// still means "did not pass through".
constexpr double kAllowedPenetration = 0.01;
constexpr double kPi = std::numbers::pi;

Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

// An empty 10 × 10 m room; the robot (r = 0.2) at `start` heading `psi`.
scenario::Scenario room(const Point& start = Point(5, 5), double psi = 0) {
  scenario::Scenario s;
  s.name = "room";
  s.workspace = rect(0, 0, 10, 10);
  s.robot.radius = 0.2;
  s.robot.start = start;
  s.robot.heading = psi;
  return s;
}

void drive(SimWorld& w, double v, double omega, double seconds) {
  const int n = static_cast<int>(std::lround(seconds / 0.01));
  for (int k = 0; k < n; ++k) w.step(v, omega);
}

double wrap(double a) { return std::remainder(a, 2 * kPi); }

// The held object's centre in the robot frame.
Point offset(const SimWorld& w, std::size_t i) {
  const Pose p = w.pose();
  const Point d = w.object_center(i) - p.x;
  const double c = std::cos(p.psi), s = std::sin(p.psi);
  return Point(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
}

// ---------------------------------------------------------------- free motion

TEST(SimWorld, StraightDriveMovesVTimesT) {
  for (const double psi : {0.0, 0.7, -2.3}) {
    SimWorld w(room(Point(5, 5), psi));
    drive(w, 0.4, 0, 5.0);
    const Point expected = Point(5, 5) + 0.4 * 5.0 * Point(std::cos(psi), std::sin(psi));
    EXPECT_NEAR((w.pose().x - expected).norm(), 0, kFreeTol) << "psi " << psi;
    EXPECT_NEAR(wrap(w.pose().psi - psi), 0, kFreeTol);
    EXPECT_NEAR(w.time(), 5.0, 1e-12);
    EXPECT_EQ(w.collisions(), 0);
  }
}

TEST(SimWorld, PureTurnChangesHeadingByOmegaTimesT) {
  SimWorld w(room(Point(5, 5), 0.3));
  drive(w, 0, 0.8, 2.0);
  EXPECT_NEAR(w.pose().psi - 0.3, 1.6, kFreeTol);
  EXPECT_NEAR((w.pose().x - Point(5, 5)).norm(), 0, kFreeTol);
  // Many turns: the heading stays wrapped and accurate.
  drive(w, 0, -1.5, 20.0);
  EXPECT_LE(std::abs(w.pose().psi), kPi);
  EXPECT_NEAR(wrap(w.pose().psi - (0.3 + 1.6 - 30.0)), 0, kFreeTol);
  EXPECT_EQ(w.collisions(), 0);
}

TEST(SimWorld, ConstantTwistDrivesTheExactArc) {
  // ẋ = v(cos ψ, sin ψ), ψ̇ = ω from (x0, ψ0): a circle of radius v/ω, in closed form.
  const Point x0(5, 3);
  const double psi0 = 0.4, v = 0.3, omega = 0.25, T = 8.0;
  SimWorld w(room(x0, psi0));
  drive(w, v, omega, T);
  const double psi = psi0 + omega * T;
  const Point expected =
      x0 + v / omega * Point(std::sin(psi) - std::sin(psi0), std::cos(psi0) - std::cos(psi));
  EXPECT_NEAR((w.pose().x - expected).norm(), 0, kFreeTol);
  EXPECT_NEAR(wrap(w.pose().psi - psi), 0, kFreeTol);
}

TEST(SimWorld, ClearanceIsTheNearestSurface) {
  scenario::Scenario s = room(Point(2, 5));
  s.familiar = {{"F", rect(3, 4, 4, 6)}};
  s.objects = {{"M", geometry::Disk{Point(2, 7), 0.3}}};
  SimWorld w(s);
  // Left wall at 2, F's face at 1, M at 2 - 0.3 from the centre: F is nearest.
  EXPECT_NEAR(w.clearance(), 1 - 0.2, 1e-12);
  EXPECT_NEAR(w.min_clearance(), 0.8, 1e-12);
  // Near the object: centre distance 0.6 → 0.6 - 0.3 - 0.2.
  scenario::Scenario t = s;
  t.robot.start = Point(2, 6.4);
  SimWorld v(t);
  EXPECT_NEAR(v.clearance(), 0.1, 1e-12);
}

// ---------------------------------------------------------------- collisions

TEST(SimWorld, EachWallStopsTheRobotWithOneCollision) {
  for (int k = 0; k < 4; ++k) {
    const double psi = k * kPi / 2;
    SimWorld w(room(Point(5, 5), psi));
    drive(w, 0.4, 0, 20.0);  // 8 m toward a wall 5 m away
    SCOPED_TRACE("wall " + std::to_string(k));
    EXPECT_EQ(w.collisions(), 1);
    const Point x = w.pose().x;
    // Distance to the nearest wall minus the radius: no deeper than the slop, and it got there.
    const double gap = std::min({x.x(), 10 - x.x(), x.y(), 10 - x.y()}) - 0.2;
    EXPECT_GT(gap, -kAllowedPenetration);
    EXPECT_LT(gap, 1e-3);
    EXPECT_TRUE(geometry::contains(rect(0, 0, 10, 10), x));
    EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
    EXPECT_LT(w.min_clearance(), 1e-3);
  }
}

TEST(SimWorld, DrivingAlongAWallCountsOneCollision) {
  // Into the bottom wall at an angle, then along it into the corner: one continuous contact with
  // the boundary, whose two edges the robot ends up touching together.
  SimWorld w(room(Point(5, 2), -kPi / 4));
  drive(w, 0.4, 0, 15.0);
  EXPECT_EQ(w.collisions(), 1);
  EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
  EXPECT_NEAR(w.pose().x.y(), 0.2, kAllowedPenetration);
}

TEST(SimWorld, LShapedFamiliarObstacleStopsTheRobotInItsNotch) {
  scenario::Scenario s = room(Point(8, 7), -3 * kPi / 4);
  // The reflex corner at (6, 4); a collinear vertex (7, 3) on the bottom edge.
  const Polygon l{
      {Point(5, 3), Point(7, 3), Point(8, 3), Point(8, 4), Point(6, 4), Point(6, 7), Point(5, 7)}};
  s.familiar = {{"L", l}};
  SimWorld w(s);
  drive(w, 0.4, 0, 15.0);
  EXPECT_EQ(w.collisions(), 1);  // touching both arms of one obstacle is one collision
  const Point x = w.pose().x;
  EXPECT_FALSE(geometry::contains(l, x));
  EXPECT_NEAR(x.x(), 6.2, kAllowedPenetration);
  EXPECT_NEAR(x.y(), 4.2, kAllowedPenetration);
  EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
}

TEST(SimWorld, UShapedFamiliarObstacleStopsTheRobotInsideItsCavity) {
  const Polygon u{{Point(3, 2), Point(7, 2), Point(7, 5), Point(6, 5), Point(6, 3), Point(4, 3),
                   Point(4, 5), Point(3, 5)}};
  // Down into the cavity onto its floor y = 3, and from below onto the bottom y = 2.
  for (const auto& [start, psi, stop_y] :
       {std::tuple{Point(5, 8), -kPi / 2, 3.2}, std::tuple{Point(5, 0.5), kPi / 2, 1.8}}) {
    scenario::Scenario s = room(start, psi);
    s.familiar = {{"U", u}};
    SimWorld w(s);
    drive(w, 0.4, 0, 15.0);
    SCOPED_TRACE("from y = " + std::to_string(start.y()));
    EXPECT_EQ(w.collisions(), 1);
    EXPECT_FALSE(geometry::contains(u, w.pose().x));
    EXPECT_NEAR(w.pose().x.y(), stop_y, kAllowedPenetration);
    EXPECT_NEAR(w.pose().x.x(), 5, 1e-4);
    EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
  }
}

TEST(SimWorld, UnknownConvexObstacleStopsTheRobot) {
  Polygon hexagon;
  for (int k = 0; k < 6; ++k) {
    hexagon.vertices.push_back(Point(7, 5) + Point(std::cos(k * kPi / 3), std::sin(k * kPi / 3)));
  }
  scenario::Scenario s = room(Point(3, 5), 0);
  s.unknown = {{"H", hexagon}};
  SimWorld w(s);
  drive(w, 0.4, 0, 15.0);
  EXPECT_EQ(w.collisions(), 1);
  EXPECT_FALSE(geometry::contains(hexagon, w.pose().x));
  EXPECT_NEAR(w.pose().x.x(), 6 - 0.2, kAllowedPenetration);  // the vertex (6, 5)
  EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
}

TEST(SimWorld, ObstacleOfManyVerticesHitAtItsSeamsIsOneCollision) {
  // A 20-gon is cut into three 8-vertex pieces fanned from v0 = (8, 5): v0 lies on all three.
  // Driving west into v0, and north into v5 (inside one piece's edge run), each makes one
  // collision.
  Polygon gon;
  for (int k = 0; k < 20; ++k) {
    gon.vertices.push_back(Point(7, 5) + Point(std::cos(k * kPi / 10), std::sin(k * kPi / 10)));
  }
  for (const auto& [start, psi] :
       {std::pair{Point(9.5, 5), kPi}, std::pair{Point(7, 8.5), -kPi / 2}}) {
    scenario::Scenario s = room(start, psi);
    s.familiar = {{"G", gon}};
    SimWorld w(s);
    drive(w, 0.4, 0, 10.0);
    EXPECT_EQ(w.collisions(), 1);
    EXPECT_FALSE(geometry::contains(gon, w.pose().x));
    EXPECT_NEAR((w.pose().x - Point(7, 5)).norm(), 1.2, kAllowedPenetration);
    EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
  }
}

TEST(SimWorld, VerticesCollinearOnlyInFloatDoNotChangeTheShape) {
  // A 1 × 2 block whose west face has a midpoint off the line by 1e-9 m, bulging out (convex,
  // one 5-vertex piece) or in (reflex, two pieces): in float the midpoint is on the line, where
  // b2PolygonShape::Set would drop it; the world builds and the face stops the robot.
  for (const double bulge : {1e-9, -1e-9}) {
    scenario::Scenario s = room(Point(3, 5), 0);
    s.familiar = {
        {"B", Polygon{{Point(6, 4), Point(7, 4), Point(7, 6), Point(6, 6), Point(6 - bulge, 5)}}}};
    SimWorld w(s);
    drive(w, 0.4, 0, 10.0);
    EXPECT_EQ(w.collisions(), 1);
    EXPECT_NEAR(w.pose().x.x(), 6 - 0.2, kAllowedPenetration);
    EXPECT_NEAR(w.pose().x.y(), 5, 1e-4);
  }
}

TEST(SimWorld, PushingAFreeObjectCountsOneCollisionAndMovesIt) {
  scenario::Scenario s = room(Point(2, 5), 0);
  s.objects = {{"M", geometry::Disk{Point(3, 5), 0.25}}};
  SimWorld w(s);
  drive(w, 0.4, 0, 4.0);  // contact after 0.55 / 0.4 s, then pushing
  EXPECT_EQ(w.collisions(), 1);
  const Point c = w.object_center(0);
  EXPECT_GT(c.x(), 3.0 + 1.0);  // pushed about 1.6 − 0.55 m
  EXPECT_NEAR(c.y(), 5, 1e-3);
  // The robot did not pass through it: the disks overlap by at most the slop.
  EXPECT_GT((c - w.pose().x).norm() - 0.45, -kAllowedPenetration);
  EXPECT_LT(w.min_clearance(), 0.0);
  EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
}

TEST(SimWorld, RobotStopsAtAnObjectPinnedAgainstAWall) {
  scenario::Scenario s = room(Point(8, 5), 0);
  s.objects = {{"M", geometry::Disk{Point(9.7, 5), 0.25}}};  // 5 cm from the right wall
  SimWorld w(s);
  drive(w, 0.4, 0, 10.0);
  EXPECT_EQ(w.collisions(), 1);  // the robot touches M only; M then touches the wall
  EXPECT_LT(w.object_center(0).x(), 10 - 0.25 + kAllowedPenetration);
  EXPECT_LT(w.pose().x.x(), 10 - 0.5 - 0.2 + 2 * kAllowedPenetration);
}

// ---------------------------------------------------------------- gripper

scenario::Scenario grip_scene() {
  scenario::Scenario s = room(Point(3, 5), 0);
  // Gap 5 mm between the boundaries, straight ahead.
  s.objects = {{"M", geometry::Disk{Point(3 + 0.2 + 0.15 + 0.005, 5), 0.15}},
               {"N", geometry::Disk{Point(3, 3), 0.15}}};
  return s;
}

TEST(SimWorld, GripFollowsReachAndCone) {
  SimWorld w(grip_scene());
  EXPECT_THROW(w.grip(2), Error);
  EXPECT_FALSE(w.grip(1));  // N is 2 m away, to the side
  EXPECT_FALSE(w.held());
  EXPECT_TRUE(w.grip(0));
  EXPECT_EQ(w.held(), 0u);
  EXPECT_FALSE(w.grip(1));  // already holding
  w.release();
  EXPECT_FALSE(w.held());
  w.release();  // no-op

  scenario::Scenario far = grip_scene();
  far.objects[0].disk.center.x() += 0.01;  // gap 15 mm > grip_reach
  SimWorld f(far);
  EXPECT_FALSE(f.grip(0));
  scenario::Scenario side = grip_scene();
  side.robot.heading = 0.2;  // bearing −0.2 outside the 0.1 rad cone
  SimWorld g(side);
  EXPECT_FALSE(g.grip(0));
  side.robot.heading = 0.05;
  SimWorld h(side);
  EXPECT_TRUE(h.grip(0));
}

TEST(SimWorld, HeldObjectMovesRigidlyAndIsNoCollision) {
  SimWorld w(grip_scene());
  ASSERT_TRUE(w.grip(0));
  const Point start = offset(w, 0);
  double worst = 0;
  for (const auto& [v, omega] :
       {std::pair{0.3, 0.5}, std::pair{0.25, -0.6}, std::pair{0.0, 1.0}, std::pair{-0.2, 0.3}}) {
    for (int k = 0; k < 300; ++k) {
      w.step(v, omega);
      worst = std::max(worst, (offset(w, 0) - start).norm());
    }
  }
  EXPECT_LT(worst, kFloatTol);
  EXPECT_EQ(w.collisions(), 0);
  EXPECT_GT(w.min_clearance(), 0.0);
  // It went somewhere: the pose differs from the start.
  EXPECT_GT((w.pose().x - Point(3, 5)).norm(), 0.5);
  // Turning in place with the object: the robot stays put, the object circles around it.
  const Point x = w.pose().x;
  const Point c = w.object_center(0);
  drive(w, 0, 1.0, 3.14);
  EXPECT_NEAR((w.pose().x - x).norm(), 0, kFreeTol);
  const double a = 3.14;
  const Point turned = x + Point(std::cos(a) * (c - x).x() - std::sin(a) * (c - x).y(),
                                 std::sin(a) * (c - x).x() + std::cos(a) * (c - x).y());
  EXPECT_NEAR((w.object_center(0) - turned).norm(), 0, kFloatTol);
}

TEST(SimWorld, ReleasedObjectSlidesStopsAndStaysPut) {
  SimWorld w(grip_scene());
  ASSERT_TRUE(w.grip(0));
  drive(w, 0.4, 0, 2.0);
  const Point at_release = w.object_center(0);
  w.release();
  drive(w, 0, 0, 3.0);  // the robot stops; the object slides on, v/damping = 8 cm
  const Point rest = w.object_center(0);
  EXPECT_NEAR(rest.x() - at_release.x(), 0.4 / 5.0, 0.01);
  EXPECT_NEAR(rest.y(), 5, 1e-4);
  drive(w, 0, 0, 3.0);
  EXPECT_LT((w.object_center(0) - rest).norm(), 1e-6);
  EXPECT_EQ(w.collisions(), 0);
}

TEST(SimWorld, ObjectGrippedInContactIsNoCollisionOnRelease) {
  scenario::Scenario s = grip_scene();
  s.objects.pop_back();
  SimWorld w(s);
  drive(w, 0.2, 0, 0.5);  // 10 cm: into M, and pushing it
  ASSERT_EQ(w.collisions(), 1);
  ASSERT_TRUE(w.grip(0));
  drive(w, 0.2, 0.3, 1.0);
  w.release();
  drive(w, 0, 0, 0.5);
  EXPECT_EQ(w.collisions(), 1);  // the contact of the grip is not a new one
  drive(w, -0.2, 0, 1.0);        // back off
  drive(w, 0, 0, 1.0);
  EXPECT_EQ(w.collisions(), 1);
  drive(w, 0.3, 0, 2.0);  // and bump into it again: a new collision
  EXPECT_EQ(w.collisions(), 2);
}

TEST(SimWorld, CarriedObjectHittingAWallIsACollision) {
  scenario::Scenario s = grip_scene();
  s.robot.start = Point(8, 5);
  s.objects = {{"M", geometry::Disk{Point(8.355, 5), 0.15}}};
  SimWorld w(s);
  ASSERT_TRUE(w.grip(0));
  drive(w, 0.3, 0, 8.0);
  EXPECT_EQ(w.collisions(), 1);
  EXPECT_LT(w.object_center(0).x(), 10 - 0.15 + kAllowedPenetration);
  EXPECT_GT(w.min_clearance(), -kAllowedPenetration);
  EXPECT_EQ(w.held(), 0u);
}

TEST(SimWorld, RandomDrivingInClutterNeverPassesThrough) {
  // Piecewise-constant random twists in a cluttered room, gripping whatever comes in reach and
  // releasing at random: the robot and the objects stay out of every obstacle and inside the
  // workspace, and no overlap ever exceeds the slop.
  scenario::Scenario s = room(Point(5, 5), 0);
  s.familiar = {{"L", Polygon{{Point(6.5, 1), Point(9, 1), Point(9, 2), Point(7.5, 2),
                               Point(7.5, 4), Point(6.5, 4)}}},
                {"U", Polygon{{Point(1, 6.5), Point(4, 6.5), Point(4, 9), Point(3, 9),
                               Point(3, 7.5), Point(2, 7.5), Point(2, 9), Point(1, 9)}}}};
  s.unknown = {{"Q", rect(1.5, 1.5, 2.5, 3)},
               {"T", Polygon{{Point(7, 7), Point(9, 7.5), Point(7.5, 9)}}}};
  s.objects = {{"A", geometry::Disk{Point(5, 3), 0.2}},
               {"B", geometry::Disk{Point(3, 5), 0.25}},
               {"C", geometry::Disk{Point(6, 6.5), 0.15}}};
  std::vector<Polygon> obstacles;
  for (const auto& f : s.familiar) obstacles.push_back(f.polygon);
  for (const auto& u : s.unknown) obstacles.push_back(u.polygon);
  double worst = 1e9;
  int collisions = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    SimWorld w(s);
    double v = 0, omega = 0;
    for (int k = 0; k < 6000; ++k) {
      if (k % 80 == 0) {
        v = rng.uniform(-0.2, 0.5);
        omega = rng.uniform(-1.0, 1.0);
        if (w.held() && rng.bernoulli(0.3)) w.release();
      }
      w.step(v, omega);
      if (!w.held()) {
        for (std::size_t i = 0; i < w.object_count(); ++i) w.grip(i);
      }
      const Point x = w.pose().x;
      ASSERT_TRUE(geometry::contains(s.workspace, x)) << "seed " << seed << " step " << k;
      for (const Polygon& o : obstacles) {
        ASSERT_FALSE(geometry::contains(o, x)) << "seed " << seed << " step " << k;
        for (std::size_t i = 0; i < w.object_count(); ++i) {
          ASSERT_FALSE(geometry::contains(o, w.object_center(i))) << "seed " << seed;
        }
      }
    }
    worst = std::min(worst, w.min_clearance());
    collisions += w.collisions();
    // Static shapes have no skin: a contact begins where the exact shapes overlap.
    EXPECT_EQ(w.collisions() > 0, w.min_clearance() < 0) << "seed " << seed;
  }
  EXPECT_GT(collisions, 10);  // the walk did run into things
  EXPECT_GT(worst, -kAllowedPenetration);
}

// ---------------------------------------------------------------- validation

TEST(SimWorld, RejectsInvalidInput) {
  const auto throws = [](const scenario::Scenario& s, const SimConfig& c, const char* what) {
    try {
      SimWorld w(s, c);
      ADD_FAILURE() << "no error for " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  const scenario::Scenario ok = room();
  SimConfig c;
  c.dt = 0;
  throws(ok, c, "dt");
  c.dt = std::nan("");
  throws(ok, c, "dt");
  c = {};
  c.velocity_iterations = 0;
  throws(ok, c, "iterations");
  c = {};
  c.position_iterations = -1;
  throws(ok, c, "iterations");
  c = {};
  c.object_linear_damping = -1;
  throws(ok, c, "damping");
  c = {};
  c.robot_density = 0;
  throws(ok, c, "densit");
  c = {};
  c.grip_cone = 4;
  throws(ok, c, "grip_cone");

  scenario::Scenario s = ok;
  s.robot.radius = 0;
  throws(s, {}, "radius");
  s = ok;
  s.robot.start = Point(11, 5);
  throws(s, {}, "outside the workspace");
  s = ok;
  s.robot.heading = std::numeric_limits<double>::infinity();
  throws(s, {}, "not finite");
  s = ok;
  s.objects = {{"M", geometry::Disk{Point(-1, 5), 0.2}}};
  throws(s, {}, "object 'M'");
  s = ok;
  s.familiar = {{"B", Polygon{{Point(1, 1), Point(2, 2), Point(2, 1), Point(1, 2)}}}};
  throws(s, {}, "familiar obstacle 'B'");
  s = ok;
  s.unknown = {{"T", Polygon{{Point(1, 1), Point(1.001, 1), Point(1, 2)}}}};
  throws(s, {}, "weld");
  s = ok;
  s.workspace.vertices.insert(s.workspace.vertices.begin() + 1, Point(0.002, 0.001));
  throws(s, {}, "workspace");

  SimWorld w(ok);
  EXPECT_THROW(w.step(std::nan(""), 0), Error);
  EXPECT_THROW(w.step(0, std::numeric_limits<double>::infinity()), Error);
  EXPECT_THROW(w.step(300, 0), Error);  // 3 m in one step
  EXPECT_THROW(w.step(0, 200), Error);  // 2 rad in one step
  EXPECT_THROW(w.object_center(0), Error);
  EXPECT_THROW(w.grip(0), Error);
  EXPECT_EQ(w.time(), 0);
}

TEST(SimWorld, ConfigForTakesTheScenarioStep) {
  scenario::Scenario s = room();
  s.simulation.dt = 0.02;
  s.simulation.velocity_iterations = 6;
  s.simulation.position_iterations = 2;
  SimConfig base;
  base.grip_reach = 0.03;
  const SimConfig c = config_for(s, base);
  EXPECT_EQ(c.dt, 0.02);
  EXPECT_EQ(c.velocity_iterations, 6);
  EXPECT_EQ(c.position_iterations, 2);
  EXPECT_EQ(c.grip_reach, 0.03);
  SimWorld w(s, c);
  for (int k = 0; k < 50; ++k) w.step(0.4, 0);
  EXPECT_NEAR(w.time(), 1.0, 1e-12);
  EXPECT_NEAR(w.pose().x.x(), 5.4, kFreeTol);
}

// ---------------------------------------------------------------- determinism

// A run touching every feature: pushing, gripping, carrying along a curve, a wall, releasing.
std::vector<double> scripted_run() {
  scenario::Scenario s = room(Point(2, 2), 0.3);
  s.familiar = {{"L", Polygon{{Point(5, 3), Point(8, 3), Point(8, 4), Point(6, 4), Point(6, 7),
                               Point(5, 7)}}}};
  s.unknown = {{"Q", rect(2, 7, 3, 8)}};
  s.objects = {{"A", geometry::Disk{Point(3.2, 2.4), 0.2}},
               {"B", geometry::Disk{Point(8.5, 8.5), 0.3}}};
  SimWorld w(s);
  std::vector<double> out;
  const auto record = [&] {
    const Pose p = w.pose();
    out.insert(out.end(), {p.x.x(), p.x.y(), p.psi, w.clearance()});
    for (std::size_t i = 0; i < w.object_count(); ++i) {
      out.insert(out.end(), {w.object_center(i).x(), w.object_center(i).y()});
    }
  };
  for (int k = 0; k < 400; ++k) {
    w.step(0.4, 0.3 * std::sin(0.01 * k));
    record();
    if (k % 50 == 0 && !w.held()) w.grip(0);
  }
  for (int k = 0; k < 600; ++k) {
    w.step(0.35, 0.4);
    record();
  }
  w.release();
  for (int k = 0; k < 600; ++k) {
    w.step(0.4, -0.2);
    record();
  }
  out.push_back(w.collisions());
  out.push_back(w.min_clearance());
  return out;
}

TEST(SimWorld, RepeatedRunsAreBitIdentical) {
  const std::vector<double> a = scripted_run();
  const std::vector<double> b = scripted_run();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "entry " << i;
  EXPECT_GT(a[a.size() - 2], 0);  // the script did collide with something
}

TEST(SimWorld, ConcurrentRunsAreBitIdentical) {
  const std::vector<double> reference = scripted_run();
  std::vector<double> r1, r2;
  std::thread t1([&] { r1 = scripted_run(); });
  std::thread t2([&] { r2 = scripted_run(); });
  t1.join();
  t2.join();
  EXPECT_EQ(r1, reference);
  EXPECT_EQ(r2, reference);
}

}  // namespace
}  // namespace rearm::sim
