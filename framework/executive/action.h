// The state of one action of the interface layer (paper §IV): what it is (MOVE, GRASP, RELEASE,
// DISASSEMBLE; LTL or Fix mode), the phase it is in, the knowledge its plan and its
// diffeomorphism were computed for, its progress monitor and the robust variant's per-action
// recovery state (docs/executive.md, "Recoveries: causes, units and the policy table"); and
// Advance, what one tick of an action gives.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "executive/map_news.h"
#include "executive/progress_monitor.h"
#include "executive/recovery_state.h"
#include "executive/release_pose.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "reactive/kinematics.h"
#include "symbolic/action.h"

namespace rearm::executive {

using geometry::Point;
using reactive::Twist;

enum class ActionKind { kMove, kGrasp, kRelease, kDisassemble };
enum class ActionPhase { kNavigate, kAlign, kDock, kGrip, kWithdraw, kOpen, kBackOff };

// A way the topology check found closed by objects (Appendix III): from the centre `from` to x*
// `to`, for a disk of `radius`.
// `fragments`: the check counted the visible unknown fragments as fixed obstacles
// (recovery_plan_among_fragments.cpp). `movers`: the objects Fix mode moves to open it, as they
// lay when it was entered, and their ids; `path`: from `from` to `to` with the movers removed
// (targets.h, way_path), empty when none was found.
struct Way {
  Point from = Point::Zero();
  Point to = Point::Zero();
  double radius = 0;
  bool fragments = false;
  std::vector<geometry::Disk> movers;
  std::vector<std::string> mover_ids;
  std::vector<Point> path;
  int checks = 0;  // drop candidates checked exactly against it (targets.cpp, kMaxWayChecks)
};

struct ActionState {
  ActionKind kind = ActionKind::kMove;
  std::string object;
  std::string region;
  bool fix = false;
  symbolic::Action ltl;  // the automaton's action (LTL actions only)
  ActionPhase phase = ActionPhase::kNavigate;
  double t_start = 0;
  double phase_start = 0;
  int interruptions = 0;
  // Planning state: the knowledge the target and topology verdict were computed for.
  bool planned = false;
  std::size_t plan_familiar = 0;
  std::vector<geometry::Disk> plan_movable;
  std::optional<std::string> plan_carried;
  std::optional<Point> target;
  std::string note;          // how navigation ended (reached x*, or stopped early), for the log
  bool open_sent = false;    // Phase::kOpen: the open command was given
  double withdrawn = 0;      // Phase::kWithdraw: m reversed so far
  double withdraw_goal = 0;  // Phase::kWithdraw: m to reverse (withdraw_distance)
  bool bare = false;         // planned at the bare radius r: the contact margin alone closed x*
  std::optional<Way> blocked_way;  // the way the last plan found closed by objects (Fix mode's)
  // RELEASE, RobustParams::release_pose: the pose it sets the object down from, and whether the
  // straight last stretch (lead-in to x*) has begun.
  std::optional<ReleasePose> pose;
  bool pose_stretch = false;
  // Reactive rebuild state.
  std::uint64_t built_version = 0;
  bool built = false;
  Point built_target = Point::Zero();
  double built_radius = 0;
  std::uint64_t checked_version = 0;  // the map version the approach point was checked for
  // RobustParams::defer: the map the diffeomorphism was built for, and the distance of the
  // news since then from the centre `news_at`, computed for map version `news_version`.
  MapSnapshot built_map;
  std::uint64_t news_version = 0;
  double news = std::numeric_limits<double>::infinity();
  Point news_at = Point::Zero();
  Point goal = Point::Zero();  // x* as the controller holds it (snapped onto F_k)
  ProgressMonitor monitor;
  // The robust variant's recovery units, one slice each (executive/recovery_state.h).
  GuideState guide;
  BackUpState back_up;
  DropState drop;
  FragmentPlanState fragment_plan;
  BlockerState blockers;
  OnceState once;
  std::string name() const;
};

enum class GripperAction { kNone, kClose, kOpen };

// A new action in its first phase at time t, its progress monitor started.
ActionState make_action(ActionKind kind, std::string object, std::string region, bool fix, double t,
                        const ProgressParams& progress);

// What advancing the current action by one tick gave.
struct Advance {
  enum Kind { kCommand, kDone, kInfeasible, kBlocked, kStuck, kRestart } kind = kCommand;
  Twist u;
  std::string reason;
  std::vector<std::string> blocking;  // B_M, top last (kBlocked)
  bool center_not_free = false;       // rebuild(): the centre left its freespace
  // kCommand: the gripper action to perform before the step (dock closes, open opens) and the
  // object to close on; whether u is the reactive law's command.
  GripperAction gripper = GripperAction::kNone;
  std::string grip_object;
  bool law = false;
};

// An Advance that ends the action stuck, or infeasible, with `reason`.
Advance stuck(std::string reason);
Advance infeasible(std::string reason);
// An Advance that ends this transition (the action goes on at the next one, this tick).
Advance restart();

}  // namespace rearm::executive
