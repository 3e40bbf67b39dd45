// The Box2D plan executor of the baselines (docs/experiments.md, "Baseline"): replays a
// rearrangement plan (plan.h) in a sim::SimWorld with the robot driven by (v, ω) every step, and
// logs what happened in the metrics' terms (collisions, minimum clearance, simulated and wall
// time, path lengths, actions named as rearm's executive names them).
//
// The primitives (plan.h):
//  - transit (robot centre polyline): turn in place towards the next vertex, drive straight to
//    it; then turn in place to the grasp heading and dock, driving straight ahead until the
//    robot's boundary is grip_gap from the object's; then SimWorld::grip.
//  - transfer (pair centre polyline): the off-axis unicycle law (the paper's gripping Jacobian
//    T(ψ)⁻¹): for a desired velocity u of the pair centre p = x + ℓ·h(ψ), v = u·h and
//    ω = u·h⊥/ℓ, with u = s·t̂ + k·(p_ref − p) and a reference point p_ref advancing along the
//    polyline at s; u is scaled down to respect v_max and ω_max and the reference is slowed by
//    the same factor, so p stays on the path. h is evaluated at the step's mean heading
//    ψ + ω·dt/2, which makes the exact unicycle step move p by dt·sinc(ω·dt/2)·u, and the
//    reference stops on every vertex: the pair centre stays within ~1e-8 m of the polyline in
//    free space, corners included, and the heading follows dψ/ds = sin(θ − ψ)/ℓ, the model the
//    planners predict the release heading (and the object's landing) with.
//  - release: one still step, SimWorld::release, back off straight (standoff − grip_gap) along
//    the heading the robot has.
// Every plan the validator accepts keeps the robot grip_gap from an object at the grip, so
// ExecutionLog::min_clearance is at most grip_gap; sim::SimConfig::grip_reach must exceed
// grip_gap (and the grip cone the heading error at the dock, ~1e-9 rad).
// An ObjectMove with held_at_start starts at its transfer (the robot already holds the object).
// After the moves the robot follows final_transit like a transit.
//
// The executor is incremental (load, tick, interrupt, load again) so that the replanning variant
// can interleave sensing and replanning with execution; execute_plan runs a whole plan.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "baselines/plan.h"
#include "baselines/problem.h"
#include "geometry/clearance_by_kind.h"
#include "scenario/scenario.h"
#include "sim/sim_world.h"

