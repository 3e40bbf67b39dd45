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
//  - Fix mode is bounded: at most max_fix_rounds entries per LTL action and a stack of at most
//    2 × (objects + 1) actions, after which the task ends stuck with the reason.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "executive/interface_layer.h"
#include "executive/plant.h"
#include "executive/progress_monitor.h"
#include "executive/region.h"
#include "perception/semantic_map.h"
#include "reactive/params.h"
#include "reactive/reactive_controller.h"
#include "symbolic/mission_controller.h"
#include "topology/topology_check.h"

namespace rearm::executive {

struct ExecutiveParams {
  double robot_radius = 0.2;  // r (m)
  reactive::DiffeoParams diffeo;
  reactive::NavParams nav;
  GraspParams grasp;
  ProgressParams progress;
  double goal_tolerance = 0.05;        // m: MOVE, RELEASE, DISASSEMBLE reach x*
  double grasp_goal_tolerance = 0.01;  // m: the robot reaches the grasp approach point
  double align_tolerance = 1e-3;       // rad: the gripper faces the object
  double dock_speed = 0.05;            // m/s
  double backoff_speed = 0.1;          // m/s
  // After a release the robot backs off until its centre is this far (m) outside the released
  // object's dilated polygon (circumradius (ρ_i + r)/cos(π/32)).
  double backoff_margin = 0.01;
  double phase_timeout = 30;  // s allowed for align, dock and back off
  int max_fix_rounds = 8;     // Fix mode entries per LTL action
  // LTL actions after which the task ends (0: none): completed when the mission is then
  // accepting (a patrol run for a fixed number of visits), timeout otherwise.
  int max_ltl_actions = 0;
};

// Throws rearm::Error naming the first invalid field.
void validate(const ExecutiveParams& p);

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

enum class GripperAction { kNone, kClose, kOpen };

struct Command {
  Twist u;
  GripperAction gripper = GripperAction::kNone;
  std::string object;  // the object to close on
};

// Wall time (s) the executive spent in each part of its work, for the compute split of a run:
// the mission controller's decisions and reports (paper §III), the topology checks and the
// freespaces the interface layer derives from them (Appendix III), and the diffeomorphism
// rebuilds of the reactive controller ([7], Appendix II). The rest of Executive::step is
// control (the law's evaluation, phases, targets).
struct ComputeTimes {
  double mission_s = 0;
  double topology_s = 0;
  double rebuild_s = 0;
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
  const ComputeTimes& compute_times() const { return times_; }
  bool in_fix_mode() const { return !fix_.empty(); }
  // "move(l1)" etc., or "" when idle.
  std::string current_action() const;
  const reactive::ReactiveController& controller() const { return controller_; }

 private:
  enum class Kind { kMove, kGrasp, kRelease, kDisassemble };
  enum class Phase { kNavigate, kAlign, kDock, kGrip, kOpen, kBackOff };

  struct Activity {
    Kind kind = Kind::kMove;
    std::string object;
    std::string region;
    bool fix = false;
    symbolic::Action ltl;  // the automaton's action (LTL actions only)
    Phase phase = Phase::kNavigate;
    double t_start = 0;
    double phase_start = 0;
    int interruptions = 0;
    // Planning state: the knowledge the target and topology verdict were computed for.
    bool planned = false;
    std::size_t plan_familiar = 0;
    std::vector<geometry::Disk> plan_movable;
    std::optional<std::string> plan_carried;
    std::optional<Point> target;
    std::string note;        // how navigation ended (reached x*, or stopped early), for the log
    bool open_sent = false;  // Phase::kOpen: the open command was given
    // Reactive rebuild state.
    std::uint64_t built_version = 0;
    bool built = false;
    Point built_target = Point::Zero();
    double built_radius = 0;
    ProgressMonitor monitor;
    std::string name() const;
  };

  // What advancing the current activity by one tick gave.
  struct Advance {
    enum Kind { kCommand, kDone, kInfeasible, kBlocked, kStuck, kRestart } kind = kCommand;
    Twist u;
    std::string reason;
    std::vector<std::string> blocking;  // B_M, top last (kBlocked)
  };

  Activity* current();
  Activity make(Kind kind, std::string object, std::string region, bool fix, double t) const;
  bool fetch_ltl(double t);
  Advance advance(Activity& a, const Pose& pose, double t, double dt);
  Advance navigate(Activity& a, const Pose& pose, double t, double dt);
  Advance plan(Activity& a, const Pose& pose);
  Advance plan_grasp(Activity& a, const Pose& pose);
  void end_current(ActionOutcome outcome, const std::string& reason, double t);
  void enter_fix(const std::vector<std::string>& blocking, double t);
  void finish(TaskStatus status, const std::string& reason, double t);
  reactive::SemanticInput semantic_input() const;
  // The topology check of Appendix III for a disk of `radius` at x and the target (no carried
  // object excluded), its time added to times_.topology_s.
  topology::TopologyResult timed_check(double radius, const Point& x, const Point& target);
  const RegionOfInterest& region(const std::string& id) const;
  double object_radius(const std::string& id) const;
  bool knowledge_changed(const Activity& a) const;

  ExecutiveParams p_;
  std::vector<RegionOfInterest> regions_;
  symbolic::MissionController& mission_;
  const perception::SemanticMap& map_;
  reactive::ReactiveController controller_;
  // Workspace erosions, obstacle dilations and bound − ∪fixed, kept across topology checks (they
  // change only when a familiar obstacle is localized or the radius changes).
  topology::TopologyCache topology_cache_;
  std::optional<Activity> ltl_;  // the current LTL action (suspended while fix_ is not empty)
  std::vector<Activity> fix_;    // Fix-mode actions, back() runs first
  int fix_rounds_ = 0;           // Fix mode entries for the current LTL action
  int fix_entries_ = 0;
  int ltl_done_ = 0;
  int topology_checks_ = 0;
  ComputeTimes times_;
  GripperAction gripper_ = GripperAction::kNone;
  std::string gripper_object_;
  std::vector<ActionRecord> log_;
  TaskStatus status_ = TaskStatus::kRunning;
  std::string reason_;
};

}  // namespace rearm::executive
