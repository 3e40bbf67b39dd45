// The topology check of the paper's Section V-A and Appendix III (docs/executive.md,
// "Topology check"): does a movable object or a fixed obstacle disconnect the robot (or the
// robot–object pair) from its target, and which objects must be moved, in which order?
//
// The robot alone and the robot–object pair are the same call with different dilation radii
// (r, or r + ρ_i): the caller dilates, or uses make_input(). Every topological decision
// (components, containment, touching) is made on exact polygon Booleans and predicates
// (geometry/boolean.h, geometry/polygon.h); the inputs are doubles.
//
// Algorithm (Appendix III, with the choices the paper leaves open):
//  1. F_list = bound − ∪(fixed ∪ movable), exactly. F = the component containing x (an error
//     when there is none); F_e = Conv(F) = the convex hull of F's outer boundary.
//  2. x* ∈ F → kReachable. The paper writes "x* ∈ F_e"; taken literally a target in another
//     pocket of Conv(F) (behind an obstacle bordering the hull) would pass although the
//     robot cannot reach it, so F itself is tested.
//  3. x and x* in different components of bound − ∪fixed → kBlockedByFixed (the action is
//     infeasible). The paper tests components of (∪ F_list) ∪ (∪ movable). The two agree
//     whenever no object physically overlaps a fixed obstacle or the workspace boundary (a
//     disk dilated by r cannot reach past an obstacle dilated by r); with such an overlap (a
//     localization error) a dilated object would bridge a wall that moving it cannot open,
//     so the objects are treated as free space inside bound − ∪fixed only.
//  4. Otherwise kBlockedByObjects. The object clusters are the connected components of the
//     union of the movable objects (touching or overlapping closures are one cluster),
//     clipped to the component C of bound − ∪fixed that holds x and x* (so a cluster cut by
//     a fixed obstacle becomes two vertices). The graph: vertices are the freespace
//     components of F_list and the clusters, edges join closures that touch (see
//     kAdjacencySlack). Breadth-first search from F to the vertex holding x* (a freespace
//     component, or a cluster when x* lies inside an object); walking back from that vertex
//     to F, the objects of every cluster met are pushed onto B_M, so the cluster nearest the
//     robot ends on top. Inside one cluster the objects are pushed farthest from x first
//     (distance from x to the object's polygon; on a tie the lower index on top), so the
//     nearest is on top. An object met twice keeps its position nearest the top. The paper
//     assumes a tree (each cluster touches at most two freespace components); breadth-first
//     search handles any graph and gives a path through the fewest vertices.
//     Rounding guards (the Booleans are exact, their results rounded to doubles): when the
//     rounded pieces do not link F to x*, B_M lists every object in C (farthest first, the
//     reason says so); when C holds no object at all, x* is a rounding hair outside F and the
//     verdict is kReachable.
//
// Speed (target: ≤ 1 ms at 10 objects and 20 familiar obstacles). CGAL's exact overlays cost
// about 1 µs per input edge, so one global overlay of the bound, the obstacles and the objects
// (~550 edges) took 2 ms. They are now kept to where shapes interact (topology/freespace.h):
// bound − ∪fixed is computed once and kept exact (TopologyCache, below); per call an object
// whose bounding box meets no other object's and no edge of bound − ∪fixed becomes a hole of
// the component one exact point location names, without any overlay, and the other objects
// are subtracted inside small windows around them, splicing the result into the kept loops.
// bound − ∪fixed itself and step 4's clusters are localized the same way; steps 3–4 run only
// when step 2 fails, and step 3 reads the kept components of bound − ∪fixed. The sets are those
// of one global overlay (every decision still on exact Booleans and predicates); only the
// order of the components and the first vertex of a loop can differ from it.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/dilation.h"
#include "geometry/polygon.h"

