// Semantic → mapped space (docs/reactive.md §2, paper Appendix III's freespace components).
#include "reactive/mapped_space.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"

namespace rearm::reactive {
namespace {

using geometry::Region;
using geometry::RegionSet;

// Points closer than this (relative to the workspace size) to ∂F_e count as on it when the
// lid of a pocket is identified; pocket vertices on the lid are copies of F_k's vertices, so
// only rounding of the hull's own arithmetic is absorbed here.
constexpr double kLidTolerance = 1e-9;
// Pockets (and clusters) of smaller area than this, relative to the workspace area, are
// rounding slivers of the exact Booleans, not obstacles.
constexpr double kRelativeSliverArea = 1e-12;

using geometry::kContactSlack;  // obstacles are dilated by r + kContactSlack (dilation.h)
// Vertices closer than this (m) to the segment joining their neighbours are dropped from the
// purged components: such nearly flat corners (and the sliver pieces they make) admit no purge
// centre. The obstacle moves by at most this distance.
constexpr double kFlatVertexDistance = 1e-6;

// Drops nearly flat vertices (kFlatVertexDistance), repeatedly, keeping at least 3 and the
// vertices in `keep`.
Polygon drop_flat_vertices(const Polygon& p, const std::vector<Point>& keep = {}) {
  std::vector<Point> v = geometry::remove_collinear(p).vertices;
  bool changed = true;
  while (changed && v.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < v.size() && v.size() > 3; ++i) {
      if (std::find(keep.begin(), keep.end(), v[i]) != keep.end()) continue;
      const Point& a = v[(i + v.size() - 1) % v.size()];
      const Point& c = v[(i + 1) % v.size()];
      if ((geometry::nearest_on_segment(a, c, v[i]) - v[i]).norm() < kFlatVertexDistance) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  return Polygon{std::move(v)};
}

void check_point(const Point& p, const std::string& what) {
  if (!p.allFinite()) throw Error(what + " is not finite");
}

double segment_distance(const Point& a, const Point& b, const Point& x) {
  return (geometry::nearest_on_segment(a, b, x) - x).norm();
}

double boundary_distance(const Polygon& p, const Point& x) {
  return geometry::nearest_on_boundary(p, x).distance;
}

// The lid of a pocket: its longest edge lying on ∂F_e (both ends and the midpoint on it).
std::optional<std::pair<Point, Point>> find_lid(const Polygon& pocket, const Polygon& hull,
                                                double tol) {
  std::optional<std::pair<Point, Point>> lid;
  double best = 0;
  for (std::size_t i = 0, n = pocket.size(); i < n; ++i) {
    const Point& a = pocket.vertices[i];
    const Point& b = pocket.vertices[(i + 1) % n];
    if (boundary_distance(hull, a) > tol || boundary_distance(hull, b) > tol ||
        boundary_distance(hull, (a + b) / 2) > tol) {
      continue;
    }
    // The edge must lie along one hull edge (not cut a corner of the hull).
    bool along = false;
    for (std::size_t k = 0, m = hull.size(); k < m && !along; ++k) {
      const Point& p = hull.vertices[k];
      const Point& q = hull.vertices[(k + 1) % m];
      along = segment_distance(p, q, a) <= tol && segment_distance(p, q, b) <= tol;
    }
    if (along && (b - a).norm() > best) {
      best = (b - a).norm();
      lid = std::make_pair(a, b);
    }
  }
  return lid;
}

}  // namespace

DilationCache::DilationCache(double miter_limit) : miter_limit_(miter_limit) {
  set_miter_limit(miter_limit);
}

void DilationCache::set_miter_limit(double limit) {
  REARM_REQUIRE(std::isfinite(limit) && limit >= 1,
                "dilation cache: the miter limit must be finite and >= 1, got ", limit);
  if (limit != miter_limit_) miters_.clear();
  miter_limit_ = limit;
}

template <class Make>
const geometry::RegionSet& DilationCache::lookup(std::vector<Entry>& entries, const Polygon& p,
                                                 double d, Make make) {
  for (const Entry& e : entries) {
    if (e.distance == d && e.polygon.vertices == p.vertices) return e.result;
  }
  if (entries.size() >= kDilationCacheEntries) entries.clear();
  entries.push_back(Entry{p, d, make()});
  return entries.back().result;
}

const geometry::RegionSet& DilationCache::miter(const Polygon& p, double d) {
  return lookup(miters_, p, d, [&] { return geometry::dilate_miter(p, d, miter_limit_); });
}

const geometry::RegionSet& DilationCache::round(const Polygon& p, double d) {
  return lookup(rounds_, p, d, [&] { return geometry::dilate_round(p, d); });
}

const geometry::RegionSet& DilationCache::eroded(const Polygon& workspace, double d) {
  return lookup(erosions_, workspace, d, [&] { return geometry::erode(workspace, d); });
}

MappedSpace build_mapped_space(const SemanticInput& in, double radius, const Point& robot) {
  DilationCache none;
  return build_mapped_space(in, radius, robot, none);
}

namespace {

// The obstacles of the semantic input dilated (§2), with a representative point of each that
// lies strictly inside its dilation and identifies the cluster it belongs to.
struct Dilated {
  enum class Kind { kFamiliar, kUnknown, kMovable };
  struct Source {
    Kind kind;
    std::size_t index;
    Point rep;
  };
  std::vector<Source> sources;
  std::vector<Polygon> outers;
  std::vector<RegionSet> dilated;
  bool has_holes = false;
  std::vector<Polygon> unknown_dilated;  // convex hulls of the unknown fragments' dilations

