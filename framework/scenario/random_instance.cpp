// generate_instance() of random_instance.h: rejection sampling of the Monte Carlo instances
// (classes random, cyclic and sealed). Placement order: the sealed pocket, object starts, goal
// points, robot start, parking spot, then obstacles, so that the obstacle density never makes a
// required placement impossible; an obstacle is accepted only when it keeps every clearance of
// the header and the pair raster's connectivity (pair_raster.h). Clearance tests are doubles
// (accept-or-retry decisions); polygon validity uses the exact predicates of
// geometry::validated, and the finished instance passes scenario::validate and the exact
// certificate of solvability.h.
#include "scenario/random_instance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/format.h"
#include "core/rng.h"
#include "geometry/boolean.h"
#include "geometry/box.h"
#include "geometry/convex.h"
#include "geometry/distance.h"
#include "geometry/polygon.h"
#include "geometry/proximity.h"
#include "scenario/coverage_grid.h"
#include "scenario/instance_layout.h"
#include "scenario/pair_raster.h"
#include "scenario/scenario_io.h"
#include "scenario/sealed_pocket.h"
#include "scenario/solvability.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;

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
// completed against 55/60 with 24 (the baseline comparison, N = 1..6). With semi-axes >=
// kMinObstacleSide / 2 every edge is >= 0.2 · 2 sin(π/48) = 0.026 m, five times Box2D's linear
// slop. Aspect ratio at most kMaxEllipseAspect keeps the curvature radius at the ends of the
// minor axis, a²/b, within 3.4 times the semi-major axis.
constexpr int kEllipseSides = 48;
constexpr double kMaxEllipseAspect = 1.5;
// Up to this many poses of a new obstacle that pass the cheap tests are drawn; the largest that
// keeps the raster certificate is kept (large obstacles reach a density with fewer raster
// checks). Clusters make the old preference of 30 unnecessary; 4 keeps generation fast.
constexpr int kCandidatesPerObstacle = 4;
// m: an overlap between two obstacles is accepted only this deep (a vertex of one lies this far
// inside the other), so clusters have no sliver-thin seams.
constexpr double kMinOverlapDepth = 0.05;
// m: a snapped obstacle is moved this far past contact into its neighbour (> kMinOverlapDepth,
// so that the overlap passes the depth test for most shapes).
constexpr double kSnapDepth = 0.15;
// Clipped familiar rectangles (touching the boundary): shortest edge (as hulls) and least area.
constexpr double kMinClippedArea = 0.1;  // m²
constexpr double kWallSnap = 1e-9;       // m: clipped vertices this close to a wall lie on it

// A new obstacle must add at least this share of its area to the union (measured on a coverage
// grid of kRasterCell cells): piling obstacles onto clusters would reach a density only with
// hundreds of them.
constexpr double kMinNewShare = 0.25;

constexpr double kObstacleObjectGap = 0.02;  // m: obstacle to blocker disk

// Raster of the pair freespace (pair_raster.h).
constexpr double kRasterCell = 0.05;  // m
constexpr std::size_t kMaxRasterCells = 250'000;

// Sealed pocket (random_instance.h, "Sealed pocket").
constexpr double kWallThickness = 0.2;  // m
constexpr double kMinStub = 0.1;        // m: front wall beside the mouth, at least
constexpr std::uint64_t kRedrawStreamStride = 100;

// Simulated seconds: a base plus a share per object (each needs a grasp, a carry, a release).
constexpr double kBaseTimeBudget = 600;
constexpr double kTimeBudgetPerObject = 300;

// Rng::derive streams (random_instance.h, "Determinism").
constexpr std::uint64_t kStartsStream = 1;
constexpr std::uint64_t kGoalsStream = 2;
constexpr std::uint64_t kRobotStream = 3;
constexpr std::uint64_t kObstaclesStream = 4;
constexpr std::uint64_t kPocketStream = 5;
constexpr std::uint64_t kParkingStream = 6;

std::string fixed3(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return Polygon{{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}};
}

using geometry::Box;
using geometry::closer_than;
using geometry::nearest_points;
using geometry::square_distance;
using geometry::vertex_depth;

struct Obstacle {
  Polygon polygon;
  Box box;
  bool unknown = false;
};

double wall_gap(const Polygon& p, double width, double height) {
  double gap = std::numeric_limits<double>::infinity();
  for (const Point& v : p.vertices) {
    gap = std::min({gap, v.x(), width - v.x(), v.y(), height - v.y()});
  }
  return gap;
}

// The candidate's relation to the walls: every wall either touched (gap 0) or >= w away.
bool boundary_rule(const Polygon& p, double width, double height, double w) {
  double gaps[4] = {
      std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
      std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const Point& v : p.vertices) {
    if (v.x() < 0 || v.x() > width || v.y() < 0 || v.y() > height) return false;
    gaps[0] = std::min(gaps[0], v.x());
    gaps[1] = std::min(gaps[1], width - v.x());
    gaps[2] = std::min(gaps[2], v.y());
    gaps[3] = std::min(gaps[3], height - v.y());
  }
  return std::all_of(std::begin(gaps), std::end(gaps), [&](double g) { return g == 0 || g >= w; });
}

