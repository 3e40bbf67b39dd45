// random_instance() of random_instance.h: rejection sampling of the Monte Carlo instances
// (docs/experiments.md, "Monte Carlo runner", classes a and b). Placement order: object starts,
// goal points, robot start, then obstacles, so that the obstacle density never makes a required
// placement impossible; an obstacle is accepted only when it keeps every clearance of the
// header's solvability argument. Clearance tests are doubles with the margins of the header
// (accept-or-retry decisions, re-checked by scenario::validate); polygon validity is checked
// with the exact predicates of geometry::validated.
#include "scenario/random_instance.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "geometry/convex.h"
#include "geometry/distance.h"
#include "geometry/polygon.h"
#include "scenario/scenario_io.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;

// Input ranges (random_instance.h, InstanceSpec).
constexpr int kMinObjects = 1;
constexpr double kMinLength = 0.01;           // m: below this no length is meaningful
constexpr double kMaxWorkspaceSide = 100;     // m: bounds the obstacle count (and run time)
constexpr int kMaxAttemptsLimit = 1'000'000;  // bounds the run time of a hopeless spec

// Clearances of the header's solvability argument.
constexpr double kRegionGap = 0.1;        // m: start/goal spacing beyond the region diagonal
constexpr double kRobotObjectGap = 0.5;   // m: robot start disk to object start disk
constexpr double kPlacementSlack = 1e-6;  // m: keeps region vertices inside despite rounding

// Obstacle shapes: sides of rectangles and L-shapes, hull disk diameters, in
// [kMinObstacleSide, kMaxObstacleSide]; hulls of kMinHullPoints..kMaxHullPoints points (Box2D
// takes polygons of at most 8 vertices, docs/experiments.md) with at least kMinHullArea.
constexpr double kMinObstacleSide = 0.4;
constexpr int kMinHullPoints = 5;
constexpr int kMaxHullPoints = 8;
constexpr double kMinHullArea = 0.1;  // m²: rejects slivers
// m: Box2D welds vertices closer than its linear slop (0.005 m), and very short edges make the
// reactive layer's polygon operations ill-conditioned; hulls with a shorter edge are redrawn.
constexpr double kMinHullEdge = 0.05;
// Unknown obstacles by default (InstanceSpec::round_unknown): ellipses, the paper's strongly
// convex unknown obstacles (§II, [35, Assumption 2]: positive curvature everywhere, so the
// navigation law of [7] has no stable equilibrium on a flat face that squarely faces the goal).
// kEllipseSides vertices at uniform parametric angles. The polygon's own edges are flat: the
// law stops on the edge that squarely faces the goal when it first touches that edge, which
// happens for a share of head-on approaches of about one edge's width over the obstacle's; 48
// sides (the reactive closed-loop tests' round obstacles) measured 59/60 random-goal instances
// completed against 55/60 with 24 (issue 7's comparison, N = 1..6). With semi-axes >=
// kMinObstacleSide / 2 every edge is >= 0.2 · 2 sin(π/48) = 0.026 m, five times Box2D's linear
// slop. Aspect ratio at most kMaxEllipseAspect keeps the curvature radius at the ends of the
// minor axis, a²/b, within 3.4 times the semi-major axis.
constexpr int kEllipseSides = 48;
constexpr double kMaxEllipseAspect = 1.5;
// Among this many acceptable poses of a new obstacle the largest is kept. Every obstacle costs
// a w-wide passage around it, so uniform sequential placement jams early (about 0.05 in the
// default 10 x 10 m instance); preferring large obstacles roughly doubles the density reached
// (measured over 40 seeds, N = 1..12), and 30 gets most of the gain of 100 at a third the cost.
constexpr int kCandidatesPerObstacle = 30;

// Simulated seconds: a base plus a share per object (each needs a grasp, a carry, a release).
constexpr double kBaseTimeBudget = 600;
constexpr double kTimeBudgetPerObject = 300;

