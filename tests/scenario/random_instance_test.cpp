// random_instance / generate_instance (random_instance.h: classes random, cyclic and sealed;
// clusters and passages; dense footprints): validity, the clearance and passage rules measured
// with geometry written here (independent of geometry/ and of the generator), the density
// measured on an independent raster of the obstacles' union, the cyclic goal structure,
// determinism (twice, and in two threads) and the input checks.
#include "scenario/random_instance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "ltl/parser.h"
#include "scenario/scenario_io.h"
#include "support/geometry_oracle.h"
#include "support/scale.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;

// Slack for comparing the generator's double-precision clearances with the ones measured here.
constexpr double kTol = 1e-9;

// --- Independent geometry (no geometry/ functions) -------------------------------------------

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

double shoelace(const Polygon& p) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i)
    a += cross(p.vertices[i], p.vertices[(i + 1) % n]);
  return a / 2;
}

// Distance from x to the closed polygon (0 inside).
double point_polygon(const Point& x, const Polygon& p) {
  if (test_support::ray_cast_inside(p, x)) return 0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    d = std::min(d, test_support::segment_distance(p.vertices[i], p.vertices[(i + 1) % n], x));
  }
  return d;
}

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

// Distance between two closed polygons (0 when they touch or overlap).
double polygon_polygon(const Polygon& p, const Polygon& q) {
  if (test_support::ray_cast_inside(q, p.vertices.front()) ||
      test_support::ray_cast_inside(p, q.vertices.front()))
    return 0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % p.size()];
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Point& c = q.vertices[j];
      const Point& e = q.vertices[(j + 1) % q.size()];
      if (segments_cross(a, b, c, e)) return 0;
      d = std::min(
          {d, test_support::segment_distance(c, e, a), test_support::segment_distance(c, e, b),
           test_support::segment_distance(a, b, c), test_support::segment_distance(a, b, e)});
    }
  }
  return d;
}

double wall_gap(const Polygon& p, double w, double h) {
  double g = std::numeric_limits<double>::infinity();
  for (const Point& v : p.vertices) g = std::min({g, v.x(), w - v.x(), v.y(), h - v.y()});
  return g;
}

std::vector<Polygon> obstacles_of(const Scenario& s) {
  std::vector<Polygon> out;
  for (const NamedPolygon& p : s.familiar) out.push_back(p.polygon);
  for (const NamedPolygon& p : s.unknown) out.push_back(p.polygon);
  return out;
}

// The union's density by an independent raster (geometry_oracle.h).
double raster_density(const Scenario& s, double W, double H, double cell) {
  return test_support::raster_union_share(obstacles_of(s), W, H, cell);
}

InstanceSpec make_spec(int n, GoalClass c, double density, std::uint64_t seed) {
  InstanceSpec spec;
  spec.objects = n;
  spec.goal_class = c;
  spec.obstacle_density = density;
  spec.seed = seed;
  return spec;
}

constexpr GoalClass kClasses[] = {GoalClass::kRandom, GoalClass::kCyclic, GoalClass::kSealed};

Point region_centre(const Polygon& square) {
  Point c = Point::Zero();
  for (const Point& v : square.vertices) c += v;
  return c / static_cast<double>(square.size());
}

// The rules of random_instance.h ("Clusters and passages", "Clearances"), measured directly.
void expect_rules(const InstanceSpec& spec, const GeneratedInstance& g) {
  const Scenario& s = g.scenario;
  SCOPED_TRACE(s.name + " density " + std::to_string(spec.obstacle_density));
  const double r = spec.robot_radius, rho = spec.object_radius;
  const double W = s.workspace.vertices[2].x(), H = s.workspace.vertices[2].y();
  const double w = 2 * (r + rho) + spec.passage_margin;
  const std::vector<Polygon> obstacles = obstacles_of(s);
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const double b = wall_gap(obstacles[i], W, H);
    EXPECT_TRUE(b == 0 || b >= w - kTol) << "obstacle " << i << " wall gap " << b;
    EXPECT_GT(shoelace(obstacles[i]), 0);
    for (std::size_t j = i + 1; j < obstacles.size(); ++j) {
      const double d = polygon_polygon(obstacles[i], obstacles[j]);
      EXPECT_TRUE(d == 0 || d >= w - kTol) << i << " vs " << j << ": gap " << d;
    }
  }
  const std::size_t n = static_cast<std::size_t>(spec.objects);
  ASSERT_EQ(s.regions.size(), n);
  ASSERT_EQ(s.objects.size(), n + (spec.goal_class == GoalClass::kSealed ? 1 : 0));
  const double cg = 2 * r + rho + 0.05;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(s.objects[i].name, "M" + std::to_string(i + 1));
    for (const Point& p : {s.objects[i].disk.center, region_centre(s.regions[i].polygon)}) {
      for (const Polygon& o : obstacles) EXPECT_GE(point_polygon(p, o), cg - kTol);
    }
    for (std::size_t j = i + 1; j < n; ++j) {  // regions disjoint, objects apart
      const Point d =
          (region_centre(s.regions[i].polygon) - region_centre(s.regions[j].polygon)).cwiseAbs();
      EXPECT_TRUE(d.x() > g.region_side || d.y() > g.region_side) << "regions " << i << ", " << j;
      EXPECT_GE((s.objects[i].disk.center - s.objects[j].disk.center).norm(), 2 * rho);
    }
  }
  if (spec.goal_class == GoalClass::kSealed) {
    EXPECT_EQ(s.objects.back().name, "B1");
  }
}

