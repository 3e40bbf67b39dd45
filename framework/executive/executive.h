// The interface layer of paper §IV–V (docs/executive.md): it takes the symbolic controller's
// actions (LTL mode), turns each into a target x* and a gripper command, runs the topology
// check of Appendix III when the map or the action changes, rearranges blocking objects in
// Fix mode (GRASP + DISASSEMBLE per object of B_M, disassembling a carried object first and
// re-grasping it after), reports successes and infeasible actions to the mission controller,
// and ends every action with a reason. It drives the reactive controller of [7]
// (reactive/reactive_controller.h); the plant and perception are the caller's (task_runner.h).
//
// Each action runs through phases:
//  - navigate: the reactive controller drives the robot (or the robot–object pair) to x*;
//  - GRASP only: align (turn in place until the gripper faces the object, paper §V-B), dock
//    (drive straight to dock_gap from contact), close the gripper and wait one tick for the
//    map to report the object carried;
//  - RELEASE and DISASSEMBLE: stop (one tick, so the object is let go at rest), open the
//    gripper (one tick), then back off straight until the robot is clear of the released
//    object's dilation (so the next action starts in the freespace).
//
// Choices beyond the paper (each documented where it is made):
//  - RELEASE(M, ℓ) without M in the gripper first grasps M, and GRASP(M) (or RELEASE of another
//    object) with another object in the gripper first disassembles that one: both as
//    interface-layer steps invisible to the automaton, logged as Fix-mode actions.
//  - An LTL action whose target is separated from the robot by the visible fragments of unknown
//    obstacles (which Appendix III does not consider: the paper's separation assumptions rule it
//    out) is reported infeasible; fragments are subsets of the true obstacles, so this is sound.
//  - An action that ends stuck (the progress monitor, after the robust variant's recoveries) is
//    reported infeasible to the mission controller, which picks an alternative (paper §III-A);
//    when none is left the task ends stuck, with every stuck action in the reason.
//  - Fix mode is bounded: at most max_fix_rounds entries per LTL action and a stack of at most
//    2 × (objects + 1) actions, after which the task ends stuck with the reason.
//  - The robust variant (RobustParams, the default; experiments/sweeps/README.md "Variants"):
//    guide paths after the progress monitor fires, convex pieces where h cannot be built or Dh
//    is singular, back-ups out of a dilation, a contact margin, drop points clear of everything
//    for DISASSEMBLE, and objects Fix mode displaced released again at the end. The paper
//    variant turns all of them off.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "executive/action.h"
#include "executive/context.h"
#include "executive/guide_path.h"
#include "executive/interface_layer.h"
#include "executive/map_news.h"
#include "executive/params.h"
#include "executive/plant.h"
#include "executive/progress_monitor.h"
#include "executive/region.h"
#include "executive/restores.h"
#include "perception/semantic_map.h"
#include "reactive/params.h"
#include "reactive/reactive_controller.h"
#include "symbolic/mission_controller.h"
#include "topology/topology_check.h"

namespace rearm::executive {

enum class TaskStatus { kRunning, kCompleted, kInfeasible, kStuck, kTimeout };
const char* to_string(TaskStatus s);  // "running", "completed", "infeasible", "stuck", "timeout"

enum class ActionOutcome { kSucceeded, kInfeasible, kStuck, kAbandoned };
const char* to_string(ActionOutcome o);

// One executed action, logged when it ends.
struct ActionRecord {
  std::string action;  // "move(l1)", "grasp(M1)", "release(M1,l2)", "disassemble(M2)"
  bool fix = false;    // a Fix-mode (or interface-layer) action, invisible to the automaton
  ActionOutcome outcome = ActionOutcome::kSucceeded;
  std::string reason;  // why it ended
  double t_start = 0;  // s
  double t_end = 0;
  int interruptions = 0;        // Fix mode entries while it was suspended
  std::optional<Point> target;  // its last x*
};

struct Command {
  Twist u;
  GripperAction gripper = GripperAction::kNone;
  std::string object;  // the object to close on
};

class Executive {
 public:
  // Validates the parameters and the regions (against the map's workspace). The mission
  // controller and the semantic map are the caller's and must outlive the executive; the
  // executive asks the first for actions and reports to it, and reads the second. The caller
  // performs the gripper actions and records the outcome in the map (set_carried): a GRASP
  // succeeds on the tick after the close command only if the map then reports the object
  // carried, and ends stuck otherwise.
  Executive(const ExecutiveParams& params, const std::vector<RegionOfInterest>& regions,
            symbolic::MissionController& mission, const perception::SemanticMap& map);
  // Its Context refers to its own members: neither copied nor moved.
  Executive(const Executive&) = delete;
  Executive& operator=(const Executive&) = delete;

