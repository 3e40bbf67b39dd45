// check_solvability and check_seal of solvability.h: the exact freespaces of the certificate
// (geometry/boolean.h, geometry/dilation.h) and exact point location (geometry::contains).
#include "scenario/solvability.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/convex.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"

namespace rearm::scenario {
namespace {

using geometry::Point;
using geometry::Polygon;
using geometry::RegionSet;

std::vector<Polygon> fixed_obstacles(const Scenario& s) {
  std::vector<Polygon> out;
  for (const NamedPolygon& p : s.familiar) out.push_back(p.polygon);
  for (const NamedPolygon& p : s.unknown) out.push_back(p.polygon);
  return out;
}

// The union of the obstacles dilated by radius (round joins), plus the extra polygons.
RegionSet grown(const std::vector<Polygon>& obstacles, double radius,
                const std::vector<Polygon>& extra = {}) {
  std::vector<Polygon> outers = extra;
  std::vector<RegionSet> with_holes;
  for (const Polygon& o : obstacles) {
    for (geometry::Region& g : geometry::dilate_round(o, radius)) {
      if (g.holes.empty()) {
        outers.push_back(std::move(g.outer));
      } else {
        with_holes.push_back(RegionSet{std::move(g)});
      }
    }
  }
  RegionSet u = outers.empty() ? RegionSet{} : geometry::unite_all(outers);
  for (const RegionSet& h : with_holes) u = geometry::unite(u, h);
  return u;
}

// Workspace eroded by radius minus the grown obstacles.
RegionSet freespace(const Scenario& s, const std::vector<Polygon>& obstacles, double radius,
                    const std::vector<Polygon>& extra = {}) {
  const RegionSet bound = geometry::erode(s.workspace, radius);
  const RegionSet blocked = grown(obstacles, radius, extra);
  return blocked.empty() ? bound : geometry::subtract(bound, blocked);
}

std::optional<std::size_t> component_of(const RegionSet& f, const Point& p) {
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (geometry::contains(f[k], p)) return k;
  }
  return std::nullopt;
}

std::vector<Point> grasp_positions(const Point& p, double r) {
  std::vector<Point> out;
  for (int k = 0; k < kGraspDirections; ++k) {
    const double a = 2 * std::numbers::pi * k / kGraspDirections;
    out.push_back(p + (r + kGripOffset) * Point(std::cos(a), std::sin(a)));
  }
  return out;
}

// Components of f holding a grasp position of p (sorted, unique).
std::vector<std::size_t> grasp_components(const RegionSet& f, const Point& p, double r) {
  std::vector<std::size_t> out;
  for (const Point& q : grasp_positions(p, r)) {
    if (const auto k = component_of(f, q)) out.push_back(*k);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool has_grasp_in(const RegionSet& f, std::size_t c, const Point& p, double r) {
  const std::vector<std::size_t> ks = grasp_components(f, p, r);
  return std::find(ks.begin(), ks.end(), c) != ks.end();
}

// The points of (a): object starts, then region targets (area centroids).
std::vector<Point> required_points(const Scenario& s) {
  std::vector<Point> out;
  for (const Object& o : s.objects) out.push_back(o.disk.center);
  for (const NamedPolygon& g : s.regions) out.push_back(g.polygon.centroid());
  return out;
}

// (a): the component of F_pair holding a grasp position of every required point.
std::optional<std::size_t> common_component(const RegionSet& f, const std::vector<Point>& pts,
                                            double r) {
  std::vector<std::size_t> common = grasp_components(f, pts.front(), r);
  for (std::size_t i = 1; i < pts.size() && !common.empty(); ++i) {
    const std::vector<std::size_t> ks = grasp_components(f, pts[i], r);
    std::vector<std::size_t> both;
    std::set_intersection(common.begin(), common.end(), ks.begin(), ks.end(),
                          std::back_inserter(both));
    common = std::move(both);
  }
  if (common.empty()) return std::nullopt;
  return common.front();
}

// (d): the first grid point (row by row from the lower left) that parks an object.
std::optional<Point> find_parking(const Scenario& s, const RegionSet& f, std::size_t c,
                                  double rho) {
  double x0 = s.workspace.vertices.front().x(), x1 = x0, y0 = s.workspace.vertices.front().y(),
         y1 = y0;
  for (const Point& v : s.workspace.vertices) {
    x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
    y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
  }
  const double r = s.robot.radius;
  for (double y = y0 + kParkingStep; y < y1; y += kParkingStep) {
    for (double x = x0 + kParkingStep; x < x1; x += kParkingStep) {
      const Point p(x, y);
      const bool off_regions = std::all_of(s.regions.begin(), s.regions.end(), [&](const auto& g) {
        return geometry::signed_distance(g.polygon, p) >= rho;
      });
      const bool off_objects = std::all_of(s.objects.begin(), s.objects.end(), [&](const auto& o) {
        return (o.disk.center - p).norm() >= rho + o.disk.radius;
      });
      if (off_regions && off_objects && has_grasp_in(f, c, p, r)) return p;
    }
  }
  return std::nullopt;
}

double max_object_radius(const Scenario& s) {
  double rho = 0;
  for (const Object& o : s.objects) rho = std::max(rho, o.disk.radius);
  return rho;
}

}  // namespace

SolvabilityReport check_solvability(const Scenario& s) {
  if (s.objects.empty()) throw Error("check_solvability: scenario '" + s.name + "' has no objects");
  SolvabilityReport rep;
  const double r = s.robot.radius;
  const double rho = max_object_radius(s);
  rep.pair_radius = r + rho + kPairMargin;
  const std::vector<Polygon> obstacles = fixed_obstacles(s);
  const RegionSet pair = freespace(s, obstacles, rep.pair_radius);
  rep.pair_components = pair.size();
  const std::optional<std::size_t> c = common_component(pair, required_points(s), r);
  rep.connected = c.has_value();
  if (!rep.connected) {
    rep.failure =
        "(a) no component of the pair freespace holds a grasp position of every "
        "object start and region target";
    return rep;
  }
  const RegionSet robot = freespace(s, obstacles, r);
  const std::optional<std::size_t> k = component_of(robot, s.robot.start);
  const Point inside_c = pair[*c].outer.vertices.front();  // C ⊂ F_r: any point of C
  rep.robot_connected = k.has_value() && geometry::contains(robot[*k], inside_c);
  if (!rep.robot_connected) {
    rep.failure = "(c) the robot start is not in the robot freespace component holding C";
    return rep;
  }
  if (const auto p = find_parking(s, pair, *c, rho)) {
    rep.parking_found = true;
    rep.parking = *p;
  } else {
    rep.failure = "(d) no parking spot found";
    return rep;
  }
  rep.solvable = true;
  return rep;
}

std::vector<bool> walled_in_objects(const Scenario& s) {
  const double r = s.robot.radius;
  const double inner = r / (1 + kSealSlack);
  std::vector<Polygon> objects;
  for (const Object& o : s.objects) {
    const geometry::Disk d{o.disk.center, o.disk.radius + inner};
    objects.push_back(geometry::regular_polygon(d, geometry::kDiskPolygonSides, false));
  }
  const RegionSet sup =
      geometry::subtract(geometry::to_set(s.workspace), grown(fixed_obstacles(s), inner, objects));
  const std::optional<std::size_t> k = component_of(sup, s.robot.start);
  std::vector<bool> out;
  for (const Object& o : s.objects) {
    // Robot grasp positions: the pair's grasp_positions for a robot of radius r + ρ.
    out.push_back(!k || !has_grasp_in(sup, *k, o.disk.center, r + o.disk.radius));
  }
  return out;
}

SealReport check_seal(const Scenario& s, std::size_t object, std::size_t blocker,
                      const Point& goal) {
  if (object >= s.objects.size() || blocker >= s.objects.size() || object == blocker) {
    throw Error("check_seal: object " + std::to_string(object) + " and blocker " +
                std::to_string(blocker) + " must be distinct indices below " +
                std::to_string(s.objects.size()));
  }
  SealReport rep;
  const double r = s.robot.radius;
  const Point start = s.objects[object].disk.center;
  const double pair_r = r + s.objects[object].disk.radius;
  const std::vector<Polygon> obstacles = fixed_obstacles(s);
  // Sealed: a superset of the freespace with the blocker as the only movable object (inscribed
  // disk, shrunk radius, uneroded workspace).
  const double inner = pair_r / (1 + kSealSlack);
  const geometry::Disk b{s.objects[blocker].disk.center, s.objects[blocker].disk.radius + inner};
  const std::vector<Polygon> inscribed{
      geometry::regular_polygon(b, geometry::kDiskPolygonSides, false)};
  const RegionSet sup =
      geometry::subtract(geometry::to_set(s.workspace), grown(obstacles, inner, inscribed));
  const std::optional<std::size_t> g = component_of(sup, goal);
  rep.sealed = !g || !has_grasp_in(sup, *g, start, r);
  // Opens: a subset of the freespace with no movable object.
  const double outer = pair_r + kPairMargin;
  const RegionSet sub = freespace(s, obstacles, outer);
  const std::optional<std::size_t> h = component_of(sub, goal);
  rep.opens = h && has_grasp_in(sub, *h, start, r);
  if (!rep.sealed) {
    rep.failure = "the pair reaches the goal with the blocker in place";
  } else if (!rep.opens) {
    rep.failure = "the pair cannot reach the goal with the blocker removed";
  }
  return rep;
}

}  // namespace rearm::scenario