// --- Tests ---------------------------------------------------------------------------------------

TEST(RandomInstance, ValidSolvableAndKeepsThePassageRulesAcrossClassesAndDensities) {
  for (const GoalClass c : kClasses) {
    for (const int n : {1, 4, 8}) {
      for (const double density : {0.0, 0.15, 0.35}) {
        for (std::uint64_t seed = 0; seed < test_support::scaled(2); ++seed) {
          const InstanceSpec spec = make_spec(n, c, density, seed);
          const GeneratedInstance g = generate_instance(spec);
          EXPECT_NO_THROW(validate(g.scenario)) << g.scenario.name;
          EXPECT_TRUE(g.solvability.solvable) << g.solvability.failure;
          expect_rules(spec, g);
        }
      }
    }
  }
}

// The committed sweep's densities in the 10 x 10 m default workspace for small N: reached within
// kDensityTolerance for every seed (no overshoot by a last large obstacle), and the reported
// density is the union's (an independent raster of it).
TEST(RandomInstance, DensityReachesTheTargetAndIsTheUnionsArea) {
  for (const GoalClass c : kClasses) {
    for (const int n : {1, 4}) {
      for (std::uint64_t seed = 0; seed < test_support::scaled(3); ++seed) {
        const InstanceSpec spec = make_spec(n, c, 0.35, seed);
        const GeneratedInstance g = generate_instance(spec);
        SCOPED_TRACE(g.scenario.description);
        EXPECT_TRUE(g.density_reached);
        // Within the tolerance of the target, by the generator's exact area and by a raster.
        EXPECT_NEAR(g.achieved_density, 0.35, kDensityTolerance);
        const double raster = raster_density(g.scenario, 10, 10, 0.02);
        EXPECT_NEAR(raster, 0.35, kDensityTolerance + 0.01);
        EXPECT_NEAR(raster, g.achieved_density, 0.01);
        double sum = 0;
        for (const Polygon& p : obstacles_of(g.scenario)) sum += shoelace(p);
        EXPECT_GE(sum / 100, g.achieved_density - 1e-9);  // overlaps counted once
        EXPECT_EQ(g.scenario.description.find("stopped"), std::string::npos);
      }
    }
  }
}

TEST(RandomInstance, FootprintDensitySetsTheWorkspaceAndDenseSpacingKeepsObjectsApart) {
  for (const double fp : {0.1, 0.2}) {
    for (const GoalClass c : {GoalClass::kRandom, GoalClass::kCyclic}) {
      InstanceSpec spec = make_spec(16, c, 0.0, 1);
      spec.footprint_density = fp;
      const GeneratedInstance g = generate_instance(spec);
      const double area = 16 * std::numbers::pi * 0.25 * 0.25;
      const double side = std::sqrt(area / fp);
      EXPECT_NEAR(g.scenario.workspace.vertices[2].x(), side, 1e-12);
      EXPECT_NEAR(g.footprint_density, fp, 1e-12);
      EXPECT_TRUE(g.dense);
      EXPECT_GE(g.region_side, 2 * 0.25);
      EXPECT_TRUE(g.solvability.solvable);
      expect_rules(spec, g);
    }
  }
}

