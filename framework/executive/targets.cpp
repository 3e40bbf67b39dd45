#include "executive/targets.h"

#include <array>
#include <string>

#include "core/stopwatch.h"
#include "executive/guide_path.h"
#include "executive/interface_layer.h"
#include "reactive/mapped_space.h"

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
  if (!carried || !clear_of_regions(q, c.p.robot_radius + rho, c.regions)) return false;
  if (a.drop.level >= kDropLevels.size()) return true;
  return known_clearance(c.map, q, *carried) >=
         kDropLevels[a.drop.level] * (c.p.robot_radius + max_object_radius(c));
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
  auto accept = [&](const Point& q, std::size_t k) {
    for (const Point& x : a.drop.rejected) {
      if ((q - x).norm() < kRejectedDropRadius * unit) return false;
    }
    // RobustParams::object_blockers: not onto the side or pose the objects are moved off.
    for (const geometry::Disk& k : c.keep_clear) {
      if ((q - k.center).norm() < k.radius + radius) return false;
    }
    return clear_of_regions(q, c.p.robot_radius + rho + kDropSlack, c.regions) &&
           (k == need.size() || known_clearance(c.map, q, carried) >= need[k]);
  };
  const auto q = nearest_clear_point(where, center, raster_need, accept, c.p.guide, true);
  a.drop.level = q ? q->level : kDropLevels.size();  // none: the paper's target, kept as is
  if (!q) return std::nullopt;
  if (q->level > 0) ++c.recoveries.pocket_drops;
  return q->point;
}

}  // namespace rearm::executive
