// Minimum-constraint-removal (MCR) paths for a disk in the plane (Hauser, "The minimum
// constraint removal problem with three robotics applications", IJRR 2014), the primitive fmRS
// builds its dependency graph from (Krontiris & Bekris, ICRA 2016, Sec. IV): among the fixed
// obstacles a path must avoid, and "constraints" it may cross at a cost (the movable objects,
// each at its current and its target place), find a path crossing the fewest constraints.
//
// The graph is an 8-connected grid over the workspace's box (step `grid_step`), its vertices
// and edges checked lazily and exactly against the fixed geometry for each disk radius
// (DiskWorld::segment_free), the query's sources and targets joined to the grid vertices of
// their cell's neighbourhood by exact straight segments. Each edge's constraint set is exact
// too: the swept disk (a capsule) meets constraint disk c when the distance from c's centre to
// the segment is below radius + c.radius + margin. The search is Hauser's label search: states
// (vertex, set of crossed constraints) in order of the set's size, then path length plus the
// distance to the nearest target; a state is dropped when another at its vertex crossed a
// subset no longer. Exact MCR is NP-hard; keeping at most kMaxLabels sets per vertex bounds the
// work (the greedy variant keeps one), which can miss the optimum in rare cases.
#pragma once

#include <bitset>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "baselines/disk_world.h"

namespace rearm::baselines {

inline constexpr std::size_t kMaxConstraints = 128;  // two places for each of 64 objects
using ConstraintSet = std::bitset<kMaxConstraints>;

struct McrQuery {
  double radius = 0;  // the moving disk
  double margin = 0;  // clearance demanded of it, as in the motion queries
  std::vector<geometry::Point> sources, targets;
  std::vector<geometry::Disk> constraints;  // may be crossed, each at a cost of one
  std::vector<geometry::Disk> hard;         // may not be crossed (objects that stay)
};

struct McrPath {
  bool found = false;
  ConstraintSet crossed;              // indices into McrQuery::constraints
  std::vector<geometry::Point> path;  // a source ... a target
};

class McrRoadmap {
 public:
  static constexpr std::size_t kMaxLabels = 8;  // constraint sets kept per vertex

  // grid_step (m) > 0 and finite; the grid is at most kMaxVertices vertices (else a clear error).
  McrRoadmap(const DiskWorld& world, double grid_step);
  static constexpr std::size_t kMaxVertices = 1'000'000;

  // Not thread safe (the lazy validity cache): one roadmap per planner run.
  McrPath search(const McrQuery& q) const;

  std::size_t vertex_count() const { return nx_ * ny_; }

 private:
  friend class McrSearch;
  struct Cache {  // per (radius + margin): 0 unknown, 1 free, 2 blocked
    std::vector<std::uint8_t> vertex, edge;
  };
  Cache& cache(double clearance) const;
  bool vertex_free(Cache& c, std::size_t v, double radius, double margin) const;
  static std::size_t edge_key(std::size_t v, std::size_t w, int dir);
  bool edge_free(Cache& c, std::size_t v, std::size_t w, int dir, double radius,
                 double margin) const;
  geometry::Point position(std::size_t v) const;
  std::vector<std::size_t> near_vertices(const geometry::Point& p) const;

  const DiskWorld& world_;
  double step_;
  std::size_t nx_ = 0, ny_ = 0;
  mutable std::map<double, Cache> caches_;
};

}  // namespace rearm::baselines
