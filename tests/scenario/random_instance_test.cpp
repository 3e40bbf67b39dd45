// random_instance (docs/experiments.md, "Monte Carlo runner": classes a random goals, b cyclic):
// validity over a sweep of specs, determinism, the cyclic goal structure, every clearance of
// the header's solvability argument measured with geometry written here (independent of
// geometry/ and of the generator), the density window, and the input checks.
#include "scenario/random_instance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "scenario/scenario_io.h"
#include "support/scale.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;

// Slack for comparing the generator's double-precision clearances with the ones measured here.
constexpr double kTol = 1e-9;
constexpr double kSqrt2 = 1.4142135623730951;

// --- Independent geometry (no geometry/ functions) -------------------------------------------

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

double point_segment(const Point& x, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.dot(ab), 0.0, 1.0);
  return (a + t * ab - x).norm();
}

// Closed segments [a, b] and [c, d] share a point (orientation signs, collinear overlap).
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
    return true;
  }
  return point_segment(c, a, b) == 0 || point_segment(d, a, b) == 0 ||
         point_segment(a, c, d) == 0 || point_segment(b, c, d) == 0;
}

double segment_segment(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (segments_meet(a, b, c, d)) return 0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                   point_segment(d, a, b)});
}

// Crossing-number point-in-polygon (interior; boundary points are measured as distance 0 by
// the callers anyway).
bool inside(const Polygon& p, const Point& x) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

double point_polygon(const Point& x, const Polygon& p) {
  if (inside(p, x)) return 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    best = std::min(best, point_segment(x, p.vertices[i], p.vertices[(i + 1) % n]));
  }
  return best;
}

double polygon_polygon(const Polygon& p, const Polygon& q) {
  if (inside(q, p.vertices[0]) || inside(p, q.vertices[0])) return 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    for (std::size_t j = 0, m = q.size(); j < m; ++j) {
      best = std::min(best, segment_segment(p.vertices[i], p.vertices[(i + 1) % n], q.vertices[j],
                                            q.vertices[(j + 1) % m]));
    }
  }
  return best;
}

// Distance from a polygon inside [0, W] x [0, H] to the rectangle's boundary: attained at a
// vertex (distance to a line is affine along an edge). Negative when a vertex is outside.
double boundary_gap(const Polygon& p, double W, double H) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point& v : p.vertices) {
    best = std::min({best, v.x(), W - v.x(), v.y(), H - v.y()});
  }
  return best;
}

double boundary_gap(const Point& v, double W, double H) {
  return std::min({v.x(), W - v.x(), v.y(), H - v.y()});
}

double shoelace(const Polygon& p) {
  double twice = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    twice += cross(p.vertices[i], p.vertices[(i + 1) % n]);
  }
  return twice / 2;
}

Point vertex_mean(const Polygon& p) {
  Point m = Point::Zero();
  for (const Point& v : p.vertices) m += v;
  return m / static_cast<double>(p.size());
}

