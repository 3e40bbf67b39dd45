// check_solvability and check_seal (solvability.h) on hand-made scenes whose answer is known by
// construction (a wall that splits the room, passages just narrower and just wider than the
// pair), and the generated instances (random_instance.h) against an independent raster flood
// fill of the pair's freespace written here: connectivity of every start and goal to the robot,
// and the sealed pocket (closed with B1 in place, open without it).
#include "scenario/solvability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "scenario/random_instance.h"
#include "scenario/scenario_io.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"
#include "support/task_scenes.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;

using test_support::rect;

// One object at (2, 5), its region around (8, 5), robot at (2, 2) in a 10 x 10 m room.
Scenario room() {
  Scenario s;
  s.name = "room";
  s.workspace = rect(0, 0, 10, 10);
  s.robot.start = Point(2, 2);
  s.objects.push_back(Object{"M1", geometry::Disk{Point(2, 5), 0.25}});
  s.regions.push_back(NamedPolygon{"l1", rect(7.5, 4.5, 8.5, 5.5)});
  s.task = "<>release(M1,l1)";
  return s;
}

TEST(Solvability, EmptyRoomIsSolvableWithAParkingSpot) {
  const Scenario s = room();
  validate(s);
  const SolvabilityReport r = check_solvability(s);
  EXPECT_TRUE(r.solvable) << r.failure;
  EXPECT_EQ(r.pair_components, 1u);
  EXPECT_NEAR(r.pair_radius, 0.2 + 0.25 + kPairMargin, 1e-12);
  // The spot parks an object off the region and the object.
  EXPECT_GE((r.parking - Point(2, 5)).norm(), 0.5);
  EXPECT_FALSE(r.parking.x() > 7.5 - 0.25 && r.parking.x() < 8.5 + 0.25 &&
               r.parking.y() > 4.5 - 0.25 && r.parking.y() < 5.5 + 0.25);
}

TEST(Solvability, AWallAcrossTheRoomDisconnects) {
  Scenario s = room();
  s.familiar.push_back(NamedPolygon{"P1", rect(4.9, 0, 5.1, 10)});
  const SolvabilityReport r = check_solvability(s);
  EXPECT_FALSE(r.solvable);
  EXPECT_FALSE(r.connected);
  EXPECT_NE(r.failure.find("(a)"), std::string::npos);
}

// A wall with a gap of width g: the pair (diameter 2R = 0.92 m) passes iff g >= 2R, with the
// dilation's 0.5 % slack.
TEST(Solvability, APassageIsOpenExactlyWhenThePairFits) {
  const double pair_diameter = 2 * (0.2 + 0.25 + kPairMargin);
  for (const double gap : {pair_diameter - 0.02, pair_diameter + 0.02}) {
    Scenario s = room();
    const double y0 = 5 - gap / 2, y1 = 5 + gap / 2;
    s.familiar.push_back(NamedPolygon{"P1", rect(4.9, 0.0, 5.1, y0)});
    s.familiar.push_back(NamedPolygon{"P2", rect(4.9, y1, 5.1, 10.0)});
    const SolvabilityReport r = check_solvability(s);
    EXPECT_EQ(r.connected, gap > pair_diameter) << "gap " << gap << ": " << r.failure;
  }
}

TEST(Solvability, ARobotBoxedInIsReported) {
  Scenario s = room();
  s.robot.start = Point(8, 8.5);
  // A closed ring around the robot: four walls.
  s.familiar.push_back(NamedPolygon{"P1", rect(7, 7, 9, 7.2)});
  s.familiar.push_back(NamedPolygon{"P2", rect(7, 9.3, 9, 9.5)});
  s.familiar.push_back(NamedPolygon{"P3", rect(7, 7.2, 7.2, 9.3)});
  s.familiar.push_back(NamedPolygon{"P4", rect(8.8, 7.2, 9, 9.3)});
  const SolvabilityReport r = check_solvability(s);
  EXPECT_TRUE(r.connected);
  EXPECT_FALSE(r.robot_connected);
  EXPECT_NE(r.failure.find("(c)"), std::string::npos);
}

