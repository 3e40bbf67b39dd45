// Seeded random rearrangement instances for the Monte Carlo runner (docs/experiments.md,
// "Monte Carlo runner": instance classes a — random goals — and b — cyclic shift of goals,
// non-monotone; object count N, obstacle area fraction, familiar/unknown obstacle mix;
// rejection-sampled so that the task is solvable with full knowledge).
//
// The instance lives in the rectangle [0, width] x [0, height]. Objects M1..MN (radius ρ =
// object_radius) start at random points; region li is the axis-aligned square of side
// region_side centred at the goal point of Mi; the task (formula (1) of the paper, as fig5) is
// the sequential nesting "<>(grasp(M1) && <>(release(M1,l1) && <>(grasp(M2) && ...)))", one
// object after the other. Class b (kCyclic) puts the goal of Mi on the start of M(i+1 mod N),
// so every goal is occupied by another object when its turn comes; class a (kRandom) draws the
// goals at random (a goal may cover another object's start, so some class-a instances are
// non-monotone too, as in the rearrangement literature). Obstacles are added after the objects,
// goals and robot: familiar ones P1.. (rotated rectangles and L-shapes, possibly non-convex)
// and unknown ones C1.. (rotated ellipses, strongly convex as the paper's §II assumes; or, with
// round_unknown off, rotated rectangles and convex hulls of random points in a disk), each
// unknown with probability unknown_fraction, until their total area reaches obstacle_density
// of the workspace or max_attempts consecutive draws of an obstacle fail. Of the first 30
// acceptable poses drawn for an obstacle the largest is kept (large obstacles waste less of the
// workspace on the w-wide passages around them).
//
// Reachable density: the passages cap it. Measured over 40 seeds (mean, worst seed) with the
// default sizes: 10 x 10 m: N=1 0.10 (0.07), N=3 0.07-0.09 (0.04), N=6 0.03-0.06 (0.02), N=12
// 0.00-0.02; 15 x 15 m: N<=3 0.11-0.12 (0.09), N=6 0.09-0.11, N=12 0.05-0.08; 20 x 20 m: N<=6
// 0.11-0.14 (0.10), N=12 0.09-0.11 (class a first, then b). A target of 0.1 is reached for
// every seed in 20 x 20 m with N<=6; 0.2 and 0.3 are out of reach for these obstacle sizes
// whatever the workspace (0.16 in 60 x 60 m with N=1). Those figures were measured with
// rectangular and hull unknown obstacles (round_unknown = false); with the default ellipses,
// 10 x 10 m, target 0.1, 20 seeds per N (both classes): mean (worst) N=1 0.098 (0.083), N=3
// 0.079 (0.058), N=6 0.049 (0.009), against 0.094, 0.075, 0.045 with the polygons on the same
// seeds. The description records the density reached.
//
// Clearances (r = robot_radius, ρ = object_radius, s = region_side):
//   w  = 2(r + ρ) + kPassageMargin  the width every passage keeps: it leaves kPassageMargin / 2
//                                   on either side of the robot carrying an object, modelled as
//                                   one disk of radius r + ρ (see (i) below).
//   cb = max(w + ρ, s/2 + 1e-6)     object start and goal point ↔ workspace boundary
//                                   (the second term keeps each region inside the workspace);
//   co = max(w + ρ, s/√2)           object start and goal point ↔ every obstacle (the second
//                                   term keeps every region free of obstacles);
//   d  = max(s√2 + 0.1, w)          between any two object starts, and between any two goals.
// Guarantees, each enforced while sampling and rechecked by scenario::validate at the end:
//   - every obstacle is >= w from every other obstacle and from the workspace boundary;
//   - every object start and goal point is >= cb from the boundary and >= co from every
//     obstacle;
//   - object starts are pairwise >= d apart, goal points likewise (so the regions, squares of
//     half-diagonal s/√2 < d/2, are pairwise disjoint, and objects at their starts or at their
//     goals never overlap since s >= 2ρ);
//   - the robot start is >= w from every obstacle and the boundary, >= r + ρ + 0.5 from every
//     object start, and its disk enters no region (it may touch one).
// Why the task is solvable with full knowledge (by construction, not by running a planner):
//   (i) The robot carrying an object is modelled, as in the paper and the baselines, by one disk
//   of radius r + ρ. Dilating every obstacle by r + ρ and shrinking the workspace by the same
//   amount leaves obstacles that are disjoint (gaps >= kPassageMargin), simply connected and
//   strictly inside a rectangle, so the free space of that disk among the obstacles is one
//   connected set; every start and goal point has clearance >= w + ρ > 2r + ρ, the reach of the
//   robot grasping an object from any side, so the robot can carry any object between any start
//   and any goal, approaching from any direction. (ii) With every object at its start, any two of
//   the obstacles, objects and boundary are >= 2r + kPassageMargin apart (objects d - 2ρ >= w - 2ρ,
//   object–obstacle >= w, obstacle–obstacle and boundary >= w), so the robot alone reaches
//   every object. (iii) Objects are movable: an object standing on another's goal (class b, or
//   class a by chance) is first carried to a free spot of the connected free space of (i) —
//   there is room, since the goals are pairwise disjoint and far from obstacles — and the
//   sequence then completes. This is the full-knowledge solvability the paper's Fix mode and the
//   baselines rely on; it is not a proof that a particular planner finds the solution in budget.
//
// Determinism (docs/architecture.md, house style 6): every draw comes from rearm::Rng streams
// derived from spec.seed (one stream each for starts, goals, robot and obstacles, so the same
// seed gives the same starts in both classes and the same objects, goals and robot at every
// density). Same spec → the same scenario, bit for bit.
#pragma once

