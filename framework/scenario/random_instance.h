// Seeded random rearrangement instances for the Monte Carlo runner (paper §II: a disk robot of
// radius r moves disk objects of radius ρ among familiar and unknown polygonal obstacles; the
// task is formula (1) of the paper extended to N objects). Classes: kRandom (random goals),
// kCyclic (the goal of Mi is the start of M(i+1 mod N): non-monotone, as the paper's Fig. 5) and
// kSealed (the goal region of M1 lies in a pocket of familiar walls whose only entrance a
// goal-less movable object B1 blocks: Fix mode or a buffer move is needed).
//
// The instance lives in the rectangle [0, width] x [0, height], or, with footprint_density > 0,
// in the square of side sqrt(A / footprint_density), A the objects' total disk area (B1
// included). Objects M1..MN start at random points; region li is the axis-aligned square of
// side s centred at the goal point of Mi; the task is "<>(grasp(M1) && <>(release(M1,l1) &&
// <>(grasp(M2) && ...)))". Class kRandom draws goals at random (a goal may cover another
// object's start). Obstacles are added last: familiar ones P1.. (rotated rectangles and
// L-shapes, possibly non-convex; rectangles that cross the boundary are clipped to it and then
// touch it) and unknown ones C1.. (rotated ellipses, 48-gons, strongly convex as §II assumes;
// with round_unknown off, rotated rectangles and hulls of random points), each unknown with
// probability unknown_fraction, until their area (the sealed pocket's walls included) reaches
// obstacle_density of the workspace or max_attempts consecutive draws fail. Of up to
// kCandidatesPerObstacle poses passing the cheap tests the largest that keeps the certificate
// is kept; an obstacle that would take the union past obstacle_density + kDensityTolerance is
// not (in a small room one large obstacle would overshoot by more). A draw that ends outside
// target ± kDensityTolerance is redrawn like one that fails the exact checks; after the last
// redraw the closest solvable draw is returned with density_reached false, and a sweep refuses
// such a cell before it runs (experiment/cell_check.h).
//
// Clusters and passages. Obstacles may overlap (each overlap at least kMinOverlapDepth deep: a
// vertex of one lies that far inside the other) and then form one cluster; two obstacles that
// do not overlap keep >= w = 2(r + ρ) + passage_margin apart, and an obstacle keeps >= w from
// the boundary unless it touches it (clipped familiar rectangles). So every gap is 0 (one
// cluster, or a cluster on the wall) or a passage at least the carrying pair's diameter plus
// passage_margin wide. Unknown ellipses may overlap familiar obstacles and each other: the
// paper's separation assumptions on unknown obstacles (§II) are then violated — on purpose,
// that is what the dense cells of the study measure. scenario::validate does not forbid
// overlapping obstacles; Box2D's static shapes may overlap.
//
// Clearances (r, ρ, s the region side in use, R = r + ρ + kPairMargin the pair radius of
// solvability.h):
//   cg = 2r + ρ + kGraspMargin     object start / goal point / parking spot ↔ every obstacle
//                                  (the robot can stand anywhere around the object), also
//                                  >= s/√2 so that regions hold no obstacle; in dense layouts
//                                  co = max(ρ + kDenseWallGap, s/√2 + slack) instead, as at
//                                  the walls (graspable from the free side); the sealed
//                                  pocket's box keeps cg in every layout;
//   cb = cg (sparse) or max(ρ + kDenseWallGap, s/2) (dense, see below) ↔ the boundary;
//   d  = spacing of starts, of goals and of the parking spot: Euclidean >= max(s√2 + 0.1, w)
//        (sparse, the regions are then disjoint whatever their orientation); Chebyshev >=
//        s + kDenseRegionGap (dense: the axis-aligned regions are disjoint and objects >= 2ρ +
//        kDenseRegionGap apart);
//   the robot start keeps cg from obstacles and the boundary, r + ρ + 0.5 (sparse) or r + ρ +
//   kDenseRegionGap (dense) from every object start, and its disk enters no region.
// Dense footprints: the spacing that fits, d_fit = sqrt(kPackingFraction · A_pts / n) (A_pts the
// area where points may lie, n the points of the most crowded stream), is compared with the
// sparse d; when it is smaller the instance is "dense": s shrinks to min(region_side, d_fit −
// kDenseRegionGap) but not below 2ρ + kMinRegionMargin, the spacing becomes Chebyshev s +
// kDenseRegionGap and cb drops as above (objects near a wall are graspable from the inside
// only; the certificate's grasp test is one-sided, solvability.h (b)).
//
// Solvability (solvability.h): while obstacles are sampled, a PairRaster (pair_raster.h) of the
// pair freespace rejects every obstacle after which some start, goal, the blocker or the parking
// spot has no grasp position connected to the robot start (raster connectivity implies true
// connectivity); the finished instance is checked once with check_solvability (exact), and for
// class kSealed with check_seal; an instance that fails is redrawn from the next redraw stream
// (at most kMaxRedraws times, then rearm::Error). A parking spot (solvability.h (d)) is
// reserved among the points for every class: drawn after the starts and goals (sparse) or
// before them, which then keep the spacing d from it (dense: a crowd would leave it no site).
//
// Sealed pocket: a C-shaped familiar polygon (wall thickness kWallThickness) around an interior
// square of side 2·max(cg, s/√2 + slack, w/2 + kMinStub), mouth of width w in the front wall; the
// goal point of M1 is the interior's centre; B1 (radius ρ) stands on the mouth's axis
// kBlockerSetback outside it, so the pair (and the robot alone) cannot pass on either side of it,
// and the pair can once B1 is moved. Other starts, goals, the parking spot and the robot keep out
// of the pocket's box grown by cg (by robot clearance for the robot) and >= 2ρ + 2R +
// kDenseRegionGap from B1, so that no object stands in the mouth's approach.
//
// Crowded fallback: a spec whose standard rules find no site for a required placement (a
// point, the robot start, the pocket) is drawn again from scratch under relaxed rules, and only
// then refused (the message names both failures); every instance the standard rules place stays
// bit for bit, and one placed under the fallback says so (crowded_rules, the description). The
// relaxations: the pocket may lie flush with a room wall (back wall on it, mouth facing the
// room; along the wall it touches a corner or keeps >= w from the side walls, the familiar
// obstacles' boundary rule); points keep co (not cg) from the pocket's box and the spacing d
// (not 2ρ + 2R + kDenseRegionGap) from B1, so other objects may stand in the mouth's approach
// (B1 is then not the pocket's only blocker); the robot may start inside a goal region; lattice
// sites are d·(1 + 1e-9) apart, so rounding cannot reject a neighbour. The exact certificate and
// the seal check still decide every instance. Generable at density 0 (random, cyclic; 10 seeds
// per cell, `rearm sweep --check-cells`): N >= 8 up to footprint 0.2, N = 4 up to 0.16 (its
// 1.98 m room at 0.2 leaves no robot start >= R + 2·margin from the walls and >= r + ρ + 0.05
// from four starts). Sealed (targets 0.05 and 0.1; the pocket's walls alone cover 0.04-0.07 of
// the small rooms, so some of these cells miss a target and are refused by a sweep): N = 16 up to
// 0.2, N = 12 up to 0.16, N = 8 up to 0.12, N = 4 up to 0.08; beyond, the 1.8 m pocket plus a
// passage w does not fit the room, or the starts find no site beside it.
//
// Reached densities (GeneratedInstance::achieved_density: the exact area of the obstacles'
// union, overlaps counted once, over the workspace area; default radii and max_obstacle_side,
// 10 seeds per cell, Release, 2 cores). Workspace side max(10 m, sqrt(Nπρ²/0.01)) (10, 10, 10,
// 12.5, 15.3, 17.7 m for N = 1, 2, 4, 8, 12, 16): every cell of N ∈ {1,2,4,8,12,16} x target
// {0.05,0.15,0.25,0.35} x {random, cyclic, sealed} reached its target for every seed (worst
// seed >= target, mean <= target + 0.03; the overshoot is one obstacle). Side max(10 m,
// sqrt(Nπρ²/0.02)) (10 m up to N = 8, 12.5 m for N = 16): all reached up to 0.25, and 0.35
// for N <= 4; at 0.35, N = 8..16 reach 0.28-0.36 (mean 0.30-0.36). A fixed 10 x 10 m room
// with N = 16 reaches about 0.25 (those measurements predate the cap at target +
// kDensityTolerance). Footprint densities, with the cap and the redraws (10 seeds per cell,
// N ∈ {4, 8, 12, 16}, targets 0.05 and 0.15; `rearm sweep --check-cells`, 1440 instances in 37
// s on 2 threads): up to footprint 0.03 every cell is accepted but sealed N = 4 at 0.15; at 0.05
// the random and cyclic cells at target 0.05 and the cyclic ones at 0.15, not the random ones
// at 0.15 (0.08-0.12 reached); at 0.08-0.12 random and cyclic at 0.05 for N >= 8 (and N = 4
// random at 0.08), at target 0.15 only cyclic N >= 8 (0.08) and N >= 12 (0.12) and random N = 8
// (0.08); sealed pockets (target 0.05) fit only rooms of N >= 8 at 0.05 and N >=
// 12 at 0.08-0.12; at 0.2 no cell before the crowded fallback (the robot start, the parking spot or
// the pocket finds no place for N = 4 and 8; the density is missed for N = 12, 16). Time per
// instance: 0.01-0.4 s for random and cyclic cells, 0.05-3.4 s (mean) for sealed cells at 0.35
// (exact seal and solvability checks, occasional redraws).
//
// Determinism (house style 6): every draw comes from rearm::Rng streams derived from spec.seed
// (one each for starts, goals, robot, obstacles, the pocket and the parking spot; redraw k > 0
// offsets every stream by k · kRedrawStreamStride). No global state: instances of different
// specs may be generated in parallel threads. Same spec → the same scenario, bit for bit.
// Instances differ from those of the generator before clusters (the rules changed).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/polygon.h"
#include "scenario/scenario.h"
#include "scenario/solvability.h"

