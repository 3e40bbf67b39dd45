#include "executive/targets.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "core/stopwatch.h"
#include "executive/blockers.h"
#include "executive/guide_path.h"
#include "executive/interface_layer.h"
#include "geometry/distance.h"
#include "reactive/mapped_space.h"
#include "topology/topology_check.h"

namespace rearm::executive {

bool drop_points(const Context& c, const ActionState& a) {
  return c.p.robust.drop && a.drop.retargets <= kMaxDropRetargets;
}

// Robust drop rule: the paper's early-stop test (clear of every region, and 2(r + max ρ) from
// everything known), with kDropClearance (r + max ρ) instead of 2(r + max ρ), so that the
// dropped object leaves a passage for the pair between itself and anything else.
bool drop_clear(const Context& c, const Point& xc, double rho, double slack) {
  const std::optional<std::string> carried = c.map.carried();
  if (!carried) return false;
  if (!disassembly_done(xc, c.p.robot_radius + rho + slack, c.p.robot_radius, c.map, *carried,
                        c.regions)) {
    return false;
  }
  return known_clearance(c.map, xc, *carried) >=
         kDropClearance * (c.p.robot_radius + max_object_radius(c)) + slack;
}

// As drop_clear for the first level; the lower levels keep the point while it meets their
// clearance and the region rule (both without the slack the point was chosen with, so that the
// target does not jump as the map grows).
bool drop_kept(const Context& c, const ActionState& a, const Point& q, double rho) {
  if (a.drop.level == 0) return drop_clear(c, q, rho);
  const std::optional<std::string> carried = c.map.carried();
  if (!carried) return false;
  if (!a.drop.in_region && !clear_of_regions(q, c.p.robot_radius + rho, c.regions)) return false;
  if (a.drop.level >= kDropLevels.size()) return true;
  return known_clearance(c.map, q, *carried) >=
         kDropLevels[a.drop.level] * (c.p.robot_radius + max_object_radius(c));
}

namespace {

// The movable objects but the way's movers that still lie where they lay (not yet moved).
std::vector<geometry::Disk> left_in_place(const Context& c, const Way& w) {
  std::vector<geometry::Disk> objects;
  for (const geometry::Disk& d : c.map.movable()) {
    const bool mover = std::any_of(w.movers.begin(), w.movers.end(), [&](const auto& m) {
      return m.center == d.center && m.radius == d.radius;
    });
    if (!mover) objects.push_back(d);
  }
  return objects;
}

// Appendix III's check of the way with `objects` (with_fragments: the fragments as fixed
// obstacles too, uncached); throws topology::CenterNotFree.
topology::TopologyResult way_check(const Context& c, const Way& w,
                                   const std::vector<geometry::Disk>& objects,
                                   bool with_fragments) {
  const ScopedStopwatch sw(c.times.topology_s);
  ++c.topology_checks;
  if (with_fragments) {
    return topology::check_topology(input_with_fragments(c, objects, w.radius, w.from, w.to));
  }
  return topology::check_topology(
      topology::make_input(c.map.workspace(), c.map.familiar(), objects, w.radius, w.from, w.to,
                           std::nullopt, c.topology_cache),
      c.topology_cache);
}

// Fix mode's ways (Context::fix_ways) stay open with the carried object at the drop point q: a
// candidate whose object reach (r + dock gap + ρ) comes within twice that plus the way's radius
// of the way's path is checked exactly (Appendix III's check with the object's disk at q, the
// way's movers not yet moved left out): rejected when the disk joins the objects that close the
// way. At most kMaxWayChecks exact checks per way (over all the searches of its Fix-mode
// entry); past them, the path's neighbourhood alone decides (rejected within reach + radius).
// A way without a path (the guide's raster found none through passages the exact check passes,
// narrower than its cells) has every candidate checked exactly, within the same budget.
bool keeps_way_open(const Context& c, Way& w, const Point& q, double reach) {
  double off = w.path.empty() ? 0 : std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < w.path.size(); ++k) {
    off = std::min(off, (geometry::nearest_on_segment(w.path[k - 1], w.path[k], q) - q).norm());
  }
  if (off >= 2 * (reach + w.radius)) return true;
  if (w.checks >= kMaxWayChecks) return w.path.empty() || off >= reach + w.radius;
  ++w.checks;
  std::vector<geometry::Disk> objects = left_in_place(c, w);
  objects.push_back(geometry::Disk{q, reach});
  try {
    const topology::TopologyResult res = way_check(c, w, objects, false);
    return !(res.verdict == topology::Verdict::kBlockedByObjects &&
             std::find(res.blocking.begin(), res.blocking.end(), objects.size() - 1) !=
                 res.blocking.end());
  } catch (const topology::CenterNotFree&) {
    return false;  // the disk covers where the way starts
  }
}

// Only a mover keeps off its way: the interrupted action's own object, set down so that Fix mode
// can move the others, is gripped again right after them (measured: kept off the way too, it was
// carried 1,000 s to a far drop point on a corpus instance). A mover is never set down where its
// disk could meet the disk it lay on when the way was found closed (the pair centre within
// reach + ρ of it): dropped back there, it closed the way again, round after round.
bool keeps_ways_open(const Context& c, const std::string& carried, const Point& q, double rho) {
  const double reach = c.p.robot_radius + c.p.grasp.dock_gap + rho;
  for (Way& w : c.fix_ways) {
    const auto it = std::find(w.mover_ids.begin(), w.mover_ids.end(), carried);
    if (it == w.mover_ids.end()) continue;
    // Not back where it lay: the way was found closed with the mover there.
    const geometry::Disk& lay = w.movers[static_cast<std::size_t>(it - w.mover_ids.begin())];
    if ((q - lay.center).norm() < reach + lay.radius) return false;
    if (!keeps_way_open(c, w, q, reach)) return false;
  }
  return true;
}

// The goal regions a drop must keep clear of even when no point clear of every region keeps Fix
// mode's ways open: those within the pair's reach of a way's end (the interrupted action's target
// region, where the way leads).
std::vector<RegionOfInterest> regions_of_ways(const Context& c, double rho) {
  std::vector<RegionOfInterest> out;
  for (const RegionOfInterest& reg : c.regions) {
    for (const Way& w : c.fix_ways) {
      if (geometry::distance(reg.polygon, w.to) <= w.radius + c.p.robot_radius + rho) {
        out.push_back(reg);
        break;
      }
    }
  }
  return out;
}

}  // namespace