  void add(const RegionSet& d) {
    for (const Region& r : d) {
      outers.push_back(r.outer);
      has_holes = has_holes || !r.holes.empty();
    }
    dilated.push_back(d);
  }
};

// Familiar with miter joins, unknown with round joins, movable objects as circumscribed
// polygons, each by radius + kContactSlack.
Dilated dilate_obstacles(const SemanticInput& in, double radius, DilationCache& cache) {
  using Kind = Dilated::Kind;
  Dilated out;
  for (std::size_t i = 0; i < in.familiar.size(); ++i) {
    const std::string what = "familiar obstacle " + std::to_string(i);
    const Polygon p = geometry::validated(in.familiar[i], what.c_str());
    out.add(cache.miter(p, radius + kContactSlack));
    out.sources.push_back({Kind::kFamiliar, i, p.vertices.front()});
  }
  for (std::size_t i = 0; i < in.unknown.size(); ++i) {
    const std::string what = "unknown obstacle " + std::to_string(i);
    const Polygon p = geometry::validated(in.unknown[i], what.c_str());
    if (!geometry::remove_collinear(p).is_convex()) throw Error(what + " is not convex");
    const RegionSet& d = cache.round(p, radius + kContactSlack);
    out.add(d);
    out.unknown_dilated.push_back(geometry::convex_hull(d.front().outer.vertices));
    out.sources.push_back({Kind::kUnknown, i, p.vertices.front()});
  }
  for (std::size_t i = 0; i < in.movable.size(); ++i) {
    const Disk& d = in.movable[i];
    const std::string what = "movable object " + std::to_string(i);
    check_point(d.center, what + " centre");
    REARM_REQUIRE(std::isfinite(d.radius) && d.radius > 0, what,
                  ": radius must be finite and > 0, got ", d.radius);
    out.add(geometry::to_set(
        geometry::disk_polygon(Disk{d.center, d.radius + radius + kContactSlack})));
    out.sources.push_back({Kind::kMovable, i, d.center});
  }
  return out;
}

// Overlapping obstacles are consolidated (§2). A dilated obstacle with a hole (a U closing on
// itself) keeps it: then the union is folded region set by region set, holes included.
RegionSet consolidate(const Dilated& d) {
  if (!d.has_holes) return geometry::unite_all(d.outers);
  RegionSet obstacles;
  for (const RegionSet& r : d.dilated) obstacles = geometry::unite(obstacles, r);
  return obstacles;
}

// Holes of F_k: one per obstacle cluster. A lone unknown fragment stays a convex obstacle and a
// lone movable object a disk; every other cluster is a familiar component. The lone fragments
// are listed in m.unknown by their index in the input, and `lone` records, per fragment, its
// hole and its place in m.unknown (MappedSpaceBuilder updates them in place).
void add_clusters(MappedSpace& m, const Dilated& d, const SemanticInput& in, double radius,
                  double sliver, LoneFragments& lone) {
  using Kind = Dilated::Kind;
  lone.hole.assign(in.unknown.size(), -1);
  lone.slot.assign(in.unknown.size(), -1);
  for (std::size_t h = 0; h < m.freespace.holes.size(); ++h) {
    const Polygon& hole = m.freespace.holes[h];
    if (hole.area() <= sliver) continue;
    int n_familiar = 0, n_unknown = 0, n_movable = 0;
    const Dilated::Source* last = nullptr;
    for (const Dilated::Source& s : d.sources) {
      if (!geometry::contains(hole, s.rep)) continue;
      last = &s;
      (s.kind == Kind::kFamiliar ? n_familiar : s.kind == Kind::kUnknown ? n_unknown : n_movable)++;
    }
    if (n_familiar == 0 && n_unknown + n_movable == 1) {
      if (last->kind == Kind::kUnknown) {
        lone.hole[last->index] = static_cast<int>(h);
      } else {
        // The model disk circumscribes the hole (the circumscribed polygon of radius
        // ρ + r + kContactSlack): the navigation law then keeps the robot outside the very
        // polygon that the next rebuild's freespace excludes.
        const Disk& disk = in.movable[last->index];
        m.movable.push_back(Disk{disk.center, geometry::disk_polygon_circumradius(
                                                  disk.radius + radius + kContactSlack)});
      }
      continue;
    }
    m.familiar.push_back(
        FamiliarComponent{drop_flat_vertices(hole), std::nullopt, n_unknown + n_movable > 0});
  }
  for (std::size_t j = 0; j < in.unknown.size(); ++j) {
    if (lone.hole[j] < 0) continue;
    lone.slot[j] = static_cast<int>(m.unknown.size());
    m.unknown.push_back(d.unknown_dilated[j]);
  }
}

// Indices in `outer` of the hull's vertices, in the hull's order, when every hull vertex is a
// vertex of outer and they come in the same cyclic order.
std::optional<std::vector<std::size_t>> hull_indices(const Polygon& hull, const Polygon& outer) {
  const std::size_t n = outer.size();
  std::vector<std::size_t> at;
  std::size_t travelled = 0;
  for (const Point& v : hull.vertices) {
    const auto it = std::find(outer.vertices.begin(), outer.vertices.end(), v);
    if (it == outer.vertices.end()) return std::nullopt;
    at.push_back(static_cast<std::size_t>(it - outer.vertices.begin()));
    if (at.size() > 1) travelled += (at.back() + n - at[at.size() - 2]) % n;
  }
  if (at.size() < 3 || travelled + (at.front() + n - at.back()) % n != n) return std::nullopt;
  return at;
}

// The pockets of conv(outer) − outer without the Boolean sweep (exact predicates only): the
// chain of outer between two consecutive hull vertices, closed by the hull edge joining them
// (its lid), counter-clockwise. nullopt when a chain vertex is not strictly inside its lid's
// side (collinear vertices pinch the pocket, and an inexact hull may leave a vertex outside):
// the caller then sweeps.
std::optional<RegionSet> chain_pockets(const Polygon& hull, const Polygon& outer) {
  const auto at = hull_indices(hull, outer);
  if (!at) return std::nullopt;
  const std::size_t n = outer.size(), m = hull.size();
  RegionSet out;
  for (std::size_t k = 0; k < m; ++k) {
    const Point& a = hull.vertices[k];
    const Point& b = hull.vertices[(k + 1) % m];
    const std::size_t from = (*at)[k], to = (*at)[(k + 1) % m];
    if ((from + 1) % n == to) continue;  // the hull edge is an edge of outer
    Polygon pocket{{a, b}};
    for (std::size_t j = (to + n - 1) % n; j != from; j = (j + n - 1) % n) {
      if (geometry::orientation(a, b, outer.vertices[j]) <= 0) return std::nullopt;
      pocket.vertices.push_back(outer.vertices[j]);
    }
    out.push_back(Region{std::move(pocket), {}});
  }
  return out;
}

// One pocket, merged into the boundary through its lid. A loop cut from a pocket that touched
// itself (simple_parts) may not reach the hull: it stays a component without a lid.
void add_pocket(MappedSpace& m, const Dilated& d, const Polygon& outer, double scale, bool cut) {
  Polygon pocket = drop_flat_vertices(outer);
  auto lid = find_lid(pocket, m.enclosing, kLidTolerance * scale);
  if (!lid && !cut) {
    // A lid endpoint (a hull vertex) within kFlatVertexDistance of the segment joining its
    // neighbours was dropped as flat, and with it the lid: drop the others, keep the lid's.
    lid = find_lid(outer, m.enclosing, kLidTolerance * scale);
    if (lid) pocket = drop_flat_vertices(outer, {lid->first, lid->second});
  }
  if (!lid && !cut) {
    // A bug, not bad input: every pocket of the hull has an edge on it. Per trial (the sweep's
    // status `error`, `rearm run`'s exit 1), not `stuck` and not an abort of the whole sweep.
    throw InvariantViolation(
        "mapped space: a pocket of the freespace's convex hull has no edge on the hull "
        "(please report the scene)");
  }
  const bool curved = std::any_of(d.sources.begin(), d.sources.end(), [&](const auto& s) {
    return s.kind != Dilated::Kind::kFamiliar && geometry::contains(outer, s.rep);
  });
  m.familiar.push_back(FamiliarComponent{std::move(pocket), lid, curved});
}

// Pockets between F_k and ∂F_e, each merged into the boundary through its lid.
void add_pockets(MappedSpace& m, const Dilated& d, double scale, double sliver) {
  std::optional<RegionSet> chained = chain_pockets(m.enclosing, m.freespace.outer);
  const RegionSet pockets = chained ? std::move(*chained)
                                    : geometry::subtract(geometry::to_set(m.enclosing),
                                                         geometry::to_set(m.freespace.outer));
  for (const Region& r : pockets) {
    if (r.outer.area() <= sliver) continue;
    // A chained pocket is simple (its chain lies strictly on the inner side of its lid). A swept
    // one, rounded from the exact Booleans against the inexact hull, can touch itself away from
    // its vertices (a vertex of F_k on its lid, a zero-area spike along it): cut into its parts.
    if (chained) {
      add_pocket(m, d, r.outer, scale, false);
      continue;
    }
    const std::vector<Polygon> parts = geometry::simple_parts(r.outer, kFlatVertexDistance, sliver);
    const bool cut = parts.size() != 1 || parts.front().vertices != r.outer.vertices;
    for (const Polygon& part : parts) add_pocket(m, d, part, scale, cut);
  }
}

MappedSpace build_full(const SemanticInput& in, double radius, const Point& robot,
                       DilationCache& cache, LoneFragments& lone) {
  REARM_REQUIRE(std::isfinite(radius) && radius > 0,
                "mapped space: dilation radius must be finite and > 0, got ", radius);
  check_point(robot, "mapped space: robot position");
  // The workspace eroded by the radius (conservative), minus the dilated obstacles (§2).
  const RegionSet eroded = cache.eroded(in.workspace, radius);  // a copy: the cache grows below
  const Dilated d = dilate_obstacles(in, radius, cache);
  const RegionSet free = geometry::subtract(eroded, consolidate(d));

  MappedSpace m;
  m.radius = radius;
  const Region* component = nullptr;
  for (const Region& r : free) {
    if (geometry::contains(r, robot)) {
      component = &r;
      break;
    }
  }
  if (component == nullptr) {
    throw NotInFreespace(
        "mapped space: the robot centre (" + std::to_string(robot.x()) + ", " +
        std::to_string(robot.y()) + ") is not in the freespace for radius " +
        std::to_string(radius) +
        " (it starts inside an obstacle, too close to one, or outside the workspace)");
  }
  m.freespace = *component;
  m.enclosing = geometry::convex_hull(m.freespace.outer.vertices);
  const double scale = std::sqrt(m.enclosing.area());
  const double sliver = kRelativeSliverArea * scale * scale;
  add_clusters(m, d, in, radius, sliver, lone);
  add_pockets(m, d, scale, sliver);
  return m;
}

}  // namespace

MappedSpace build_mapped_space(const SemanticInput& in, double radius, const Point& robot,
                               DilationCache& cache) {
  LoneFragments lone;
  return build_full(in, radius, robot, cache, lone);
}

namespace {

bool same_polygons(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].vertices != b[i].vertices) return false;
  }
  return true;
}