// Rng::derive streams: independent draws for each placement stage (random_instance.h,
// "Determinism").
constexpr std::uint64_t kStartsStream = 1;
constexpr std::uint64_t kGoalsStream = 2;
constexpr std::uint64_t kRobotStream = 3;
constexpr std::uint64_t kObstaclesStream = 4;

// The shortest decimal that reads back to x.
std::string num(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

std::string fixed3(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

[[noreturn]] void bad_field(const char* field, const std::string& reason) {
  throw Error(std::string("random_instance: ") + field + ": " + reason);
}

void check_length(double x, const char* field,
                  double max = std::numeric_limits<double>::infinity()) {
  if (!(std::isfinite(x) && x >= kMinLength && x <= max)) {
    const std::string range = std::isfinite(max)
                                  ? "in [" + num(kMinLength) + ", " + num(max) + "] m"
                                  : ">= " + num(kMinLength) + " m";
    bad_field(field, "must be finite and " + range + ", got " + num(x));
  }
}

void check_fraction(double x, const char* field, double max) {
  if (!(std::isfinite(x) && x >= 0 && x <= max)) {
    bad_field(field, "must be finite and in [0, " + num(max) + "], got " + num(x));
  }
}

// Lengths derived from the spec (random_instance.h, "Clearances").
struct Clearances {
  double passage = 0;         // w
  double point_boundary = 0;  // cb
  double point_obstacle = 0;  // co
  double point_spacing = 0;   // d
  double robot_object = 0;    // robot start to object start (centres)
};

Clearances clearances(const InstanceSpec& spec) {
  const double r = spec.robot_radius;
  const double rho = spec.object_radius;
  const double s = spec.region_side;
  Clearances c;
  c.passage = 2 * (r + rho) + kPassageMargin;
  c.point_boundary = std::max(c.passage + rho, s / 2 + kPlacementSlack);
  c.point_obstacle = std::max(c.passage + rho, s / std::numbers::sqrt2);
  c.point_spacing = std::max(s * std::numbers::sqrt2 + kRegionGap, c.passage);
  c.robot_object = r + rho + kRobotObjectGap;
  return c;
}

void check_spec(const InstanceSpec& spec) {
  if (spec.objects < kMinObjects || spec.objects > kMaxInstanceObjects) {
    bad_field("objects", "must be an integer in [" + std::to_string(kMinObjects) + ", " +
                             std::to_string(kMaxInstanceObjects) + "], got " +
                             std::to_string(spec.objects));
  }
  check_fraction(spec.obstacle_density, "obstacle_density", kMaxObstacleDensity);
  check_fraction(spec.unknown_fraction, "unknown_fraction", 1);
  check_length(spec.width, "width", kMaxWorkspaceSide);
  check_length(spec.height, "height", kMaxWorkspaceSide);
  check_length(spec.robot_radius, "robot_radius");
  check_length(spec.object_radius, "object_radius");
  check_length(spec.region_side, "region_side");
  check_length(spec.sensor_range, "sensor_range");
  if (spec.max_attempts < 1 || spec.max_attempts > kMaxAttemptsLimit) {
    bad_field("max_attempts", "must be an integer in [1, " + std::to_string(kMaxAttemptsLimit) +
                                  "], got " + std::to_string(spec.max_attempts));
  }
  if (spec.region_side < 2 * spec.object_radius) {
    bad_field("region_side", "must be >= 2 object_radius = " + num(2 * spec.object_radius) +
                                 " m (an object must fit in its region), got " +
                                 num(spec.region_side));
  }
  const Clearances c = clearances(spec);
  auto wide_enough = [&](double side, const char* field) {
    if (!(side > 2 * c.point_boundary)) {
      bad_field(field, "workspace too small: must exceed " + num(2 * c.point_boundary) +
                           " m (twice the " + num(c.point_boundary) +
                           " m that object starts and goals keep from the boundary), got " +
                           num(side));
    }
  };
  wide_enough(spec.width, "width");
  wide_enough(spec.height, "height");
}

std::string describe(const InstanceSpec& spec) {
  return std::string("random_instance(class ") + to_string(spec.goal_class) +
         ", N=" + std::to_string(spec.objects) + ", density " + num(spec.obstacle_density) +
         ", seed " + std::to_string(spec.seed) + ", " + num(spec.width) + " x " + num(spec.height) +
         " m)";
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

// Axis-aligned bounding box, for cheap rejection before exact distances.
struct Box {
  Point lo, hi;
};

Box bounding_box(const Polygon& p) {
  Box b{p.vertices.front(), p.vertices.front()};
  for (const Point& v : p.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

// Lower bound on the distance between anything inside a and anything inside b.
double box_gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, a.lo.x() - b.hi.x(), b.lo.x() - a.hi.x()});
  const double dy = std::max({0.0, a.lo.y() - b.hi.y(), b.lo.y() - a.hi.y()});
  return std::hypot(dx, dy);
}

double box_gap(const Box& a, const Point& p) { return box_gap(a, Box{p, p}); }

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Distance between segments [a, b] and [c, d]; 0 when they may touch (collinear or crossing:
// conservative, a rejected candidate is simply redrawn).
double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double abc = cross(b - a, c - a), abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c), cdb = cross(d - c, b - c);
  if (abc * abd <= 0 && cda * cdb <= 0) return 0;
  return std::min({(geometry::nearest_on_segment(c, d, a) - a).norm(),
                   (geometry::nearest_on_segment(c, d, b) - b).norm(),
                   (geometry::nearest_on_segment(a, b, c) - c).norm(),
                   (geometry::nearest_on_segment(a, b, d) - d).norm()});
}

// Whether two closed simple polygons are less than w apart (they overlap, one contains the
// other, or two edges come closer than w). Edge pairs whose bounding boxes are >= w apart are
// skipped: the box gap is a lower bound of the segments' distance, so the answer is the one
// of the full O(n m) scan, at a cost proportional to the edges that face each other.
bool closer_than(const Polygon& p, const Polygon& q, double w) {
  if (geometry::contains(q, p.vertices.front()) || geometry::contains(p, q.vertices.front())) {
    return true;
  }
  auto edge_box = [](const Point& a, const Point& b) {
    return Box{a.cwiseMin(b), a.cwiseMax(b)};
  };
  const Box qbox = bounding_box(q);
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[(i + 1) % n];
    const Box ebox = edge_box(a, b);
    if (box_gap(ebox, qbox) >= w) continue;
    for (std::size_t j = 0, m = q.size(); j < m; ++j) {
      const Point& c = q.vertices[j];
      const Point& d = q.vertices[(j + 1) % m];
      if (box_gap(ebox, edge_box(c, d)) >= w) continue;
      if (segment_distance(a, b, c, d) < w) return true;
    }
  }
  return false;
}

