// The closed loop of one task without Box2D concerns (docs/architecture.md, "A control tick"):
// plant → perception (object positions, sensor update) → executive (mission controller,
// topology check, reactive controller) → gripper and (v, ω) → plant, at a fixed step, until
// the task ends with a reason (mission complete, mission infeasible, an action stuck, the time
// budget exhausted). The plant is the ground truth for collisions and clearance.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "executive/executive.h"
#include "executive/plant.h"
#include "executive/region.h"
#include "geometry/clearance_by_kind.h"
#include "ltl/formula.h"
#include "perception/sensor.h"
#include "perception/world.h"
#include "reactive/model_space.h"
#include "symbolic/action.h"

namespace rearm::executive {

// Everything a task needs besides the plant: the world as the plant starts it (the ground
// truth perception reads from), the regions, the formula and the robot.
struct TaskSpec {
  perception::World world;
  std::vector<RegionOfInterest> regions;
  ltl::Formula formula;                     // φ over move(l), grasp(M), release(M,l), parsed
  std::optional<symbolic::Action> initial;  // π0 (Appendix I-B); none: the empty symbol
  perception::SensorParams sensor{3.0};
  perception::ChangeTolerances map_tolerances;
  ExecutiveParams executive;
  ltl::TranslateOptions translate;
};

struct TaskOptions {
  double dt = reactive::kDefaultStep;  // s
  double max_time = 1200;              // s of simulated time (the time budget)
  bool record_path = true;
  // Checked mode: after every tick's command, the closed loop's invariants: (v, ω) finite; the
  // robot and the object it holds (the plant's ground-truth clearance) overlapping nothing by
  // more than kInvariantSlop; and, for the reactive law's commands, det Dh > 0 at the centre
  // and its model point strictly inside the model freespace (Executive::law_invariant_violation);
  // the gripper opening only after a tick at rest (v = ω = 0: a pair let go while moving slides
  // on). A violation throws rearm::InvariantViolation naming the time, the action and the breach.
  bool check_invariants = false;
  // Track TaskResult::clearance_by_kind on every tick (a point-to-polygon distance per obstacle
  // per tick; off in sweeps).
  bool clearance_by_kind = false;
  // Record TaskResult::spaces and model_path (the paper's video: semantic, mapped and model
  // spaces side by side); needs record_path.
  bool record_spaces = false;
};

// The mapped and model spaces of one diffeomorphism build (Appendix II; [7]), from the tick
// that first used it.
struct SpacesSnapshot {
  double t = 0;                 // s
  int build = 0;                // the controller's rebuild count (ReactiveController::rebuilds)
  geometry::Region freespace;   // F_k, the robot's (or pair's) freespace component
  geometry::Polygon enclosing;  // F_e
  reactive::ModelSpace model;   // F_e with model disks and unknown convex obstacles
};

// m: the overlap the checked mode tolerates, Box2D's linear slop (b2_linearSlop, the
// penetration its contact solver allows); the kinematic plant's exact geometry meets it too.
inline constexpr double kInvariantSlop = 0.005;

struct TaskResult {
  TaskStatus status = TaskStatus::kRunning;
  std::string reason;
  std::vector<ActionRecord> actions;
  int fix_mode_entries = 0;
  RecoveryCounts recoveries;  // the robust variant's recoveries (executive.h)
  int collisions = 0;
  std::vector<std::string> collision_events;  // Plant::collision_events
  double min_clearance = 0;                   // m, ground truth over every step
  // The same per kind of thing (TaskOptions::clearance_by_kind; +infinity when not tracked).
  geometry::ClearanceByKind clearance_by_kind;
  double sim_time = 0;  // s
  int steps = 0;
  double robot_path_length = 0;   // m
  double object_path_length = 0;  // m, summed over objects
  double controller_time = 0;     // s of wall time inside Executive::step
  // The compute split (s of wall time): the mission controller (building the automaton, G and
  // d_F before the first step, then its decisions), the topology checks, the diffeomorphism
  // rebuilds, and the rest of Executive::step (control). They add up to compute_time().
  double mission_time = 0;
  double topology_time = 0;
  double rebuild_time = 0;
  double control_time = 0;
  double compute_time() const { return mission_time + topology_time + rebuild_time + control_time; }
  // The compute (s of wall time) before the robot's first act: the mission set-up and every
  // Executive::step up to and including the first tick whose command moves the robot or the
  // gripper (v or ω non-zero, or a grip or release). NaN when the task ended without one. A
  // planner's counterpart is its planning time (it acts once its plan is complete).
  double first_action_time = std::numeric_limits<double>::quiet_NaN();
  double wall_time = 0;  // s of wall time for the whole run
  int rebuilds = 0;
  int topology_checks = 0;
  std::vector<Pose> path;                        // robot poses (when recorded)
  std::vector<std::vector<Point>> object_paths;  // per object, centres (when recorded)
  // TaskOptions::record_spaces: one snapshot per build, and per tick the law's model point
  // h(x) (NaN on ticks whose command did not come from the law).
  std::vector<SpacesSnapshot> spaces;
  std::vector<Point> model_path;
};

// Runs the task on `plant` (whose objects are in the world order of spec.world.movable). The
// formula is checked against the world's names (objects and regions); bad input
// (a malformed formula, unknown names, invalid regions or parameters) throws rearm::Error
// before the first step. Everything that happens afterwards is a value in the result.
TaskResult run_task(const TaskSpec& spec, Plant& plant, const TaskOptions& options = {});

}  // namespace rearm::executive
