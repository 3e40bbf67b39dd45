// A rearrangement plan (docs/experiments.md, "Baseline"): object moves, each a transit of the
// robot alone, a grasp, a transfer of the robot–object pair and a release, followed by an
// optional final transit to the robot's goal region. The Box2D executor (executor.h) replays
// it; the validator (validator.h) checks it against exact geometry, independently of the
// planners' own validity checks.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "baselines/problem.h"

namespace rearm::baselines {

struct ObjectMove {
  std::size_t object = 0;
  // Set only by the replanning variant: the robot already holds the object, so the move has no
  // transit, turn, dock or grip, and the transfer starts at the pair's current centre.
  bool held_at_start = false;
  Point from = Point::Zero(), to = Point::Zero();  // object centres
  // Robot centre, piecewise linear, from where the robot is to the standoff pose
  // standoff_position(from, r, ρ, grasp_heading): the robot turns in place at each vertex and
  // drives straight between them, then turns to grasp_heading and docks straight ahead.
  std::vector<Point> transit;
  double grasp_heading = 0;
  // Pair centre (pair_offset ahead of the robot's centre), piecewise linear, from the grip to
  // the release: from grip_position(from, ..., grasp_heading) + ℓ·h(grasp_heading) to
  // to − (r + gap/2)·h(release_heading). Its last segment is the straight approach, at least
  // max(approach_min, approach_factor·ℓ) long. Tracked by the off-axis law (the paper's
  // gripping Jacobian), so the robot's heading is free inside the pair disk, which holds robot
  // and object at any heading; release_heading is the heading that law reaches at the end
  // (tracked_heading), which decides where the object lands (`to`).
  std::vector<Point> transfer;
  double release_heading = 0;
};

struct Plan {
  std::vector<ObjectMove> moves;
  std::vector<Point> final_transit;  // robot centre to the robot goal (empty: none)
  Arrangement final_arrangement;
};

// How a planner run went (the metrics' planning_time_s, subqueries, nodes).
// kInfeasible: proven by exact geometry that the method cannot solve the instance (B1 on a
// non-monotone instance); kUnsolved: the search ended without a plan and without such a proof
// (some motion query failed); kTimeout: the time budget ran out first.
enum class PlanStatus { kSolved, kInfeasible, kUnsolved, kTimeout };
const char* to_string(PlanStatus s);  // "solved", "infeasible", "unsolved", "timeout"

struct PlanResult {
  PlanStatus status = PlanStatus::kTimeout;
  std::string reason;  // why not solved; for kInfeasible, the proof (e.g. "non-monotone ...")
  Plan plan;           // valid when solved
  double planning_time_s = 0;  // the planning thread's CPU time (what the budget counts)
  double planning_wall_s = 0;  // wall time of the same
  bool wall_net = false;       // kTimeout by the wall-clock safety net, not the CPU budget
  long subqueries = 0;         // OMPL motion queries (transit and transfer) posed
  long nodes = 0;  // states in every RRTConnect tree, summed (+ arrangement nodes for B2)
  long arrangement_nodes = 0;  // B2's two arrangement trees, summed
  long queries = 0;            // motion queries, straight-line checks included
};

}  // namespace rearm::baselines
