// Bad input to perception (house style 3): each defect throws rearm::Error with a message that
// names the offending item; valid input passes and comes back counter-clockwise.
#include "perception/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "perception/semantic_map.h"
#include "perception/sensor.h"

namespace rearm::perception {
namespace {

Polygon square(double x0, double y0, double side) {
  return Polygon{{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}};
}

World valid_world() {
  World w;
  w.workspace = square(-10, -10, 20);
  w.familiar.push_back({"shelf", Polygon{{{1, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}}}});
  w.unknown.push_back({"rock", square(-4, -4, 1)});
  w.movable.push_back({"M1", Disk{Point(5, 5), 0.3}});
  return w;
}

// The message of the rearm::Error thrown by f ("" when none is thrown).
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void ExpectErrorNaming(const World& w, const std::string& fragment) {
  const std::string msg = ErrorOf([&] { validated(w); });
  EXPECT_NE(msg.find(fragment), std::string::npos) << "message: '" << msg << "'";
}

TEST(WorldTest, ValidWorldPassesAndIsCounterClockwise) {
  World w = valid_world();
  std::reverse(w.unknown[0].polygon.vertices.begin(), w.unknown[0].polygon.vertices.end());
  const World v = validated(w);
  EXPECT_GT(v.unknown[0].polygon.signed_area(), 0);
  EXPECT_GT(v.familiar[0].polygon.signed_area(), 0);
  EXPECT_GT(v.workspace.signed_area(), 0);
  EXPECT_EQ(v.movable.size(), 1u);
}

TEST(WorldTest, NanVertexNamesTheObstacle) {
  World w = valid_world();
  w.familiar[0].polygon.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  ExpectErrorNaming(w, "familiar obstacle 'shelf'");
  ExpectErrorNaming(w, "not finite");
}

TEST(WorldTest, InfiniteUnknownVertexNamesTheObstacle) {
  World w = valid_world();
  w.unknown[0].polygon.vertices[0].x() = std::numeric_limits<double>::infinity();
  ExpectErrorNaming(w, "unknown obstacle 'rock'");
}

TEST(WorldTest, NonConvexUnknownObstacle) {
  World w = valid_world();
  w.unknown[0].polygon = Polygon{{{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}}};
  ExpectErrorNaming(w, "unknown obstacle 'rock'");
  ExpectErrorNaming(w, "convex");
}

TEST(WorldTest, SelfIntersectingPolygon) {
  World w = valid_world();
  w.familiar[0].polygon = Polygon{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};  // bow tie
  ExpectErrorNaming(w, "familiar obstacle 'shelf'");
}

TEST(WorldTest, InvalidWorkspace) {
  World w = valid_world();
  w.workspace = Polygon{{{0, 0}, {1, 0}}};
  ExpectErrorNaming(w, "workspace");
}

TEST(WorldTest, DuplicateIdAcrossKinds) {
  World w = valid_world();
  w.movable.push_back({"rock", Disk{Point(0, 0), 0.2}});
  ExpectErrorNaming(w, "duplicate id 'rock'");
  World w2 = valid_world();
  w2.familiar.push_back({"shelf", square(6, 6, 1)});
  ExpectErrorNaming(w2, "duplicate id 'shelf'");
}

TEST(WorldTest, EmptyId) {
  World w = valid_world();
  w.unknown[0].id.clear();
  ExpectErrorNaming(w, "empty id");
}

TEST(WorldTest, NegativeOrZeroRadius) {
  World w = valid_world();
  w.movable[0].disk.radius = -0.1;
  ExpectErrorNaming(w, "movable object 'M1'");
  ExpectErrorNaming(w, "radius");
  w.movable[0].disk.radius = 0;
  ExpectErrorNaming(w, "movable object 'M1'");
  w.movable[0].disk.radius = std::numeric_limits<double>::quiet_NaN();
  ExpectErrorNaming(w, "movable object 'M1'");
}

TEST(WorldTest, NonFiniteMovableCentre) {
  World w = valid_world();
  w.movable[0].disk.center.x() = std::numeric_limits<double>::quiet_NaN();
  ExpectErrorNaming(w, "movable object 'M1'");
}

TEST(WorldTest, RangeMustBePositiveAndFinite) {
  for (const double r : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity()}) {
    const std::string msg = ErrorOf([&] { Sensor s({.range = r}); });
    EXPECT_NE(msg.find("range"), std::string::npos) << r << ": '" << msg << "'";
  }
  EXPECT_THROW(Sensor({.range = 1, .footprint_tolerance = 0}), Error);
  EXPECT_THROW(Sensor({.range = 1, .footprint_tolerance = 1e-12}), Error);  // > max sides
  EXPECT_THROW(Sensor({.range = 1, .sliver_area = -1}), Error);
}

TEST(WorldTest, SemanticMapRejectsBadInput) {
  const Sensor s({.range = 2});
  World w = valid_world();
  w.unknown[0].polygon = Polygon{{{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}}};
  EXPECT_THROW(SemanticMap(w, s), Error);
  EXPECT_THROW(SemanticMap(valid_world(), s, {.fragment = -1}), Error);
  SemanticMap map(valid_world(), s);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(map.update(Point(nan, 0)), Error);
  EXPECT_NE(ErrorOf([&] { map.move_object("M9", Point(0, 0)); }).find("'M9'"), std::string::npos);
  EXPECT_THROW(map.move_object("M1", Point(0, nan)), Error);
  EXPECT_NE(ErrorOf([&] {
              map.add_object({"shelf", Disk{Point(0, 0), 0.2}});
            }).find("duplicate id 'shelf'"),
            std::string::npos);
  EXPECT_THROW(map.add_object({"M2", Disk{Point(0, 0), -0.2}}), Error);
  EXPECT_THROW(map.set_carried("nope"), Error);
  EXPECT_THROW(map.remove_object("nope"), Error);
  EXPECT_EQ(map.version(), 0u);  // failed calls change nothing
}

}  // namespace
}  // namespace rearm::perception