// A region is an axis-aligned square of the given side; returns its centre.
Point square_centre(const Polygon& p, double side) {
  EXPECT_EQ(p.size(), 4u);
  Point lo = p.vertices[0], hi = p.vertices[0];
  for (const Point& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  // Every vertex is a corner of the bounding box.
  for (const Point& v : p.vertices) {
    EXPECT_TRUE(v.x() == lo.x() || v.x() == hi.x());
    EXPECT_TRUE(v.y() == lo.y() || v.y() == hi.y());
  }
  EXPECT_NEAR(hi.x() - lo.x(), side, kTol);
  EXPECT_NEAR(hi.y() - lo.y(), side, kTol);
  return (lo + hi) / 2;
}

bool in_closed_square(const Polygon& p, const Point& x) {
  Point lo = p.vertices[0], hi = p.vertices[0];
  for (const Point& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y();
}

std::vector<Polygon> obstacles_of(const Scenario& s) {
  std::vector<Polygon> out;
  for (const NamedPolygon& p : s.familiar) out.push_back(p.polygon);
  for (const NamedPolygon& p : s.unknown) out.push_back(p.polygon);
  return out;
}

double obstacle_area(const Scenario& s) {
  double a = 0;
  for (const Polygon& p : obstacles_of(s)) a += shoelace(p);
  return a;
}

InstanceSpec make_spec(int n, GoalClass c, double density, std::uint64_t seed) {
  InstanceSpec spec;
  spec.objects = n;
  spec.goal_class = c;
  spec.obstacle_density = density;
  spec.seed = seed;
  return spec;
}

constexpr GoalClass kClasses[] = {GoalClass::kRandom, GoalClass::kCyclic};

// Every guarantee listed in random_instance.h, measured directly.
void expect_guarantees(const InstanceSpec& spec, const Scenario& s) {
  SCOPED_TRACE(s.name + " density " + std::to_string(spec.obstacle_density));
  const double r = spec.robot_radius, rho = spec.object_radius, side = spec.region_side;
  const double W = spec.width, H = spec.height;
  const double w = 2 * (r + rho) + 0.2;
  const double cb = std::max(w + rho, side / 2);
  const double co = std::max(w + rho, side / kSqrt2);
  const double d = std::max(side * kSqrt2 + 0.1, w);

  const std::vector<Polygon> obstacles = obstacles_of(s);
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    EXPECT_GE(boundary_gap(obstacles[i], W, H), w - kTol) << "obstacle " << i;
    for (std::size_t j = i + 1; j < obstacles.size(); ++j) {
      EXPECT_GE(polygon_polygon(obstacles[i], obstacles[j]), w - kTol) << i << " vs " << j;
    }
  }
  std::vector<Point> starts, goals;
  for (const Object& o : s.objects) starts.push_back(o.disk.center);
  for (const NamedPolygon& g : s.regions) goals.push_back(square_centre(g.polygon, side));
  ASSERT_EQ(starts.size(), static_cast<std::size_t>(spec.objects));
  ASSERT_EQ(goals.size(), starts.size());
  for (const std::vector<Point>* points : {&starts, &goals}) {
    for (std::size_t i = 0; i < points->size(); ++i) {
      const Point& p = (*points)[i];
      EXPECT_GE(boundary_gap(p, W, H), cb - kTol);
      for (const Polygon& o : obstacles) EXPECT_GE(point_polygon(p, o), co - kTol);
      for (std::size_t j = i + 1; j < points->size(); ++j) {
        EXPECT_GE((p - (*points)[j]).norm(), d - kTol) << i << " vs " << j;
      }
    }
  }
  // Regions pairwise disjoint (axis-aligned squares: some axis separates them).
  for (std::size_t i = 0; i < goals.size(); ++i) {
    for (std::size_t j = i + 1; j < goals.size(); ++j) {
      const Point g = (goals[i] - goals[j]).cwiseAbs();
      EXPECT_TRUE(g.x() > side || g.y() > side) << "regions " << i << ", " << j;
    }
  }
  const Point& x = s.robot.start;
  EXPECT_GE(boundary_gap(x, W, H), w - kTol);
  for (const Polygon& o : obstacles) EXPECT_GE(point_polygon(x, o), w - kTol);
  for (const Point& p : starts) EXPECT_GE((x - p).norm(), r + rho + 0.5 - kTol);
  for (const NamedPolygon& g : s.regions) {
    EXPECT_FALSE(in_closed_square(g.polygon, x)) << g.name;
    EXPECT_GE(point_polygon(x, g.polygon), r - kTol) << g.name;
  }
}

// --- Tests ---------------------------------------------------------------------------------------

TEST(RandomInstance, ValidatesAndKeepsEveryClearanceAcrossTheSweep) {
  for (int n = 1; n <= 6; ++n) {
    for (const GoalClass c : kClasses) {
      for (const double density : {0.0, 0.1, 0.2}) {
        for (std::uint64_t seed = 0; seed < test_support::scaled(10); ++seed) {
          const InstanceSpec spec = make_spec(n, c, density, seed);
          const Scenario s = random_instance(spec);
          EXPECT_NO_THROW(validate(s)) << s.name;
          expect_guarantees(spec, s);
        }
      }
    }
  }
}

TEST(RandomInstance, ClearancesHoldForNonDefaultSizes) {
  // Large regions (the region terms of cb, co and d dominate) and a bigger robot.
  InstanceSpec spec = make_spec(3, GoalClass::kRandom, 0.15, 0);
  spec.width = 14;
  spec.height = 11;
  spec.region_side = 2.6;
  spec.robot_radius = 0.3;
  spec.object_radius = 0.4;
  for (const GoalClass c : kClasses) {
    for (std::uint64_t seed = 0; seed < test_support::scaled(5); ++seed) {
      spec.goal_class = c;
      spec.seed = seed;
      const Scenario s = random_instance(spec);
      EXPECT_NO_THROW(validate(s));
      expect_guarantees(spec, s);
    }
  }
}

TEST(RandomInstance, SameSpecGivesTheSameScenarioAndSeedsDiffer) {
  for (const GoalClass c : kClasses) {
    const InstanceSpec spec = make_spec(4, c, 0.1, 7);
    const std::string yaml = to_yaml(random_instance(spec));
    EXPECT_EQ(to_yaml(random_instance(spec)), yaml);
    InstanceSpec other = spec;
    other.seed = 8;
    EXPECT_NE(to_yaml(random_instance(other)), yaml);
    // The YAML reads back to the same scenario.
    EXPECT_EQ(to_yaml(parse_scenario(yaml, "random.yaml")), yaml);
  }
}

TEST(RandomInstance, SeedFixesObjectsAcrossClassesAndDensities) {
  // random_instance.h, "Determinism": one stream per stage.
  const Scenario a = random_instance(make_spec(5, GoalClass::kRandom, 0.0, 3));
  const Scenario b = random_instance(make_spec(5, GoalClass::kRandom, 0.2, 3));
  const Scenario c = random_instance(make_spec(5, GoalClass::kCyclic, 0.1, 3));
  ASSERT_EQ(a.objects.size(), 5u);
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].disk.center, b.objects[i].disk.center);
    EXPECT_EQ(a.objects[i].disk.center, c.objects[i].disk.center);
    EXPECT_EQ(a.regions[i].polygon.vertices, b.regions[i].polygon.vertices);
  }
  EXPECT_EQ(a.robot.start, b.robot.start);
  EXPECT_EQ(a.robot.heading, b.robot.heading);
}

