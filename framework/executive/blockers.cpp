#include "executive/blockers.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/stopwatch.h"
#include "core/text.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"
#include "topology/topology_check.h"

namespace rearm::executive {

// The topology check with `fixed` as the fixed obstacles (the topology cache only for the
// familiar ones) and every movable object grown by kNarrowSlacks in turn: the first slack whose
// verdict names objects, or whose grown objects cover the centre (then those whose grown
// dilation contains it); nullopt when fixed obstacles separate x* or no slack names any.
std::optional<Narrowing> grown_blockers(const Context& c,
                                        const std::vector<geometry::Polygon>& fixed,
                                        bool familiar_only, double radius, const Point& center,
                                        const Point& target) {
  for (double slack : kNarrowSlacks) {
    std::vector<geometry::Disk> grown = c.map.movable();
    for (geometry::Disk& d : grown) d.radius += slack;
    Narrowing n{{}, "", slack};
    try {
      const ScopedStopwatch sw(c.times.topology_s);
      const topology::TopologyResult res =
          familiar_only ? topology::check_topology(
                              topology::make_input(c.map.workspace(), fixed, grown, radius, center,
                                                   target, std::nullopt, c.topology_cache),
                              c.topology_cache)
                        : topology::check_topology(topology::make_input(
                              c.map.workspace(), fixed, grown, radius, center, target));
      ++c.topology_checks;
      if (res.verdict == topology::Verdict::kBlockedByFixed) return std::nullopt;
      if (res.verdict != topology::Verdict::kBlockedByObjects) continue;
      n.blocking = res.blocking;
      n.reason = res.reason;
    } catch (const topology::CenterNotFree&) {
      // Grown objects cover the centre: those within `slack` of the robot's dilation squeeze it.
      for (std::size_t i = 0; i < grown.size(); ++i) {
        if ((grown[i].center - center).norm() < grown[i].radius + radius) n.blocking.push_back(i);
      }
      n.reason =
          "the robot's centre lies within " + rearm::fixed(slack, 3) + " m of their dilations";
    }
    return n;
  }
  return std::nullopt;
}

// Fix mode (paper §IV) for the objects `blocking` (indices into the map's movable objects) but
// the action's own object, with the action's recovery counts reset; nullopt when none is left.
std::optional<Advance> fix_mode_for(const Context& c, ActionState& a,
                                    const std::vector<std::size_t>& blocking, std::string reason) {
  Advance out;
  const auto& ids = c.map.movable_ids();
  for (std::size_t i : blocking) {
    if (ids[i] != a.object) out.blocking.push_back(ids[i]);  // GRASP's own object stays
  }
  if (out.blocking.empty()) return std::nullopt;
  out.kind = Advance::kBlocked;
  out.reason = std::move(reason);
  a.guide.renew_budget();
  a.back_up.renew_budget();
  return out;
}

// Appendix III's B_M holds every object of each cluster that separates x from x*; where the
// objects crowd, one cluster holds most of them. Cut down: the objects whose removal leaves x*
// reachable, dropped one at a time while x* stays reachable without the rest, farthest from the
// segment x–x* first, so that the objects kept for Fix mode are those on the way.
std::vector<std::size_t> minimal_blockers(const Context& c,
                                          const std::vector<std::size_t>& blocking, double radius,
                                          const Point& center, const Point& target) {
  if (blocking.size() < 2) return blocking;
  const std::vector<geometry::Disk>& all = c.map.movable();
  auto reachable_without = [&](const std::vector<std::size_t>& removed) {
    std::vector<geometry::Disk> kept;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (std::find(removed.begin(), removed.end(), i) == removed.end()) kept.push_back(all[i]);
    }
    const ScopedStopwatch sw(c.times.topology_s);
    ++c.topology_checks;
    try {
      return topology::check_topology(
                 topology::make_input(c.map.workspace(), c.map.familiar(), kept, radius, center,
                                      target, std::nullopt, c.topology_cache),
                 c.topology_cache)
                 .verdict == topology::Verdict::kReachable;
    } catch (const topology::CenterNotFree&) {
      return false;
    }
  };
  std::vector<std::size_t> moved = blocking;
  if (!reachable_without(moved)) return blocking;
  std::vector<std::size_t> order = blocking;
  auto off_way = [&](std::size_t i) {
    return (geometry::nearest_on_segment(center, target, all[i].center) - all[i].center).norm();
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return off_way(i) > off_way(j); });
  for (std::size_t i : order) {
    std::vector<std::size_t> fewer;
    for (std::size_t k : moved) {
      if (k != i) fewer.push_back(k);
    }
    if (!fewer.empty() && reachable_without(fewer)) moved = std::move(fewer);
  }
  std::vector<std::size_t> out;
  for (std::size_t i : blocking) {
    if (std::find(moved.begin(), moved.end(), i) != moved.end()) out.push_back(i);
  }
  return out;
}