// Distance from x to the closed axis-aligned square of side `side` centred at c.
double square_distance(const Point& c, double side, const Point& x) {
  const double dx = std::max(std::abs(x.x() - c.x()) - side / 2, 0.0);
  const double dy = std::max(std::abs(x.y() - c.y()) - side / 2, 0.0);
  return std::hypot(dx, dy);
}

struct Obstacle {
  Polygon polygon;
  Box box;
  bool unknown = false;
};

class Generator {
 public:
  explicit Generator(const InstanceSpec& spec) : spec_(spec), c_(clearances(spec)) {}

  Scenario run() {
    place_starts();
    place_goals();
    place_robot();
    place_obstacles();
    return assemble();
  }

 private:
  [[noreturn]] void placement_failed(const std::string& what, const std::string& rule) const {
    throw Error(describe(spec_) + ": could not place " + what + " in " +
                std::to_string(spec_.max_attempts) + " attempts (" + rule +
                "); use a larger workspace, fewer objects or a smaller region_side");
  }

  // Uniform in the square-inset workspace [m, width - m] x [m, height - m].
  Point inset_point(Rng& rng, double m) const {
    return Point(rng.uniform(m, spec_.width - m), rng.uniform(m, spec_.height - m));
  }

  // Points pairwise >= point_spacing apart, >= point_boundary from the boundary.
  std::vector<Point> spaced_points(Rng& rng, const char* what) const {
    std::vector<Point> out;
    for (int i = 0; i < spec_.objects; ++i) {
      bool placed = false;
      for (int attempt = 0; attempt < spec_.max_attempts && !placed; ++attempt) {
        const Point p = inset_point(rng, c_.point_boundary);
        placed = std::all_of(out.begin(), out.end(),
                             [&](const Point& q) { return (p - q).norm() >= c_.point_spacing; });
        if (placed) out.push_back(p);
      }
      if (!placed) {
        placement_failed(std::string(what) + " of object M" + std::to_string(i + 1),
                         std::string(what) + "s keep >= " + num(c_.point_spacing) +
                             " m from each other and >= " + num(c_.point_boundary) +
                             " m from the boundary");
      }
    }
    return out;
  }