TEST(RandomInstance, CyclicGoalIsTheNextObjectsStart) {
  for (int n = 1; n <= 8; ++n) {
    for (std::uint64_t seed = 0; seed < test_support::scaled(5); ++seed) {
      const InstanceSpec spec = make_spec(n, GoalClass::kCyclic, 0.1, seed);
      const Scenario s = random_instance(spec);
      SCOPED_TRACE(s.name);
      ASSERT_EQ(s.regions.size(), static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const Polygon& region = s.regions[static_cast<std::size_t>(i)].polygon;
        EXPECT_EQ(s.regions[static_cast<std::size_t>(i)].name, "l" + std::to_string(i + 1));
        const std::size_t next = static_cast<std::size_t>((i + 1) % n);
        const Point& start = s.objects[next].disk.center;
        EXPECT_LT((square_centre(region, spec.region_side) - start).norm(), kTol);
        EXPECT_LT((vertex_mean(region) - start).norm(), kTol);
        for (std::size_t j = 0; j < s.objects.size(); ++j) {
          EXPECT_EQ(in_closed_square(region, s.objects[j].disk.center), j == next)
              << "region l" << i + 1 << ", object M" << j + 1;
        }
      }
    }
  }
}

TEST(RandomInstance, RandomGoalsAreNotTheCyclicShift) {
  // Class a draws goals from their own stream: at least one instance differs from the shift.
  bool differs = false;
  for (std::uint64_t seed = 0; seed < 5 && !differs; ++seed) {
    const Scenario s = random_instance(make_spec(3, GoalClass::kRandom, 0.0, seed));
    for (std::size_t i = 0; i < 3; ++i) {
      const Point c = vertex_mean(s.regions[i].polygon);
      if ((c - s.objects[(i + 1) % 3].disk.center).norm() > 1e-6) differs = true;
    }
  }
  EXPECT_TRUE(differs);
}