  // One control tick at time t (s) with the robot's true pose; the caller has updated the
  // semantic map (objects and sensor) for this pose. Returns the command to hold for dt and the
  // gripper action to perform before the step. Once finished() it returns a stop command.
  Command step(const Pose& pose, double t, double dt);

  bool finished() const { return status_ != TaskStatus::kRunning; }
  TaskStatus status() const { return status_; }
  const std::string& reason() const { return reason_; }
  // Ends the task from outside (time budget, a gripper that failed to close); the current
  // action is logged as abandoned.
  void abort(TaskStatus status, const std::string& reason, double t);

  const std::vector<ActionRecord>& actions() const { return log_; }
  int fix_mode_entries() const { return fix_entries_; }
  int ltl_actions_completed() const { return ltl_done_; }
  int topology_checks() const { return topology_checks_; }
  int rebuilds() const { return controller_.rebuilds(); }
  // The last step's command came from the reactive law (its model point is
  // controller().last_law_sample().y).
  bool law_commanded() const { return law_command_; }
  const ComputeTimes& compute_times() const { return times_; }
  // The checked mode (task_runner.h): when the last step's command was the reactive law's, why
  // the law's state breaks [7]'s invariants (det Dh(x) <= 0 at the centre, or its model point
  // h(x) not strictly inside the model freespace); nullopt when it holds or the command was
  // not the law's (a back-up, a turn, a tracked step: each checked against the map instead).
  std::optional<std::string> law_invariant_violation() const;
  RecoveryCounts recoveries() const;
  bool in_fix_mode() const { return !fix_.empty(); }
  // "move(l1)" etc., or "" when idle.
  std::string current_action() const;
  const reactive::ReactiveController& controller() const { return controller_; }

 private:
  ActionState* current();
  bool fetch_ltl(double t);
  // The end of a mission that is accepting (completed, or stuck when a restore failed).
  void finish_accepting(double t);
  // Gripper prerequisites (interface-layer steps, beyond the paper; see the header comment),
  // then the navigation phase (navigate.h).
  Advance prerequisites_then_navigate(ActionState& a, const Pose& pose, double t, double dt);
  void end_current(ActionOutcome outcome, const std::string& reason, double t);
  void end_stuck(const std::string& reason, double t);
  // Logs every action on the Fix stack as abandoned (top first) and empties it.
  void abandon_fix(const std::string& why, double t);
  void enter_fix(const std::vector<std::string>& blocking, double t);
  void finish(TaskStatus status, const std::string& reason, double t);

  ExecutiveParams p_;
  std::vector<RegionOfInterest> regions_;
  symbolic::MissionController& mission_;
  const perception::SemanticMap& map_;
  reactive::ReactiveController controller_;
  topology::TopologyCache topology_cache_;  // Context::topology_cache
  reactive::DilationCache drop_dilations_;  // Context::drop_dilations
  std::optional<ActionState> ltl_;  // the current LTL action (suspended while fix_ is not empty)
  std::vector<ActionState> fix_;    // Fix-mode actions, back() runs first
  int fix_rounds_ = 0;              // Fix mode entries for the current LTL action
  int fix_entries_ = 0;
  int ltl_done_ = 0;
  int topology_checks_ = 0;
  bool law_command_ = false;  // the last step's command came from the reactive law
  Twist last_u_;              // the last step's command (open() lets go only after a stop)
  std::vector<geometry::Disk> keep_clear_;  // Context::keep_clear
  std::vector<Way> fix_ways_;               // Context::fix_ways
  ComputeTimes times_;
  RecoveryCounts recoveries_;
  Restores restores_;
  std::vector<ActionRecord> log_;
  std::string stuck_;  // the actions that ended stuck and were reported infeasible (paper §III-A)
  TaskStatus status_ = TaskStatus::kRunning;
  std::string reason_;
  Context ctx_;  // views of the members above for the executive's free functions (context.h)
};

}  // namespace rearm::executive
