#include "support/reactive_scenes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"
#include "support/geometry_oracle.h"

namespace rearm::test_support {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;
using geometry::RegionSet;

namespace {

// Sides of the circumscribed polygons standing for disks in the exact placement checks.
// Rejection-sampling budget of the free-point draws.
constexpr int kFreePointAttempts = 100000;
// A clipped boundary-touching obstacle keeps at least this fraction of its area.
constexpr double kMinClippedFraction = 0.4;

Polygon translated_rotated(const Polygon& local, double angle, const Point& pivot,
                           const Point& center) {
  const double c = std::cos(angle), s = std::sin(angle);
  Polygon out;
  out.vertices.reserve(local.size());
  for (const Point& v : local.vertices) {
    const Point d = v - pivot;
    out.vertices.emplace_back(center.x() + c * d.x() - s * d.y(),
                              center.y() + s * d.x() + c * d.y());
  }
  return out;
}

// An obstacle being placed: its exact separation set (the obstacle dilated by r + margin/2)
// and a bounding circle of that set for a quick far-apart test.
struct Footprint {
  RegionSet set;
  Point center = Point::Zero();
  double radius = 0;
};

Footprint footprint(RegionSet set) {
  Footprint f;
  f.set = std::move(set);
  Eigen::AlignedBox2d box;
  for (const auto& r : f.set) {
    for (const Point& v : r.outer.vertices) box.extend(v);
  }
  f.center = box.center();
  for (const auto& r : f.set) {
    for (const Point& v : r.outer.vertices) f.radius = std::max(f.radius, (v - f.center).norm());
  }
  return f;
}

bool separated(const Footprint& f, const std::vector<Footprint>& placed) {
  for (const Footprint& g : placed) {
    if ((f.center - g.center).norm() > f.radius + g.radius) continue;
    if (geometry::intersects(f.set, g.set)) return false;
  }
  return true;
}

bool single_simple_region(const RegionSet& s) { return s.size() == 1 && s[0].holes.empty(); }

void check_options(const SceneOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0) {
      throw Error(std::string("SceneOptions: ") + name + " must be finite and > 0");
    }
  };
  positive(o.workspace_size, "workspace_size");
  positive(o.robot_radius, "robot_radius");
  positive(o.sensor_range, "sensor_range");
  positive(o.familiar_min_size, "familiar_min_size");
  positive(o.thickness_fraction_min, "thickness_fraction_min");
  positive(o.unknown_min_radius, "unknown_min_radius");
  positive(o.movable_min_radius, "movable_min_radius");
  positive(o.goal_clearance, "goal_clearance");
  if (!std::isfinite(o.margin) || o.margin < 0) {
    throw Error("SceneOptions: margin must be finite and >= 0");
  }
  if (!(o.familiar_max_size >= o.familiar_min_size) ||
      !(o.unknown_max_radius >= o.unknown_min_radius) ||
      !(o.movable_max_radius >= o.movable_min_radius) ||
      !(o.thickness_fraction_max >= o.thickness_fraction_min) ||
      !std::isfinite(o.familiar_max_size) || !std::isfinite(o.unknown_max_radius) ||
      !std::isfinite(o.movable_max_radius)) {
    throw Error("SceneOptions: a maximum is below its minimum or not finite");
  }
  if (o.thickness_fraction_max >= 0.5) {
    throw Error("SceneOptions: thickness_fraction_max must be < 0.5");
  }
  if (o.familiar < 0 || o.unknown < 0 || o.movable < 0 || o.boundary_touching < 0 ||
      o.boundary_touching > o.familiar) {
    throw Error("SceneOptions: counts must be >= 0 and boundary_touching <= familiar");
  }
  if (o.familiar > 0 && o.shapes.empty()) throw Error("SceneOptions: no familiar shape allowed");
  if (o.max_attempts <= 0 || o.max_restarts <= 0) {
    throw Error("SceneOptions: max_attempts and max_restarts must be > 0");
  }
}

Point uniform_in(Rng& rng, const Eigen::AlignedBox2d& box) {
  const double x = rng.uniform(box.min().x(), box.max().x());
  const double y = rng.uniform(box.min().y(), box.max().y());
  return {x, y};
}

Eigen::AlignedBox2d bounds(const Polygon& p) {
  Eigen::AlignedBox2d box;
  for (const Point& v : p.vertices) box.extend(v);
  return box;
}

// One obstacle could not be placed: random_scene starts the scene over.
}  // namespace

reactive::SemanticInput to_semantic_input(const ReactiveScene& s) {
  reactive::SemanticInput in;
  in.workspace = s.workspace;
  in.familiar = s.familiar;
  in.unknown = s.unknown;
  in.movable = s.movable;
  return in;
}