namespace rearm::topology {

// make_input() dilates objects as geometry::disk_polygon and everything by
// radius + geometry::kContactSlack, as the reactive mapped space does (geometry/dilation.h).

// Adjacency of a freespace component and an object cluster is decided against the cluster
// grown by kAdjacencySlack × (the bound's bounding-box diagonal): both come out of separate
// exact Booleans rounded to doubles, so a shared boundary can be off by ~1e-16 relative.
// They touch when a vertex or an edge midpoint of the component's boundary lies in the grown
// cluster (exact point location): every boundary stretch or vertex the component shares with
// an object gives one. Components closer than the slack count as touching; a contact at a
// single point where an object's corner meets the inside of a component's edge is missed.
inline constexpr double kAdjacencySlack = 1e-9;

struct TopologyInput {
  // The initially assumed freespace: the workspace eroded by the dilation radius (r, or
  // r + ρ_i for the robot–object pair). May be non-convex and have holes.
  geometry::RegionSet bound;
  // Dilated familiar obstacles localized so far (each a region set: a dilated U closing on
  // itself keeps its hole).
  std::vector<geometry::RegionSet> fixed;
  // Dilated movable objects, simple polygons (make_input passes circumscribed regular
  // polygons of radius ρ_k + r).
  std::vector<geometry::Polygon> movable;
  // The caller's index of each movable polygon, reported in TopologyResult::blocking. Empty:
  // the polygon's position in `movable`. Otherwise one per polygon.
  std::vector<std::size_t> movable_ids;
  geometry::Point x = geometry::Point::Zero();       // robot (or pair) centre
  geometry::Point target = geometry::Point::Zero();  // x*
};

enum class Verdict {
  kReachable,         // x* ∈ F
  kBlockedByObjects,  // x* reachable once the objects of `blocking` are moved (Fix mode)
  kBlockedByFixed,    // fixed obstacles (or the workspace) separate x* from x: infeasible
};
const char* to_string(Verdict v);

struct TopologyResult {
  Verdict verdict = Verdict::kReachable;
  geometry::Region freespace;      // F: the component of F_list containing x
  geometry::Polygon enclosing;     // F_e = Conv(F), for the diffeomorphism
  geometry::RegionSet components;  // F_list: every freespace component (F among them)
  // The stack B_M of blocking objects (caller's ids): back() is the top, the object to move
  // first. Empty unless verdict == kBlockedByObjects.
  std::vector<std::size_t> blocking;
  std::string reason;  // why: the target's component, the blocking objects, the separation
};

// Thrown by check_topology when x is not in the freespace (inside an obstacle's dilation or
// outside the bound): an outcome the interface layer answers (it backs the robot out), unlike
// malformed input.
class CenterNotFree : public Error {
 public:
  explicit CenterNotFree(const std::string& what) : Error(what) {}
};

// Appendix III. Throws rearm::Error for bad input: a non-finite x or x*, an invalid polygon
// (geometry::validated), an empty bound, movable_ids of the wrong size, or x not in the
// freespace (inside an obstacle's dilation or outside the bound).
TopologyResult check_topology(const TopologyInput& in);

// Entries a TopologyCache keeps: sets bound − ∪fixed (an executive's working set: the robot
// at r and at its planning radius, the pair while carrying, and the pair's GRASP freespace with
// its margin, per object radius; the least recently used is dropped), and dilations
// (familiar polygons, workspace erosions; emptied when full, as reactive::DilationCache).
inline constexpr std::size_t kTopologyCacheFreespaces = 6;
inline constexpr std::size_t kTopologyCacheDilations = 256;

// What stays the same between the topology checks of one executive: the exact set
// bound − ∪fixed of check_topology (keyed by the bound and fixed polygons, bit for bit) and the
// dilations of make_input (familiar polygon or workspace, and radius, bit for bit). A cached
// call returns exactly (bit for bit) what the uncached call returns for the same arguments,
// whatever the cache held before (freespace.h: the kept exact numbers are settled when built);
// the uncached calls are the cached ones with a fresh cache. Not thread-safe: one per executive
// (or per thread).
class TopologyCache {
 public:
  TopologyCache();
  ~TopologyCache();
  TopologyCache(TopologyCache&&) noexcept;
  TopologyCache& operator=(TopologyCache&&) noexcept;
  TopologyCache(const TopologyCache&) = delete;
  TopologyCache& operator=(const TopologyCache&) = delete;