namespace rearm::scenario {

// kConstructive: instances known to be solvable, built backwards from their solution by
// baselines/constructive.h (its room and goals are the kRandom rules'; generate_room below).
enum class GoalClass { kRandom, kCyclic, kSealed, kConstructive };

const char* to_string(GoalClass c);  // "random", "cyclic", "sealed", "constructive"
// The inverse of to_string; throws rearm::Error on any other text.
GoalClass goal_class_from_string(std::string_view text);

// The task's order, a sweep dimension (`goal_orders`). kChain: formula (1) of the paper
// extended to N objects (grasp M1, release it in l1, then M2, ...), the order fixed as the
// paper writes its rearrangement tasks; kAny: <>release(M1,l1) && ... && <>release(MN,lN),
// every object in its region, in any order (the final arrangement the baselines solve).
enum class GoalOrder { kChain, kAny };
const char* to_string(GoalOrder o);  // "chain", "any"
// The inverse of to_string; throws rearm::Error on any other text.
GoalOrder goal_order_from_string(std::string_view text);

// Input ranges, part of the contract below.
inline constexpr int kMaxInstanceObjects = 64;
inline constexpr double kMaxObstacleDensity = 0.5;
inline constexpr double kMaxFootprintDensity = 0.3;
// An instance reaches its target obstacle density when the achieved one is within this of it
// (GeneratedInstance::density_reached); a sweep refuses a cell with an instance that does not.
inline constexpr double kDensityTolerance = 0.02;
// Redraws (from the next streams) after a draw that fails the exact checks or misses the density.
inline constexpr int kMaxRedraws = 3;
// The default and the smallest extra width (m) of every passage beyond the pair's diameter.
inline constexpr double kPassageMargin = 0.2;
inline constexpr double kMinPassageMargin = 0.05;
inline constexpr double kMaxPassageMargin = 2.0;
// Default side (m) of the square every random obstacle fits in (InstanceSpec::max_obstacle_side,
// in [kMinMaxObstacleSide, kMaxMaxObstacleSide]); one obstacle adds at most its square.
inline constexpr double kMaxObstacleSide = 3.0;
inline constexpr double kMinMaxObstacleSide = 0.8;
inline constexpr double kMaxMaxObstacleSide = 5.0;
// The constructive class's scatter moves K (InstanceSpec::scatter_moves), per object at most.
inline constexpr int kMaxScatterMovesPerObject = 8;

struct InstanceSpec {
  int objects = 3;                // N, in [1, kMaxInstanceObjects]
  double obstacle_density = 0.1;  // target fixed-obstacle area / workspace area, [0, 0.5]
  GoalClass goal_class = GoalClass::kRandom;
  GoalOrder goal_order = GoalOrder::kChain;  // the task's formula only: same geometry either way
  std::uint64_t seed = 0;
  double unknown_fraction = 0.5;  // probability that a new obstacle is unknown, in [0, 1]
  // Unknown obstacles are ellipses (48-gons, aspect <= 1.5), strongly convex as the paper
  // assumes (§II); false: rectangles and hulls of 5-8 random points.
  bool round_unknown = true;
  double width = 10, height = 10;  // workspace sides (m), in [0.01, 100]; see footprint_density
  // Objects' total disk area / workspace area; 0: use width and height; in (0, 0.3]: the
  // workspace is the square of side sqrt(area / footprint_density) (<= 100 m).
  double footprint_density = 0;
  double robot_radius = 0.2;    // r (m), >= 0.01
  double object_radius = 0.25;  // ρ (m), >= 0.01
  double region_side = 1.0;     // s (m), >= 2ρ (it shrinks in dense footprints, see above)
  double sensor_range = 3.0;    // R (m), >= 0.01
  double passage_margin = kPassageMargin;       // m, in [kMinPassageMargin, kMaxPassageMargin]
  double max_obstacle_side = kMaxObstacleSide;  // m, see kMaxObstacleSide
  int max_attempts = 2000;  // rejection-sampling attempts per placement, in [1, 1e6]
  // Class kConstructive: the pick-and-place moves K that scatter the objects from their goals
  // (baselines/constructive.h); 0: K = 2N. In [0, kMaxScatterMovesPerObject·N]; other classes
  // ignore it.
  int scatter_moves = 0;
  // The K in force: scatter_moves, or 2N when it is 0.
  int scatter_move_count() const { return scatter_moves > 0 ? scatter_moves : 2 * objects; }
};

// The sealed class's pocket (GeneratedInstance::pocket).
struct SealedPocket {
  bool present = false;                               // class kSealed only
  std::string walls;                                  // name of the familiar polygon (e.g. "P1")
  geometry::Point goal = geometry::Point::Zero();     // M1's goal point, inside the pocket
  geometry::Point blocker = geometry::Point::Zero();  // B1's start
  geometry::Point mouth = geometry::Point::Zero();    // centre of the entrance
  SealReport seal;                                    // check_seal(scenario, M1, B1, goal)
};

struct GeneratedInstance {
  Scenario scenario;
  double achieved_density = 0;         // fixed-obstacle area (shoelace) / workspace area
  double footprint_density = 0;        // objects' disk area (B1 included) / workspace area
  bool density_reached = false;        // |achieved_density - target| <= kDensityTolerance
  bool dense = false;                  // the dense spacing rules were in force (see above)
  double region_side = 0;              // s in use
  double point_spacing = 0;            // d in use (Euclidean sparse, Chebyshev dense)
  int redraws = 0;                     // redraws after a failed exact check
  bool crowded_rules = false;          // placed under the crowded fallback rules
  std::vector<geometry::Point> goals;  // M1..MN's goal points (the centres of l1..lN)
  SolvabilityReport solvability;       // check_solvability(scenario); always solvable
  SealedPocket pocket;
  // Class kConstructive: the witness plan that solves the instance (baselines' plan format as
  // JSON, baselines/plan_json.h), written beside the instance by a sweep; "" for other classes.
  std::string witness;
};

// A random instance of the spec. Scenario::name is "random_<class>_n<N>_s<seed>", source "",
// description e.g. "random instance: class cyclic, N=3, density 0.100 (target 0.100), seed 7,
// 4 familiar and 3 unknown obstacles" (with "; obstacle placement stopped after K consecutive
// failed attempts" when the target density was not reached); controller defaults; simulation
// time_budget 600 + 300 N s. The achieved density is >= the target unless placement stopped,
// and below target + max_obstacle_side² / (workspace area). Objects: M1..MN, then B1 (class
// kSealed, no goal). The result always passes scenario::validate and check_solvability.
//
// Throws rearm::Error naming the field for a bad spec (out of range, non-finite, region_side <
// 2 object_radius, a workspace too small for the clearances), and naming the spec when an
// object start, a goal, the robot start, the parking spot or the pocket cannot be placed in
// max_attempts attempts, or the exact checks fail kMaxRedraws + 1 times (never a hang).
// Class kConstructive throws rearm::Error: its objects' starts are the constructive generator's
// (baselines/constructive.h), which builds on generate_room.
GeneratedInstance generate_instance(const InstanceSpec& spec);
// generate_instance for every class, kConstructive drawn by the kRandom rules (its name and
// description say constructive; the objects stand at the random class's starts, to be replaced).
GeneratedInstance generate_room(const InstanceSpec& spec);
// generate_instance(spec).scenario.
Scenario random_instance(const InstanceSpec& spec);

}  // namespace rearm::scenario