// fragment_blockers' check, whichever recovery asks for it.
namespace {

// The visible unknown fragments, and with RobustParams::memory what has been seen of each unknown
// obstacle (a convex subset of it): the way the guide found closed may run past obstacles out of
// sight now.
std::vector<geometry::Polygon> fragments(const Context& c) {
  std::vector<geometry::Polygon> out = c.map.unknown();
  if (c.p.robust.memory) {
    for (const geometry::Polygon& h : c.map.seen()) {
      if (h.size() >= 3) out.push_back(h);
    }
  }
  return out;
}

}  // namespace

std::vector<geometry::Polygon> fixed_with_fragments(const Context& c) {
  std::vector<geometry::Polygon> fixed = c.map.familiar();
  const std::vector<geometry::Polygon> seen = fragments(c);
  fixed.insert(fixed.end(), seen.begin(), seen.end());
  return fixed;
}

topology::TopologyInput input_with_fragments(const Context& c,
                                             const std::vector<geometry::Disk>& objects,
                                             double radius, const Point& x, const Point& target,
                                             std::optional<std::size_t> carried) {
  topology::TopologyInput in = topology::make_input(c.map.workspace(), c.map.familiar(), objects,
                                                    radius, x, target, carried, c.topology_cache);
  for (const geometry::Polygon& h : fragments(c)) {
    in.fixed.push_back(
        geometry::dilate_miter(h, radius + geometry::kContactSlack, miter_limit(c.p)));
  }
  return in;
}

std::optional<Advance> closing_with_fragments(const Context& c, ActionState& a, double radius,
                                              const Point& center) {
  const std::vector<geometry::Polygon> fixed = fixed_with_fragments(c);
  topology::TopologyResult res;
  try {
    const ScopedStopwatch sw(c.times.topology_s);
    res = topology::check_topology(
        topology::make_input(c.map.workspace(), fixed, c.map.movable(), radius, center, *a.target));
    ++c.topology_checks;
  } catch (const topology::CenterNotFree&) {
    return std::nullopt;
  }
  std::optional<Advance> out;
  a.blocked_way =
      Way{center, *a.target, radius, true, {}, {}, {}, 0};  // Fix mode's drop points keep it open
  if (res.verdict == topology::Verdict::kBlockedByObjects) {
    out = fix_mode_for(
        c, a, res.blocking,
        "objects close the way to x* together with visible unknown obstacles: " + res.reason);
  } else if (res.verdict == topology::Verdict::kReachable) {
    // The exact check finds a way that the mapped space (its polygonal dilations) closes: a gap
    // within millimetres of the pair's width. Objects that narrow it, as in `narrow`.
    if (const std::optional<Narrowing> n =
            grown_blockers(c, fixed, false, radius, center, *a.target)) {
      out = fix_mode_for(c, a, n->blocking,
                         "objects narrow the way to x* beside visible unknown obstacles (grown "
                         "by " +
                             rearm::fixed(n->slack, 3) + " m): " + n->reason);
    }
  }
  if (out) ++c.recoveries.fragment_fixes;
  return out;
}

geometry::RegionSet fixed_components(const Context& c, double radius, bool with_fragments) {
  const Point any = c.map.workspace().vertices.front();  // not used by freespace_components
  const ScopedStopwatch sw(c.times.topology_s);
  ++c.topology_checks;
  if (with_fragments) {
    topology::TopologyCache none;  // bound − ∪fixed changes as the fragments grow
    return topology::freespace_components(input_with_fragments(c, {}, radius, any, any), none);
  }
  return topology::freespace_components(
      topology::make_input(c.map.workspace(), c.map.familiar(), {}, radius, any, any, std::nullopt,
                           c.topology_cache),
      c.topology_cache);
}

std::optional<geometry::Region> fixed_component(const Context& c, double radius,
                                                const Point& center, bool with_fragments) {
  for (geometry::Region& f : fixed_components(c, radius, with_fragments)) {
    if (geometry::contains(f, center)) return std::move(f);
  }
  return std::nullopt;
}

void add_intruders(const Context& c, const Point& x, double clearance, const std::string& except,
                   std::vector<std::size_t>& out) {
  const auto& disks = c.map.movable();
  const auto& ids = c.map.movable_ids();
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (ids[i] == except || std::find(out.begin(), out.end(), i) != out.end()) continue;
    if ((disks[i].center - x).norm() - disks[i].radius < clearance) out.push_back(i);
  }
}

}  // namespace rearm::executive