// A convex polygon clipped to [0, width] x [0, height], vertices within kWallSnap of a wall
// moved onto it; empty when too small or with a too short edge.
Polygon clip_to_workspace(const Polygon& convex, double width, double height) {
  using geometry::HalfPlane;
  Polygon p = convex;
  for (const HalfPlane& h : {HalfPlane{Point(-1, 0), 0}, HalfPlane{Point(1, 0), width},
                             HalfPlane{Point(0, -1), 0}, HalfPlane{Point(0, 1), height}}) {
    p = geometry::clip(p, h);
    if (p.size() < 3) return Polygon{};
  }
  for (Point& v : p.vertices) {
    auto snap = [](double& c, double wall) {
      if (std::abs(c - wall) <= kWallSnap) c = wall;
    };
    snap(v.x(), 0), snap(v.x(), width), snap(v.y(), 0), snap(v.y(), height);
  }
  p = geometry::remove_collinear(p);
  if (p.size() < 3 || p.area() < kMinClippedArea) return Polygon{};
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    if ((p.vertices[(i + 1) % n] - p.vertices[i]).norm() < kMinHullEdge) return Polygon{};
  }
  return p;
}

// A required placement (a point, the robot start, the pocket) found no site.
class PlacementFailure : public Error {
 public:
  using Error::Error;
};

// The rules a Generator keeps (random_instance.h, "Crowded fallback").
enum class Rules { kStandard, kCrowded };

// Crowded fallback: lattice pitch d·(1 + kLatticeStretch), so that neighbouring sites keep the
// spacing d despite rounding (with pitch d a rounded difference can fall just below d and
// reject the neighbour).
constexpr double kLatticeStretch = 1e-9;

class Generator {
 public:
  Generator(const InstanceSpec& spec, int redraw, Rules rules)
      : spec_(spec),
        l_(layout(spec)),
        redraw_(redraw),
        rules_(rules),
        raster_(l_.width, l_.height, l_.pair, kRasterCell, kMaxRasterCells),
        coverage_(l_.width, l_.height, raster_.cell_side()) {}

  // The instance, or nullopt when the exact checks fail (the caller redraws).
  std::optional<GeneratedInstance> run() {
    if (spec_.goal_class == GoalClass::kSealed) place_pocket();
    if (l_.dense) place_parking();  // reserved before the crowd takes the room
    place_starts();
    place_goals();
    place_robot();
    if (!l_.dense) place_parking();
    build_targets();
    if (pocket_ && !commit_pocket()) return std::nullopt;
    place_obstacles();
    return assemble();
  }

 private:
  Rng stream(std::uint64_t s) const {
    return Rng::derive(spec_.seed, s + kRedrawStreamStride * static_cast<std::uint64_t>(redraw_));
  }

  [[noreturn]] void placement_failed(const std::string& what, const std::string& rule) const {
    throw PlacementFailure(
        describe(spec_) + ": could not place " + what + " in " +
        std::to_string(spec_.max_attempts) + " attempts (" + rule +
        "); use a larger workspace, fewer objects, a smaller footprint_density or a "
        "smaller region_side");
  }

  // Uniform in the inset workspace [m, width - m] x [m, height - m].
  Point inset_point(Rng& rng, double m) const {
    return Point(rng.uniform(m, l_.width - m), rng.uniform(m, l_.height - m));
  }

  bool spaced(const Point& p, const Point& q) const {
    if (!l_.dense) return (p - q).norm() >= l_.spacing;
    return std::max(std::abs(p.x() - q.x()), std::abs(p.y() - q.y())) >= l_.spacing;
  }

  bool spaced_from(const Point& p, const std::vector<Point>& list) const {
    return std::all_of(list.begin(), list.end(), [&](const Point& q) { return spaced(p, q); });
  }

  // Out of the sealed pocket's box and away from its blocker.
  bool clear_of_pocket(const Point& p, double clearance) const {
    if (!pocket_) return true;
    const Point local = pocket_->pose.inverse(p);
    const PocketFrame& f = pocket_->frame;
    const double e = clearance;
    const bool in_box = local.x() > -f.a - f.t - e && local.x() < f.a + f.t + e &&
                        local.y() > -f.t - e && local.y() < 2 * f.a + f.t + e;
    return !in_box && (p - pocket_->blocker).norm() >= pocket_->keepout;
  }

  bool point_ok(const Point& p, const std::vector<Point>& out,
                const std::vector<Point>& also) const {
    return spaced_from(p, out) && spaced_from(p, also) &&
           clear_of_pocket(p, crowded() ? l_.point_obstacle : l_.point_pocket);
  }

