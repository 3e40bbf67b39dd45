#include "executive/guides.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "geometry/convex.h"
#include "reactive/mapped_space.h"

namespace rearm::executive {
namespace {

// What has been seen of each unknown obstacle (perception::SemanticMap::seen) dilated by
// `radius`: the hull's Minkowski sum with the regular kSeenDilationSides-gon circumscribed about
// the disk of that radius (a convex superset of the round dilation F_k uses).
std::vector<geometry::Polygon> seen_dilated(const Context& c, double radius) {
  const geometry::Polygon ring =
      geometry::regular_polygon({Point::Zero(), radius}, kSeenDilationSides, true);
  std::vector<geometry::Polygon> out;
  for (const geometry::Polygon& h : c.map.seen()) {
    if (h.size() < 3) continue;
    std::vector<Point> points;
    points.reserve(h.size() * ring.size());
    for (const Point& v : h.vertices) {
      for (const Point& w : ring.vertices) points.push_back(v + w);
    }
    out.push_back(geometry::convex_hull(std::move(points)));
  }
  return out;
}

// A guide path from `center` to x* in F_k; with RobustParams::memory around what has been seen of
// the unknown obstacles too, in F_k alone when that finds none.
std::optional<std::vector<Point>> guide_to(const Context& c, ActionState& a, const Point& center,
                                           const GuideParams& gp) {
  const geometry::Region& free = c.controller.mapped().freespace;
  bool closed = false;
  if (c.p.robust.memory) {
    const std::vector<geometry::Polygon> seen = seen_dilated(c, a.built_radius);
    if (!seen.empty()) {
      if (auto path = guide_path(free, center, a.goal, gp, seen)) return path;
      closed = true;
    }
  }
  std::optional<std::vector<Point>> path = guide_path(free, center, a.goal, gp);
  if (closed && path) a.guide.memory_closed = true;
  return path;
}

}  // namespace

bool plan_guide(const Context& c, ActionState& a, const Point& center, double t,
                std::string& note) {
  // Robust variant (RobustParams::persist): the budget starts again once the centre is
  // kPersistProgress closer to x* than at every earlier guide of the action (the guides counted
  // for widen go on).
  const double to_goal = (center - a.goal).norm();
  if (c.p.robust.persist && to_goal <= a.guide.best - kPersistProgress)
    a.guide.base = a.guide.planned;
  a.guide.best = std::min(a.guide.best, to_goal);
  if (a.guide.planned - a.guide.base >= c.p.guide.max_recoveries) {
    note = " (after " + std::to_string(a.guide.planned) + " guide paths)";
    return false;
  }
  // Robust variant (RobustParams::widen): each guide after a failed one keeps kGuideWiden more
  // clearance than the last, so that it leaves the passage where the pair stalled for a wider
  // way round when there is one (the plain path otherwise).
  std::optional<std::vector<Point>> path;
  if (c.p.robust.widen && a.guide.planned > 0) {
    GuideParams wide = c.p.guide;
    wide.avoid = kGuideWiden * a.guide.planned;
    path = guide_to(c, a, center, wide);
  }
  if (!path) path = guide_to(c, a, center, c.p.guide);
  if (!path || path->size() < 2) {
    if (path && c.p.robust.track && !a.guide.tracking) {
      // x* in sight (the segment to it keeps the guide's clearance in F_k), yet the law
      // stalled: drive straight at it (RobustParams::track), the pair centre as a fully
      // actuated point, which may back the robot in where the law of [7] would have to turn the
      // pair around.
      a.guide.path.clear();
      a.guide.tracking = true;
      a.back_up.facing = Facing::kNo;
      ++a.guide.planned;
      ++c.recoveries.guides;
      a.monitor.reset(t);
      return true;
    }
    note = path ? " (x* is in sight: no guide helps)" : " (no guide path in the known freespace)";
    return false;
  }
  a.guide.path.assign(path->begin(), path->end() - 1);
  a.guide.tracking = c.p.robust.track;
  a.back_up.facing = c.p.robust.face && !a.guide.tracking ? Facing::kPending : Facing::kNo;
  ++a.guide.planned;
  ++c.recoveries.guides;
  a.monitor.reset(t);
  return true;
}

// The guide in use planned again from `center` (empty when the raster finds no path).
void replan_guide(const Context& c, ActionState& a, const Point& center) {
  const auto path = guide_to(c, a, center, c.p.guide);
  a.guide.path = path ? std::vector<Point>(path->begin(), path->end() - 1) : std::vector<Point>{};
}

}  // namespace rearm::executive