TEST(Solvability, SealTestOnAHandMadePocket) {
  // A U of walls open to the top around the goal (5, 5); the mouth (1.1 m) blocked by B1.
  Scenario s = room();
  s.familiar.push_back(NamedPolygon{
      "P1", Polygon{{Point(4.1, 4.1), Point(5.9, 4.1), Point(5.9, 6.1), Point(5.55, 6.1),
                     Point(5.55, 5.9), Point(5.7, 5.9), Point(5.7, 4.3), Point(4.3, 4.3),
                     Point(4.3, 5.9), Point(4.45, 5.9), Point(4.45, 6.1), Point(4.1, 6.1)}}});
  s.regions[0].polygon = rect(4.75, 4.85, 5.25, 5.35);
  s.objects.push_back(Object{"B1", geometry::Disk{Point(5, 6.1), 0.25}});
  validate(s);
  const SealReport closed = check_seal(s, 0, 1, Point(5, 5.1));
  EXPECT_TRUE(closed.sealed) << closed.failure;
  EXPECT_TRUE(closed.opens) << closed.failure;
  // Without a blocker the goal is reachable: "sealed" must fail when B1 stands elsewhere.
  s.objects[1].disk.center = Point(8, 2);
  EXPECT_FALSE(check_seal(s, 0, 1, Point(5, 5.1)).sealed);
  EXPECT_THROW((void)check_seal(s, 0, 0, Point(5, 5)), Error);
}

// --- Independent raster of the pair's freespace -----------------------------------------------

// Cells of side kCell free for a disk of radius `radius` (centre test) among the obstacles and
// the disks, 4-connected flood fill.
class Oracle {
 public:
  static constexpr double kCell = 0.04;
  Oracle(const Scenario& s, double radius, const std::vector<geometry::Disk>& disks)
      : W_(s.workspace.vertices[2].x()), H_(s.workspace.vertices[2].y()) {
    nx_ = static_cast<int>(std::ceil(W_ / kCell));
    ny_ = static_cast<int>(std::ceil(H_ / kCell));
    free_.assign(static_cast<std::size_t>(nx_ * ny_), 1);
    for (int iy = 0; iy < ny_; ++iy) {
      for (int ix = 0; ix < nx_; ++ix) {
        const Point c((ix + 0.5) * kCell, (iy + 0.5) * kCell);
        if (std::min({c.x(), W_ - c.x(), c.y(), H_ - c.y()}) < radius) free_[iy * nx_ + ix] = 0;
        for (const geometry::Disk& d : disks) {
          if ((c - d.center).norm() < radius + d.radius) free_[iy * nx_ + ix] = 0;
        }
      }
    }
    std::vector<Polygon> obstacles;
    for (const auto& p : s.familiar) obstacles.push_back(p.polygon);
    for (const auto& p : s.unknown) obstacles.push_back(p.polygon);
    for (const Polygon& p : obstacles) block(p, radius);
  }

  void block(const Polygon& p, double radius) {
    double x0 = W_, x1 = 0, y0 = H_, y1 = 0;
    for (const Point& v : p.vertices) {
      x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
      y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
    }
    for (int iy = std::max(0, static_cast<int>((y0 - radius) / kCell));
         iy < ny_ && iy * kCell <= y1 + radius; ++iy) {
      for (int ix = std::max(0, static_cast<int>((x0 - radius) / kCell));
           ix < nx_ && ix * kCell <= x1 + radius; ++ix) {
        std::uint8_t& f = free_[iy * nx_ + ix];
        if (f == 0) continue;
        const Point c((ix + 0.5) * kCell, (iy + 0.5) * kCell);
        double d =
            test_support::ray_cast_inside(p, c) ? 0 : std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < p.size() && d >= radius; ++i) {
          d = std::min(
              d, test_support::segment_distance(p.vertices[i], p.vertices[(i + 1) % p.size()], c));
        }
        if (d < radius) f = 0;
      }
    }
  }

  int cell(const Point& p) const {
    const int ix = std::clamp(static_cast<int>(p.x() / kCell), 0, nx_ - 1);
    const int iy = std::clamp(static_cast<int>(p.y() / kCell), 0, ny_ - 1);
    return iy * nx_ + ix;
  }

  // Cells reached from the free cells among `sources`.
  std::vector<char> fill(const std::vector<int>& sources) const {
    std::vector<char> seen(free_.size(), 0);
    std::vector<int> stack;
    for (const int s : sources) {
      if (free_[s] != 0 && seen[s] == 0) seen[s] = 1, stack.push_back(s);
    }
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      const int ix = k % nx_, iy = k / nx_;
      for (const int n : {ix > 0 ? k - 1 : -1, ix + 1 < nx_ ? k + 1 : -1, iy > 0 ? k - nx_ : -1,
                          iy + 1 < ny_ ? k + nx_ : -1}) {
        if (n >= 0 && free_[n] != 0 && seen[n] == 0) seen[n] = 1, stack.push_back(n);
      }
    }
    return seen;
  }

 private:
  double W_, H_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint8_t> free_;
};