  // Dense fallback: the sites of a square lattice of pitch d over the inset workspace that keep
  // the rules, in random order (Fisher–Yates with rng.index), as many as needed.
  void lattice_points(Rng& rng, int n, std::vector<Point>& out,
                      const std::vector<Point>& also) const {
    const double m = l_.point_boundary;
    const double d = crowded() ? l_.spacing * (1 + kLatticeStretch) : l_.spacing;
    const int cols = static_cast<int>(std::floor((l_.width - 2 * m) / d)) + 1;
    const int rows = static_cast<int>(std::floor((l_.height - 2 * m) / d)) + 1;
    const Point offset((l_.width - (cols - 1) * d) / 2, (l_.height - (rows - 1) * d) / 2);
    std::vector<Point> sites;
    for (int iy = 0; iy < rows; ++iy) {
      for (int ix = 0; ix < cols; ++ix) {
        const Point p = offset + d * Point(ix, iy);
        if (point_ok(p, out, also)) sites.push_back(p);
      }
    }
    for (std::size_t i = sites.size(); i > 1; --i) {
      std::swap(sites[i - 1], sites[static_cast<std::size_t>(rng.index(i))]);
    }
    for (const Point& p : sites) {
      if (n == 0) return;
      if (point_ok(p, out, also)) out.push_back(p), --n;
    }
  }

  // n points spaced from `out` (appended) and from `also`, cb from the boundary, off the pocket;
  // in dense instances, when random draws cannot place them all, all n come from
  // lattice_points instead.
  void spaced_points(Rng& rng, int n, std::vector<Point>& out, const std::vector<Point>& also,
                     const std::string& what, int first_index) const {
    const std::size_t initial = out.size();
    for (int i = 0; i < n; ++i) {
      bool placed = false;
      for (int attempt = 0; attempt < spec_.max_attempts && !placed; ++attempt) {
        const Point p = inset_point(rng, l_.point_boundary);
        placed = point_ok(p, out, also);
        if (placed) out.push_back(p);
      }
      if (placed) continue;
      if (l_.dense) {  // start over on the lattice
        out.resize(initial);
        lattice_points(rng, n, out, also);
        if (out.size() == initial + static_cast<std::size_t>(n)) return;
      }
      placement_failed(what + " " + std::to_string(first_index + i),
                       "points keep a spacing >= " + shortest_decimal(l_.spacing) +
                           (l_.dense ? " m (Chebyshev)" : " m") + " and >= " +
                           shortest_decimal(l_.point_boundary) + " m from the boundary");
    }
  }

  void place_starts() {
    Rng rng = stream(kStartsStream);
    spaced_points(rng, spec_.objects, starts_, reserved(), "the start of object M", 1);
  }

  void place_goals() {
    if (spec_.goal_class == GoalClass::kCyclic) {
      const std::size_t n = starts_.size();
      for (std::size_t i = 0; i < n; ++i) goals_.push_back(starts_[(i + 1) % n]);
      return;
    }
    Rng rng = stream(kGoalsStream);
    int n = spec_.objects;
    if (pocket_) {
      goals_.push_back(pocket_->goal);
      --n;
    }
    spaced_points(rng, n, goals_, reserved(), "the goal of object M", spec_.objects - n + 1);
  }

  // The parking spot keeps the points' spacing from every start and goal: drawn after them
  // (sparse) or before them, which then keep clear of it (dense: in a crowded room the starts
  // and goals would leave no site for it).
  void place_parking() {
    Rng rng = stream(kParkingStream);
    std::vector<Point> all = starts_;
    all.insert(all.end(), goals_.begin(), goals_.end());
    std::vector<Point> spot;
    spaced_points(rng, 1, spot, all, "the parking spot", 1);
    parking_ = spot.front();
  }

  std::vector<Point> reserved() const {
    return parking_ ? std::vector<Point>{*parking_} : std::vector<Point>{};
  }

  // The robot start: clear of the boundary (the pair's raster needs it), every object start
  // and every region, off the pocket.
  double robot_clearance() const { return l_.pair + 2 * raster_.margin(); }

  void place_robot() {
    Rng rng = stream(kRobotStream);
    for (int attempt = 0; attempt < spec_.max_attempts; ++attempt) {
      const Point p = inset_point(rng, std::max(robot_clearance(), spec_.robot_radius));
      const bool clear_of_objects =
          std::all_of(starts_.begin(), starts_.end(),
                      [&](const Point& q) { return (p - q).norm() >= l_.robot_object; });
      const bool clear_of_regions =
          crowded() || std::all_of(goals_.begin(), goals_.end(), [&](const Point& g) {
            return square_distance(g, l_.region_side, p) >= spec_.robot_radius;
          });
      if (clear_of_objects && clear_of_regions && clear_of_pocket(p, l_.grasp)) {
        robot_start_ = p;
        robot_heading_ = rng.uniform(-std::numbers::pi, std::numbers::pi);
        return;
      }
    }
    placement_failed("the robot start",
                     "it keeps >= " + shortest_decimal(robot_clearance()) +
                         " m from the boundary, >= " + shortest_decimal(l_.robot_object) +
                         " m from every object start and out of every region");
  }

