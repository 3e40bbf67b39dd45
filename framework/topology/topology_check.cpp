// Appendix III of the paper: freespace components, blocking objects, feasibility
// (docs/executive.md, "Topology check"). The contract and the choices are in the header.
#include "topology/topology_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"
#include "topology/freespace.h"

namespace rearm::topology {
namespace {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;
using geometry::Region;
using geometry::RegionSet;
using Box = Eigen::AlignedBox2d;

void check_point(const Point& p, const std::string& what) {
  if (!p.allFinite()) throw Error("topology: " + what + " is not finite");
}

std::string format(const Point& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

Region validated_region(const Region& r, const std::string& what) {
  Region out;
  out.outer = geometry::validated(r.outer, (what + " outer boundary").c_str());
  for (std::size_t k = 0; k < r.holes.size(); ++k) {
    out.holes.push_back(
        geometry::validated(r.holes[k], (what + " hole " + std::to_string(k)).c_str()));
  }
  return out;
}

Box box_of(const Polygon& p) {
  Box b;
  for (const Point& v : p.vertices) b.extend(v);
  return b;
}

// Closures touch (exact), after a bounding-box filter.
bool touch(const Region& a, const Box& box_a, const Region& b, const Box& box_b) {
  return box_a.intersects(box_b) && geometry::intersects(RegionSet{a}, RegionSet{b});
}

// The polygon grown by d > 0 (a superset of its d-neighbourhood): a mitered offset when it is
// convex, else the outer boundary of its round dilation.
Polygon grown(const Polygon& p, double d) {
  const Polygon c = geometry::remove_collinear(p);
  if (c.size() >= 3 && c.is_convex()) return geometry::offset_convex(c, d);
  return geometry::dilate_round(p, d).front().outer;
}

// Step 4: the stack B_M. `c` is the component of bound − ∪fixed holding x and x*; `root` the
// index of F in `components`.
// Objects sorted farthest from x first, ties by index (pushed in this order, nearest on top).
std::vector<std::size_t> farthest_first(std::vector<std::pair<double, std::size_t>> order) {
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second > b.second;
  });
  std::vector<std::size_t> out;
  out.reserve(order.size());
  for (const auto& [dist, k] : order) out.push_back(k);
  return out;
}

// The vertices of Appendix III's tree: the freespace components, then the object clusters.
struct TreeVertices {
  std::vector<Region> regions;
  std::vector<Box> boxes;
  std::size_t n_free = 0;
};

// Objects of each cluster, farthest from x first. Only the candidates can touch a cluster (the
// others' boxes miss it); a cluster that is one isolated grown object touches its own object only.
std::vector<std::vector<std::size_t>> cluster_members(const TopologyInput& in,
                                                      const detail::Clusters& clusters,
                                                      const TreeVertices& t) {
  std::vector<std::vector<std::size_t>> members(clusters.regions.size());
  for (std::size_t j = 0; j < clusters.regions.size(); ++j) {
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t k : clusters.candidates[j]) {
      const Region object{in.movable[k], {}};
      if (clusters.sole[j] ||
          touch(object, box_of(in.movable[k]), t.regions[t.n_free + j], t.boxes[t.n_free + j])) {
        order.emplace_back(geometry::distance(in.movable[k], in.x), k);
      }
    }
    members[j] = farthest_first(std::move(order));
  }
  return members;
}

// The vertex holding x*: a freespace component, else a cluster (x* inside an object).
// Rounding can leave x* a hair outside every vertex; then the nearest one.
std::size_t goal_vertex(const TreeVertices& t, const Point& target) {
  for (std::size_t v = 0; v < t.regions.size(); ++v) {
    if (t.boxes[v].exteriorDistance(target) == 0 && geometry::contains(t.regions[v], target)) {
      return v;
    }
  }
  std::size_t goal = t.regions.size();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < t.regions.size(); ++v) {
    const double d = geometry::distance(t.regions[v].outer, target);
    if (d < best) {
      best = d;
      goal = v;
    }
  }
  return goal;
}