#include <cstdint>
#include <string_view>

#include "scenario/scenario.h"

namespace rearm::scenario {

// docs/experiments.md, "Monte Carlo runner": class a (random goals) and class b (cyclic shift).
enum class GoalClass { kRandom, kCyclic };

const char* to_string(GoalClass c);  // "random", "cyclic"
// The inverse of to_string; throws rearm::Error on any other text.
GoalClass goal_class_from_string(std::string_view text);

// Input ranges, part of the contract below.
inline constexpr int kMaxInstanceObjects = 12;
inline constexpr double kMaxObstacleDensity = 0.3;
// The extra width (m) of every passage beyond the carried pair's diameter (see above).
inline constexpr double kPassageMargin = 0.2;
// Every obstacle fits in a kMaxObstacleSide square (rectangles and L-shapes: sides <= this;
// hulls: in a disk of diameter kMaxObstacleSide), so one obstacle adds at most
// kMaxObstacleSide² m² to the obstacle area.
inline constexpr double kMaxObstacleSide = 1.6;

struct InstanceSpec {
  int objects = 3;                // N, in [1, kMaxInstanceObjects]
  double obstacle_density = 0.1;  // target obstacle area / workspace area, in [0, 0.3]
  GoalClass goal_class = GoalClass::kRandom;
  std::uint64_t seed = 0;
  double unknown_fraction = 0.5;   // probability that a new obstacle is unknown, in [0, 1]
  // Unknown obstacles are ellipses (48-gons, aspect <= 1.5), strongly convex as the paper
  // assumes (§II); false: rectangles and hulls of 5-8 random points, whose flat faces break
  // that assumption (the reactive law can then stop in front of a face).
  bool round_unknown = true;
  double width = 10, height = 10;  // workspace sides (m), in [0.01, 100]
  double robot_radius = 0.2;       // r (m), >= 0.01
  double object_radius = 0.25;     // ρ (m), >= 0.01
  double region_side = 1.0;        // s (m), >= 2ρ (an object fits in its region)
  double sensor_range = 3.0;       // R (m), >= 0.01
  int max_attempts = 2000;         // rejection-sampling attempts per placement, in [1, 1e6]
};

// A random instance of the spec. Scenario::name is "random_<class>_n<N>_s<seed>", source "",
// description e.g. "random instance: class cyclic, N=3, density 0.100 (target 0.100), seed 7,
// 4 familiar and 3 unknown obstacles" (with "; obstacle placement stopped after K consecutive
// failed attempts" when the target density was not reached); controller defaults; simulation
// time_budget 600 + 300 N s. The achieved density is >= the target unless placement stopped,
// and below target + kMaxObstacleSide² / (width·height).
//
// Throws rearm::Error naming the field for a bad spec (an out-of-range N, density, fraction or
// attempt count; a non-finite or too small length; region_side < 2 object_radius; a workspace
// narrower than 2 cb), and naming the spec when an object start, a goal or the robot start
// cannot be placed in max_attempts attempts. The result always passes scenario::validate.
Scenario random_instance(const InstanceSpec& spec);

}  // namespace rearm::scenario