  // The pocket frame for this spec: interior half-side a, walls t, mouth m (>= what the
  // raster can certify, pair_raster.h).
  PocketFrame pocket_frame() const {
    PocketFrame f;
    f.t = kWallThickness;
    f.m = std::max(l_.passage, 2 * (l_.pair + raster_.margin()) + 2 * raster_.cell_side());
    f.a = std::max(
        {l_.grasp, l_.region_side / std::numbers::sqrt2 + kPlacementSlack, f.m / 2 + kMinStub});
    return f;
  }

  // The pocket at pose k.pose when its walls keep the rule `walls_ok` and B1 has room to be
  // grasped from outside (>= cg + r from the boundary).
  template <class WallRule>
  bool try_pocket(Pocket& k, WallRule walls_ok) {
    if (!walls_ok(snapped(k.pose.apply(k.frame.walls())))) return false;
    k.blocker = k.pose.apply(k.frame.blocker());
    const double room = l_.grasp + spec_.robot_radius;
    const Point& b = k.blocker;
    if (b.x() < room || b.x() > l_.width - room || b.y() < room || b.y() > l_.height - room) {
      return false;
    }
    k.goal = k.pose.apply(k.frame.goal());
    k.mouth = k.pose.apply(k.frame.mouth());
    k.outward = Point(-k.pose.sn, k.pose.cs);
    k.keepout = crowded() ? l_.spacing : 2 * spec_.object_radius + 2 * l_.pair + kDenseRegionGap;
    pocket_ = k;
    return true;
  }

  // Vertices within kWallSnap of a wall moved onto it (a pocket flush with a wall).
  Polygon snapped(Polygon p) const {
    for (Point& v : p.vertices) {
      for (const auto& [c, wall] : {std::pair<double*, double>{&v.x(), 0.0},
                                    {&v.x(), l_.width},
                                    {&v.y(), 0.0},
                                    {&v.y(), l_.height}}) {
        if (std::abs(*c - wall) <= kWallSnap) *c = wall;
      }
    }
    return p;
  }

  // Fallback when no free pose fits (small rooms, random_instance.h "Sealed pocket"): the back
  // wall flush with a room wall, the mouth facing the room; along the wall the pocket touches a
  // corner or keeps >= w from the side walls (the familiar obstacles' boundary rule).
  bool place_pocket_on_wall(Rng& rng, Pocket& k) {
    const double half = k.frame.a + k.frame.t;
    auto rule = [&](const Polygon& walls) {
      return boundary_rule(walls, l_.width, l_.height, l_.passage);
    };
    for (int attempt = 0; attempt < spec_.max_attempts; ++attempt) {
      const int wall = static_cast<int>(rng.index(4));  // bottom, right, top, left
      const double along = (wall % 2 == 0) ? l_.width : l_.height;
      if (along < 2 * half) continue;
      double u = rng.uniform(half, along - half);  // the pocket's axis along the wall
      if (u - half < l_.passage) u = half;         // touch the corner
      if (along - u - half < l_.passage) u = along - half;
      static constexpr double kCos[4] = {1, 0, -1, 0}, kSin[4] = {0, 1, 0, -1};
      const double t = k.frame.t;
      const Point origin[4] = {Point(u, t), Point(l_.width - t, u), Point(u, l_.height - t),
                               Point(t, u)};
      k.pose = Pose{origin[wall], kCos[wall], kSin[wall]};
      if (try_pocket(k, rule)) return true;
    }
    return false;
  }

  void place_pocket() {
    Rng rng = stream(kPocketStream);
    Pocket k;
    k.frame = pocket_frame();
    auto inside = [&](const Polygon& walls) {
      return std::all_of(walls.vertices.begin(), walls.vertices.end(), [&](auto& v) {
        return v.x() >= l_.passage && v.x() <= l_.width - l_.passage && v.y() >= l_.passage &&
               v.y() <= l_.height - l_.passage;
      });
    };
    for (int attempt = 0; attempt < spec_.max_attempts; ++attempt) {
      const double angle = rng.uniform(0, 2 * std::numbers::pi);
      k.pose = Pose{inset_point(rng, 0), std::cos(angle), std::sin(angle)};
      if (try_pocket(k, inside)) return;
    }
    if (crowded() && place_pocket_on_wall(rng, k)) return;
    placement_failed("the sealed pocket", "its walls keep >= " + shortest_decimal(l_.passage) +
                                              " m from the boundary" +
                                              (crowded() ? ", or lie flush with a wall" : ""));
  }

  // Raster targets (random_instance.h, "Solvability"): the grasp positions of every start,
  // goal and the parking spot, and the blocker's outward one.
  std::vector<int> grasp_cells(const Point& p) const {
    std::vector<int> out;
    for (int k = 0; k < kGraspDirections; ++k) {
      const double a = 2 * std::numbers::pi * k / kGraspDirections;
      out.push_back(raster_.cell_of(p + (spec_.robot_radius + kGripOffset) *
                                            Point(std::cos(a), std::sin(a))));
    }
    return out;
  }