// [target, target + one obstacle) when the target is reachable: 0.1 in 20 x 20 m, 0.04 in the
// default 10 x 10 m (random_instance.h, "Reachable density").
TEST(RandomInstance, DensityReachesTheTargetWithinOneObstacle) {
  const double max_one = kMaxObstacleSide * kMaxObstacleSide;
  struct Case {
    double side, target;
  };
  for (const Case k : {Case{20, 0.1}, Case{10, 0.04}}) {
    for (int n = 1; n <= 3; ++n) {
      for (const GoalClass c : kClasses) {
        for (std::uint64_t seed = 0; seed < test_support::scaled(5); ++seed) {
          InstanceSpec spec = make_spec(n, c, k.target, seed);
          spec.width = spec.height = k.side;
          const Scenario s = random_instance(spec);
          SCOPED_TRACE(s.name + " in " + std::to_string(k.side) + " m");
          const double area = spec.width * spec.height;
          const double density = obstacle_area(s) / area;
          EXPECT_GE(density, k.target);
          EXPECT_LT(density, k.target + max_one / area);
          EXPECT_EQ(s.description.find("stopped"), std::string::npos) << s.description;
          for (const Polygon& p : obstacles_of(s)) {
            EXPECT_GT(shoelace(p), 0);  // counter-clockwise
            EXPECT_LE(shoelace(p), max_one);
          }
          if (k.side == 20 && n == 2) expect_guarantees(spec, s);
        }
      }
    }
  }
}

TEST(RandomInstance, ZeroDensityHasNoObstacles) {
  for (const GoalClass c : kClasses) {
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      const Scenario s = random_instance(make_spec(4, c, 0.0, seed));
      EXPECT_TRUE(s.familiar.empty());
      EXPECT_TRUE(s.unknown.empty());
    }
  }
}

TEST(RandomInstance, UnreachableDensityStopsAndSaysSo) {
  InstanceSpec spec = make_spec(6, GoalClass::kRandom, 0.3, 1);
  spec.max_attempts = 200;
  const Scenario s = random_instance(spec);
  EXPECT_LT(obstacle_area(s) / (spec.width * spec.height), 0.3);
  EXPECT_NE(s.description.find("stopped after 200 consecutive failed attempts"), std::string::npos)
      << s.description;
  expect_guarantees(spec, s);
}

// Exterior (turning) angles of a polygon, in (−π, π]: all positive for a strictly convex
// counter-clockwise polygon.
std::vector<double> turning_angles(const Polygon& p) {
  std::vector<double> out;
  for (std::size_t k = 0, m = p.size(); k < m; ++k) {
    const Point e0 = p.vertices[(k + 1) % m] - p.vertices[k];
    const Point e1 = p.vertices[(k + 2) % m] - p.vertices[(k + 1) % m];
    out.push_back(std::atan2(cross(e0, e1), e0.dot(e1)));
  }
  return out;
}

