// The rearrangement problem the sampling-based baselines solve (docs/experiments.md,
// "Baseline"; Krontiris & Bekris, RSS 2015 and ICRA 2016, the paper's reference [19]): a disk
// robot that moves disk objects one at a time, each carried as one robot–object disk of radius
// r + ρ_i (the paper's pair model), among polygonal obstacles that are all known offline.
//
// A scenario (scenario/) becomes a problem through its task: every release(M, l) atom gives
// object M the goal "inside region l" (its point target: executive::region_target), a move(l)
// atom gives the robot a final region. Rearrangement planners solve the final arrangement; the
// order the formula imposes is not theirs to keep, and they plan no patrols: a formula built
// of anything but action atoms, && and <> is rejected with a clear error.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::baselines {

using geometry::Point;
using Arrangement = std::vector<Point>;  // object centres, scenario object order

// Geometry of the manipulation primitives and the planners' clearances. Every length in m.
struct BaselineParams {
  // Robot boundary to object boundary at the pre-grasp pose and after backing off a release.
  double standoff = 0.03;
  // Robot boundary to object boundary while the object is held (the dock drives standoff −
  // grip_gap forward; sim::SimConfig::grip_reach must exceed grip_gap).
  double grip_gap = 0.005;
  // Clearance a motion query demands of the robot disk (transit) and of the pair disk
  // (transfer) along every path segment, on top of the disk itself. It absorbs the executor's
  // tracking error in Box2D (a few mm); the plan validator demands only >= 0.
  double transit_margin = 0.01;
  double transfer_margin = 0.02;
  // Minimum gap between two objects in an arrangement (placements, goals).
  double placement_margin = 0.02;
  // Every transfer ends with a straight approach of length max(approach_min, approach_factor ·
  // ℓ) (ℓ: the pair's offset below) towards the target. Along it the off-axis tracking law turns
  // the robot's heading onto the approach direction (tracked_heading: the heading error decays
  // like exp(−s/ℓ) over distance s), so the object lands within a few cm of the target; the
  // plan records where exactly (the predicted heading at the release).
  double approach_min = 0.3;
  double approach_factor = 3.0;
  int directions = 16;  // candidate grasp / release headings, evenly spaced
  // RRTConnect's range (m); 0 = OMPL's default (a fifth of the space's extent).
  double range = 0.0;
};

struct RearrangementProblem {
  std::string name;
  geometry::Polygon workspace;
  std::vector<geometry::Polygon> obstacles;  // every familiar and unknown obstacle (full map)
  std::size_t familiar_count = 0;            // obstacles[0, familiar_count) are the familiar
  std::vector<std::string> obstacle_names;
  double robot_radius = 0.2;
  Point robot_start = Point::Zero();
  double robot_heading = 0;
  double v_max = 0.4, omega_max = 1.0;
  std::vector<std::string> object_names;
  std::vector<double> object_radii;  // ρ_i
  Arrangement start;
  // Per object: the goal point and the region it must end inside; nullopt = the task does not
  // release this object (it may be moved, and ends anywhere).
  std::vector<std::optional<Point>> goals;
  std::vector<std::optional<geometry::Polygon>> goal_regions;
  std::vector<std::string> goal_region_names;  // "" where no goal
  // The robot's final region (a move(l) atom), if any.
  std::optional<Point> robot_goal;
  std::optional<geometry::Polygon> robot_goal_region;
  std::string robot_goal_name;

  std::size_t object_count() const { return start.size(); }
  // The goal arrangement with unconstrained objects at their starts.
  Arrangement goal_arrangement() const;
  // Constrained objects inside their goal regions (exact point location of the centres).
  bool goals_reached(const Arrangement& a) const;
};

// The problem of a validated scenario. Throws scenario::ScenarioError(source, "task", reason)
// for a formula the baselines cannot plan for (patrols, negations, an object released twice, two
// robot goals) or one naming unknown objects or regions.
RearrangementProblem problem_from_scenario(const scenario::Scenario& s);

// Pair geometry (docs: "robot + object i as one disk of radius r + ρ_i"). With the object held
// at grip_gap in front of the robot, the smallest disk holding both is centred ℓ = ρ + gap/2
// ahead of the robot's centre, with radius r + ρ + gap/2.
double pair_offset(double rho, const BaselineParams& p);
double pair_radius(double r, double rho, const BaselineParams& p);
// Robot centre at the pre-grasp (or backed-off) pose for an object at o, robot heading psi.
Point standoff_position(const Point& o, double r, double rho, double psi, const BaselineParams& p);
// Robot centre while holding an object at o with heading psi.
Point grip_position(const Point& o, double r, double rho, double psi, const BaselineParams& p);
Point heading_vector(double psi);
// The robot's heading at the end of a pair-centre polyline tracked exactly by the off-axis law
// (v = u·h, ω = u·h⊥/ℓ; the paper's gripping Jacobian), starting at heading psi0. Along a
// segment of direction θ the angle φ = θ − ψ obeys dφ/ds = −sin φ / ℓ, so
// tan(φ/2) = tan(φ₀/2)·exp(−s/ℓ) in closed form (φ₀ = ±π, driving straight backwards, stays).
double tracked_heading(const std::vector<Point>& path, double psi0, double ell);
// Angle wrapped to (−π, π].
double wrap_angle(double a);

}  // namespace rearm::baselines