// Edges. Freespace component – cluster: a vertex or an edge midpoint of the component's
// boundary lies in the (grown) cluster; a boundary stretch shared with an object always
// has one, at a rounding distance from the object, well inside the grown cluster. Cluster –
// cluster: pieces of one union touch only at shared (bit-identical) vertices. Two freespace
// components never share more than a point.
std::vector<std::vector<std::size_t>> adjacency(const TreeVertices& t) {
  const std::size_t n = t.regions.size();
  std::vector<std::vector<std::size_t>> adjacent(n);
  auto link = [&adjacent](std::size_t u, std::size_t v) {
    if (std::find(adjacent[u].begin(), adjacent[u].end(), v) == adjacent[u].end()) {
      adjacent[u].push_back(v);
      adjacent[v].push_back(u);
    }
  };
  for (std::size_t i = 0; i < t.n_free; ++i) {
    std::vector<bool> linked(n, false);  // a linked pair needs no more probes
    auto probe = [&](const Point& q) {
      for (std::size_t v = t.n_free; v < n; ++v) {
        if (!linked[v] && t.boxes[v].exteriorDistance(q) == 0 &&
            geometry::contains(t.regions[v], q)) {
          link(i, v);
          linked[v] = true;
        }
      }
    };
    auto probe_loop = [&](const Polygon& loop) {
      for (std::size_t k = 0, m = loop.size(); k < m; ++k) {
        probe(loop.vertices[k]);
        probe((loop.vertices[k] + loop.vertices[(k + 1) % m]) / 2);
      }
    };
    probe_loop(t.regions[i].outer);
    for (const Polygon& h : t.regions[i].holes) probe_loop(h);
  }
  for (std::size_t u = t.n_free; u < n; ++u) {
    for (std::size_t v = u + 1; v < n; ++v) {
      if (!t.boxes[u].intersects(t.boxes[v])) continue;
      const auto& ring = t.regions[u].outer.vertices;
      if (std::any_of(ring.begin(), ring.end(),
                      [&](const Point& q) { return geometry::contains(t.regions[v], q); })) {
        link(u, v);
      }
    }
  }
  return adjacent;
}

// Breadth-first search from the root: each reached vertex's parent (the root and unreached
// vertices: adjacent.size()); stops once `goal` is reached.
std::vector<std::size_t> search_tree(const std::vector<std::vector<std::size_t>>& adjacent,
                                     std::size_t root, std::size_t goal) {
  const std::size_t none = adjacent.size();
  std::vector<std::size_t> parent(adjacent.size(), none);
  std::vector<bool> seen(adjacent.size(), false);
  std::deque<std::size_t> queue{root};
  seen[root] = true;
  while (!queue.empty() && !seen[goal]) {
    const std::size_t u = queue.front();
    queue.pop_front();
    for (std::size_t v : adjacent[u]) {
      if (!seen[v]) {
        seen[v] = true;
        parent[v] = u;
        queue.push_back(v);
      }
    }
  }
  return parent;
}

// An object met twice (it reaches into two clusters) keeps its position nearest the top.
std::vector<std::size_t> unique_nearest_top(const std::vector<std::size_t>& pushed,
                                            std::size_t objects) {
  std::vector<std::size_t> stack;
  std::vector<bool> taken(objects, false);
  for (auto it = pushed.rbegin(); it != pushed.rend(); ++it) {
    if (!taken[*it]) {
      taken[*it] = true;
      stack.push_back(*it);
    }
  }
  std::reverse(stack.begin(), stack.end());
  return stack;
}

std::vector<std::size_t> blocking_stack(const TopologyInput& in, const RegionSet& components,
                                        std::size_t root, const Region& c, double slack,
                                        std::string& note) {
  // The clusters: components of the union of the (slightly grown) objects, clipped to C
  // (localized: freespace.h).
  std::vector<Polygon> grown_objects;
  grown_objects.reserve(in.movable.size());
  for (const Polygon& p : in.movable) grown_objects.push_back(grown(p, slack));
  const detail::Clusters clusters = detail::clip_union(grown_objects, c);

  TreeVertices t;
  t.n_free = components.size();
  t.regions.assign(components.begin(), components.end());
  t.regions.insert(t.regions.end(), clusters.regions.begin(), clusters.regions.end());
  t.boxes.reserve(t.regions.size());
  for (const Region& r : t.regions) t.boxes.push_back(box_of(r.outer));

  const std::vector<std::vector<std::size_t>> members = cluster_members(in, clusters, t);
  const std::size_t goal = goal_vertex(t, in.target);
  const std::vector<std::size_t> parent = search_tree(adjacency(t), root, goal);

  std::vector<std::size_t> pushed;
  if (goal != root && parent[goal] != t.regions.size()) {
    for (std::size_t v = goal; v != root; v = parent[v]) {
      if (v >= t.n_free) {
        const auto& m = members[v - t.n_free];
        pushed.insert(pushed.end(), m.begin(), m.end());
      }
    }
  } else {
    // Exact arithmetic says x* is in x's component of bound − ∪fixed, but the rounded
    // components did not link up: every object in that component is a candidate.
    note = " (adjacency inconclusive after rounding: every object in the component listed)";
    std::vector<std::pair<double, std::size_t>> order;
    for (const auto& m : members) {
      for (std::size_t k : m) order.emplace_back(geometry::distance(in.movable[k], in.x), k);
    }
    pushed = farthest_first(std::move(order));
  }
  return unique_nearest_top(pushed, in.movable.size());
}

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::kReachable:
      return "reachable";
    case Verdict::kBlockedByObjects:
      return "blocked by movable objects";
    case Verdict::kBlockedByFixed:
      return "blocked by fixed obstacles";
  }
  return "unknown verdict";
}

