// The map's news for the deferred rebuild (executive/map_news.h): distances to boxes and disks
// computed by hand on a semantic map (the fragments' difference is tested in
// tests/geometry/convex_difference_test.cpp).
#include "executive/map_news.h"

#include <gtest/gtest.h>

#include <limits>

#include "perception/semantic_map.h"
#include "perception/sensor.h"

namespace rearm::executive {
namespace {

using perception::Sensor;
using perception::SensorParams;

constexpr double kInf = std::numeric_limits<double>::infinity();

Polygon box(double x0, double y0, double x1, double y1) {
  return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

// Room 40 x 40 m; familiar box F whose nearest point to (8, 0) is (12, 0); unknown wall W along
// y in [0.5, 1] for x in [-10, 10]; object M at (0, -2).
perception::World scene() {
  perception::World w;
  w.workspace = box(-20, -20, 20, 20);
  w.familiar.push_back({"F", box(12, -1, 13, 1)});
  w.unknown.push_back({"W", box(-10, 0.5, 10, 1.0)});
  w.movable.push_back({"M", geometry::Disk{Point(0, -2), 0.3}});
  return w;
}

TEST(MapNews, SemanticMapNews) {
  const Sensor sensor(SensorParams{3.0});
  perception::SemanticMap map(scene(), sensor);
  map.update(Point(0, 0));
  const MapSnapshot then = MapSnapshot::of(map);
  EXPECT_EQ(news_distance(then, map, Point(0, 0)), kInf);  // nothing new

  // The wall's fragment grows at both ends' footprint edges, ≈ R from the robot.
  map.update(Point(0.5, 0));
  const double wall = news_distance(then, map, Point(0.5, 0));
  EXPECT_GT(wall, 3.0 - 0.5 - 1e-6);
  EXPECT_LT(wall, 3.0 + 0.1);

  // The object moved: the news is its disk at the new place.
  map.move_object("M", Point(0.5, -1.0));
  EXPECT_NEAR(news_distance(then, map, Point(0.5, 0)), 1.0 - 0.3, 1e-12);

  // F localized from (9.5, 0), 2.5 m away; the wall first seen there too.
  perception::SemanticMap far(scene(), sensor);
  far.update(Point(9.5, -4));
  const MapSnapshot before = MapSnapshot::of(far);
  far.update(Point(9.5, 0));
  ASSERT_TRUE(far.is_localized("F"));
  // The wall's fragment is new as a whole, its near edge 0.5 m away: the nearer of the two.
  EXPECT_NEAR(news_distance(before, far, Point(9.5, 0)), 0.5, 1e-12);

  // Walking away, the fragment shrinks: what the map lost is not news.
  perception::SemanticMap away(scene(), sensor);
  away.update(Point(-9, 0));
  const MapSnapshot near = MapSnapshot::of(away);
  away.update(Point(-12, 0));
  EXPECT_EQ(news_distance(near, away, Point(-12, 0)), kInf);
}

}  // namespace
}  // namespace rearm::executive