bool same_disks(const std::vector<Disk>& a, const std::vector<Disk>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].center != b[i].center || a[i].radius != b[i].radius) return false;
  }
  return true;
}

Eigen::AlignedBox2d box_of(const Polygon& p) {
  Eigen::AlignedBox2d b;
  for (const Point& v : p.vertices) b.extend(v);
  return b;
}

// A bound (relative to the dilation distance, with room for rounding) on how far the round
// dilations and disk polygons reach: 1 / cos(π / n) for n >= 32 sides is below 1.005.
constexpr double kRoundReach = 1.01;

// Does the closed polygon d meet the closed set s (exact)?
bool meets(const Polygon& d, const RegionSet& s) {
  return geometry::intersects(geometry::to_set(d), s);
}

// Does d (with bounding box `box`) lie in the interior of the eroded workspace? No edge of its
// boundary rings may come near d's box (conservative), and one vertex of d must be inside.
bool strictly_inside(const Polygon& d, const Eigen::AlignedBox2d& box, const RegionSet& eroded) {
  auto near = [&](const Polygon& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      Eigen::AlignedBox2d e(ring.vertices[i]);
      e.extend(ring.vertices[(i + 1) % n]);
      if (e.intersects(box)) return true;
    }
    return false;
  };
  for (const Region& r : eroded) {
    if (near(r.outer)) return false;
    for (const Polygon& h : r.holes) {
      if (near(h)) return false;
    }
  }
  return geometry::contains(eroded, d.vertices.front());
}

}  // namespace