TEST(RandomInstance, SameSpecGivesTheSameScenarioAlsoAcrossThreads) {
  std::vector<InstanceSpec> specs;
  for (const GoalClass c : kClasses) specs.push_back(make_spec(4, c, 0.25, 7));
  std::vector<std::string> a(specs.size()), b(specs.size());
  std::thread t1([&] {
    for (std::size_t i = 0; i < specs.size(); ++i) a[i] = to_yaml(random_instance(specs[i]));
  });
  std::thread t2([&] {
    for (std::size_t i = specs.size(); i-- > 0;) b[i] = to_yaml(random_instance(specs[i]));
  });
  t1.join();
  t2.join();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    EXPECT_EQ(a[i], b[i]);
    EXPECT_EQ(to_yaml(random_instance(specs[i])), a[i]);
    InstanceSpec other = specs[i];
    other.seed = 8;
    EXPECT_NE(to_yaml(random_instance(other)), a[i]);
    EXPECT_EQ(to_yaml(parse_scenario(a[i], "random.yaml")), a[i]);
  }
}

TEST(RandomInstance, CyclicGoalIsTheNextObjectsStart) {
  for (int n = 1; n <= 8; ++n) {
    for (std::uint64_t seed = 0; seed < test_support::scaled(3); ++seed) {
      const Scenario s = random_instance(make_spec(n, GoalClass::kCyclic, 0.1, seed));
      SCOPED_TRACE(s.name);
      for (int i = 0; i < n; ++i) {
        const std::size_t next = static_cast<std::size_t>((i + 1) % n);
        EXPECT_LT((region_centre(s.regions[static_cast<std::size_t>(i)].polygon) -
                   s.objects[next].disk.center)
                      .norm(),
                  kTol);
      }
    }
  }
}

TEST(RandomInstance, GoalClassNames) {
  for (const GoalClass c : kClasses) EXPECT_EQ(goal_class_from_string(to_string(c)), c);
  EXPECT_STREQ(to_string(GoalClass::kSealed), "sealed");
  EXPECT_THROW(goal_class_from_string("Sealed"), Error);
}

// The goal order changes the task's formula only: the same geometry, and for `any` the
// conjunction of every object's eventual release in its own region, whose parts are the objects
// (read back by the LTL parser, independent of the generator's text).
TEST(RandomInstance, GoalOrderChangesOnlyTheTask) {
  EXPECT_EQ(goal_order_from_string("any"), GoalOrder::kAny);
  EXPECT_STREQ(to_string(GoalOrder::kChain), "chain");
  EXPECT_THROW(goal_order_from_string("Any"), Error);
  for (const GoalClass c : kClasses) {
    InstanceSpec spec = make_spec(4, c, 0.1, 3);
    Scenario chain = random_instance(spec);
    spec.goal_order = GoalOrder::kAny;
    Scenario any = random_instance(spec);
    EXPECT_EQ(any.name, chain.name + "_any");
    const ltl::Formula f = ltl::parse(any.task);
    ASSERT_EQ(f.op(), ltl::Op::And);
    ASSERT_EQ(f.children().size(), 4u);
    for (int i = 0; i < 4; ++i) {
      const std::string k = std::to_string(i + 1);
      EXPECT_EQ(f.child(static_cast<std::size_t>(i)),
                ltl::Formula::eventually(ltl::Formula::ap("release(M" + k + ",l" + k + ")")));
    }
    EXPECT_NE(chain.task, any.task);
    chain.name = any.name;
    chain.task = any.task;
    EXPECT_EQ(to_yaml(chain), to_yaml(any));
  }
}