const char* to_string(Shape s) {
  switch (s) {
    case Shape::kL:
      return "L";
    case Shape::kU:
      return "U";
    case Shape::kT:
      return "T";
    case Shape::kStaircase:
      return "staircase";
    case Shape::kCross:
      return "cross";
    case Shape::kStar:
      return "star";
  }
  return "?";
}

Polygon make_shape(Rng& rng, Shape shape, double s, double w, double angle, const Point& center) {
  if (!std::isfinite(s) || s <= 0 || !std::isfinite(angle) || !center.allFinite()) {
    throw Error("make_shape: size must be finite and > 0, angle and centre finite");
  }
  const bool halves = shape == Shape::kU || shape == Shape::kCross;
  if (shape != Shape::kStar && shape != Shape::kStaircase &&
      (!std::isfinite(w) || w <= 0 || w >= (halves ? s / 2 : s))) {
    throw Error(std::string("make_shape: thickness out of range for shape ") + to_string(shape));
  }
  Polygon p;
  auto& v = p.vertices;
  switch (shape) {
    case Shape::kL:
      v = {{0, 0}, {s, 0}, {s, w}, {w, w}, {w, s}, {0, s}};
      break;
    case Shape::kU:
      v = {{0, 0}, {s, 0}, {s, s}, {s - w, s}, {s - w, w}, {w, w}, {w, s}, {0, s}};
      break;
    case Shape::kT: {
      const double a = (s - w) / 2, b = (s + w) / 2;
      v = {{a, 0}, {b, 0}, {b, s - w}, {s, s - w}, {s, s}, {0, s}, {0, s - w}, {a, s - w}};
      break;
    }
    case Shape::kStaircase: {
      const double a = s / 3;
      v = {{0, 0}, {s, 0}, {s, a}, {2 * a, a}, {2 * a, 2 * a}, {a, 2 * a}, {a, s}, {0, s}};
      break;
    }
    case Shape::kCross: {
      const double a = (s - w) / 2, b = (s + w) / 2;
      v = {{a, 0}, {b, 0}, {b, a}, {s, a}, {s, b}, {b, b},
           {b, s}, {a, s}, {a, b}, {0, b}, {0, a}, {a, a}};
      break;
    }
    case Shape::kStar: {
      const int n = static_cast<int>(rng.uniform_int(5, 9));
      const Polygon star = random_star(rng, n, 0.25 * s, 0.5 * s);
      return translated_rotated(star, angle, Point::Zero(), center);
    }
  }
  return translated_rotated(p, angle, Point(s / 2, s / 2), center);
}

// Sides of a "round" unknown obstacle (SceneOptions::round_unknown).
constexpr int kRoundSides = 48;

Polygon random_convex(Rng& rng, const Point& center, double radius) {
  if (!std::isfinite(radius) || radius <= 0 || !center.allFinite()) {
    throw Error("random_convex: radius must be finite and > 0, centre finite");
  }
  const double two_pi = 2 * std::numbers::pi;
  std::vector<Point> pts;
  if (rng.bernoulli(0.5)) {
    // Hull of points at sorted random angles; at least one per third of the circle so the
    // hull is never a thin sliver.
    const int n = static_cast<int>(rng.uniform_int(5, 9));
    const double phase = rng.uniform(0, two_pi);
    for (int k = 0; k < n; ++k) {
      const double a = phase + two_pi * (k + rng.uniform(0.1, 0.9)) / n;
      const double rho = radius * rng.uniform(0.6, 1.0);
      pts.push_back(center + rho * Point(std::cos(a), std::sin(a)));
    }
  } else {
    const int n = static_cast<int>(rng.uniform_int(3, 8));
    const double phase = rng.uniform(0, two_pi);
    for (int k = 0; k < n; ++k) {
      const double a = phase + two_pi * (k + rng.uniform(-0.15, 0.15)) / n;
      const double rho = radius * rng.uniform(0.85, 1.0);
      pts.push_back(center + rho * Point(std::cos(a), std::sin(a)));
    }
  }
  return geometry::convex_hull(std::move(pts));
}

Polygon make_workspace(WorkspaceShape shape, double s) {
  if (!std::isfinite(s) || s <= 0) throw Error("make_workspace: size must be finite and > 0");
  Polygon w;
  switch (shape) {
    case WorkspaceShape::kSquare:
      w.vertices = {{0, 0}, {s, 0}, {s, s}, {0, s}};
      break;
    case WorkspaceShape::kLRoom:
      w.vertices = {{0, 0}, {s, 0}, {s, s / 2}, {s / 2, s / 2}, {s / 2, s}, {0, s}};
      break;
  }
  return w;
}