  std::size_t freespaces() const;  // sets bound − ∪fixed held
  std::size_t dilations() const;   // dilations and erosions held
  void clear();
  // The miter limit of make_input's familiar dilations (geometry::dilate_miter; kMiterLimit
  // unless set). A new limit empties the cache.
  void set_miter_limit(double limit);

  struct Impl;  // topology_check.cpp

 private:
  std::unique_ptr<Impl> impl_;
  friend TopologyResult check_topology(const TopologyInput& in, TopologyCache& cache);
  friend geometry::RegionSet freespace_components(const TopologyInput& in, TopologyCache& cache);
  friend TopologyInput make_input(const geometry::Polygon& workspace,
                                  const std::vector<geometry::Polygon>& familiar,
                                  const std::vector<geometry::Disk>& objects, double radius,
                                  geometry::Point x, geometry::Point target,
                                  std::optional<std::size_t> carried, TopologyCache& cache);
};

// check_topology with bound − ∪fixed taken from (or added to) `cache`: bit for bit the result
// and the errors of check_topology(in). A bound and fixed set seen before skip their
// validation (they passed it then) and the Boolean bound − ∪fixed, most of a cold call when
// dilated obstacles reach the workspace boundary or each other (~0.7 ms of 1.1–1.4 ms at 10
// objects and 20 obstacles, carrying; results/debian12-2core/topology.md).
TopologyResult check_topology(const TopologyInput& in, TopologyCache& cache);

// Step 1 of Appendix III alone: F_list, the components of (bound − ∪fixed) − ∪movable, with
// bound − ∪fixed taken from (or added to) `cache` and the objects subtracted by the localized
// Booleans (the sets of one global exact overlay; only the order of the components and the
// first vertex of a loop may differ). x and target are not used. Throws rearm::Error for an
// empty bound or an invalid polygon.
geometry::RegionSet freespace_components(const TopologyInput& in, TopologyCache& cache);

// Builds the input for a robot of radius `radius` (or a robot–object pair, radius r + ρ_i):
//  - bound: the workspace (a simple polygon) eroded by radius: W minus the stadiums
//    (circumscribed-polygon hulls) of its edges, conservative;
//  - fixed: each familiar polygon dilated with geometry::dilate_miter;
//  - movable: each object as a circumscribed geometry::kDiskPolygonSides-gon of radius ρ + radius,
//    except `carried` (the object in the gripper), which is left out; movable_ids keep the
//    caller's indices.
// All dilations use radius + geometry::kContactSlack. Throws rearm::Error for a non-finite or
// non-positive radius or object radius, an invalid polygon, a non-finite point, or a carried
// index out of range.
TopologyInput make_input(const geometry::Polygon& workspace,
                         const std::vector<geometry::Polygon>& familiar,
                         const std::vector<geometry::Disk>& objects, double radius,
                         geometry::Point x, geometry::Point target,
                         std::optional<std::size_t> carried = std::nullopt);

// make_input with the workspace erosion and the familiar dilations taken from (or added to)
// `cache`: bit for bit the same result and the same errors. The erosion and the dilations
// (exact Booleans) are nearly all of make_input's time, ~7 ms at 20 familiar obstacles; with
// the cache warm, a call after the objects moved takes ~10 µs. A familiar polygon seen before
// skips its validation (it passed it then). The bound and fixed returned are those of every
// call with the same workspace, familiar polygons and radius (dilation is deterministic, cached
// or not), so check_topology(…, cache) finds its bound − ∪fixed.
TopologyInput make_input(const geometry::Polygon& workspace,
                         const std::vector<geometry::Polygon>& familiar,
                         const std::vector<geometry::Disk>& objects, double radius,
                         geometry::Point x, geometry::Point target,
                         std::optional<std::size_t> carried, TopologyCache& cache);

}  // namespace rearm::topology