// --- TopologyCache ---

namespace {

bool same_bits(const Polygon& a, const Polygon& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      if (std::bit_cast<std::uint64_t>(a.vertices[i][k]) !=
          std::bit_cast<std::uint64_t>(b.vertices[i][k])) {
        return false;
      }
    }
  }
  return true;
}

bool same_bits(const RegionSet& a, const RegionSet& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a[i].outer, b[i].outer) || a[i].holes.size() != b[i].holes.size()) return false;
    for (std::size_t k = 0; k < a[i].holes.size(); ++k) {
      if (!same_bits(a[i].holes[k], b[i].holes[k])) return false;
    }
  }
  return true;
}

bool same_bits(const std::vector<RegionSet>& a, const std::vector<RegionSet>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a[i], b[i])) return false;
  }
  return true;
}

}  // namespace

struct TopologyCache::Impl {
  struct Freespace {
    RegionSet bound;  // the key: the caller's polygons, as given
    std::vector<RegionSet> fixed;
    std::shared_ptr<const detail::ExactFreespace> set;
  };
  std::vector<Freespace> freespaces;           // least recently used first
  double miter_limit = geometry::kMiterLimit;  // of every familiar dilation held

  struct Dilation {
    Polygon polygon;  // the key: the caller's polygon, as given
    double radius;
    bool erosion;  // workspace erosion (else a familiar polygon's miter dilation)
    RegionSet result;
  };
  std::vector<Dilation> dilations;

  // bound − ∪fixed; on a miss the input is validated (the same errors as before) and the set
  // built.
  std::shared_ptr<const detail::ExactFreespace> freespace(const RegionSet& bound,
                                                          const std::vector<RegionSet>& fixed) {
    for (std::size_t e = 0; e < freespaces.size(); ++e) {
      if (same_bits(freespaces[e].bound, bound) && same_bits(freespaces[e].fixed, fixed)) {
        std::rotate(freespaces.begin() + static_cast<std::ptrdiff_t>(e),
                    freespaces.begin() + static_cast<std::ptrdiff_t>(e) + 1, freespaces.end());
        return freespaces.back().set;
      }
    }
    RegionSet valid_bound;
    for (std::size_t i = 0; i < bound.size(); ++i) {
      valid_bound.push_back(
          validated_region(bound[i], "topology: bound region " + std::to_string(i)));
    }
    RegionSet valid_fixed;
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      for (std::size_t k = 0; k < fixed[i].size(); ++k) {
        valid_fixed.push_back(validated_region(
            fixed[i][k],
            "topology: fixed obstacle " + std::to_string(i) + " region " + std::to_string(k)));
      }
    }
    auto set = std::make_shared<const detail::ExactFreespace>(valid_bound, valid_fixed);
    if (freespaces.size() >= kTopologyCacheFreespaces) freespaces.erase(freespaces.begin());
    freespaces.push_back(Freespace{bound, fixed, set});
    return set;
  }

  // geometry::erode(p, r) or geometry::dilate_miter(validated p, r), computed once per key.
  const RegionSet& dilation(const Polygon& p, double r, bool erosion, const std::string& what) {
    for (const Dilation& d : dilations) {
      if (d.erosion == erosion &&
          std::bit_cast<std::uint64_t>(d.radius) == std::bit_cast<std::uint64_t>(r) &&
          same_bits(d.polygon, p)) {
        return d.result;
      }
    }
    RegionSet result =
        erosion ? geometry::erode(p, r)
                : geometry::dilate_miter(geometry::validated(p, what.c_str()), r, miter_limit);
    if (dilations.size() >= kTopologyCacheDilations) dilations.clear();
    dilations.push_back(Dilation{p, r, erosion, std::move(result)});
    return dilations.back().result;
  }
};

