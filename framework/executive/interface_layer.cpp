#include "executive/interface_layer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

const geometry::Disk& object_disk(const perception::SemanticMap& map, std::string_view id,
                                  std::optional<geometry::Disk>& holder) {
  holder = map.object(id);
  if (!holder) throw Error("interface layer: unknown object '" + std::string(id) + "'");
  return *holder;
}

// Points checked along the docking segment.
constexpr int kDockSamples = 4;
// The reactive mapped space dilates unknown fragments by circumscribed polygons, up to
// kMaxDilationError beyond the exact dilation: DISASSEMBLE targets keep this much more room.
constexpr double kUnknownRoom = 1 + 2 * geometry::kMaxDilationError;

}  // namespace

double fixed_clearance(const perception::SemanticMap& map, const Point& x) {
  if (!x.allFinite()) throw Error("interface layer: point is not finite");
  double best = -geometry::signed_distance(map.workspace(), x);
  for (const geometry::Polygon& p : map.familiar())
    best = std::min(best, geometry::signed_distance(p, x));
  for (const geometry::Polygon& p : map.unknown())
    best = std::min(best, geometry::signed_distance(p, x));
  return best;
}

double known_clearance(const perception::SemanticMap& map, const Point& x,
                       std::string_view except) {
  double best = fixed_clearance(map, x);
  const auto& disks = map.movable();
  const auto& ids = map.movable_ids();
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (!except.empty() && ids[i] == except) continue;
    best = std::min(best, (disks[i].center - x).norm() - disks[i].radius);
  }
  return best;
}

namespace {

// The grasp from `approach` (robot centre), docking straight toward the object's centre: the
// checks of grasp_candidates (header), nullopt when one fails.
std::optional<GraspCandidate> grasp_along(const perception::SemanticMap& map,
                                          std::string_view object, const geometry::Disk& m,
                                          double r, const Point& approach, const Point& robot,
                                          const GraspParams& p, Objects objects) {
  auto clearance = [&](const Point& x, std::string_view except) {
    return objects == Objects::kCounted ? known_clearance(map, x, except) : fixed_clearance(map, x);
  };
  const double d = (approach - m.center).norm();
  if (!(d > m.radius + r + p.dock_gap)) return std::nullopt;
  const Point u = (approach - m.center) / d;
  GraspCandidate c;
  c.approach = approach;
  c.contact = m.center + (m.radius + r + p.dock_gap) * u;
  c.pair_center = m.center + r * u;
  c.distance = (c.approach - robot).norm();
  // The approach point itself is checked against the object too (clearance standoff).
  if (clearance(c.approach, {}) < r ||
      (objects == Objects::kIgnored && (c.approach - m.center).norm() - m.radius < r)) {
    return std::nullopt;
  }
  for (int s = 1; s <= kDockSamples; ++s) {
    const Point q = c.approach + (c.contact - c.approach) * (double(s) / kDockSamples);
    if (clearance(q, object) < r) return std::nullopt;
  }
  if (clearance(c.pair_center, object) < r + m.radius + p.pair_margin) {
    return std::nullopt;
  }
  return c;
}

}  // namespace

std::optional<GraspCandidate> grasp_from(const perception::SemanticMap& map,
                                         std::string_view object, double r, const Point& robot,
                                         const GraspParams& p) {
  if (!std::isfinite(r) || !(r > 0)) throw Error("grasp: robot radius must be finite and > 0");
  if (!robot.allFinite()) throw Error("grasp: robot position is not finite");
  std::optional<geometry::Disk> holder;
  const geometry::Disk& m = object_disk(map, object, holder);
  return grasp_along(map, object, m, r, robot, robot, p, Objects::kCounted);
}

std::vector<GraspCandidate> grasp_candidates(const perception::SemanticMap& map,
                                             std::string_view object, double r, const Point& robot,
                                             const GraspParams& p, Objects objects) {
  if (p.samples < 1) throw Error("grasp: samples must be >= 1");
  if (!std::isfinite(p.standoff) || !(p.standoff > p.dock_gap) || !(p.dock_gap > 0) ||
      !std::isfinite(p.pair_margin) || !(p.pair_margin >= 0)) {
    throw Error("grasp: need standoff > dock_gap > 0 and pair_margin >= 0 (finite)");
  }
  if (!std::isfinite(r) || !(r > 0)) throw Error("grasp: robot radius must be finite and > 0");
  if (!robot.allFinite()) throw Error("grasp: robot position is not finite");
  std::optional<geometry::Disk> holder;
  const geometry::Disk& m = object_disk(map, object, holder);
  std::vector<GraspCandidate> out;
  for (int k = 0; k < p.samples; ++k) {
    const double a = 2 * std::numbers::pi * k / p.samples;
    const Point u(std::cos(a), std::sin(a));
    const Point approach = m.center + (m.radius + r + p.standoff) * u;
    if (auto c = grasp_along(map, object, m, r, approach, robot, p, objects)) out.push_back(*c);
  }
  std::stable_sort(out.begin(), out.end(), [](const GraspCandidate& a, const GraspCandidate& b) {
    return a.distance < b.distance;
  });
  return out;
}

