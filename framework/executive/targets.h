// Where DISASSEMBLE drops its object (paper §V-B; docs/executive.md, "Recoveries"): the robust
// variant's drop rule (RobustParams::drop) and drop points, beside the paper's early stop
// (interface_layer.h, disassembly_done) and target (disassemble_target).
#pragma once

#include <optional>

#include "executive/action.h"
#include "executive/context.h"
#include "geometry/polygon.h"

namespace rearm::executive {

// A drop point that a recovery rejected (ActionState::drop.rejected) keeps later targets this
// many times r + max ρ away: a fragment that took it likely covers its surroundings too.
inline constexpr double kRejectedDropRadius = 2;

// Exact checks of drop-point candidates against each of Fix mode's ways (Context::fix_ways),
// over all the searches of its Fix-mode entry.
inline constexpr int kMaxWayChecks = 100;

// The path of a way Fix mode is entered to open (Context::fix_ways): the topology check with
// the way's movers removed (the fragments too for a way found closed among them), and a guide
// path (guide_path.h) from `from` to `to` in the freespace it gives, `from` first; empty when
// x* is not reachable so or the raster finds no path. RobustParams::drop's drop points near it
// are checked against the way (targets.cpp, keeps_way_open).
std::vector<Point> way_path(const Context& c, const Way& w);

// RobustParams::drop's drop points serve this action (it has not given up on them after
// kMaxDropRetargets); else the paper's target and early stop.
bool drop_points(const Context& c, const ActionState& a);
// Robust drop rule at the pair centre xc; `slack` (m) tightens both tests.
bool drop_clear(const Context& c, const Point& xc, double rho, double slack = 0);
// The drop point q still meets its level's clearance (ActionState::drop_level) and region rule.
bool drop_kept(const Context& c, const ActionState& a, const Point& q, double rho);
// The drop point in the pair's freespace `free` (or its mapped F_k), setting
// ActionState::drop_level; nullopt when none is reachable.
std::optional<Point> drop_point(const Context& c, ActionState& a, const geometry::Region& free,
                                double radius, const Point& center, double rho);

}  // namespace rearm::executive