// Crowded fallback (random_instance.h): a 3.50 m room (N = 4 sealed, footprint 0.08) cannot hold
// the 1.8 m pocket with passages of w = 1.1 m on both sides (1.8 + 2.2 > 3.50), so only the
// fallback places it, flush with a wall; the instance is valid, certified and sealed, keeps the
// passage rule and its objects apart, and the standard rules still place what they placed.
TEST(RandomInstance, CrowdedFallbackPlacesWhatTheStandardRulesCannot) {
  for (std::uint64_t seed = 0; seed < test_support::scaled(3); ++seed) {
    InstanceSpec spec = make_spec(4, GoalClass::kSealed, 0.05, seed);
    spec.footprint_density = 0.08;
    const GeneratedInstance g = generate_instance(spec);
    const Scenario& s = g.scenario;
    SCOPED_TRACE(s.description);
    const double W = s.workspace.vertices[2].x(), H = s.workspace.vertices[2].y();
    ASSERT_LT(W, 1.8 + 2 * 1.1);
    EXPECT_TRUE(g.crowded_rules);
    EXPECT_NE(s.description.find("crowded fallback rules"), std::string::npos);
    EXPECT_NO_THROW(validate(s));
    EXPECT_TRUE(g.solvability.solvable) << g.solvability.failure;
    EXPECT_TRUE(g.pocket.present);
    EXPECT_TRUE(g.pocket.seal.failure.empty()) << g.pocket.seal.failure;
    EXPECT_EQ(wall_gap(s.familiar.front().polygon, W, H), 0);  // flush with a wall
    const double w = 2 * (spec.robot_radius + spec.object_radius) + spec.passage_margin;
    for (const Polygon& o : obstacles_of(s)) {
      const double b = wall_gap(o, W, H);
      EXPECT_TRUE(b == 0 || b >= w - kTol) << "wall gap " << b;
    }
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      for (std::size_t j = i + 1; j < s.objects.size(); ++j) {
        const double d = (s.objects[i].disk.center - s.objects[j].disk.center).norm();
        EXPECT_GE(d, 2 * spec.object_radius) << s.objects[i].name << ", " << s.objects[j].name;
      }
      const double robot = (s.objects[i].disk.center - s.robot.start).norm();
      EXPECT_GE(robot, spec.object_radius + spec.robot_radius) << s.objects[i].name;
    }
    EXPECT_EQ(to_yaml(generate_instance(spec).scenario), to_yaml(s));  // deterministic
  }
  // A spec the standard rules place is not touched by the fallback.
  InstanceSpec roomy = make_spec(4, GoalClass::kSealed, 0.05, 0);
  roomy.footprint_density = 0.01;
  EXPECT_FALSE(generate_instance(roomy).crowded_rules);
}

void expect_rejected(const InstanceSpec& spec, const std::string& field) {
  try {
    (void)generate_instance(spec);
    ADD_FAILURE() << field << " accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(RandomInstance, BadSpecsNameTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const InstanceSpec base = make_spec(3, GoalClass::kRandom, 0.1, 0);
  auto with = [&](auto change) {
    InstanceSpec s = base;
    change(s);
    return s;
  };
  expect_rejected(with([](InstanceSpec& s) { s.objects = 0; }), "objects");
  expect_rejected(with([](InstanceSpec& s) { s.objects = kMaxInstanceObjects + 1; }), "objects");
  expect_rejected(with([](InstanceSpec& s) { s.obstacle_density = 0.51; }), "obstacle_density");
  expect_rejected(with([&](InstanceSpec& s) { s.obstacle_density = nan; }), "obstacle_density");
  expect_rejected(with([](InstanceSpec& s) { s.footprint_density = 0.31; }), "footprint_density");
  expect_rejected(with([&](InstanceSpec& s) { s.footprint_density = nan; }), "footprint_density");
  expect_rejected(with([](InstanceSpec& s) { s.footprint_density = 1e-6; }), "footprint_density");
  expect_rejected(with([](InstanceSpec& s) { s.passage_margin = 0.01; }), "passage_margin");
  expect_rejected(with([](InstanceSpec& s) { s.max_obstacle_side = 0.5; }), "max_obstacle_side");
  expect_rejected(with([](InstanceSpec& s) { s.unknown_fraction = 2; }), "unknown_fraction");
  expect_rejected(with([](InstanceSpec& s) { s.width = 0; }), "width");
  expect_rejected(with([](InstanceSpec& s) { s.height = 0.5; }), "height");
  expect_rejected(with([](InstanceSpec& s) { s.region_side = 0.4; }), "region_side");
  expect_rejected(with([](InstanceSpec& s) { s.max_attempts = 0; }), "max_attempts");
  // An impossible placement: a clear error, never a hang.
  expect_rejected(with([](InstanceSpec& s) {
                    s.objects = 64;
                    s.width = s.height = 4;
                  }),
                  "could not place");
  // A room narrower than the pocket plus one passage (N = 4 sealed at footprint 0.2: 1.98 m):
  // refused under both rule sets, the message naming both.
  expect_rejected(with([](InstanceSpec& s) {
                    s.goal_class = GoalClass::kSealed;
                    s.objects = 4;
                    s.footprint_density = 0.2;
                  }),
                  "under the crowded fallback rules too: could not place the sealed pocket");
}

}  // namespace
}  // namespace rearm::scenario