  void place_starts() {
    Rng rng = Rng::derive(spec_.seed, kStartsStream);
    starts_ = spaced_points(rng, "the start");
  }

  void place_goals() {
    if (spec_.goal_class == GoalClass::kCyclic) {
      // Class b: the goal of object i is the start of object i + 1 (mod N).
      const std::size_t n = starts_.size();
      for (std::size_t i = 0; i < n; ++i) goals_.push_back(starts_[(i + 1) % n]);
      return;
    }
    Rng rng = Rng::derive(spec_.seed, kGoalsStream);
    goals_ = spaced_points(rng, "the goal");
  }

  void place_robot() {
    Rng rng = Rng::derive(spec_.seed, kRobotStream);
    for (int attempt = 0; attempt < spec_.max_attempts; ++attempt) {
      const Point p = inset_point(rng, c_.passage);
      const bool clear_of_objects =
          std::all_of(starts_.begin(), starts_.end(),
                      [&](const Point& q) { return (p - q).norm() >= c_.robot_object; });
      const bool clear_of_regions = std::all_of(goals_.begin(), goals_.end(), [&](const Point& g) {
        return square_distance(g, spec_.region_side, p) >= spec_.robot_radius;
      });
      if (clear_of_objects && clear_of_regions) {
        robot_start_ = p;
        robot_heading_ = rng.uniform(-std::numbers::pi, std::numbers::pi);
        return;
      }
    }
    placement_failed("the robot start", "it keeps >= " + num(c_.passage) +
                                            " m from the boundary, >= " + num(c_.robot_object) +
                                            " m from every object start and out of every region");
  }

  // A familiar shape (a rectangle or an L, possibly non-convex) or an unknown one (an ellipse,
  // or with round_unknown off a rectangle or the hull of random points in a disk, convex),
  // centred near the origin, before rotation. Empty when a hull came out a sliver or with a
  // very short edge.
  Polygon sample_shape(Rng& rng, bool unknown) const {
    if (unknown && spec_.round_unknown) {
      const double a = rng.uniform(kMinObstacleSide, kMaxObstacleSide) / 2;
      const double b = rng.uniform(std::max(kMinObstacleSide / 2, a / kMaxEllipseAspect), a);
      std::vector<Point> points;
      for (int k = 0; k < kEllipseSides; ++k) {
        const double t = 2 * std::numbers::pi * k / kEllipseSides;
        points.emplace_back(a * std::cos(t), b * std::sin(t));
      }
      return Polygon{std::move(points)};
    }
    const bool rectangular = rng.bernoulli(0.5);
    if (rectangular) {
      const double a = rng.uniform(kMinObstacleSide, kMaxObstacleSide);
      const double b = rng.uniform(kMinObstacleSide, kMaxObstacleSide);
      return rectangle(-a / 2, -b / 2, a / 2, b / 2);
    }
    if (!unknown) {
      // An L: a x b bounding box, arms of thickness t, each arm at least kMinObstacleSide long
      // beyond the corner square.
      const double a = rng.uniform(2 * kMinObstacleSide, kMaxObstacleSide);
      const double b = rng.uniform(2 * kMinObstacleSide, kMaxObstacleSide);
      const double t = rng.uniform(kMinObstacleSide, std::min(a, b) - kMinObstacleSide);
      const Point o(-a / 2, -b / 2);
      return Polygon{
          {o, o + Point(a, 0), o + Point(a, t), o + Point(t, t), o + Point(t, b), o + Point(0, b)}};
    }
    const double radius = rng.uniform(kMinObstacleSide, kMaxObstacleSide) / 2;
    const int k = static_cast<int>(rng.uniform_int(kMinHullPoints, kMaxHullPoints));
    std::vector<Point> points;
    for (int i = 0; i < k; ++i) {
      const double rad = radius * std::sqrt(rng.uniform01());  // uniform in the disk
      const double angle = rng.uniform(0, 2 * std::numbers::pi);
      points.emplace_back(rad * std::cos(angle), rad * std::sin(angle));
    }
    Polygon hull = geometry::convex_hull(std::move(points));
    if (hull.size() < 3 || hull.area() < kMinHullArea) return Polygon{};
    for (std::size_t i = 0, n = hull.size(); i < n; ++i) {
      if ((hull.vertices[(i + 1) % n] - hull.vertices[i]).norm() < kMinHullEdge) return Polygon{};
    }
    return hull;
  }