TopologyCache::TopologyCache() : impl_(std::make_unique<Impl>()) {}
TopologyCache::~TopologyCache() = default;
TopologyCache::TopologyCache(TopologyCache&&) noexcept = default;
TopologyCache& TopologyCache::operator=(TopologyCache&&) noexcept = default;
std::size_t TopologyCache::freespaces() const { return impl_ ? impl_->freespaces.size() : 0; }
std::size_t TopologyCache::dilations() const { return impl_ ? impl_->dilations.size() : 0; }
void TopologyCache::clear() {
  const double limit = impl_ ? impl_->miter_limit : geometry::kMiterLimit;
  impl_ = std::make_unique<Impl>();
  impl_->miter_limit = limit;
}

void TopologyCache::set_miter_limit(double limit) {
  REARM_REQUIRE(std::isfinite(limit) && limit >= 1,
                "topology cache: the miter limit must be finite and >= 1, got ", limit);
  if (!impl_) impl_ = std::make_unique<Impl>();
  if (limit == impl_->miter_limit) return;
  clear();
  impl_->miter_limit = limit;
}

// --- The check ---

namespace {

// bound − ∪fixed from the cache (bound and fixed validated when first seen).
std::shared_ptr<const detail::ExactFreespace> fixed_freespace(
    const TopologyInput& in, std::unique_ptr<TopologyCache::Impl>& cache) {
  if (in.bound.empty()) throw Error("topology: the bound (initial freespace) is empty");
  if (!cache) cache = std::make_unique<TopologyCache::Impl>();  // moved from
  return cache->freespace(in.bound, in.fixed);
}

std::vector<Polygon> validated_movable(const TopologyInput& in) {
  std::vector<Polygon> out;
  out.reserve(in.movable.size());
  for (std::size_t i = 0; i < in.movable.size(); ++i) {
    const std::string what = "topology: movable object " + std::to_string(i);
    out.push_back(geometry::validated(in.movable[i], what.c_str()));
  }
  return out;
}

}  // namespace

RegionSet freespace_components(const TopologyInput& in, TopologyCache& cache) {
  const std::shared_ptr<const detail::ExactFreespace> fixed_free = fixed_freespace(in, cache.impl_);
  return fixed_free->subtract(validated_movable(in));
}

TopologyResult check_topology(const TopologyInput& in) {
  TopologyCache fresh;
  return check_topology(in, fresh);
}

