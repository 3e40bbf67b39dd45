// Straight tracking of a guide path (robust variant, RobustParams::track): when the progress
// monitor has found the reactive controller of [7] at a rest point, a saddle or on a limit
// cycle, the robot (or the robot–object pair) follows the guide's waypoints (guide_path.h)
// segment by segment instead of handing each waypoint to the law as its goal. The segments lie
// in the known freespace F_k (the guide's shortcuts keep them `clearance` from its boundary),
// so driving along them needs no law of attraction; the executive checks every step against
// everything the map knows (interface_layer.h, known_clearance) and hands control back to the
// law where a step would not be clear.
#pragma once

#include "geometry/polygon.h"
#include "reactive/kinematics.h"
#include "reactive/navigation.h"

namespace rearm::executive {

// Bearing error (rad) beyond which the robot alone turns in place before it drives on; below
// it the speed is scaled by 1 − |e|/kTrackTurn, so the robot leaves the segment by at most
// about v_max kTrackTurn / (8 kTrackTurnGain) = 1.25 mm (the guide keeps 5 cm of clearance).
inline constexpr double kTrackTurn = 0.05;
// Turn-rate gain (1/s) on the bearing error while tracking.
inline constexpr double kTrackTurnGain = 2.0;
// m: a tracked waypoint counts as reached this close (the guide's own reach, 0.15 m, lets
// the law cut corners; a tracked segment is followed to its end).
inline constexpr double kTrackReach = 0.02;

// The command that drives `point` toward `waypoint` at most at p.v_max and p.omega_max:
//  - robot alone (rho == 0, point = pose.x): turn in place while the bearing error exceeds
//    kTrackTurn, then drive with v = min(v_max, k_v d) (1 − |e|/kTrackTurn) cos e and
//    ω = kTrackTurnGain e;
//  - carrying (rho > 0, point = pair_center(x, ψ, ρ)): the pair centre as a fully actuated
//    point, u_c = k_v (waypoint − x_c) limited to v_max, [v, ω] = T(ψ)⁻¹ u_c with T of
//    reactive::pair_command (navigation.h), then reactive::limit_common.
// Throws rearm::Error on non-finite input or rho < 0.
reactive::Twist track_command(const reactive::Pose& pose, double rho,
                              const geometry::Point& waypoint, const reactive::NavParams& p);

}  // namespace rearm::executive