namespace {

// One attempt at a scene (random_scene starts over on a failure): the obstacles placed one at a
// time in a fixed order of draws from rng, so a scene is a function of the generator's state.
// A placement that fails within max_attempts is a value (draw() returns nullopt, failure() says
// which); the generator's stream continues into the next attempt.
class SceneDrawer {
 public:
  SceneDrawer(Rng& rng, const SceneOptions& o)
      : rng_(rng),
        o_(o),
        W_(make_workspace(o.workspace_shape, o.workspace_size)),
        W_set_(geometry::to_set(W_)),
        box_(bounds(W_)),
        r_(o.robot_radius),
        half_(o.robot_radius + o.margin / 2),
        inner_(geometry::erode(W_, half_)) {}

  std::optional<ReactiveScene> draw() {
    scene_.workspace = W_;
    scene_.robot_radius = o_.robot_radius;
    scene_.sensor_range = o_.sensor_range;
    // Walls attached to the boundary first: they need the most room.
    for (int i = 0; i < o_.boundary_touching; ++i) {
      if (!place_wall()) return fail("boundary-touching familiar obstacle", i);
    }
    for (int i = o_.boundary_touching; i < o_.familiar; ++i) {
      auto q = place_inside<Polygon>([&](const Point& c) { return familiar_at(c); });
      if (!q) return fail("familiar obstacle", i);
      scene_.familiar.push_back(std::move(*q));
    }
    for (int i = 0; i < o_.unknown; ++i) {
      auto q = place_inside<Polygon>([&](const Point& c) { return unknown_at(c); });
      if (!q) return fail("unknown obstacle", i);
      scene_.unknown.push_back(std::move(*q));
    }
    for (int i = 0; i < o_.movable; ++i) {
      auto d = place_inside<Disk>([&](const Point& c) { return movable_at(c); });
      if (!d) return fail("movable object", i);
      scene_.movable.push_back(*d);
    }
    scene_.goal = goal();
    return std::move(scene_);
  }

  const std::string& failure() const { return failure_; }

 private:
  template <class T>
  using Made = std::optional<std::pair<T, Footprint>>;

  std::nullopt_t fail(const char* what, int index) {
    failure_ = std::string("random_scene: could not place ") + what + " " + std::to_string(index) +
               " within " + std::to_string(o_.max_attempts) +
               " attempts (scene too crowded for the margin)";
    return std::nullopt;
  }

  // A familiar obstacle's shape, extent, arm width and rotation, in this order of draws.
  std::tuple<double, double> draw_shape(Shape& shape, double& size) {
    shape = o_.shapes[rng_.index(o_.shapes.size())];
    size = rng_.uniform(o_.familiar_min_size, o_.familiar_max_size);
    const double thick = size * rng_.uniform(o_.thickness_fraction_min, o_.thickness_fraction_max);
    const double angle = rng_.uniform(0, 2 * std::numbers::pi);
    return std::make_tuple(thick, angle);
  }

  // A star's dilation may close a notch into a hole (a freespace pocket of its own); the
  // fixed shapes with arm widths below size/2 cannot.
  bool dilation_has_no_hole(Shape shape, const Polygon& p) const {
    return shape != Shape::kStar || single_simple_region(geometry::dilate_miter(p, r_));
  }

  // A point on the boundary, uniform by arc length: the edge's start, direction and the
  // point.
  std::tuple<Point, Point> boundary_point() {
    const std::size_t n = W_.size();
    double perimeter = 0;
    for (std::size_t k = 0; k < n; ++k)
      perimeter += (W_.vertices[(k + 1) % n] - W_.vertices[k]).norm();
    double t = rng_.uniform(0, perimeter);
    std::size_t e = 0;
    for (; e + 1 < n; ++e) {
      const double len = (W_.vertices[e + 1] - W_.vertices[e]).norm();
      if (t < len) break;
      t -= len;
    }
    const Point a = W_.vertices[e], b = W_.vertices[(e + 1) % n];
    const Point dir = (b - a).normalized();
    return {Point(a + t * dir), dir};
  }

  // One wall crossing the boundary, within max_attempts.
  bool place_wall() {
    for (int attempt = 0; attempt < o_.max_attempts; ++attempt) {
      Shape shape;
      double size;
      const auto [thick, angle] = draw_shape(shape, size);
      const auto [on_edge, dir] = boundary_point();
      const Point inward(-dir.y(), dir.x());  // W is counter-clockwise
      const Point center = on_edge + rng_.uniform(-0.1, 0.35) * size * inward;
      const Polygon p = make_shape(rng_, shape, size, thick, angle, center);
      if (std::optional<Polygon> q = wall_of(p, shape)) {
        scene_.familiar.push_back(std::move(*q));
        return true;
      }
    }
    return false;
  }

