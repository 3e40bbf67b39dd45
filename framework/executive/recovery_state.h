// The robust variant's per-action state, one slice per recovery unit (docs/executive.md,
// "Recoveries: causes, units and the policy table"): each slice is read and written by its
// unit's files and resets itself (a new action starts them empty; Fix mode renews the budgets
// of the action it interrupts, paper §IV).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::executive {

using geometry::Point;

enum class Facing { kNo, kPending, kTurning };  // RobustParams::face

// A straight back-up of the robot alone (RobustParams::escape).
struct Escape {
  double heading;   // rad
  double distance;  // m
};

// The guide unit (recovery_guide.cpp, guides.cpp) with its options track, widen, persist and
// memory.
struct GuideState {
  std::vector<Point> path;  // the remaining waypoints, x* excluded
  int planned = 0;          // guides planned for this action
  // RobustParams::persist: the least distance of the centre to x* when a guide was planned,
  // and `planned` at the last renewal of the budget (planned - base count against it).
  double best = std::numeric_limits<double>::infinity();
  int base = 0;
  int replans = 0;        // planned again after their next waypoint left F_k
  bool tracking = false;  // followed straight, segment by segment (RobustParams::track)
  bool pending = false;   // plan one at the next rebuild (after a contact back-up)
  // RobustParams::memory: the last guide found a way only through what has been seen of the
  // unknown obstacles (in F_k alone); RobustParams::fragments looks for objects that close the
  // way together with them.
  bool memory_closed = false;

  // The path given up (the next rebuild plans again if asked).
  void drop() {
    path.clear();
    tracking = false;
  }
  // A fresh budget (Fix mode interrupted the action).
  void renew_budget() {
    planned = 0;
    base = 0;
  }
  // As new, for another x* (redrop).
  void restart() {
    drop();
    renew_budget();
    best = std::numeric_limits<double>::infinity();
  }
};

// The back-up units (recovery_back_up.cpp, recovery_contact_back_up.cpp, back_up.cpp) with their
// options escape and face.
struct BackUpState {
  int count = 0;         // back-ups when the centre was not free (the budget's count)
  int contact_outs = 0;  // back-ups off the boundary when the monitor fired (kContactClearance)
  bool active = false;   // a back-up is in progress
  double travel = 0;     // m moved (arc length of the centre) in this back-up
  int dir = -1;          // index into the back-up moves, -1: choose one
  std::optional<Escape> escape;  // RobustParams::escape: this back-up's line (none: moves)
  Facing facing = Facing::kNo;   // turn toward the law's goal first (RobustParams::face)

  // A new back-up, its move still to choose.
  void begin() {
    active = true;
    travel = 0;
    dir = -1;
    escape.reset();
  }
  // A fresh budget (Fix mode interrupted the action).
  void renew_budget() {
    count = 0;
    contact_outs = 0;
  }
};

// The drop-point rules (targets.cpp) and the units that choose again (recovery_retarget.cpp,
// recovery_redrop.cpp).
struct DropState {
  int retargets = 0;  // chosen again after a fragment took the point
  int redrops = 0;    // chosen again after every guide failed
  std::vector<Point> rejected;
  // The kDropLevels index the point was chosen at (kDropLevels.size(): the clearest point, no
  // clearance asked); the point is kept while it still meets it.
  std::size_t level = 0;
  // Chosen in a goal region (targets.cpp, drop_point): no point clear of the regions kept Fix
  // mode's ways open. The point is then kept without the region rule.
  bool in_region = false;
};

// The plan-among-fragments unit (recovery_plan_among_fragments.cpp): a visible unknown fragment
// took a GRASP's or RELEASE's x*; from then on the action plans with the fragments as fixed
// obstacles (planning.cpp), asked at most kMaxFragmentRetargets times.
inline constexpr int kMaxFragmentRetargets = 4;
struct FragmentPlanState {
  bool on = false;
  int retargets = 0;
};

// The object-blockers unit (recovery_object_blockers.cpp): Fix-mode entries it asked for in
// this action, at most kMaxObjectFixes.
struct BlockerState {
  int fixes = 0;
};

// The units that run at most once per action.
struct OnceState {
  bool convex_all = false;  // recovery_convex.cpp: convex pieces forced after a singular Dh
  bool narrow = false;      // recovery_narrow.cpp was tried
  bool fragments = false;   // recovery_fragment_blockers.cpp was tried
  bool memory = false;      // recovery_memory_blockers.cpp ran its check
};

}  // namespace rearm::executive