MappedSpaceBuilder::MappedSpaceBuilder(double miter_limit) : cache_(miter_limit) {}

MappedSpace MappedSpaceBuilder::build(const SemanticInput& in, double radius, const Point& robot) {
  if (std::optional<MappedSpace> m = update(in, radius, robot)) {
    ++incremental_;
    last_->input.unknown = in.unknown;
    last_->result = *m;
    return std::move(*m);
  }
  last_.reset();
  LoneFragments lone;
  MappedSpace m = build_full(in, radius, robot, cache_, lone);
  last_ = Last{in, radius, cache_.miter_limit(), m, std::move(lone)};
  return m;
}

// The previous mapped space updated in place, or nullopt when the whole construction must run.
std::optional<MappedSpace> MappedSpaceBuilder::update(const SemanticInput& in, double radius,
                                                      const Point& robot) {
  if (!last_ || last_->radius != radius || last_->miter_limit != cache_.miter_limit() ||
      !robot.allFinite() || in.unknown.size() != last_->input.unknown.size() ||
      last_->input.workspace.vertices != in.workspace.vertices ||
      !same_polygons(last_->input.familiar, in.familiar) ||
      !same_disks(last_->input.movable, in.movable)) {
    return std::nullopt;
  }
  std::vector<std::size_t> changed;
  for (std::size_t j = 0; j < in.unknown.size(); ++j) {
    if (in.unknown[j].vertices == last_->input.unknown[j].vertices) continue;
    if (last_->lone.hole[j] < 0) return std::nullopt;  // it was part of a cluster
    changed.push_back(j);
  }
  const double d = radius + kContactSlack;
  std::vector<Polygon> grown(in.unknown.size());
  std::vector<Eigen::AlignedBox2d> boxes(in.unknown.size());
  for (std::size_t j : changed) {
    const std::string what = "unknown obstacle " + std::to_string(j);
    const Polygon p = geometry::validated(in.unknown[j], what.c_str());
    if (!geometry::remove_collinear(p).is_convex()) return std::nullopt;  // the full path throws
    const RegionSet& g = cache_.round(p, d);
    if (g.size() != 1 || !g.front().holes.empty()) return std::nullopt;
    grown[j] = g.front().outer;
    boxes[j] = box_of(grown[j]);
  }
  // Each changed fragment's dilation touches nothing else and stays inside the eroded workspace.
  // An obstacle is tested exactly only when its box, grown by a bound on its dilation's reach
  // (kRoundReach·d round, hypot(L, 1)·d mitered with miter limit L: dilation.h), meets the
  // fragment's box.
  const RegionSet& eroded = cache_.eroded(in.workspace, radius);
  const double miter_reach = kRoundReach * std::hypot(cache_.miter_limit(), 1.0) * d;
  auto reaches = [&](const Eigen::AlignedBox2d& b, const Polygon& p, double reach) {
    Eigen::AlignedBox2d grown_box = box_of(p);
    grown_box.min().array() -= reach;
    grown_box.max().array() += reach;
    return grown_box.intersects(b);
  };
  for (std::size_t j : changed) {
    const Eigen::AlignedBox2d& b = boxes[j];
    if (!strictly_inside(grown[j], b, eroded)) return std::nullopt;
    for (const Polygon& f : in.familiar) {
      if (reaches(b, f, miter_reach) && meets(grown[j], cache_.miter(geometry::validated(f), d))) {
        return std::nullopt;
      }
    }
    for (std::size_t k = 0; k < in.unknown.size(); ++k) {
      if (k == j || !reaches(b, in.unknown[k], kRoundReach * d)) continue;
      const RegionSet other = grown[k].size() > 0
                                  ? geometry::to_set(grown[k])
                                  : cache_.round(geometry::validated(in.unknown[k]), d);
      if (meets(grown[j], other)) return std::nullopt;
    }
    for (const Disk& o : in.movable) {
      const Disk g{o.center, o.radius + d};
      if (!reaches(b, Polygon{{o.center}}, kRoundReach * g.radius)) continue;
      if (meets(grown[j], geometry::to_set(geometry::disk_polygon(g)))) return std::nullopt;
    }
  }
  MappedSpace m = last_->result;
  for (std::size_t j : changed) {
    const auto h = static_cast<std::size_t>(last_->lone.hole[j]);
    // The new dilation lies in F_k together with the old hole (it meets no other boundary).
    const Point& v = grown[j].vertices.front();
    if (!geometry::contains(m.freespace, v) && !geometry::contains(m.freespace.holes[h], v)) {
      return std::nullopt;
    }
    m.freespace.holes[h] = grown[j];
    m.unknown[static_cast<std::size_t>(last_->lone.slot[j])] =
        geometry::convex_hull(grown[j].vertices);
  }
  if (!geometry::contains(m.freespace, robot)) return std::nullopt;
  return m;
}

bool in_freespace(const MappedSpace& m, const Point& x) {
  check_point(x, "in_freespace: point");
  return geometry::contains(m.freespace, x);
}

}  // namespace rearm::reactive
