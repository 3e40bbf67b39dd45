// RELEASE's pose (executive/release_pose.h) against closed-form geometry: a goal region ℓ of
// 0.6 m against the west wall of a 10 m room, the pair's dilation radius 0.465 m. No point of
// ℓ keeps the pair clear for every heading (release_point finds none); a pose does, with the
// object facing the wall: the object point o at least 0.1 m inside ℓ, x* = o − 0.201 h, and
// the clearance of x* from the wall alone is its x coordinate, largest for h = (−1, 0) and the
// easternmost o. Every kept pose is checked against distances computed here, not by the code.
#include "executive/release_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using test_support::rect;
using test_support::sensed_map;

constexpr double kLead = 0.201;    // r + dock gap
constexpr double kRadius = 0.465;  // r + contact margin + ρ + pair margin
constexpr double kSlack = 0.02;

perception::World wall_room() {
  perception::World w;
  w.workspace = rect(0, 0, 10, 10);
  w.familiar = {{"P1", rect(6, 6, 7, 7)}};
  w.movable = {{"M1", geometry::Disk{Point(5, 2), 0.25}}};  // the carried object
  return w;
}

ReleasePoseParams params() {
  ReleasePoseParams p;
  p.lead = kLead;
  p.clearance = kRadius + kSlack;
  p.stretch = kRadius;
  p.inside = 0.1;
  p.approach = 0.4;
  p.enough = 0.9;
  p.step = 0.05;
  p.headings = 24;
  return p;
}

// Clearance of x from the room's walls and P1, written out.
double wall_clearance(const Point& x) {
  const double walls = std::min({x.x(), 10 - x.x(), x.y(), 10 - x.y()});
  const Point d = (x - x.cwiseMax(Point(6, 6)).cwiseMin(Point(7, 7)));
  return std::min(walls, d.norm());
}

void expect_valid(const ReleasePose& pose, const RegionOfInterest& l, const ReleasePoseParams& p) {
  // o inside ℓ by p.inside: ℓ is an axis-aligned rectangle.
  const auto& v = l.polygon.vertices;
  const double inside = std::min({pose.object.x() - v[0].x(), v[2].x() - pose.object.x(),
                                  pose.object.y() - v[0].y(), v[2].y() - pose.object.y()});
  EXPECT_GE(inside, p.inside - 1e-12);
  EXPECT_NEAR((pose.object - pose.pair).norm(), p.lead, 1e-12);
  const Point h = (pose.object - pose.pair) / p.lead;
  EXPECT_NEAR((pose.pair - p.approach * h - pose.lead_in).norm(), 0, 1e-12);
  EXPECT_GE(wall_clearance(pose.pair), p.clearance - 1e-12);
  for (int s = 0; s <= 40; ++s) {  // the stretch, finer than the code samples it
    const Point x = pose.lead_in + (pose.pair - pose.lead_in) * (s / 40.0);
    EXPECT_GE(wall_clearance(x), p.stretch - 1e-3) << s;  // 1 mm: the code samples 8 points
  }
}

TEST(ReleasePose, SetsTheObjectDownFacingTheWall) {
  const auto map = sensed_map(wall_room(), Point(5, 5));
  const geometry::RegionSet room{{rect(0, 0, 10, 10), {}}};
  const RegionOfInterest l{"l", rect(0.05, 4.7, 0.65, 5.3)};
  const ReleasePoseParams p = params();
  const auto pose = release_pose(room, l, map, "M1", Point(5, 5), p);
  ASSERT_TRUE(pose.has_value());
  expect_valid(*pose, l, p);
  // Facing the wall (h = (−1, 0)); o on the easternmost grid column that is 0.1 inside ℓ
  // (x = 0.5 or 0.55 up to rounding), on the row of the centroid (y = 5).
  EXPECT_NEAR(pose->object.y(), 5.0, 1e-9);
  EXPECT_NEAR(pose->pair.y(), 5.0, 1e-9);
  EXPECT_NEAR(pose->pair.x() - pose->object.x(), kLead, 1e-9);
  EXPECT_GE(pose->object.x(), 0.5 - 1e-9);
  EXPECT_LE(pose->object.x(), 0.55 + 1e-9);
  // The centroid itself is no pair position: 0.35 m from the wall.
  EXPECT_LT(wall_clearance(region_target(l)), kRadius);
}

TEST(ReleasePose, KeepsClearOfObjectsUnlessTheyAreIgnored) {
  perception::World w = wall_room();
  // M2 east of ℓ, on the line the best pose would use.
  w.movable.push_back({"M2", geometry::Disk{Point(1.2, 5.0), 0.25}});
  const auto map = sensed_map(w, Point(5, 5));
  const geometry::RegionSet room{{rect(0, 0, 10, 10), {}}};
  const RegionOfInterest l{"l", rect(0.05, 4.7, 0.65, 5.3)};
  ReleasePoseParams p = params();
  const auto counted = release_pose(room, l, map, "M1", Point(5, 5), p);
  ASSERT_TRUE(counted.has_value());
  expect_valid(*counted, l, p);
  auto from_m2 = [](const Point& x) { return (x - Point(1.2, 5.0)).norm() - 0.25; };
  EXPECT_GE(from_m2(counted->pair), p.clearance - 1e-12);
  for (int s = 0; s <= 8; ++s) {
    const Point x = counted->lead_in + (counted->pair - counted->lead_in) * (s / 8.0);
    EXPECT_GE(from_m2(x), p.stretch - 1e-12) << s;
  }
  p.objects = Objects::kIgnored;
  const auto ignored = release_pose(room, l, map, "M1", Point(5, 5), p);
  ASSERT_TRUE(ignored.has_value());
  EXPECT_NEAR(ignored->pair.y(), 5.0, 1e-9);  // as without M2
  EXPECT_LT(from_m2(ignored->lead_in), p.stretch);
}

TEST(ReleasePose, NoneWhereTheFreespaceHoldsNoPose) {
  const auto map = sensed_map(wall_room(), Point(5, 5));
  const RegionOfInterest l{"l", rect(0.05, 4.7, 0.65, 5.3)};
  // The pair's freespace only in the east half of the room.
  const geometry::RegionSet east{{rect(5, 0, 10, 10), {}}};
  EXPECT_FALSE(release_pose(east, l, map, "M1", Point(6, 5), params()).has_value());
  ReleasePoseParams bad = params();
  bad.step = 0;
  const geometry::RegionSet room{{rect(0, 0, 10, 10), {}}};
  EXPECT_THROW(release_pose(room, l, map, "M1", Point(5, 5), bad), Error);
  bad = params();
  bad.lead = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(release_pose(room, l, map, "M1", Point(5, 5), bad), Error);
  bad = params();
  bad.headings = 0;
  EXPECT_THROW(release_pose(room, l, map, "M1", Point(5, 5), bad), Error);
}

TEST(ReleasePose, ObjectInsideMeasuresTheSignedDistance) {
  const RegionOfInterest l{"l", rect(0, 0, 1, 1)};
  EXPECT_TRUE(object_inside(l, Point(0.5, 0.5), 0.5));
  EXPECT_FALSE(object_inside(l, Point(0.5, 0.5), 0.51));
  EXPECT_TRUE(object_inside(l, Point(0.05, 0.5), 0.05 - 1e-12));
  EXPECT_FALSE(object_inside(l, Point(-0.01, 0.5), 0));
}

}  // namespace
}  // namespace rearm::executive
