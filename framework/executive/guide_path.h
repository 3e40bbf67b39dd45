// Intermediate targets for the reactive controller along a path in the known freespace: the
// recovery of the robust variant (experiments/sweeps/README.md, "Variants") when the progress
// monitor finds the reactive controller of [7] at a rest point, a saddle or on a limit cycle.
// That controller converges when the obstacles are convex and separated (paper Appendix II);
// clusters of released objects, unknown obstacles and familiar ones break those assumptions
// ("the environment often violates our separation assumptions", paper §VI), and it can stop
// short in a concavity. The reactive law still drives every motion and keeps its safety
// guarantee: only its goal changes, to the next waypoint of a path computed here.
//
// The path is found on a raster of the exact freespace region F_k of the mapped space (the
// dilated obstacles already account for the robot's or the pair's radius): cells whose centre
// is in F_k, their clearance from a Euclidean distance transform, A* over 8-neighbours with a
// cost that prefers cells at least `comfort` from the boundary, then shortcut by exact segment
// tests against F_k's edges (each kept segment stays `clearance` from the boundary, or follows
// the raster where a passage is narrower).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::executive {

struct GuideParams {
  double resolution = 0.04;           // m: raster cell side (grows to respect max_cells)
  std::size_t max_cells = 1'000'000;  // raster cells at most
  double comfort = 0.3;               // m: cells closer to the boundary cost more
  double comfort_weight = 4;          // cost factor 1 + weight · (1 − clearance/comfort)
  double clearance = 0.05;            // m: clearance of a shortcut segment from ∂F_k
  double reach = 0.15;                // m: a waypoint counts as reached this close
  int max_recoveries = 4;             // recoveries per action before it ends stuck
  // m: cells closer than this to ∂F_k are not entered, but within kAvoidExempt of either
  // endpoint (the robot may stand in a tight spot, the goal lie in one); 0: none avoided.
  double avoid = 0;
};

// Distance (m) from the endpoints within which GuideParams::avoid does not apply.
inline constexpr double kAvoidExempt = 0.75;

// Throws rearm::Error naming the first field that is not finite and > 0 (max_recoveries >= 0).
void validate(const GuideParams& p);

// Waypoints from `from` to `to` (the last waypoint is `to`; `from` is not included) through the
// region `free` less the convex polygons `blocked` (counter-clockwise, already dilated; one that
// contains `from` or `to` is left out), or nullopt when the raster finds no path (then none at
// this resolution: the passage is narrower than a cell, or the points are in different
// components). Throws rearm::Error on non-finite endpoints or a blocked polygon of fewer than 3
// vertices.
std::optional<std::vector<geometry::Point>> guide_path(
    const geometry::Region& free, const geometry::Point& from, const geometry::Point& to,
    const GuideParams& p, std::span<const geometry::Polygon> blocked = {});

// A point found by nearest_clear_point, with the index of the clearance level it meets.
struct ClearPoint {
  geometry::Point point;
  std::size_t level = 0;
};

// Search over levels of clearance, `clearances` in order of preference (usually decreasing):
// the cell centres of `free` reachable from `from` along the raster (Dijkstra over
// 8-neighbours), and for the first level k that has one, the nearest centre at least
// clearances[k] from ∂free (raster estimate, within half a cell) for which accept(centre, k)
// holds (the caller's exact test). When no level has one and `clearest_last`, the reachable
// centre farthest from ∂free for which accept(centre, clearances.size()) holds, the nearest of
// equals, at level clearances.size(); else nullopt. One raster, one walk. The robust variant's
// drop point for DISASSEMBLE (executive.h, RobustParams::drop).
std::optional<ClearPoint> nearest_clear_point(
    const geometry::Region& free, const geometry::Point& from, std::span<const double> clearances,
    const std::function<bool(const geometry::Point&, std::size_t)>& accept, const GuideParams& p,
    bool clearest_last = false);

// nearest_clear_point's last level alone: the reachable centre farthest from ∂free for which
// `accept` holds, the nearest of equals; nullopt when none.
std::optional<geometry::Point> clearest_point(
    const geometry::Region& free, const geometry::Point& from,
    const std::function<bool(const geometry::Point&)>& accept, const GuideParams& p);

// Is the closed segment [a, b] inside `free`, at distance >= c from its boundary (doubles; the
// decision only steers the guide, never the safety of a motion)?
bool segment_clear(const geometry::Region& free, const geometry::Point& a, const geometry::Point& b,
                   double c);

}  // namespace rearm::executive
