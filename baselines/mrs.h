// B1 = mRS (Krontiris & Bekris, RSS 2015): depth-first search over the order in which objects
// are moved, each object moved once, straight to its goal (a "monotone" rearrangement). Complete
// for monotone instances, given complete motion queries; it cannot solve an instance where some
// goal is occupied by an object that has not moved yet in every order (e.g. the cyclic shift of
// the paper's Fig. 5), and it says so: when every branch of the search failed for a reason of
// exact geometry (move_planner.h: proves_impossible), the instance is reported infeasible for
// B1 ("non-monotone"), not merely unsolved.
//
// The search remembers the sets of moved objects from which it failed, so it visits at most 2^N
// sets rather than N! orders; its time still grows exponentially with N in the worst case.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "baselines/move_planner.h"

namespace rearm::baselines {

struct PlannerOptions {
  double time_limit = 10.0;  // s of wall time for the whole trial (> 0)
  std::uint64_t seed = 0;
  int iterations_per_query = 20000;  // RRTConnect iterations before one query gives up
  // Motion queries (transit and transfer, straight-line checks included) before the search
  // gives up (0: no limit; QueryContext::max_queries). Unlike time_limit it is a
  // deterministic budget: a search it ends gives the same result on any machine and at any
  // load, which the Monte Carlo sweeps need (their rows must not depend on the thread count).
  long max_queries = 0;
};

// The monotone search from arrangement `a` (robot at `robot`; nullopt: transits left to the
// caller) moving each object of `which` once to targets[i] (inside regions[i] when set), then,
// if robot_goal is set, the robot there. Also B2's local planner.
struct MonotoneResult {
  bool solved = false;
  bool proven_impossible = false;  // every branch failed by exact geometry
  bool non_monotone = false;       // ... and every failure was a goal occupied by an object
  bool timeout = false;
  std::vector<ObjectMove> moves;
  std::vector<Point> final_transit;
  Arrangement reached;
  std::optional<Point> robot_after;
  std::string reason;  // when not solved: the failures seen, e.g. "M1: target occupied by M2"
};
MonotoneResult monotone_search(const MovePlanner& planner, const Arrangement& a,
                               std::optional<Point> robot, const std::vector<std::size_t>& which,
                               const Arrangement& targets,
                               const std::vector<std::optional<geometry::Polygon>>& regions,
                               std::optional<Point> robot_goal, QueryContext& ctx);

// The PlanResult of a planner that is one such search (mRS, fmRS): the counters, the plan when
// solved, and the verdicts of a spent query budget (unsolved) or time limit (timeout). Returns
// false when the search ended otherwise: the caller states its own verdict and reason.
bool search_plan_result(const MonotoneResult& m, const QueryContext& ctx, double time_limit,
                        PlanResult& out);

// B1 on a problem: every object with a goal whose start is outside its goal region is moved.
PlanResult plan_mrs(const RearrangementProblem& problem, const BaselineParams& params,
                    const PlannerOptions& options);

}  // namespace rearm::baselines