std::vector<int> grasp_cells(const Oracle& o, const Point& p, double r) {
  std::vector<int> out;
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * std::numbers::pi * k / 16;
    out.push_back(o.cell(p + (r + 0.005) * Point(std::cos(a), std::sin(a))));
  }
  return out;
}

bool any_reached(const std::vector<char>& seen, const std::vector<int>& cells) {
  return std::any_of(cells.begin(), cells.end(), [&](int k) { return seen[k] != 0; });
}

// The oracle's disk is 2 cm thinner than the pair (its centre test loses up to half a cell
// diagonal, 2.8 cm, against the certificate's 1 cm pair margin).
constexpr double kOracleSlack = 0.02;

TEST(Solvability, GeneratedInstancesConnectOnAnIndependentRaster) {
  for (const GoalClass c : {GoalClass::kRandom, GoalClass::kCyclic, GoalClass::kSealed}) {
    for (const int n : {2, 8}) {
      for (std::uint64_t seed = 0; seed < test_support::scaled(2); ++seed) {
        InstanceSpec spec;
        spec.objects = n;
        spec.goal_class = c;
        spec.obstacle_density = 0.3;
        spec.seed = seed;
        const GeneratedInstance g = generate_instance(spec);
        const Scenario& s = g.scenario;
        SCOPED_TRACE(s.description);
        const double r = s.robot.radius;
        const Oracle oracle(s, r + 0.25 - kOracleSlack, {});
        const std::vector<char> seen = oracle.fill({oracle.cell(s.robot.start)});
        for (std::size_t i = 0; i < s.objects.size(); ++i) {
          EXPECT_TRUE(any_reached(seen, grasp_cells(oracle, s.objects[i].disk.center, r)))
              << s.objects[i].name;
        }
        for (const NamedPolygon& l : s.regions) {
          Point centre = Point::Zero();
          for (const Point& v : l.polygon.vertices) centre += v / 4.0;
          EXPECT_TRUE(any_reached(seen, grasp_cells(oracle, centre, r))) << l.name;
        }
      }
    }
  }
}

TEST(Solvability, SealedPocketIsClosedByTheBlockerOnAnIndependentRaster) {
  for (const int n : {1, 3, 6}) {
    for (std::uint64_t seed = 0; seed < test_support::scaled(3); ++seed) {
      InstanceSpec spec;
      spec.objects = n;
      spec.goal_class = GoalClass::kSealed;
      spec.obstacle_density = 0.15;
      spec.seed = seed;
      const GeneratedInstance g = generate_instance(spec);
      const Scenario& s = g.scenario;
      SCOPED_TRACE(s.description);
      ASSERT_TRUE(g.pocket.present);
      EXPECT_TRUE(g.pocket.seal.sealed && g.pocket.seal.opens) << g.pocket.seal.failure;
      ASSERT_EQ(s.objects.back().name, "B1");
      // The goal of M1 is region l1's centre, and its task has no release of B1.
      EXPECT_EQ(s.task.find("B1"), std::string::npos);
      const double r = s.robot.radius, pair = r + 0.25;
      std::vector<geometry::Disk> others;  // every object but M1, B1 included
      for (std::size_t j = 1; j < s.objects.size(); ++j) others.push_back(s.objects[j].disk);
      const std::vector<int> from = grasp_cells(Oracle(s, pair, {}), s.objects[0].disk.center, r);
      const Oracle closed(s, pair, others);
      EXPECT_FALSE(any_reached(closed.fill(from), grasp_cells(closed, g.pocket.goal, r)));
      const Oracle open(s, pair - kOracleSlack, {});
      EXPECT_TRUE(any_reached(open.fill(from), grasp_cells(open, g.pocket.goal, r)));
      // The goal lies inside the pocket's walls' hull: no straight way in but the mouth.
      EXPECT_GE((g.pocket.goal - g.pocket.blocker).norm(), 0.5);
    }
  }
}

}  // namespace
}  // namespace rearm::scenario