  // The shape rotated by a random angle and moved to a random point of the obstacle band.
  Polygon sample_obstacle(Rng& rng, bool unknown) const {
    Polygon p = sample_shape(rng, unknown);
    const double angle = rng.uniform(0, 2 * std::numbers::pi);
    const Point centre = inset_point(rng, c_.passage);
    const double cs = std::cos(angle), sn = std::sin(angle);
    for (Point& v : p.vertices) {
      v = centre + Point(cs * v.x() - sn * v.y(), sn * v.x() + cs * v.y());
    }
    return p;
  }

  // Every clearance of the header for a candidate obstacle, then exact validity.
  bool acceptable(const Polygon& p, bool unknown) const {
    if (p.size() < 3) return false;
    const double w = c_.passage;
    for (const Point& v : p.vertices) {
      if (v.x() < w || v.x() > spec_.width - w || v.y() < w || v.y() > spec_.height - w) {
        return false;
      }
    }
    const Box box = bounding_box(p);
    auto clear_of_point = [&](const Point& x, double clearance) {
      return box_gap(box, x) >= clearance || geometry::signed_distance(p, x) >= clearance;
    };
    for (const Point& x : starts_) {
      if (!clear_of_point(x, c_.point_obstacle)) return false;
    }
    for (const Point& x : goals_) {
      if (!clear_of_point(x, c_.point_obstacle)) return false;
    }
    if (!clear_of_point(robot_start_, w)) return false;
    for (const Obstacle& o : obstacles_) {
      if (box_gap(box, o.box) < w && closer_than(p, o.polygon, w)) return false;
    }
    try {
      if (geometry::validated(p, "obstacle").vertices != p.vertices) return false;
    } catch (const Error&) {
      return false;
    }
    return !unknown || p.is_convex();
  }

  // One obstacle after another until the target density (random_instance.h): for each, the
  // largest of the first kCandidatesPerObstacle acceptable poses; none in max_attempts
  // consecutive draws ends the placement.
  void place_obstacles() {
    Rng rng = Rng::derive(spec_.seed, kObstaclesStream);
    const double workspace_area = spec_.width * spec_.height;
    while (area_ / workspace_area < spec_.obstacle_density) {
      const bool unknown = rng.bernoulli(spec_.unknown_fraction);
      std::optional<Polygon> best;
      int found = 0;
      for (int attempt = 0; attempt < spec_.max_attempts && found < kCandidatesPerObstacle;
           ++attempt) {
        Polygon p = sample_obstacle(rng, unknown);
        if (!acceptable(p, unknown)) continue;
        ++found;
        if (!best || p.area() > best->area()) best = std::move(p);
      }
      if (!best) {
        stopped_ = true;
        return;
      }
      area_ += best->area();
      const Box box = bounding_box(*best);
      obstacles_.push_back(Obstacle{std::move(*best), box, unknown});
    }
  }