TopologyResult check_topology(const TopologyInput& raw, TopologyCache& cache) {
  check_point(raw.x, "robot position x");
  check_point(raw.target, "target x*");
  if (!raw.movable_ids.empty() && raw.movable_ids.size() != raw.movable.size()) {
    throw Error("topology: " + std::to_string(raw.movable_ids.size()) + " movable ids for " +
                std::to_string(raw.movable.size()) + " movable objects");
  }
  const std::shared_ptr<const detail::ExactFreespace> fixed_free =
      fixed_freespace(raw, cache.impl_);
  TopologyInput in;
  in.x = raw.x;
  in.target = raw.target;
  in.movable = validated_movable(raw);
  auto id = [&raw](std::size_t k) { return raw.movable_ids.empty() ? k : raw.movable_ids[k]; };

  // Step 1: F_list = (bound − ∪fixed) − ∪movable, F and F_e.
  TopologyResult out;
  out.components = fixed_free->subtract(in.movable);
  std::size_t root = out.components.size();
  for (std::size_t i = 0; i < out.components.size() && root == out.components.size(); ++i) {
    if (geometry::contains(out.components[i], in.x)) root = i;
  }
  if (root == out.components.size()) {
    throw CenterNotFree(
        "topology: x = " + format(in.x) +
        " is not in the freespace (inside an obstacle's dilation or outside the bound)");
  }
  out.freespace = out.components[root];
  out.enclosing = geometry::convex_hull(out.freespace.outer.vertices);

  // Step 2.
  if (geometry::contains(out.freespace, in.target)) {
    out.verdict = Verdict::kReachable;
    out.reason = "x* = " + format(in.target) + " lies in the robot's freespace component";
    return out;
  }

  // Step 3: components of bound − ∪fixed (the movable objects treated as free).
  const RegionSet& without_objects = fixed_free->components();
  const Region* c = nullptr;
  for (const Region& r : without_objects) {
    if (geometry::contains(r, in.x)) {
      c = &r;
      break;
    }
  }
  for (const Region& r : without_objects) {  // x a hair outside after rounding
    if (c == nullptr && geometry::intersects(RegionSet{r}, RegionSet{out.freespace})) c = &r;
  }
  REARM_DEMAND(c != nullptr, "topology: F lies in no component of bound minus fixed obstacles");
  if (!geometry::contains(*c, in.target)) {
    out.verdict = Verdict::kBlockedByFixed;
    const bool elsewhere = geometry::contains(without_objects, in.target);
    out.reason = "x* = " + format(in.target) +
                 (elsewhere ? " is separated from x = " + format(in.x) +
                                  " by fixed obstacles or the workspace boundary"
                            : " lies inside a fixed obstacle's dilation or outside the bound");
    return out;
  }

  // Step 4.
  Box extent;
  for (const Region& r : raw.bound) extent.extend(box_of(r.outer));
  const double slack = kAdjacencySlack * extent.diagonal().norm();
  std::string note;
  std::vector<std::size_t> stack = blocking_stack(in, out.components, root, *c, slack, note);
  if (stack.empty()) {
    // Exactly, x* ∈ C \ F needs an object in C; none means x* is a rounding hair outside F.
    out.verdict = Verdict::kReachable;
    out.reason = "x* = " + format(in.target) +
                 " lies on the boundary of the robot's freespace component (within rounding)";
    return out;
  }
  out.verdict = Verdict::kBlockedByObjects;
  for (std::size_t k : stack) out.blocking.push_back(id(k));
  std::ostringstream s;
  s << "x* = " << format(in.target) << " is cut off from x = " << format(in.x) << " by "
    << stack.size() << " movable object" << (stack.size() == 1 ? "" : "s")
    << " (move first to last:";
  for (auto it = out.blocking.rbegin(); it != out.blocking.rend(); ++it) s << " " << *it;
  s << ")" << note;
  out.reason = s.str();
  return out;
}

TopologyInput make_input(const geometry::Polygon& workspace,
                         const std::vector<geometry::Polygon>& familiar,
                         const std::vector<geometry::Disk>& objects, double radius,
                         geometry::Point x, geometry::Point target,
                         std::optional<std::size_t> carried) {
  TopologyCache fresh;
  return make_input(workspace, familiar, objects, radius, x, target, carried, fresh);
}

TopologyInput make_input(const geometry::Polygon& workspace,
                         const std::vector<geometry::Polygon>& familiar,
                         const std::vector<geometry::Disk>& objects, double radius,
                         geometry::Point x, geometry::Point target,
                         std::optional<std::size_t> carried, TopologyCache& cache) {
  REARM_REQUIRE(std::isfinite(radius) && radius > 0,
                "topology: dilation radius must be finite and > 0, got ", radius);
  check_point(x, "robot position x");
  check_point(target, "target x*");
  if (carried && *carried >= objects.size()) {
    throw Error("topology: carried object " + std::to_string(*carried) + " of " +
                std::to_string(objects.size()));
  }
  if (!cache.impl_) cache.impl_ = std::make_unique<TopologyCache::Impl>();  // moved from
  const double r = radius + geometry::kContactSlack;
  TopologyInput in;
  in.x = x;
  in.target = target;
  in.bound = cache.impl_->dilation(workspace, r, true, "workspace");
  for (std::size_t i = 0; i < familiar.size(); ++i) {
    const std::string what = "topology: familiar obstacle " + std::to_string(i);
    in.fixed.push_back(cache.impl_->dilation(familiar[i], r, false, what));
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Disk& d = objects[i];
    const std::string what = "topology: movable object " + std::to_string(i);
    check_point(d.center, what + " centre");
    if (!std::isfinite(d.radius) || !(d.radius > 0)) {
      throw Error(what + ": radius must be finite and > 0, got " + std::to_string(d.radius));
    }
    if (carried && *carried == i) continue;
    in.movable.push_back(geometry::disk_polygon(Disk{d.center, d.radius + r}));
    in.movable_ids.push_back(i);
  }
  return in;
}

}  // namespace rearm::topology
