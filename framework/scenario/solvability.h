// Solvability with full knowledge, checked by exact geometry independently of every planner
// (the Monte Carlo instances of random_instance.h; paper §II: a robot of radius r carries
// movable objects of radius ρ_i among fixed polygonal obstacles, the robot–object pair modelled
// as one disk of radius r + ρ_i).
//
// The certificate (every set below is built with the exact Booleans of geometry/boolean.h and
// located with the exact predicates of geometry::contains; dilations are the round ones of
// geometry/dilation.h, supersets of the exact dilations; the eroded workspace is a subset of the
// exact erosion, so every membership below is conservative). Let R = r + ρmax + kPairMargin
// (ρmax the largest object radius), O the fixed obstacles (familiar and unknown, full
// knowledge), W the workspace, F_pair = erode(W, R) − ∪ dilate(O, R) and F_r = erode(W, r) −
// ∪ dilate(O, r). "Grasp positions" of a point p are the kGraspDirections pair centres
// q(u) = p + (r + kGripOffset)·u, u unit; the pair disk of radius R at q(u) holds the object
// disk at p and the robot gripping it from direction u.
//   (a) connected: one component C of F_pair (a Region of the Boolean result; regions that
//       touch at a single point count as different components) holds a grasp position of
//       every object's start and of every region's target point (its area centroid, the point
//       executive::region_target navigates to — regions are convex squares in the generated
//       instances, so the centroid lies inside them; scenario/ may not include executive/);
//   (b) graspable: for each such point, the grasp positions found in C witness that the robot
//       can grip the object there and carry it (as the pair disk) anywhere in C;
//   (c) robot: the robot start lies in the component of F_r that contains C (C ⊂ F_r);
//   (d) parking: a parking spot exists — a point p of a kParkingStep grid whose object disk
//       (radius ρmax) keeps out of every region and off every object start, with a grasp
//       position in C. An object that stands on another's goal (cyclic instances, sealed
//       blockers) can be carried there and later fetched again.
// What it proves: with the movable objects out of the way, the robot reaches every object,
// and the robot carrying any object can travel between any two of the starts, region targets
// and the parking spot, approaching each from some direction; so every single pick-carry-place
// the task needs is feasible among the fixed obstacles, and a spot exists to park an object
// that is in the way. What it does not prove: that the movable objects never wall each other in
// (in dense footprints an object may be reachable only after another has been moved; moving
// objects among movable obstacles is the NAMO problem, PSPACE-hard in general), that the
// reactive controller of the paper, whose separation assumptions (§II) the dense instances
// violate on purpose, or any planner finds the plan in its budget, or anything about the
// unknown obstacles' discovery order.
//
// check_seal (the sealed class): the blocker alone keeps the pair of an object from a goal
// point — in F_sup = W − ∪ (dilations of O by R⁻) − (the inscribed kDiskPolygonSides-gon of
// radius ρ_B + R⁻ about the blocker), a superset of the pair's freespace with the blocker as the
// only movable object (R⁻ = (r + ρ)/(1 + kSealSlack), so the round dilation, within
// kMaxDilationError of the exact one, stays inside the exact dilation by r + ρ), the goal's
// component holds none of the object's grasp positions; so with every object at its start it
// cannot reach the goal either (more obstacles, less freespace) — and it can once the blocker
// is removed (in F_pair with no movable object, a subset of the freespace, the goal's component
// holds a grasp position). Whether the other objects also stand in the way is the NAMO caveat
// above: not checked.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::scenario {

// m added to r + ρmax for the pair disk: covers the baselines' grip gap and the executive's
// pair margin (5 mm) by which a gripped object sits off the nominal pair disk.
inline constexpr double kPairMargin = 0.01;
// m: the pair centre sits r + kGripOffset from the object's centre (<= kPairMargin, so the
// pair disk holds the object disk).
inline constexpr double kGripOffset = 0.005;
// Candidate grasp directions, evenly spaced from angle 0.
inline constexpr int kGraspDirections = 16;
// m: spacing of the grid searched for a parking spot (d).
inline constexpr double kParkingStep = 0.05;
// Relative shrink of the pair radius for the seal's superset test (> kMaxDilationError).
inline constexpr double kSealSlack = 0.01;

struct SolvabilityReport {
  bool solvable = false;                              // (a), (b), (c) and (d) hold
  bool connected = false;                             // (a) and (b)
  bool robot_connected = false;                       // (c)
  bool parking_found = false;                         // (d)
  geometry::Point parking = geometry::Point::Zero();  // the spot of (d) when found
  double pair_radius = 0;                             // R
  std::size_t pair_components = 0;                    // components (regions) of F_pair
  std::string failure;  // the first clause that failed, "" when solvable
};

// The certificate above for a validated scenario (scenario::validate); throws rearm::Error
// for a scenario without objects.
SolvabilityReport check_solvability(const Scenario& s);

// For each object of a validated scenario: true when it is walled in at the start, that is,
// when the robot, with every object where it stands, reaches from its start none of the
// object's kGraspDirections robot grasp positions p + (r + ρ + kGripOffset)·u. Tested in a
// superset of the robot's freespace (W − round dilations of the fixed obstacles by r⁻ − the
// inscribed kDiskPolygonSides-gons of radius ρ_j + r⁻ about every object, r⁻ = r / (1 +
// kSealSlack)), as check_seal does, so "walled in" is a proof; with the objects removed the
// certificate above reaches every object, so the walls are other objects.
std::vector<bool> walled_in_objects(const Scenario& s);

struct SealReport {
  bool sealed = false;  // the object's pair cannot reach the goal past the blocker
  bool opens = false;   // it can once the blocker is removed (no movable object in the way)
  std::string failure;  // "" when both hold
};

// The seal test above for objects[object] (its pair radius r + ρ_object), the goal point and
// the blocker objects[blocker]; throws rearm::Error for an index out of range or equal ones.
SealReport check_seal(const Scenario& s, std::size_t object, std::size_t blocker,
                      const geometry::Point& goal);

}  // namespace rearm::scenario
