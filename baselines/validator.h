// An independent check of a rearrangement plan (plan.h) against the problem's exact geometry,
// by a different method than the planners' own exact segment tests (disk_world.h): every swept
// disk is sampled with geometry::disk_clearance, the ground-truth clearance the Box2D world and
// the kinematic plant measure.
//
// Walking the plan from problem.start (objects) and problem.robot_start (robot), it checks:
//  - numbers: everything finite (the problem's start, the parameters, every vertex, heading and
//    arrangement of the plan); object indices in range; the problem's lists of equal size;
//  - continuity (kContinuityTolerance): every path starts where the robot (transit, final
//    transit) or the pair centre (transfer) is; a move's `from` is its object's position;
//  - primitives: the transit ends at standoff_position(from, r, ρ, grasp_heading); the transfer
//    starts at grip_position(from, ..., grasp_heading) + ℓ·h(grasp_heading) and ends at
//    to − (r + gap/2)·h(release_heading), its last segment (the approach) at least
//    max(approach_min, approach_factor·ℓ) long; release_heading is the heading the off-axis law
//    reaches along the transfer from the grasp heading (integrated numerically, within
//    kReleaseHeadingTolerance), so the object lands at `to`; held_at_start only for the first
//    move, with the object where the robot's start pose (problem.robot_start, robot_heading)
//    holds it;
//  - sweeps: the robot disk along transits, docks, back-offs and the final transit against the
//    workspace, every obstacle and every object (the dock and the back-off skip the handled
//    object but keep a clearance >= 0 to it, computed exactly); the pair disk along transfers
//    against everything but the held object; a released object does not overlap any object or
//    obstacle and lies inside the workspace;
//  - the end: final_arrangement is the walked arrangement, every constrained object lies inside
//    its goal region, the robot inside robot_goal_region when there is one.
//
// Sweeps: disk_clearance c(x) of a disk centred at x is 1-Lipschitz in x (a minimum of signed
// distances to sets, minus the radius). A segment is sampled at spacing δ <= kSampleSpacing,
// endpoints included; on the piece between samples x_j and x_{j+1} the clearance is at least
// (c_j + c_{j+1} − δ)/2, so c_j + c_{j+1} >= δ for every j proves c >= 0 on the whole segment.
// In particular clearance >= kSampleSpacing/2 at every sample suffices. A segment without that
// proof is a violation (it may still be clear by less than a millimetre: the planners' margins,
// BaselineParams::transit_margin and transfer_margin, are 1–2 cm).
#pragma once

#include <string>
#include <vector>

#include "baselines/plan.h"
#include "baselines/problem.h"

namespace rearm::baselines {

inline constexpr double kContinuityTolerance = 1e-6;  // m
inline constexpr double kSampleSpacing = 0.002;       // m, h of the sweep samples
// rad: release_heading against the integrated heading. The object's landing point moves by
// (r + gap/2)·δ for a heading error δ: 0.2 mm for r = 0.2 m. (Near φ = π, driving straight
// backwards, the heading is unstable and grows like exp(s/ℓ) from rounding; such a transfer
// fails this check when its landing is unpredictable.)
inline constexpr double kReleaseHeadingTolerance = 1e-3;

// Empty when the plan is valid; else one message per violation, each naming the move and its
// object, the path and segment, the place and the clearance. Validation stops at the first
// non-finite number, out-of-range index or inconsistent problem; otherwise every violation is
// reported and the walk goes on as if the move had been executed as planned.
std::vector<std::string> validate_plan(const RearrangementProblem& problem, const Plan& plan,
                                       const BaselineParams& params);

}  // namespace rearm::baselines
