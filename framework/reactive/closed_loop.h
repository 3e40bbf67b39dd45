// The kinematic closed loop (docs/reactive.md §6): a fixed-step integrator (default 0.01 s, the
// reference's ode45 MaxStep) of the robot under the reactive controller, with the map update
// between steps and the controller rebuilt only when the map changed. Independent of Box2D:
// the same loop runs in tests and benchmarks, and under the executive.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "reactive/reactive_controller.h"

namespace rearm::reactive {

struct ClosedLoopOptions {
  RobotModel model = RobotModel::kUnicycle;
  double dt = kDefaultStep;      // s
  double max_time = 600;         // s of simulated time before giving up
  double goal_tolerance = 0.05;  // m: reached when the controlled centre is this close
  double radius = 0.2;           // robot radius r (m)
  double carried_radius = 0;     // ρ_i > 0: the robot carries an object (pair law, unicycle)
  bool record_path = true;
};

struct ClosedLoopResult {
  enum class Status { kReached, kTimeout, kError };
  Status status = Status::kTimeout;
  std::string message;  // the error, when status is kError
  double time = 0;      // simulated seconds
  int steps = 0;
  int rebuilds = 0;
  double min_clearance = 0;  // smallest value the clearance callback returned
  double max_v = 0;          // largest |v| (unicycle) or ‖ẋ‖ (holonomic) commanded
  double max_omega = 0;      // largest |ω| commanded
  std::vector<Pose> path;    // poses at every step (when recorded)
};

// Perception between steps: returns the new semantic map when it changed, nullopt otherwise
// (called at the start and after every step with the current pose).
using MapUpdate = std::function<std::optional<SemanticInput>(const Pose&)>;
// The true clearance of the robot (or pair) at a pose, measured by the caller against the
// ground truth (negative inside an obstacle); the loop records its minimum.
using Clearance = std::function<double(const Pose&)>;

// Drives the robot from `start` until its controlled centre (the robot, or the pair centre
// when carrying) is within goal_tolerance of `goal`. Errors of the controller (a state that
// left the freespace, a goal that became unreachable) end the run with kError and the message;
// invalid options throw rearm::Error.
ClosedLoopResult run_closed_loop(ReactiveController& controller, const Pose& start,
                                 const Point& goal, const MapUpdate& sense,
                                 const Clearance& clearance, const ClosedLoopOptions& options);

}  // namespace rearm::reactive