  // The part of p inside W when it makes an acceptable wall (placed: its footprint recorded).
  std::optional<Polygon> wall_of(const Polygon& p, Shape shape) {
    const RegionSet p_set = geometry::to_set(p);
    if (geometry::subtract(p_set, W_set_).empty()) return std::nullopt;  // must cross the boundary
    const RegionSet clipped = geometry::intersect(p_set, W_set_);
    if (!single_simple_region(clipped)) return std::nullopt;
    const Polygon q = geometry::remove_collinear(clipped[0].outer, 1e-9);
    if (q.size() < 3 || q.area() < kMinClippedFraction * p.area()) return std::nullopt;
    // Away from the corners, so the pocket it forms has one lid on one edge.
    bool near_corner = false;
    for (const Point& v : W_.vertices) {
      if (geometry::distance(q, v) < 2 * r_ + o_.margin) near_corner = true;
    }
    if (near_corner || !dilation_has_no_hole(shape, q)) return std::nullopt;
    Footprint f = footprint(geometry::dilate_miter(q, half_));
    if (!separated(f, placed_)) return std::nullopt;
    // It must not cut the freespace in two (e.g. a U whose opening faces the wall).
    if (geometry::subtract(inner_, f.set).size() != 1) return std::nullopt;
    placed_.push_back(std::move(f));
    return q;
  }

  // A necessary condition checked before the costly dilation: the disk of radius `half` around
  // every vertex lies in the footprint, which must lie in `inner` (a subset of the erosion by
  // half) and avoid the footprints placed so far.
  bool plausible(const Polygon& q) const {
    for (const Point& v : q.vertices) {
      if (!geometry::contains(W_, v) || geometry::nearest_on_boundary(W_, v).distance < 2 * half_) {
        return false;
      }
      for (const Footprint& g : placed_) {
        if ((v - g.center).norm() <= g.radius && geometry::contains(g.set, v)) return false;
      }
    }
    return true;
  }

  // Everything but the walls: inside the eroded workspace, pairwise separated. make(c) returns
  // the obstacle centred near c and its footprint, or nullopt to draw again.
  template <class T, class Make>
  std::optional<T> place_inside(Make make) {
    for (int attempt = 0; attempt < o_.max_attempts; ++attempt) {
      const Point c = uniform_in(rng_, box_);
      if (!geometry::contains(W_, c)) continue;
      Made<T> made = make(c);
      if (!made) continue;
      if (!geometry::subtract(made->second.set, inner_).empty()) continue;
      if (!separated(made->second, placed_)) continue;
      placed_.push_back(std::move(made->second));
      return std::move(made->first);
    }
    return std::nullopt;
  }

  Made<Polygon> familiar_at(const Point& c) {
    Shape shape;
    double size;
    const auto [thick, angle] = draw_shape(shape, size);
    Polygon q = make_shape(rng_, shape, size, thick, angle, c);
    if (!plausible(q) || !dilation_has_no_hole(shape, q)) return std::nullopt;
    Footprint f = footprint(geometry::dilate_miter(q, half_));
    return std::make_pair(std::move(q), std::move(f));
  }

  Made<Polygon> unknown_at(const Point& c) {
    const double rho = rng_.uniform(o_.unknown_min_radius, o_.unknown_max_radius);
    Polygon q = o_.round_unknown
                    ? geometry::regular_polygon(geometry::Disk{c, rho}, kRoundSides, false)
                    : random_convex(rng_, c, rho);
    if (!plausible(q)) return std::nullopt;
    Footprint f = footprint(geometry::dilate_miter(q, half_));
    return std::make_pair(std::move(q), std::move(f));
  }

  Made<Disk> movable_at(const Point& c) {
    const Disk d{c, rng_.uniform(o_.movable_min_radius, o_.movable_max_radius)};
    if (geometry::nearest_on_boundary(W_, c).distance < d.radius + 2 * half_) return std::nullopt;
    Footprint f = footprint(geometry::to_set(geometry::disk_polygon(Disk{c, d.radius + half_})));
    return std::make_pair(d, std::move(f));
  }