TEST(RandomInstance, ObstacleKindsFollowUnknownFraction) {
  for (const bool round : {true, false}) {
    for (const double fraction : {0.0, 0.5, 1.0}) {
      InstanceSpec spec = make_spec(2, GoalClass::kCyclic, 0.2, 11);
      spec.unknown_fraction = fraction;
      spec.round_unknown = round;
      const Scenario s = random_instance(spec);
      if (fraction == 0.0) {
        EXPECT_TRUE(s.unknown.empty());
      }
      if (fraction == 1.0) {
        EXPECT_TRUE(s.familiar.empty());
      }
      EXPECT_FALSE(s.familiar.empty() && s.unknown.empty());
      for (std::size_t i = 0; i < s.familiar.size(); ++i) {
        EXPECT_EQ(s.familiar[i].name, "P" + std::to_string(i + 1));
      }
      for (std::size_t i = 0; i < s.unknown.size(); ++i) {
        EXPECT_EQ(s.unknown[i].name, "C" + std::to_string(i + 1));
        const Polygon& p = s.unknown[i].polygon;
        for (std::size_t k = 0, m = p.size(); k < m; ++k) {
          // No edge under 5 cm (hulls, rectangles) or 2.6 cm (ellipses: 0.2 · 2 sin(π/48)).
          EXPECT_GE((p.vertices[(k + 1) % m] - p.vertices[k]).norm(), round ? 0.026 : 0.05);
        }
        const std::vector<double> turns = turning_angles(p);
        double total = 0;
        for (const double t : turns) {
          total += t;
          // Convex (no right turn); round ones strictly, and with no corner sharper than 30°
          // (a rectangle turns 90°): the polygon of a strongly convex body, the paper's §II.
          EXPECT_GE(t, round ? 1e-3 : 0.0);
          if (round) {
            EXPECT_LE(t, std::numbers::pi / 6) << s.name << " " << s.unknown[i].name;
          }
        }
        EXPECT_NEAR(total, 2 * std::numbers::pi, 1e-9);  // one counter-clockwise turn
        if (!round) {
          EXPECT_LE(p.size(), 8u);  // hulls of at most 8 points, rectangles
        }
      }
    }
  }
}

TEST(RandomInstance, NameDescriptionBudgetAndRobot) {
  InstanceSpec spec = make_spec(3, GoalClass::kCyclic, 0.1, 7);
  spec.sensor_range = 2.5;
  const Scenario s = random_instance(spec);
  EXPECT_EQ(s.name, "random_cyclic_n3_s7");
  EXPECT_EQ(s.source, "");
  char density[32];
  std::snprintf(density, sizeof density, "%.3f", obstacle_area(s) / 100);
  EXPECT_EQ(s.description.rfind(std::string("random instance: class cyclic, N=3, density ") +
                                    density + " (target 0.100), seed 7, ",
                                0),
            0u)
      << s.description;
  EXPECT_NE(s.description.find(std::to_string(s.familiar.size()) + " familiar and " +
                               std::to_string(s.unknown.size()) + " unknown obstacles"),
            std::string::npos)
      << s.description;
  EXPECT_EQ(s.simulation.time_budget, 600 + 300 * 3);
  EXPECT_EQ(s.robot.radius, spec.robot_radius);
  EXPECT_EQ(s.robot.sensor_range, 2.5);
  EXPECT_TRUE(std::isfinite(s.robot.heading));
  EXPECT_EQ(s.workspace.vertices,
            (std::vector<Point>{Point(0, 0), Point(10, 0), Point(10, 10), Point(0, 10)}));
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    EXPECT_EQ(s.objects[i].name, "M" + std::to_string(i + 1));
    EXPECT_EQ(s.objects[i].disk.radius, spec.object_radius);
  }
  const Controller defaults;
  EXPECT_EQ(s.controller.p, defaults.p);
  EXPECT_EQ(s.controller.epsilon, defaults.epsilon);
  EXPECT_EQ(random_instance(make_spec(1, GoalClass::kRandom, 0, 0)).name, "random_random_n1_s0");
}

TEST(RandomInstance, TaskIsTheSequentialNesting) {
  EXPECT_EQ(random_instance(make_spec(2, GoalClass::kRandom, 0, 0)).task,
            "<>(grasp(M1) && <>(release(M1,l1) && <>(grasp(M2) && <>release(M2,l2))))");
  EXPECT_EQ(random_instance(make_spec(1, GoalClass::kCyclic, 0, 0)).task,
            "<>(grasp(M1) && <>release(M1,l1))");
  EXPECT_EQ(random_instance(make_spec(3, GoalClass::kCyclic, 0, 0)).task,
            "<>(grasp(M1) && <>(release(M1,l1) && <>(grasp(M2) && <>(release(M2,l2) && "
            "<>(grasp(M3) && <>release(M3,l3))))))");
}