namespace rearm::baselines {

struct ExecutionOptions {
  bool record = true;         // keep the robot's pose and the objects' centres at every step
  double time_budget = 1200;  // s of simulated time (world time); the caller passes the scenario's
  // m: the robot centre's distance from the straight segment it drives (transit, dock, back-off,
  // final transit) and the pair centre's distance from its reference point (transfer) beyond
  // which the execution fails. In free space both stay below 1e-6 m; exceeding 2 cm means a
  // contact pushed the robot off its plan.
  double tracking_tolerance = 0.02;
  // s: the world's fixed step (sim::SimConfig::dt). The commands land exactly on their targets
  // only with the world's step; the first tick checks it against SimWorld::time() and throws
  // rearm::Error on a mismatch. execute_plan sets it from the scenario.
  double dt = 0.01;
};

enum class ExecStatus { kCompleted, kFailed, kTimeout, kInterrupted };
const char* to_string(ExecStatus s);  // "completed", "failed", "timeout", "interrupted"

// One action in rearm's vocabulary: "grasp(M1)" (transit start .. gripped), "release(M1,l2)"
// (transfer start .. backed off; "release(M1)" when the object has no goal region), "move(l1)"
// (the final transit; "move" when the robot has no goal region).
struct ExecutedAction {
  std::string action;
  double t_start = 0, t_end = 0;  // s, world time
  std::string outcome;            // "succeeded", "failed", "timeout", "interrupted"
};

// Everything a run leaves. Counters and paths accumulate over every plan loaded into one
// executor; status and reason are the last plan's (meaningful once it finished).
struct ExecutionLog {
  ExecStatus status = ExecStatus::kCompleted;
  std::string reason;  // why not completed
  int collisions = 0;  // touching BeginContacts during the executor's steps (sim/)
  std::vector<std::string> collision_events;  // sim::SimWorld::collision_events, whole run
  double min_clearance = std::numeric_limits<double>::infinity();  // m, ground truth, every step
  geometry::ClearanceByKind clearance_by_kind;  // the same per kind of thing (robot, held object)
  double sim_time = 0;                          // s, world time
  long steps = 0;                               // steps taken by the executor
  double wall_time = 0;                         // s of wall time spent inside tick()
  double robot_path_length = 0;                 // m, robot centre, sum of per-step displacements
  double object_path_length = 0;                // m, summed over objects
  std::vector<ExecutedAction> actions;
  std::vector<sim::Pose> robot;      // every step when recording, the pose at construction first
  std::vector<Arrangement> objects;  // the same steps, object centres
  Arrangement objects_end;
  bool goals_reached = false;       // problem.goals_reached(objects_end)
  bool robot_goal_reached = false;  // inside robot_goal_region (true when there is none)
  std::size_t moves_done = 0;       // object moves completed (released and backed off), all plans
};

class PlanExecutor {
 public:
  // A swept disk of what remains: the robot disk (radius r) along transits, docks, back-offs and
  // the final transit; the pair disk (pair_radius) along transfers, with `held` the object it
  // carries. `move` is the plan's move index (nullopt for the final transit). The current
  // phase's path starts at the robot's (or the pair's) current centre.
  enum class SweepKind { kTransit, kDock, kTransfer, kBackOff, kFinalTransit };
  struct Sweep {
    SweepKind kind = SweepKind::kTransit;
    std::optional<std::size_t> move;
    std::vector<Point> path;
    double radius = 0;
    std::optional<std::size_t> held;
  };

  // The world must be built from the problem's scenario (same objects, in order); the executor
  // steps it and nothing else may until the executor is done with it. World and problem are
  // referenced and must outlive the executor. Throws rearm::Error for inconsistent sizes or
  // invalid options.
  PlanExecutor(sim::SimWorld& world, const RearrangementProblem& problem,
               const BaselineParams& params, const ExecutionOptions& options = {});
  ~PlanExecutor();
  PlanExecutor(const PlanExecutor&) = delete;
  PlanExecutor& operator=(const PlanExecutor&) = delete;

  // Replaces what remains of the current plan by `plan`, run from the world's current state.
  // Throws rearm::Error for object indices out of range or non-finite numbers; a plan that does
  // not start where the robot is (by more than tracking_tolerance) or that does not hold the
  // object the robot holds (held_at_start) fails at the first tick, as a value.
  void load(const Plan& plan);
  // One control step: SimWorld::step exactly once and true; or false without stepping when the
  // plan is finished (completed, failed, interrupted, out of time) or none is loaded.
  bool tick();
  bool finished() const;
  // Stops here: the current plan ends kInterrupted (the current action too), the robot keeps
  // what it holds. Load a new plan to go on.
  void interrupt();

  // The rest of the current phase's path, then every later phase of the plan (see Sweep).
  std::vector<Sweep> remaining() const;
  std::size_t move_index() const;  // the current move (moves.size() in the final transit)
  std::optional<std::size_t> held() const;

  const ExecutionLog& log() const;
  // Fills objects_end, goals_reached and robot_goal_reached from the world and returns the log.
  // A plan still running is interrupted first.
  ExecutionLog finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Builds a SimWorld from the scenario (sim::config_for(s)), executes the whole plan (dt from the
// scenario), and returns the finished log. The problem must be the scenario's.
ExecutionLog execute_plan(const scenario::Scenario& s, const RearrangementProblem& problem,
                          const Plan& plan, const BaselineParams& params,
                          const ExecutionOptions& options = {});

}  // namespace rearm::baselines