  void build_targets() {
    for (const Point& p : starts_) targets_.push_back(grasp_cells(p));
    for (const Point& p : goals_) targets_.push_back(grasp_cells(p));
    targets_.push_back(grasp_cells(*parking_));
    if (pocket_) {
      targets_.push_back({raster_.cell_of(pocket_->blocker +
                                          (spec_.robot_radius + kGripOffset) * pocket_->outward)});
    }
    source_ = raster_.cell_of(robot_start_);
  }

  // The pocket as the first familiar obstacle; false when it cuts a point off in the raster.
  bool commit_pocket() {
    Obstacle o;
    o.polygon = snapped(pocket_->pose.apply(pocket_->frame.walls()));
    o.box = geometry::box_of(o.polygon);
    const std::vector<int> cells = raster_.newly_blocked(o.polygon);
    if (!raster_.connects(source_, targets_, cells)) return false;
    raster_.block(cells);
    covered_ += o.polygon.area();
    coverage_.fresh(o.polygon, true);
    obstacles_.push_back(std::move(o));
    return true;
  }

  // A familiar shape (a rectangle or an L, possibly non-convex) or an unknown one (an ellipse,
  // or with round_unknown off a rectangle or the hull of random points in a disk, convex),
  // centred near the origin, before rotation. Empty when a hull came
  // out a sliver or with a very short edge.
  Polygon sample_shape(Rng& rng, bool unknown) const {
    const double max_side = spec_.max_obstacle_side;
    if (unknown && spec_.round_unknown) {
      const double a = rng.uniform(kMinObstacleSide, max_side) / 2;
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
      const double a = rng.uniform(kMinObstacleSide, max_side);
      const double b = rng.uniform(kMinObstacleSide, max_side);
      return rectangle(-a / 2, -b / 2, a / 2, b / 2);
    }
    if (!unknown) {
      // An L: a x b bounding box, arms of thickness t, each arm at least kMinObstacleSide long
      // beyond the corner square.
      const double a = rng.uniform(2 * kMinObstacleSide, max_side);
      const double b = rng.uniform(2 * kMinObstacleSide, max_side);
      const double t = rng.uniform(kMinObstacleSide, std::min(a, b) - kMinObstacleSide);
      const Point o(-a / 2, -b / 2);
      return Polygon{
          {o, o + Point(a, 0), o + Point(a, t), o + Point(t, t), o + Point(t, b), o + Point(0, b)}};
    }
    const double radius = rng.uniform(kMinObstacleSide, max_side) / 2;
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

  // The shape rotated by a random angle and moved to a random point of the workspace; a
  // familiar rectangle that crosses the boundary is clipped to it (random_instance.h).
  Obstacle sample_obstacle(Rng& rng, bool unknown) const {
    Obstacle o;
    o.unknown = unknown;
    o.polygon = sample_shape(rng, unknown);
    const double angle = rng.uniform(0, 2 * std::numbers::pi);
    const Pose pose{inset_point(rng, 0), std::cos(angle), std::sin(angle)};
    if (o.polygon.size() < 3) return o;
    o.polygon = pose.apply(o.polygon);
    const bool crosses =
        std::any_of(o.polygon.vertices.begin(), o.polygon.vertices.end(), [&](const Point& v) {
          return v.x() < 0 || v.x() > l_.width || v.y() < 0 || v.y() > l_.height;
        });
    if (crosses && !unknown && o.polygon.size() == 4) {  // a familiar rectangle
      o.polygon = clip_to_workspace(o.polygon, l_.width, l_.height);
    }
    if (o.polygon.size() >= 3) o.box = geometry::box_of(o.polygon);
    return o;
  }

  void translate(Obstacle& o, const Point& v) const {
    for (Point& x : o.polygon.vertices) x += v;
    o.polygon = snapped(std::move(o.polygon));
    o.box = geometry::box_of(o.polygon);
  }

  // Snapping (random_instance.h, "Clusters and passages"): a familiar obstacle less than w
  // from a wall is moved onto it, an unknown one away to w; then an obstacle less than w from
  // another (and not overlapping it) is moved into it by the gap plus kSnapDepth.
  void snap(Obstacle& o) const {
    if (o.polygon.size() < 3) return;
    const double w = l_.passage;
    const double gx0 = o.box.lo.x(), gx1 = l_.width - o.box.hi.x();
    const double gy0 = o.box.lo.y(), gy1 = l_.height - o.box.hi.y();
    Point v = Point::Zero();
    auto axis = [&](double lo, double hi, double& out) {
      if (lo > 0 && lo < w) out = o.unknown ? w - lo + kPlacementSlack : -lo;
      if (hi > 0 && hi < w) out = o.unknown ? -(w - hi + kPlacementSlack) : hi;
    };
    axis(gx0, gx1, v.x());
    axis(gy0, gy1, v.y());
    if (v != Point::Zero()) translate(o, v);
    for (const Obstacle& q : obstacles_) {
      if (geometry::gap(o.box, q.box) >= w || !closer_than(o.polygon, q.polygon, w)) continue;
      if (geometry::contains(q.polygon, o.polygon.vertices.front()) ||
          geometry::contains(o.polygon, q.polygon.vertices.front())) {
        return;
      }
      const auto [a, b] = nearest_points(o.polygon, q.polygon);
      const double gap = (b - a).norm();
      if (gap <= 0) return;  // touching or crossing: left to acceptable()
      translate(o, (b - a) * ((gap + kSnapDepth) / gap));
      return;
    }
  }

  // The clearances of the header (everything but the raster), then exact validity.
  bool acceptable(const Obstacle& o) const {
    const Polygon& p = o.polygon;
    if (p.size() < 3 || !boundary_rule(p, l_.width, l_.height, l_.passage)) return false;
    if (o.unknown && wall_gap(p, l_.width, l_.height) < l_.passage) return false;  // no touch
    auto clear_of_point = [&](const Point& x, double clearance) {
      return geometry::gap(o.box, x) >= clearance || geometry::signed_distance(p, x) >= clearance;
    };
    for (const std::vector<Point>* list : {&starts_, &goals_}) {
      for (const Point& x : *list) {
        if (!clear_of_point(x, l_.point_obstacle)) return false;
      }
    }
    if (!clear_of_point(*parking_, l_.point_obstacle)) return false;
    if (!clear_of_point(robot_start_, l_.grasp)) return false;
    if (pocket_ && !clear_of_point(pocket_->blocker, spec_.object_radius + kObstacleObjectGap)) {
      return false;
    }
    for (const Obstacle& q : obstacles_) {
      if (geometry::gap(o.box, q.box) >= l_.passage) continue;
      const bool deep = vertex_depth(p, q.polygon, q.box) >= kMinOverlapDepth ||
                        vertex_depth(q.polygon, p, o.box) >= kMinOverlapDepth;
      if (!deep && closer_than(p, q.polygon, l_.passage)) return false;
    }
    const Outcome<Polygon> valid = geometry::checked_polygon(p, "obstacle");
    if (!valid || valid->vertices != p.vertices) return false;
    return !o.unknown || p.is_convex();
  }

  // Up to kCandidatesPerObstacle poses that pass acceptable() and add at least kMinNewShare
  // of their area to the union (coverage grid), largest addition first.
  std::vector<Obstacle> candidates(Rng& rng, bool unknown, double room, int& attempts) {
    std::vector<std::pair<double, Obstacle>> found;
    for (; attempts < spec_.max_attempts &&
           found.size() < static_cast<std::size_t>(kCandidatesPerObstacle);
         ++attempts) {
      Obstacle o = sample_obstacle(rng, unknown);
      snap(o);
      if (!acceptable(o)) continue;
      const double fresh =
          static_cast<double>(coverage_.fresh(o.polygon, false)) * coverage_.cell_area();
      // The grid's estimate errs by at most the cells along the boundary of o's box.
      const Point size = o.box.hi - o.box.lo;
      const double grid_error = 2 * (size.x() + size.y()) * coverage_.cell_side();
      if (fresh < kMinNewShare * o.polygon.area() || fresh > room + grid_error) continue;
      found.emplace_back(fresh, std::move(o));
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<Obstacle> out;
    for (auto& f : found) out.push_back(std::move(f.second));
    return out;
  }

  // The area o adds to the union of the obstacles: its own minus its exact overlap (Boolean
  // intersection with the union of the obstacles whose boxes meet its box).
  double new_area(const Obstacle& o) const {
    std::vector<Polygon> near;
    for (const Obstacle& q : obstacles_) {
      if (geometry::gap(o.box, q.box) == 0) near.push_back(q.polygon);
    }
    if (near.empty()) return o.polygon.area();
    const geometry::RegionSet overlap =
        geometry::intersect(geometry::to_set(o.polygon), geometry::unite_all(near));
    return o.polygon.area() - geometry::total_area(overlap);
  }

  // One obstacle after another until the union's area (kept exactly, new_area) reaches the
  // target density; an obstacle that would take it past target + kDensityTolerance is
  // rejected (in a small room one large obstacle would overshoot by more than the tolerance);
  // max_attempts consecutive failed draws end it.
  void place_obstacles() {
    Rng rng = stream(kObstaclesStream);
    const double workspace_area = l_.width * l_.height;
    const double cap = (spec_.obstacle_density + kDensityTolerance) * workspace_area;
    int attempts = 0;
    while (covered_ / workspace_area < spec_.obstacle_density) {
      const bool unknown = rng.bernoulli(spec_.unknown_fraction);
      bool placed = false;
      while (!placed && attempts < spec_.max_attempts) {
        for (Obstacle& o : candidates(rng, unknown, cap - covered_, attempts)) {
          const double added = new_area(o);
          if (covered_ + added > cap) continue;
          const std::vector<int> cells = raster_.newly_blocked(o.polygon);
          if (!raster_.connects(source_, targets_, cells)) continue;
          raster_.block(cells);
          covered_ += added;
          coverage_.fresh(o.polygon, true);
          obstacles_.push_back(std::move(o));
          placed = true;
          break;
        }
      }
      if (!placed) {
        stopped_ = true;
        return;
      }
      attempts = 0;
    }
  }

  std::string task() const {
    const int n = spec_.objects;
    auto object = [](int i) { return "M" + std::to_string(i); };
    auto region = [](int i) { return "l" + std::to_string(i); };
    if (spec_.goal_order == GoalOrder::kAny) {
      std::string f;
      for (int i = 1; i <= n; ++i) {
        f += (i > 1 ? " && " : "") + std::string("<>release(") + object(i) + "," + region(i) + ")";
      }
      return f;
    }
    // Formula (1) of the paper extended to N objects (as fig5): innermost release first.
    std::string f = "<>release(" + object(n) + "," + region(n) + ")";
    for (int i = n; i >= 1; --i) {
      if (i < n) f = "<>(release(" + object(i) + "," + region(i) + ") && " + f + ")";
      f = "<>(grasp(" + object(i) + ") && " + f + ")";
    }
    return f;
  }

  Scenario scenario() const {
    Scenario s;
    s.name = std::string("random_") + to_string(spec_.goal_class) + "_n" +
             std::to_string(spec_.objects) + "_s" + std::to_string(spec_.seed) +
             (spec_.goal_order == GoalOrder::kAny ? "_any" : "");
    s.source = "";
    s.workspace = rectangle(0, 0, l_.width, l_.height);
    s.robot.radius = spec_.robot_radius;
    s.robot.start = robot_start_;
    s.robot.heading = robot_heading_;
    s.robot.sensor_range = spec_.sensor_range;
    const double h = l_.region_side / 2;
    for (int i = 0; i < spec_.objects; ++i) {
      const std::string k = std::to_string(i + 1);
      const Point& g = goals_[static_cast<std::size_t>(i)];
      s.regions.push_back(
          NamedPolygon{"l" + k, rectangle(g.x() - h, g.y() - h, g.x() + h, g.y() + h)});
      s.objects.push_back(Object{
          "M" + k, geometry::Disk{starts_[static_cast<std::size_t>(i)], spec_.object_radius}});
    }
    if (pocket_) {
      s.objects.push_back(Object{"B1", geometry::Disk{pocket_->blocker, spec_.object_radius}});
    }
    for (const Obstacle& o : obstacles_) {
      std::vector<NamedPolygon>& list = o.unknown ? s.unknown : s.familiar;
      const char* prefix = o.unknown ? "C" : "P";
      list.push_back(NamedPolygon{prefix + std::to_string(list.size() + 1), o.polygon});
    }
    s.task = task();
    s.simulation.time_budget = kBaseTimeBudget + kTimeBudgetPerObject * spec_.objects;
    return s;
  }

  double covered_area() const {
    std::vector<Polygon> all;
    for (const Obstacle& o : obstacles_) all.push_back(o.polygon);
    return all.empty() ? 0 : geometry::total_area(geometry::unite_all(all));
  }

  std::string description(const GeneratedInstance& g, std::size_t familiar,
                          std::size_t unknown) const {
    std::string d = std::string("random instance: class ") + to_string(spec_.goal_class) +
                    ", N=" + std::to_string(spec_.objects) + ", density " +
                    fixed3(g.achieved_density) + " (target " + fixed3(spec_.obstacle_density) +
                    "), footprint " + fixed3(g.footprint_density) + ", seed " +
                    std::to_string(spec_.seed) + ", " + std::to_string(familiar) +
                    " familiar and " + std::to_string(unknown) + " unknown obstacles";
    if (g.dense) d += "; dense spacing (region side " + fixed3(g.region_side) + ")";
    if (pocket_) d += "; goal l1 sealed in pocket " + g.pocket.walls + " behind B1";
    if (crowded()) d += "; crowded fallback rules";
    if (stopped_) {
      d += "; obstacle placement stopped after " + std::to_string(spec_.max_attempts) +
           " consecutive failed attempts";
    }
    return d;
  }

  std::optional<GeneratedInstance> assemble() const {
    GeneratedInstance g;
    g.scenario = scenario();
    const double area = l_.width * l_.height;
    g.achieved_density = covered_area() / area;
    g.footprint_density = footprint_area(spec_) / area;
    g.density_reached = std::abs(g.achieved_density - spec_.obstacle_density) <= kDensityTolerance;
    g.dense = l_.dense;
    g.region_side = l_.region_side;
    g.point_spacing = l_.spacing;
    g.redraws = redraw_;
    g.crowded_rules = crowded();
    g.goals = goals_;
    if (pocket_) {
      g.pocket.present = true;
      g.pocket.walls = g.scenario.familiar.front().name;
      g.pocket.goal = pocket_->goal;
      g.pocket.blocker = pocket_->blocker;
      g.pocket.mouth = pocket_->mouth;
    }
    g.scenario.description = description(g, g.scenario.familiar.size(), g.scenario.unknown.size());
    try {
      validate(g.scenario);
    } catch (const ScenarioError& e) {
      REARM_DEMAND(false, describe(spec_) + " produced an invalid scenario: " + e.what());
    }
    g.solvability = check_solvability(g.scenario);
    if (!g.solvability.solvable) return std::nullopt;
    if (pocket_) {
      g.pocket.seal = check_seal(g.scenario, 0, g.scenario.objects.size() - 1, pocket_->goal);
      if (!g.pocket.seal.failure.empty()) return std::nullopt;
    }
    return g;
  }

  bool crowded() const { return rules_ == Rules::kCrowded; }

  const InstanceSpec& spec_;
  const Layout l_;
  const int redraw_;
  const Rules rules_;
  PairRaster raster_;
  CoverageGrid coverage_;
  std::optional<Pocket> pocket_;
  std::vector<Point> starts_, goals_;
  std::optional<Point> parking_;  // placed before the starts (dense) or after the goals
  Point robot_start_ = Point::Zero();
  double robot_heading_ = 0;
  std::vector<std::vector<int>> targets_;
  int source_ = -1;
  std::vector<Obstacle> obstacles_;
  double covered_ = 0;
  bool stopped_ = false;
};

}  // namespace

const char* to_string(GoalClass c) {
  switch (c) {
    case GoalClass::kRandom:
      return "random";
    case GoalClass::kCyclic:
      return "cyclic";
    case GoalClass::kSealed:
      return "sealed";
    case GoalClass::kConstructive:
      return "constructive";
  }
  REARM_DEMAND(false, "to_string: invalid GoalClass " + std::to_string(static_cast<int>(c)));
  return "";
}

GoalClass goal_class_from_string(std::string_view text) {
  for (const GoalClass c :
       {GoalClass::kRandom, GoalClass::kCyclic, GoalClass::kSealed, GoalClass::kConstructive}) {
    if (text == to_string(c)) return c;
  }
  throw Error("goal class: unknown '" + std::string(text) +
              "' (expected 'random', 'cyclic', 'sealed' or 'constructive')");
}

const char* to_string(GoalOrder o) { return o == GoalOrder::kAny ? "any" : "chain"; }

GoalOrder goal_order_from_string(std::string_view text) {
  for (const GoalOrder o : {GoalOrder::kChain, GoalOrder::kAny}) {
    if (text == to_string(o)) return o;
  }
  throw Error("goal order: unknown '" + std::string(text) + "' (expected 'chain' or 'any')");
}

namespace {

GeneratedInstance generate_with(const InstanceSpec& spec, Rules rules) {
  // A draw that misses the target density (|achieved - target| > kDensityTolerance) is redrawn
  // too; after the last draw the closest solvable one is returned with density_reached false.
  std::optional<GeneratedInstance> best;
  for (int redraw = 0; redraw <= kMaxRedraws; ++redraw) {
    std::optional<GeneratedInstance> g = Generator(spec, redraw, rules).run();
    if (!g) continue;
    if (g->density_reached) return std::move(*g);
    const double miss = std::abs(g->achieved_density - spec.obstacle_density);
    if (!best || miss < std::abs(best->achieved_density - spec.obstacle_density))
      best = std::move(g);
  }
  if (best) return std::move(*best);
  throw Error(describe(spec) + ": the exact solvability check failed on " +
              std::to_string(kMaxRedraws + 1) +
              " draws; use a lower obstacle_density or a larger workspace");
}

}  // namespace

// The standard rules first; only a spec they cannot place is drawn again under the crowded
// fallback (random_instance.h), so every instance the standard rules place stays bit for bit.
GeneratedInstance generate_instance(const InstanceSpec& spec) {
  if (spec.goal_class == GoalClass::kConstructive) {
    throw Error(describe(spec) +
                ": class constructive scatters its objects with the baselines' move planner "
                "(baselines::constructive_instance, baselines/constructive.h), which sweeps do "
                "not call yet");
  }
  return generate_room(spec);
}

GeneratedInstance generate_room(const InstanceSpec& spec) {
  check_spec(spec);
  std::string standard;
  try {
    return generate_with(spec, Rules::kStandard);
  } catch (const PlacementFailure& e) {
    standard = e.what();
  }
  try {
    return generate_with(spec, Rules::kCrowded);
  } catch (const PlacementFailure& e) {
    const std::string prefix = describe(spec) + ": ";
    std::string crowded = e.what();
    if (crowded.rfind(prefix, 0) == 0) crowded.erase(0, prefix.size());
    throw Error(standard + "; under the crowded fallback rules too: " + crowded);
  }
}

Scenario random_instance(const InstanceSpec& spec) { return generate_instance(spec).scenario; }

}  // namespace rearm::scenario