TEST(RandomInstance, GoalClassStrings) {
  for (const GoalClass c : kClasses) EXPECT_EQ(goal_class_from_string(to_string(c)), c);
  EXPECT_STREQ(to_string(GoalClass::kRandom), "random");
  EXPECT_STREQ(to_string(GoalClass::kCyclic), "cyclic");
  EXPECT_THROW(goal_class_from_string("Cyclic"), Error);
  EXPECT_THROW(goal_class_from_string(""), Error);
}

// Throws rearm::Error whose message names `field`.
void expect_bad(const std::function<void(InstanceSpec&)>& edit, const std::string& field) {
  InstanceSpec spec;
  edit(spec);
  try {
    random_instance(spec);
    ADD_FAILURE() << "no error for a bad " << field;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(field + ":"), std::string::npos) << e.what();
  }
}

TEST(RandomInstance, BadSpecsThrowNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expect_bad([](InstanceSpec& s) { s.objects = 0; }, "objects");
  expect_bad([](InstanceSpec& s) { s.objects = 13; }, "objects");
  expect_bad([](InstanceSpec& s) { s.objects = -3; }, "objects");
  expect_bad([](InstanceSpec& s) { s.obstacle_density = -0.1; }, "obstacle_density");
  expect_bad([](InstanceSpec& s) { s.obstacle_density = 0.31; }, "obstacle_density");
  expect_bad([&](InstanceSpec& s) { s.obstacle_density = nan; }, "obstacle_density");
  expect_bad([](InstanceSpec& s) { s.unknown_fraction = 1.5; }, "unknown_fraction");
  expect_bad([&](InstanceSpec& s) { s.unknown_fraction = nan; }, "unknown_fraction");
  expect_bad([&](InstanceSpec& s) { s.width = nan; }, "width");
  expect_bad([&](InstanceSpec& s) { s.height = inf; }, "height");
  expect_bad([](InstanceSpec& s) { s.width = -10; }, "width");
  expect_bad([](InstanceSpec& s) { s.height = 0; }, "height");
  expect_bad([](InstanceSpec& s) { s.width = 1e6; }, "width");
  expect_bad([](InstanceSpec& s) { s.robot_radius = 0; }, "robot_radius");
  expect_bad([&](InstanceSpec& s) { s.robot_radius = nan; }, "robot_radius");
  expect_bad([](InstanceSpec& s) { s.object_radius = -0.25; }, "object_radius");
  expect_bad([](InstanceSpec& s) { s.region_side = 0; }, "region_side");
  expect_bad([](InstanceSpec& s) { s.region_side = 0.4; }, "region_side");  // < 2 ρ
  expect_bad([&](InstanceSpec& s) { s.sensor_range = -inf; }, "sensor_range");
  expect_bad([](InstanceSpec& s) { s.max_attempts = 0; }, "max_attempts");
  // Workspace too small: object starts and goals keep 1.35 m from the boundary by default.
  expect_bad([](InstanceSpec& s) { s.width = 2.7; }, "width");
  expect_bad([](InstanceSpec& s) { s.height = 2; }, "height");
  expect_bad([](InstanceSpec& s) { s.robot_radius = 20; }, "width");
}

TEST(RandomInstance, ImpossiblePlacementThrowsNamingTheSpec) {
  InstanceSpec spec = make_spec(12, GoalClass::kCyclic, 0.1, 5);
  spec.width = 4;
  spec.height = 4;
  spec.max_attempts = 50;
  try {
    random_instance(spec);
    ADD_FAILURE() << "12 objects fit in a 4 x 4 m workspace";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("random_instance(class cyclic, N=12, density 0.1, seed 5, 4 x 4 m)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("could not place the start of object M"), std::string::npos) << what;
  }
}

TEST(RandomInstance, TwelveObjectsFitTheDefaultWorkspace) {
  for (const GoalClass c : kClasses) {
    const InstanceSpec spec = make_spec(kMaxInstanceObjects, c, 0.05, 2);
    const Scenario s = random_instance(spec);
    EXPECT_EQ(s.objects.size(), 12u);
    expect_guarantees(spec, s);
  }
}

}  // namespace
}  // namespace rearm::scenario