std::vector<Point> way_path(const Context& c, const Way& w) {
  topology::TopologyResult res;
  try {
    res = way_check(c, w, left_in_place(c, w), w.fragments);
  } catch (const topology::CenterNotFree&) {
    return {};
  }
  if (res.verdict != topology::Verdict::kReachable) return {};
  const std::optional<std::vector<Point>> path = guide_path(res.freespace, w.from, w.to, c.p.guide);
  if (!path) return {};
  std::vector<Point> out{w.from};
  out.insert(out.end(), path->begin(), path->end());
  return out;
}

// The robust variant's drop point: searched in the pair's mapped freespace F_k (the visible
// unknown fragments included, as the reactive controller will see it); in F when the centre is
// not in F_k. The nearest point clear of every region and kDropClearance (r + max ρ) from
// everything known; in a pocket where none is reachable, the nearest at the first of the lower
// kDropLevels that has one, then the clearest reachable point. Nearest, not clearest: the
// farther a point, the likelier an unseen fragment takes it (measured: clearest-first chose
// points 2–3 m away in unexplored space, eight of them taken in turn).
std::optional<Point> drop_point(const Context& c, ActionState& a, const geometry::Region& free,
                                double radius, const Point& center, double rho) {
  const double unit = c.p.robot_radius + max_object_radius(c);
  geometry::Region where = free;
  try {
    const ScopedStopwatch sw(c.times.rebuild_s);
    where =
        reactive::build_mapped_space(semantic_input(c), radius, center, c.drop_dilations).freespace;
  } catch (const reactive::NotInFreespace&) {
  }
  // Exact clearance of each level from everything known; the raster measures from ∂F_k, which
  // lies the pair radius closer.
  std::array<double, kDropLevels.size()> need{};
  std::array<double, kDropLevels.size()> raster_need{};
  for (std::size_t k = 0; k < need.size(); ++k) {
    need[k] = kDropLevels[k] * unit + kDropSlack;
    raster_need[k] = need[k] - radius;
  }
  // Points near a drop point a fragment took before are skipped: fragments are what the sensor
  // sees now, so a point can look clear from one side and not from another.
  const std::string carried = c.map.carried().value_or("");
  // The second search's regions (goal regions allowed, but those of the ways); empty in the
  // first, which keeps clear of every region.
  std::vector<RegionOfInterest> targets;
  bool in_region = false;
  auto accept = [&](const Point& q, std::size_t k) {
    for (const Point& x : a.drop.rejected) {
      if ((q - x).norm() < kRejectedDropRadius * unit) return false;
    }
    // RobustParams::object_blockers: not onto the side or pose the objects are moved off.
    for (const geometry::Disk& k : c.keep_clear) {
      if ((q - k.center).norm() < k.radius + radius) return false;
    }
    return clear_of_regions(q, c.p.robot_radius + rho + kDropSlack,
                            in_region ? targets : c.regions) &&
           (k == need.size() || known_clearance(c.map, q, carried) >= need[k]) &&
           keeps_ways_open(c, carried, q, rho);
  };
  auto q = nearest_clear_point(where, center, raster_need, accept, c.p.guide, true);
  if (!q && !c.fix_ways.empty()) {
    targets = regions_of_ways(c, rho);
    in_region = true;
    q = nearest_clear_point(where, center, raster_need, accept, c.p.guide, true);
  }
  a.drop.level = q ? q->level : kDropLevels.size();  // none: the paper's target, kept as is
  a.drop.in_region = q && in_region;
  if (!q) return std::nullopt;
  if (q->level > 0) ++c.recoveries.pocket_drops;
  return q->point;
}

}  // namespace rearm::executive
