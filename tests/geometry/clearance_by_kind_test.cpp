// Clearance per kind of thing (geometry/clearance_by_kind.h) in a hand-built room whose
// distances are computed by hand: a 10 x 10 room, a familiar box, an unknown box, two objects.
#include "geometry/clearance_by_kind.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/task_scenes.h"

namespace rearm::geometry {
namespace {

const Polygon kRoom = test_support::rect(0, 0, 10, 10);
// The familiar box F (its left face x = 6), then the unknown box U (its corner (3, 7)).
const std::vector<Polygon> kObstacles = {test_support::rect(6, 4, 7, 6),
                                         test_support::rect(2, 7, 3, 8)};
const std::vector<Disk> kObjects = {Disk{Point(5, 2), 0.25}, Disk{Point(1, 1), 0.3}};

void lower(ClearanceByKind& c, const Point& x, double r, std::optional<std::size_t> skip) {
  c.lower(kRoom, kObstacles, 1, kObjects, x, r, skip);
}

TEST(ClearanceByKind, EachKindByHand) {
  ClearanceByKind c;
  EXPECT_EQ(c.familiar, ClearanceByKind::kNone);
  lower(c, Point(5, 5), 0.2, std::nullopt);
  EXPECT_NEAR(c.familiar, 1.0 - 0.2, 1e-12);                  // to x = 6
  EXPECT_NEAR(c.unknown, std::hypot(2.0, 2.0) - 0.2, 1e-12);  // to (3, 7)
  EXPECT_NEAR(c.objects, 3.0 - 0.25 - 0.2, 1e-12);            // to M1's centre (5, 2)
  EXPECT_NEAR(c.boundary, 5.0 - 0.2, 1e-12);                  // to every wall
  // The held object (M1) is skipped; entries only go down; inside an obstacle it is negative.
  ClearanceByKind held;
  lower(held, Point(5, 2.3), 0.2, 0);
  EXPECT_NEAR(held.objects, std::hypot(4.0, 1.3) - 0.3 - 0.2, 1e-12);  // M2 only
  lower(c, Point(5, 2.3), 0.2, 0);
  EXPECT_NEAR(c.objects, 3.0 - 0.25 - 0.2, 1e-12);
  EXPECT_NEAR(c.familiar, 0.8, 1e-12);
  lower(c, Point(6.5, 5), 0.2, std::nullopt);
  EXPECT_NEAR(c.familiar, -0.5 - 0.2, 1e-12);
  lower(c, Point(0.1, 5), 0.2, std::nullopt);
  EXPECT_NEAR(c.boundary, 0.1 - 0.2, 1e-12);
}

}  // namespace
}  // namespace rearm::geometry
