// fmRS, the fast extension primitive of Krontiris & Bekris ("Efficiently solving general
// rearrangement tasks: a fast extension primitive for an incremental sampling-based planner",
// ICRA 2016), adapted to the paper's mobile robot. For each object to move, a
// minimum-constraint-removal path (mcr.h) for its transfer (the robot–object pair disk, from
// the grip to the release approach) and for the robot's transit to it (the robot disk, from the
// robot's place at the start of the call to a pre-grasp pose), the constraints being every other
// moving object at its current and at its target place. A path crossing object j where j is now
// means j must move first; crossing j's target means j must move after. These constraints form
// the dependency graph; fmRS moves the objects in a topological order, each once, without
// backtracking: a cycle, or a move the motion queries then fail to plan, ends the attempt.
//
// Where the mobile robot departs from the arm of the paper: (1) the transit's start depends on
// the order (the robot stands where the previous release left it); the graph is built before
// the order exists, so transits are constrained from the robot's place at the start of the
// call, as the arm's from its rest pose, and a transit the order then closes fails when it is
// planned; (2) objects that do not move in the call (no goal, or not chosen by BiRRT's
// extension) are fixed obstacles for the MCR paths, since fmRS has no place to put them;
// (3) every path is then re-planned by the same OMPL motion queries as mRS's (move_planner.h),
// so fmRS's plans are checked like every baseline's; the MCR grid only decides the order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "baselines/mcr.h"
#include "baselines/mrs.h"

namespace rearm::baselines {

struct FmrsOptions {
  double grid_step = 0.1;  // m: the MCR grid (half the robot's radius)
};

// For each moved object (index k into `which`): the indices into `which` of the objects that
// must move before it. `unreachable`: objects with no MCR path even crossing every constraint.
struct FmrsDependencies {
  std::vector<std::vector<std::size_t>> before;
  std::vector<std::size_t> unreachable;
};

// A topological order of the graph (Kahn's, the smallest index first), or the members of one
// cycle (in the order they depend on each other) when there is none.
struct TopologicalOrder {
  std::vector<std::size_t> order;
  std::vector<std::size_t> cycle;  // non-empty when no order exists
};
TopologicalOrder topological_order(const std::vector<std::vector<std::size_t>>& before);

class Fmrs {
 public:
  Fmrs(const MovePlanner& planner, const FmrsOptions& options);

  FmrsDependencies dependencies(const Arrangement& a, std::optional<Point> robot,
                                const std::vector<std::size_t>& which,
                                const Arrangement& targets) const;

  // monotone_search's contract (mrs.h) by fmRS: solved, or the reason it stopped (a cycle, an
  // unreachable object, a failed move); never proven_impossible (fmRS searches no orders).
  MonotoneResult solve(const Arrangement& a, std::optional<Point> robot,
                       const std::vector<std::size_t>& which, const Arrangement& targets,
                       const std::vector<std::optional<geometry::Polygon>>& regions,
                       std::optional<Point> robot_goal, QueryContext& ctx) const;

 private:
  McrQuery transfer_query(const Arrangement& a, std::size_t i, const Point& target) const;
  McrQuery transit_query(const Arrangement& a, const Point& robot, std::size_t i) const;

  const MovePlanner& planner_;
  McrRoadmap roadmap_;
};

// fmRS alone on a problem: every object with a goal it is not in, once, in the graph's order.
PlanResult plan_fmrs(const RearrangementProblem& problem, const BaselineParams& params,
                     const PlannerOptions& options, const FmrsOptions& fmrs = {});

}  // namespace rearm::baselines