std::optional<Point> disassemble_target(const geometry::Region& f,
                                        const perception::SemanticMap& map,
                                        std::string_view carried,
                                        const std::vector<RegionOfInterest>& regions,
                                        double pair_radius, double inset,
                                        const std::vector<geometry::Disk>& keep) {
  if (!std::isfinite(pair_radius) || !(pair_radius > 0) || !std::isfinite(inset) || !(inset >= 0)) {
    throw Error("disassemble target: pair radius must be > 0 and inset >= 0 (finite)");
  }
  const auto& disks = map.movable();
  const auto& ids = map.movable_ids();
  auto score = [&](const Point& q) {
    double s = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < disks.size(); ++i) {
      if (ids[i] == carried) continue;
      s = std::min(s, (disks[i].center - q).norm() - disks[i].radius);
    }
    for (const RegionOfInterest& r : regions) s = std::min(s, geometry::distance(r.polygon, q));
    for (const geometry::Disk& k : keep) s = std::min(s, (k.center - q).norm() - k.radius);
    return s;
  };
  auto clear_of_unknown = [&](const Point& q) {
    for (const geometry::Polygon& u : map.unknown()) {
      if (geometry::signed_distance(u, q) < pair_radius * kUnknownRoom) return false;
    }
    return true;
  };
  std::optional<Point> best;
  double best_score = -std::numeric_limits<double>::infinity();
  auto consider = [&](const geometry::Polygon& ring, bool hole) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = ring.vertices[i];
      const Point& b = ring.vertices[(i + 1) % n];
      const Point edge = b - a;
      if (edge.norm() == 0) continue;
      Point mid = (a + b) / 2;
      // Left of a counter-clockwise outer edge is inside F; a hole's inside is not F.
      Point normal = Point(-edge.y(), edge.x()) / edge.norm();
      if (hole) normal = -normal;
      const Point in = mid + inset * normal;
      if (inset > 0 && geometry::contains(f, in)) mid = in;
      if (!clear_of_unknown(mid)) continue;
      const double s = score(mid);
      if (s > best_score) {
        best_score = s;
        best = mid;
      }
    }
  };
  consider(f.outer, false);
  for (const geometry::Polygon& h : f.holes) consider(h, true);
  return best;
}

std::optional<Point> release_point(const geometry::Region& freespace,
                                   const RegionOfInterest& region,
                                   const perception::SemanticMap& map, std::string_view carried,
                                   double inset, double enough, double step) {
  if (!std::isfinite(inset) || !std::isfinite(enough) || !std::isfinite(step) || !(step > 0)) {
    throw Error("release point: inset, enough and step must be finite (step > 0)");
  }
  const Point centroid = region_target(region);
  // A region too large for kMaxReleaseCandidates points at `step` gets a coarser grid.
  const std::vector<Point> candidates = region_grid(region, step, kMaxReleaseCandidates);
  std::optional<Point> best;
  double best_score = -std::numeric_limits<double>::infinity();
  double best_distance = 0;
  for (const Point& p : candidates) {
    if (-geometry::signed_distance(region.polygon, p) < inset) continue;
    if (!geometry::contains(freespace, p)) continue;
    const double score = std::min(known_clearance(map, p, carried), enough);
    const double distance = (p - centroid).norm();
    if (!best || score > best_score || (score == best_score && distance < best_distance)) {
      best = p;
      best_score = score;
      best_distance = distance;
    }
  }
  return best;
}

bool clear_of_regions(const Point& xc, double radius,
                      const std::vector<RegionOfInterest>& regions) {
  for (const RegionOfInterest& reg : regions) {
    if (geometry::distance(reg.polygon, xc) <= radius) return false;
  }
  return true;
}

bool disassembly_done(const Point& xc, double pair_radius, double r,
                      const perception::SemanticMap& map, std::string_view carried,
                      const std::vector<RegionOfInterest>& regions) {
  if (!clear_of_regions(xc, pair_radius, regions)) return false;
  double max_rho = 0;
  for (const auto& m : map.ground_truth().movable) max_rho = std::max(max_rho, m.disk.radius);
  return known_clearance(map, xc, carried) >= 2 * (r + max_rho);
}

}  // namespace rearm::executive