  // The goal: a free point with clearance from every dilated obstacle and the eroded boundary.
  Point goal() {
    const double g = r_ + o_.goal_clearance;
    const RegionSet goal_inner = geometry::erode(W_, g);
    std::vector<RegionSet> blocked;
    for (const Polygon& p : scene_.familiar) blocked.push_back(geometry::dilate_miter(p, g));
    for (const Polygon& p : scene_.unknown) blocked.push_back(geometry::dilate_miter(p, g));
    for (int attempt = 0; attempt < kFreePointAttempts; ++attempt) {
      const Point x = uniform_in(rng_, box_);
      if (!geometry::contains(goal_inner, x)) continue;
      bool free = true;
      for (const RegionSet& b : blocked) free = free && !geometry::contains(b, x);
      for (const Disk& d : scene_.movable) free = free && (x - d.center).norm() >= d.radius + g;
      if (free) return x;
    }
    throw Error("random_scene: no free goal found");
  }

  Rng& rng_;
  const SceneOptions& o_;
  const Polygon W_;
  const RegionSet W_set_;
  const Eigen::AlignedBox2d box_;
  const double r_, half_;
  const RegionSet inner_;
  std::vector<Footprint> placed_;
  ReactiveScene scene_;
  std::string failure_;
};

}  // namespace

ReactiveScene random_scene(Rng& rng, const SceneOptions& o) {
  check_options(o);
  for (int restart = 0;; ++restart) {
    SceneDrawer drawer(rng, o);
    if (std::optional<ReactiveScene> scene = drawer.draw()) return std::move(*scene);
    if (restart + 1 >= o.max_restarts) throw Error(drawer.failure());
  }
}

Point random_free_point(Rng& rng, const reactive::MappedSpace& m, double clearance) {
  if (!std::isfinite(clearance) || clearance < 0) {
    throw Error("random_free_point: clearance must be finite and >= 0");
  }
  const Eigen::AlignedBox2d box = bounds(m.freespace.outer);
  auto clear_of = [&](const Polygon& p, const Point& x) {
    return geometry::nearest_on_boundary(p, x).distance >= clearance;
  };
  for (int attempt = 0; attempt < kFreePointAttempts; ++attempt) {
    const Point x = uniform_in(rng, box);
    if (!reactive::in_freespace(m, x)) continue;
    bool ok = clear_of(m.freespace.outer, x);
    for (const Polygon& h : m.freespace.holes) ok = ok && clear_of(h, x);
    for (const auto& c : m.familiar) ok = ok && clear_of(c.polygon, x);
    for (const Polygon& u : m.unknown) ok = ok && clear_of(u, x);
    for (const Disk& d : m.movable) ok = ok && (x - d.center).norm() - d.radius >= clearance;
    if (ok) return x;
  }
  throw Error("random_free_point: no free point with clearance " + std::to_string(clearance) +
              " in " + std::to_string(kFreePointAttempts) + " draws");
}

ReactiveScene benchmark_scene(int K, std::uint64_t seed) {
  constexpr int kCols = 5, kRows = 4;
  constexpr double kLo = 1.0, kHi = 19.0;  // the grid's extent inside the 20 m room
  constexpr double kSize = 1.8, kThickness = 0.6, kJitter = 0.2, kAngleJitter = 0.1;
  if (K < 0 || K > kCols * kRows) {
    throw Error("benchmark_scene: K must be in [0, 20], got " + std::to_string(K));
  }
  Rng rng(seed);
  ReactiveScene scene;
  scene.workspace = make_workspace(WorkspaceShape::kSquare, 20.0);
  scene.robot_radius = 0.2;
  scene.sensor_range = 5.0;
  scene.goal = Point(18.8, 18.8);
  std::vector<int> cells(kCols * kRows);
  for (int i = 0; i < kCols * kRows; ++i) cells[i] = i;
  for (int i = kCols * kRows - 1; i > 0; --i) {
    std::swap(cells[i], cells[rng.index(static_cast<std::uint64_t>(i) + 1)]);
  }
  const double cw = (kHi - kLo) / kCols, ch = (kHi - kLo) / kRows;
  for (int k = 0; k < K; ++k) {
    const int col = cells[k] % kCols, row = cells[k] / kCols;
    const Point c(kLo + (col + 0.5) * cw + rng.uniform(-kJitter, kJitter),
                  kLo + (row + 0.5) * ch + rng.uniform(-kJitter, kJitter));
    const double angle = std::numbers::pi / 2 * static_cast<double>(rng.uniform_int(0, 3)) +
                         rng.uniform(-kAngleJitter, kAngleJitter);
    scene.familiar.push_back(make_shape(rng, kNonConvexShapes[k % 5], kSize, kThickness, angle, c));
  }
  return scene;
}

}  // namespace rearm::test_support