  std::string task() const {
    // Formula (1) of the paper extended to N objects (as fig5): innermost release first.
    const int n = spec_.objects;
    auto object = [](int i) { return "M" + std::to_string(i); };
    auto region = [](int i) { return "l" + std::to_string(i); };
    std::string f = "<>release(" + object(n) + "," + region(n) + ")";
    for (int i = n; i >= 1; --i) {
      if (i < n) f = "<>(release(" + object(i) + "," + region(i) + ") && " + f + ")";
      f = "<>(grasp(" + object(i) + ") && " + f + ")";
    }
    return f;
  }

  Scenario assemble() const {
    Scenario s;
    s.name = std::string("random_") + to_string(spec_.goal_class) + "_n" +
             std::to_string(spec_.objects) + "_s" + std::to_string(spec_.seed);
    s.source = "";
    s.workspace = rectangle(0, 0, spec_.width, spec_.height);
    s.robot.radius = spec_.robot_radius;
    s.robot.start = robot_start_;
    s.robot.heading = robot_heading_;
    s.robot.sensor_range = spec_.sensor_range;
    const double h = spec_.region_side / 2;
    for (int i = 0; i < spec_.objects; ++i) {
      const std::string k = std::to_string(i + 1);
      const Point& g = goals_[static_cast<std::size_t>(i)];
      s.regions.push_back(
          NamedPolygon{"l" + k, rectangle(g.x() - h, g.y() - h, g.x() + h, g.y() + h)});
      s.objects.push_back(Object{
          "M" + k, geometry::Disk{starts_[static_cast<std::size_t>(i)], spec_.object_radius}});
    }
    for (const Obstacle& o : obstacles_) {
      std::vector<NamedPolygon>& list = o.unknown ? s.unknown : s.familiar;
      const char* prefix = o.unknown ? "C" : "P";
      list.push_back(NamedPolygon{prefix + std::to_string(list.size() + 1), o.polygon});
    }
    s.task = task();
    s.simulation.time_budget = kBaseTimeBudget + kTimeBudgetPerObject * spec_.objects;

    const double density = area_ / (spec_.width * spec_.height);
    s.description = std::string("random instance: class ") + to_string(spec_.goal_class) +
                    ", N=" + std::to_string(spec_.objects) + ", density " + fixed3(density) +
                    " (target " + fixed3(spec_.obstacle_density) + "), seed " +
                    std::to_string(spec_.seed) + ", " + std::to_string(s.familiar.size()) +
                    " familiar and " + std::to_string(s.unknown.size()) + " unknown obstacles";
    if (stopped_) {
      s.description += "; obstacle placement stopped after " + std::to_string(spec_.max_attempts) +
                       " consecutive failed attempts";
    }

    try {
      validate(s);
    } catch (const ScenarioError& e) {
      REARM_DEMAND(false, describe(spec_) + " produced an invalid scenario: " + e.what());
    }
    return s;
  }

  const InstanceSpec& spec_;
  const Clearances c_;
  std::vector<Point> starts_, goals_;
  Point robot_start_ = Point::Zero();
  double robot_heading_ = 0;
  std::vector<Obstacle> obstacles_;
  double area_ = 0;
  bool stopped_ = false;
};

}  // namespace

const char* to_string(GoalClass c) {
  switch (c) {
    case GoalClass::kRandom:
      return "random";
    case GoalClass::kCyclic:
      return "cyclic";
  }
  REARM_DEMAND(false, "to_string: invalid GoalClass " + std::to_string(static_cast<int>(c)));
  return "";
}

GoalClass goal_class_from_string(std::string_view text) {
  for (const GoalClass c : {GoalClass::kRandom, GoalClass::kCyclic}) {
    if (text == to_string(c)) return c;
  }
  throw Error("goal class: unknown '" + std::string(text) + "' (expected 'random' or 'cyclic')");
}

Scenario random_instance(const InstanceSpec& spec) {
  check_spec(spec);
  return Generator(spec).run();
}

}  // namespace rearm::scenario
