#include "executive/executive.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/stopwatch.h"
#include "core/text.h"
#include "executive/motion_checks.h"
#include "executive/path_tracker.h"
#include "geometry/dilation.h"
#include "geometry/distance.h"
#include "reactive/grasp.h"
#include "reactive/navigation.h"
#include "topology/topology_check.h"

namespace rearm::executive {
namespace {

// Phase changes allowed in one tick before the executive gives up (each action takes a handful:
// plan, reach, align, dock, …); more means a bug, reported as stuck rather than a hang.
constexpr int kMaxTransitionsPerTick = 64;

std::string point_text(const Point& p) {
  return "(" + rearm::fixed(p.x(), 3) + ", " + rearm::fixed(p.y(), 3) + ")";
}

bool same_disks(const std::vector<geometry::Disk>& a, const std::vector<geometry::Disk>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].center != b[i].center || a[i].radius != b[i].radius) return false;
  }
  return true;
}

}  // namespace

void validate(const ExecutiveParams& p) {
  const std::pair<const char*, double> positive[] = {
      {"robot_radius", p.robot_radius},
      {"goal_tolerance", p.goal_tolerance},
      {"grasp_goal_tolerance", p.grasp_goal_tolerance},
      {"align_tolerance", p.align_tolerance},
      {"dock_speed", p.dock_speed},
      {"backoff_speed", p.backoff_speed},
      {"backoff_margin", p.backoff_margin},
      {"phase_timeout", p.phase_timeout}};
  for (const auto& [name, v] : positive) {
    REARM_REQUIRE(std::isfinite(v) && v > 0, "executive: ", name, " must be finite and > 0, got ",
                  v);
  }
  if (p.max_fix_rounds < 1) throw Error("executive: max_fix_rounds must be >= 1");
  if (p.max_ltl_actions < 0) throw Error("executive: max_ltl_actions must be >= 0");
  if (p.grasp.samples < 1 || !(p.grasp.dock_gap > 0) || !(p.grasp.standoff > p.grasp.dock_gap) ||
      !std::isfinite(p.grasp.standoff) || !std::isfinite(p.grasp.pair_margin) ||
      !(p.grasp.pair_margin >= 0)) {
    throw Error("executive: grasp needs samples >= 1, standoff > dock_gap > 0, pair_margin >= 0");
  }
  reactive::validate(p.diffeo);
  reactive::validate(p.nav);
  validate(p.progress);
  validate(p.guide);
  if (!std::isfinite(p.robust.withdraw_clearance) || p.robust.withdraw_clearance < 0 ||
      !std::isfinite(p.robust.withdraw_max) || p.robust.withdraw_max < 0) {
    throw Error("executive: withdraw_clearance and withdraw_max must be finite and >= 0");
  }
  REARM_REQUIRE(std::isfinite(p.robust.rebuild_margin) && p.robust.rebuild_margin >= 0,
                "executive: rebuild_margin must be finite and >= 0, got ", p.robust.rebuild_margin);
  if (!std::isfinite(p.robust.back_out_step) || !(p.robust.back_out_step > 0) ||
      p.robust.max_back_outs < 0 || !std::isfinite(p.robust.contact_margin) ||
      p.robust.contact_margin < 0 || p.robust.contact_margin > p.robot_radius) {
    throw Error(
        "executive: back_out_step must be finite and > 0, max_back_outs >= 0, contact_margin in "
        "[0, robot_radius]");
  }
}

const char* to_string(TaskStatus s) {
  switch (s) {
    case TaskStatus::kRunning:
      return "running";
    case TaskStatus::kCompleted:
      return "completed";
    case TaskStatus::kInfeasible:
      return "infeasible";
    case TaskStatus::kStuck:
      return "stuck";
    case TaskStatus::kTimeout:
      return "timeout";
  }
  return "?";
}

const char* to_string(ActionOutcome o) {
  switch (o) {
    case ActionOutcome::kSucceeded:
      return "succeeded";
    case ActionOutcome::kInfeasible:
      return "infeasible";
    case ActionOutcome::kStuck:
      return "stuck";
    case ActionOutcome::kAbandoned:
      return "abandoned";
  }
  return "?";
}

Executive::Executive(const ExecutiveParams& params, const std::vector<RegionOfInterest>& regions,
                     symbolic::MissionController& mission, const perception::SemanticMap& map)
    : p_(params),
      regions_(validated(regions, map.workspace())),
      mission_(mission),
      map_(map),
      controller_(params.diffeo, params.nav),
      ctx_{p_,          regions_,        map_,
           controller_, topology_cache_, drop_dilations_,
           times_,      recoveries_,     topology_checks_} {
  validate(p_);
  controller_.set_convex_fallback(p_.robust.convex_fallback);
  controller_.set_miter_limit(miter_limit(p_));
  topology_cache_.set_miter_limit(miter_limit(p_));
  drop_dilations_.set_miter_limit(miter_limit(p_));
}

ActionState Executive::make(Kind kind, std::string object, std::string region, bool fix,
                            double t) const {
  Activity a;
  a.kind = kind;
  a.object = std::move(object);
  a.region = std::move(region);
  a.fix = fix;
  a.t_start = a.phase_start = t;
  a.monitor = ProgressMonitor(p_.progress);
  a.monitor.reset(t);
  return a;
}

ActionState* Executive::current() {
  if (!fix_.empty()) return &fix_.back();
  return ltl_ ? &*ltl_ : nullptr;
}

std::string Executive::current_action() const {
  if (!fix_.empty()) return fix_.back().name();
  return ltl_ ? ltl_->name() : std::string();
}

bool Executive::knowledge_changed(const Activity& a) const {
  return map_.familiar().size() != a.plan_familiar || map_.carried() != a.plan_carried ||
         !same_disks(map_.movable(), a.plan_movable);
}

bool Executive::fetch_ltl(double t) {
  if (p_.max_ltl_actions > 0 && ltl_done_ >= p_.max_ltl_actions) {
    const std::string n = std::to_string(ltl_done_);
    if (mission_.status() == symbolic::MissionStatus::Accepting) {
      finish(TaskStatus::kCompleted,
             "mission accepting after " + n + " actions (the configured action limit)", t);
    } else {
      finish(TaskStatus::kTimeout,
             "the action limit (" + n + ") was reached before the mission was accepting", t);
    }
    return false;
  }
  std::optional<symbolic::Action> next;
  {
    const ScopedStopwatch sw(times_.mission_s);
    next = mission_.next_action();
  }
  if (!next) {
    switch (mission_.status()) {
      case symbolic::MissionStatus::Infeasible:
        if (!stuck_.empty()) {
          // The alternatives ran out after actions the controller could not complete: the
          // task ends stuck (a controller failure), not proven infeasible.
          finish(TaskStatus::kStuck, stuck_ + "; no alternative action: " + mission_.reason(), t);
        } else {
          finish(TaskStatus::kInfeasible, "mission infeasible: " + mission_.reason(), t);
        }
        break;
      case symbolic::MissionStatus::Accepting:
        if (restore_next(t)) return true;
        finish_accepting(t);
        break;
      case symbolic::MissionStatus::InProgress:
        finish(TaskStatus::kStuck, "the mission controller returned no action", t);
        break;
    }
    return false;
  }
  switch (next->kind) {
    case symbolic::ActionKind::Move:
      ltl_ = make(Kind::kMove, "", next->region, false, t);
      break;
    case symbolic::ActionKind::Grasp:
      ltl_ = make(Kind::kGrasp, next->object, "", false, t);
      break;
    case symbolic::ActionKind::Release:
      ltl_ = make(Kind::kRelease, next->object, next->region, false, t);
      break;
  }
  ltl_->ltl = *next;
  fix_rounds_ = 0;
  // Unknown names fail here, with the name, rather than deep inside a phase.
  if (!ltl_->region.empty()) region(ctx_, ltl_->region);
  if (!ltl_->object.empty()) object_radius(ctx_, ltl_->object);
  return true;
}

Command Executive::step(const Pose& pose, double t, double dt) {
  if (finished()) return {};
  if (!pose.x.allFinite() || !std::isfinite(pose.psi) || !std::isfinite(t) || !std::isfinite(dt) ||
      !(dt > 0)) {
    throw Error("executive: non-finite pose or time, or dt <= 0");
  }
  gripper_ = GripperAction::kNone;
  gripper_object_.clear();
  law_command_ = false;
  for (int guard = 0; guard < kMaxTransitionsPerTick && !finished(); ++guard) {
    Activity* a = current();
    if (a == nullptr) {
      if (!fetch_ltl(t)) break;
      continue;
    }
    Advance r;
    try {
      r = advance(*a, pose, t, dt);
    } catch (const Error& e) {
      r.kind = Advance::kStuck;
      r.reason = e.what();
    }
    switch (r.kind) {
      case Advance::kCommand:
        last_u_ = r.u;
        return Command{r.u, gripper_, gripper_object_};
      case Advance::kRestart:
        break;
      case Advance::kDone:
        end_current(ActionOutcome::kSucceeded, r.reason, t);
        break;
      case Advance::kInfeasible:
        end_current(ActionOutcome::kInfeasible, r.reason, t);
        break;
      case Advance::kBlocked:
        enter_fix(r.blocking, t);
        break;
      case Advance::kStuck:
        end_stuck(r.reason, t);
        break;
    }
  }
  if (!finished()) {
    finish(TaskStatus::kStuck,
           "no motion command after " + std::to_string(kMaxTransitionsPerTick) +
               " action transitions in one tick (at " + current_action() + ")",
           t);
  }
  last_u_ = Twist{};
  return Command{Twist{}, gripper_, gripper_object_};
}

Advance Executive::advance(Activity& a, const Pose& pose, double t, double dt) {
  switch (a.phase) {
    case Phase::kNavigate:
      return prerequisites_then_navigate(a, pose, t, dt);
    case Phase::kAlign:
      return align(a, pose, t);
    case Phase::kDock:
      return dock(a, pose, t, dt);
    case Phase::kGrip:
      return grip(a, pose, t);
    case Phase::kWithdraw:
      return withdraw(a, pose, t, dt);
    case Phase::kOpen:
      return open(a, t);
    case Phase::kBackOff:
      return back_off(a, pose, t, dt);
  }
  Advance out;
  out.kind = Advance::kStuck;
  out.reason = "unknown phase";
  return out;
}

// Gripper prerequisites (interface-layer steps, beyond the paper; see the header), then the
// navigation phase.
Advance Executive::prerequisites_then_navigate(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const std::optional<std::string> carried = map_.carried();
  std::vector<Activity> before;  // execution order
  if (a.kind == Kind::kGrasp && carried) {
    if (*carried == a.object) {
      out.kind = Advance::kDone;
      out.reason = "already in the gripper";
      return out;
    }
    before.push_back(make(Kind::kDisassemble, *carried, "", true, t));
  } else if (a.kind == Kind::kRelease && carried != a.object) {
    if (carried) before.push_back(make(Kind::kDisassemble, *carried, "", true, t));
    before.push_back(make(Kind::kGrasp, a.object, "", true, t));
  } else if (a.kind == Kind::kDisassemble && carried != a.object) {
    out.kind = Advance::kInfeasible;
    out.reason = "the object is not in the gripper";
    return out;
  }
  if (!before.empty()) {
    // `a` may live in fix_: nothing touches it after the push.
    for (auto it = before.rbegin(); it != before.rend(); ++it) fix_.push_back(*it);
    out.kind = Advance::kRestart;
    return out;
  }
  return navigate(a, pose, t, dt);
}

// GRASP: turn in place until the gripper faces the object (paper §V-B).
Advance Executive::align(Activity& a, const Pose& pose, double t) {
  Advance out;
  const geometry::Disk m = *map_.object(a.object);
  if (reactive::aligned(pose.psi, pose.x, m.center, p_.align_tolerance)) {
    a.phase = Phase::kDock;
    a.phase_start = t;
    out.kind = Advance::kRestart;
    return out;
  }
  if (t - a.phase_start > p_.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not turn the gripper toward the object within " +
                 rearm::fixed(p_.phase_timeout, 3) + " s";
    return out;
  }
  out.u = reactive::align_command(pose.psi, pose.x, m.center, p_.nav);
  return out;
}

// GRASP: drive straight in to dock_gap from contact, then close the gripper.
Advance Executive::dock(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *map_.object(a.object);
  const double gap = (m.center - pose.x).norm() - p_.robot_radius - m.radius;
  if (gap <= p_.grasp.dock_gap) {
    gripper_ = GripperAction::kClose;
    gripper_object_ = a.object;
    a.phase = Phase::kGrip;
    a.phase_start = t;
    a.note = "gripped at gap " + rearm::fixed(gap * 1000, 3) + " mm";
    return out;  // stand still while the gripper closes
  }
  if (t - a.phase_start > p_.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not dock to the object within " + rearm::fixed(p_.phase_timeout, 3) + " s";
    return out;
  }
  // Straight in, never closer than half the gap allowance in one step, steering to keep
  // facing the centre.
  out.u.v = std::min(p_.dock_speed, (gap - p_.grasp.dock_gap / 2) / dt);
  out.u.omega = reactive::align_command(pose.psi, pose.x, m.center, p_.nav).omega;
  return out;
}

// GRASP: the tick after the close command, the map must report the object carried.
Advance Executive::grip(Activity& a, const Pose& pose, double t) {
  Advance out;
  if (map_.carried() != a.object) {
    out.kind = Advance::kStuck;
    out.reason = "the gripper did not close on " + a.object;
    return out;
  }
  if (p_.robust.withdraw) {
    a.phase = Phase::kWithdraw;
    a.phase_start = t;
    a.withdrawn = 0;
    a.withdraw_goal = withdraw_distance(a, pose);
    out.kind = Advance::kRestart;
    return out;
  }
  out.kind = Advance::kDone;
  out.reason = a.note;
  return out;
}

// GRASP, robust variant (RobustParams::withdraw): how far to reverse along the docking line.
// The line is sampled every kWithdrawSample (m) up to withdraw_max, as long as the robot and the
// gripped object stay clear of everything known: the first sample where the pair's centre is
// withdraw_clearance clear of its dilated surroundings, else the sample where it is clearest
// (0 when that is where it stands). A pocket's mouth narrows before it widens, so the clearance
// is looked ahead along the line, not followed step by step.
double Executive::withdraw_distance(const Activity& a, const Pose& pose) const {
  constexpr double kWithdrawSample = 0.01;
  const geometry::Disk m = *map_.object(a.object);
  const double pair_radius = plan_radius(ctx_) + m.radius + p_.grasp.pair_margin;
  const Point back = -Point(std::cos(pose.psi), std::sin(pose.psi));
  const Point xc = reactive::pair_center(pose.x, pose.psi, m.radius);
  double best = known_clearance(map_, xc, a.object);
  double best_s = 0;
  const int samples = static_cast<int>(std::floor(p_.robust.withdraw_max / kWithdrawSample));
  for (int k = 0; k <= samples; ++k) {
    const double s = k * kWithdrawSample;
    if (!reverse_clear(ctx_, m, a.object, pose.x + s * back, m.center + s * back)) break;
    const double c = known_clearance(map_, xc + s * back, a.object);
    if (c >= pair_radius + p_.robust.withdraw_clearance) return s;
    if (c > best) {
      best = c;
      best_s = s;
    }
  }
  return best_s;
}

// GRASP, robust variant: reverse straight to withdraw_distance(), each step checked again
// against the map (a fragment seen on the way ends it).
Advance Executive::withdraw(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *map_.object(a.object);
  auto done = [&](const std::string& how) {
    if (a.withdrawn > 0) {
      ++recoveries_.withdrawals;
      a.note += "; withdrew " + rearm::fixed(a.withdrawn, 3) + " m" + how;
    }
    out.kind = Advance::kDone;
    out.reason = a.note;
    return out;
  };
  if (a.withdrawn >= a.withdraw_goal || t - a.phase_start > p_.phase_timeout) return done("");
  const double v = std::min(p_.backoff_speed, (a.withdraw_goal - a.withdrawn) / dt);
  out.u.v = -v;
  const Pose next = reactive::unicycle_step(pose, out.u, dt);
  if (!reverse_clear(ctx_, m, a.object, next.x, m.center + (next.x - pose.x))) {
    return done(" (blocked behind)");
  }
  a.withdrawn += v * dt;
  return out;
}

// RELEASE, DISASSEMBLE: the gripper opens once the robot stood still for one tick (so the object
// is at rest when it is let go: one let go while the pair moved slides on, Box2D's damping
// stopping it only after v/5 s, and can strike the robot that stops or turns), and the map must
// say so on the next tick. Every way into this phase asks for the stop; this check keeps it
// true where two actions end in one tick (a withdrawal ending as the DISASSEMBLE that needed
// the grasp stops at once).
Advance Executive::open(Activity& a, double t) {
  Advance out;
  if (map_.carried()) {
    if (last_u_.v != 0 || last_u_.omega != 0) return out;  // stop this tick, open the next
    if (!a.open_sent) {
      gripper_ = GripperAction::kOpen;
      a.open_sent = true;
      return out;
    }
    out.kind = Advance::kStuck;
    out.reason = "the gripper did not open";
    return out;
  }
  a.phase = Phase::kBackOff;
  a.phase_start = t;
  out.kind = Advance::kRestart;
  return out;
}

// RELEASE, DISASSEMBLE: back off straight until the robot is clear of the released object's
// dilation, so the next action starts in the freespace.
Advance Executive::back_off(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *map_.object(a.object);
  const double need =
      geometry::disk_polygon_circumradius(m.radius + plan_radius(ctx_) + geometry::kContactSlack) +
      p_.backoff_margin;
  const double d = (m.center - pose.x).norm();
  if (d >= need) {
    out.kind = Advance::kDone;
    out.reason = a.note + "; released " + a.object + " at " + point_text(m.center);
    return out;
  }
  if (t - a.phase_start > p_.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not back off from the released object";
    return out;
  }
  out.u.v = -std::min(p_.backoff_speed, (need - d) / dt + 1e-3);
  const Point next = reactive::unicycle_step(pose, out.u, dt).x;
  if (known_clearance(map_, next) < p_.robot_radius) {
    out.kind = Advance::kStuck;
    out.reason = "no room to back off from the released object at " + point_text(pose.x);
    return out;
  }
  return out;
}

Advance Executive::navigate(Activity& a, const Pose& pose, double t, double dt) {
  const auto [rho, radius, center] = moving(ctx_, a, pose);
  if (a.backing) return back_out(a, pose, t, dt);

  // A grasp approach point chosen earlier may have lost its clearance to a newly seen unknown
  // fragment (the topology knowledge is unchanged then).
  if (a.planned && a.kind == Kind::kGrasp && a.built && a.checked_version != map_.version()) {
    a.checked_version = map_.version();
    if (known_clearance(map_, *a.target) < plan_radius(ctx_, a)) a.planned = false;
  }
  if (!a.planned || knowledge_changed(a)) {
    Advance p;
    try {
      p = plan(a, pose);
    } catch (const topology::CenterNotFree& e) {
      return start_back_out(a, pose, e.what(), t, dt);
    }
    if (p.kind != Advance::kCommand) return p;
  }
  if (!a.built || a.built_target != *a.target || a.built_radius != radius ||
      stale(a, radius, center)) {
    Advance b = rebuild(a, radius, center, t);
    if (b.center_not_free) return start_back_out(a, pose, b.reason, t, dt);
    if (b.kind != Advance::kCommand) return b;
  }
  // The guide's waypoints (robust variant): passed ones are dropped, the next is the law's goal.
  const double reach = a.tracking ? kTrackReach : p_.guide.reach;
  while (!a.guide.empty() && (center - a.guide.front()).norm() <= reach) {
    a.guide.erase(a.guide.begin());
    a.monitor.reset(t);
  }
  Point nav = a.guide.empty() ? a.goal : a.guide.front();
  if (controller_.goal() != nav && !controller_.retarget(nav)) {
    // The next waypoint has left F_k since the guide was planned (the map changed under it): the
    // guide is planned again from here (kMaxGuideReplans per action) rather than dropped for a
    // straight run at x*.
    if (a.replans < kMaxGuideReplans) {
      ++a.replans;
      replan_guide(a, center);
    } else {
      a.guide.clear();
    }
    nav = a.guide.empty() ? a.goal : a.guide.front();
    if (!controller_.retarget(nav)) {
      a.guide.clear();
      nav = a.goal;
      controller_.retarget(nav);
    }
  }
  if (std::optional<Advance> f = closed_by_memory(a, radius, center)) return *f;
  if (std::optional<Advance> done = arrive(a, center, rho, t)) return *done;
  if (a.facing != Facing::kNo) {
    if (std::optional<Advance> f = face(a, pose, controller_.goal(), t, dt)) return *f;
  }
  if (auto stuck =
          a.monitor.observe(t, pose, (center - controller_.goal()).norm(), map_.version())) {
    return recover(a, pose, center, *stuck, t, dt);
  }
  if (a.tracking) {
    if (std::optional<Advance> step = track(a, pose, nav, rho, dt)) return *step;
  }
  return command(a, pose, rho, t, dt);
}

// A map version newer than the build: stale at once in the paper variant, else once the news
// (map_news.h) comes within rebuild_margin of the centre's disk. The news is measured once per
// map version; as the centre moves, its distance shrinks by at most the centre's travel.
bool Executive::stale(Activity& a, double radius, const Point& center) {
  if (a.built_version == map_.version()) return false;
  if (!p_.robust.defer) return true;
  if (a.news_version != map_.version()) {
    a.news_version = map_.version();
    a.news = news_distance(a.built_map, map_, center);
    a.news_at = center;
  }
  return a.news - (center - a.news_at).norm() <= radius + p_.robust.rebuild_margin;
}

// The diffeomorphism for the current map, radius and x* (reactive controller of [7]); a guide
// whose next waypoint left the new mapped space is planned again. center_not_free: the centre
// is not in the freespace (the caller backs out, or ends stuck in the paper variant).
Advance Executive::rebuild(Activity& a, double radius, const Point& center, double t) {
  Advance out;
  const Point target = *a.target;
  controller_.set_convexify_all(a.convex_all);
  reactive::RebuildResult rr;
  {
    const ScopedStopwatch sw(times_.rebuild_s);
    rr = controller_.try_rebuild(semantic_input(ctx_), radius, center, target);
  }
  if (rr.status == reactive::RebuildStatus::kCenterNotFree) {
    a.built = false;
    out.center_not_free = true;  // the caller backs out (or ends stuck without back_out)
    out.reason = rr.message;
    return out;
  }
  if (rr.status == reactive::RebuildStatus::kNoDiffeomorphism) {
    out.kind = Advance::kStuck;  // no law to follow here (the paper variant has no fallback)
    out.reason = rr.message;
    return out;
  }
  if (rr.status == reactive::RebuildStatus::kGoalNotFree) {
    if (a.kind == Kind::kDisassemble && drop_points(a)) {
      // A newly seen unknown fragment took the drop point (the topology knowledge, which
      // re-plans, is unchanged): choose another; after kMaxDropRetargets, the paper's target
      // (disassemble_target) and early stop, as near as the pair's freespace allows.
      ++a.retargets;
      a.rejected_drops.push_back(target);
      a.planned = false;
      a.target.reset();
      out.kind = Advance::kRestart;
      out.reason = rr.message;
    } else if (a.kind == Kind::kDisassemble) {
      // Every drop point taken and the paper's target cut off too: release where the pair
      // stands when that is clear of the regions (drop_short), else the action ends stuck.
      if (p_.robust.drop) {
        if (std::optional<Advance> d = drop_short(a, center, t)) return *d;
      }
      out.kind = Advance::kStuck;
      out.reason =
          "the disassembly target " + point_text(target) + " is not reachable: " + rr.message;
    } else if (std::optional<Advance> f = fragment_blockers(a, radius, center)) {
      return *f;
    } else {
      out.kind = Advance::kInfeasible;
      out.reason = "x* = " + point_text(target) +
                   " is inside or behind obstacles the topology check does not model "
                   "(visible unknown obstacles): " +
                   rr.message;
    }
    return out;
  }
  if (a.built && (a.built_target - target).norm() > p_.progress.progress_step) {
    a.monitor.reset(t);
    a.guide_best = std::numeric_limits<double>::infinity();  // distances to another x*
  }
  a.built = true;
  a.built_version = map_.version();
  a.checked_version = map_.version();
  if (p_.robust.defer) a.built_map = MapSnapshot::of(map_);
  a.built_target = target;
  a.built_radius = radius;
  a.goal = controller_.goal();
  if (a.guide_pending) {
    a.guide_pending = false;
    std::string note;
    plan_guide(a, center, t, note);
  }
  // A guide in use stays while its next waypoint is still free (a path costs tens of ms; the
  // map changes every few ticks as fragments grow), else it is planned again.
  if (!a.guide.empty() && !reactive::in_freespace(controller_.mapped(), a.guide.front())) {
    replan_guide(a, center);
  }
  return out;
}

// The guide in use planned again from `center` (empty when the raster finds no path).
void Executive::replan_guide(Activity& a, const Point& center) const {
  const auto path = guide_to(a, center, p_.guide);
  a.guide = path ? std::vector<Point>(path->begin(), path->end() - 1) : std::vector<Point>{};
}

// Reached x* (MOVE: done; GRASP: align; RELEASE, DISASSEMBLE: stop and open), or the early stop
// of DISASSEMBLE (paper §V-B); nullopt while still on the way.
std::optional<Advance> Executive::arrive(Activity& a, const Point& center, double rho, double t) {
  Advance out;
  const double tol = a.kind == Kind::kGrasp ? p_.grasp_goal_tolerance : p_.goal_tolerance;
  bool reached = a.guide.empty() && (center - a.goal).norm() <= tol;
  std::string why;  // written only once reached (formatting every tick cost 3% of a trial)
  auto early = [&] {
    return drop_points(a) ? drop_clear(center, rho)
                          : disassembly_done(center, p_.robot_radius + rho, p_.robot_radius, map_,
                                             *map_.carried(), regions_);
  };
  if (!reached && a.kind == Kind::kDisassemble && map_.carried() && early()) {
    reached = true;
    why = "early stop at " + point_text(center) + " (clear of regions and of every obstacle)";
  }
  if (!reached) return std::nullopt;
  if (why.empty()) why = "reached x* = " + point_text(a.goal);
  switch (a.kind) {
    case Kind::kMove:
      out.kind = Advance::kDone;
      out.reason = why;
      return out;
    case Kind::kGrasp:
      a.phase = Phase::kAlign;
      a.phase_start = t;
      out.kind = Advance::kRestart;
      return out;
    case Kind::kRelease:
    case Kind::kDisassemble:
      a.note = why;
      a.phase = Phase::kOpen;
      a.phase_start = t;
      a.open_sent = false;
      return out;  // stop for one tick, then open (Phase::kOpen)
  }
  return out;
}

// The progress monitor fired (a rest point, saddle or limit cycle of [7]): in the robust
// variant the law's goal becomes the next waypoint of a path in the known freespace F_k.
Advance Executive::recover(Activity& a, const Pose& pose, const Point& center,
                           const std::string& why, double t, double dt) {
  Advance out;
  if (a.kind == Kind::kRelease && p_.robust.early_release && map_.carried() == a.object) {
    // RELEASE(M, ℓ) holds once M lies in ℓ (paper §II-B), wherever in ℓ: stopped short of the
    // centroid with M inside ℓ, release here.
    const geometry::Disk m = *map_.object(a.object);
    const geometry::Polygon& goal = region(ctx_, a.region).polygon;
    if (geometry::contains(goal, m.center) &&
        -geometry::signed_distance(goal, m.center) >= p_.goal_tolerance) {
      ++recoveries_.early_releases;
      a.note =
          "early release at " + point_text(m.center) + " inside " + a.region + " (" + why + ")";
      a.phase = Phase::kOpen;
      a.phase_start = t;
      a.open_sent = false;
      return out;  // stop for one tick, then open
    }
  }
  if (a.kind == Kind::kGrasp && p_.robust.early_dock && early_dock(a, pose)) {
    // Stopped beside the object short of the chosen approach point, with a clear docking line
    // from here: the grasp proceeds from where the robot stands.
    ++recoveries_.early_docks;
    a.phase = Phase::kAlign;
    a.phase_start = t;
    out.kind = Advance::kRestart;
    return out;
  }
  out.kind = Advance::kStuck;
  out.reason = why;
  if (!p_.robust.guide) return out;
  if (p_.robust.back_out && a.contact_outs < p_.robust.max_back_outs &&
      geometry::nearest_on_boundary(controller_.mapped().freespace, center).distance <
          kContactClearance) {
    // Pressed onto ∂F_k (kContactClearance): back out first, then follow a guide planned from
    // where the back-up ends (the next rebuild).
    ++a.contact_outs;
    a.guide.clear();
    a.guide_pending = true;
    Advance b = start_back_out(a, pose, why, t, dt, /*contact=*/true);
    if (b.kind != Advance::kStuck) return b;
    a.guide_pending = false;
  }
  std::string note;
  if (!plan_guide(a, center, t, note)) {
    out.reason += note;
    if (std::optional<Advance> r = redrop(a, t)) return *r;
    if (std::optional<Advance> n = narrow(a, pose)) return *n;
    return out;
  }
  out.kind = Advance::kRestart;
  return out;
}

// Robust variant (RobustParams::early_release): a DISASSEMBLE still pressed against a dilation
// after every back-up releases its object where it stands when the object is clear of every
// region there: DISASSEMBLE only has to move the object out of the way (paper §V-B), and an
// object left in the way is one that Fix mode can move again, where a wedged pair ends the task
// (measured: the pair pushed into a corner of F_k beside its drop point, four back-ups without
// a millimetre of motion). rebuild() asks the same when every drop point was taken and the
// paper's target is cut off as well. nullopt otherwise.
std::optional<Advance> Executive::drop_short(Activity& a, const Point& at, double t) {
  if (a.kind != Kind::kDisassemble || !p_.robust.early_release || map_.carried() != a.object) {
    return std::nullopt;
  }
  const geometry::Disk m = *map_.object(a.object);
  if (!clear_of_regions(m.center, m.radius, regions_)) return std::nullopt;
  ++recoveries_.early_releases;
  a.note = "released at " + point_text(m.center) + " short of the drop point (centre at " +
           point_text(at) + ")";
  a.phase = Phase::kOpen;
  a.phase_start = t;
  a.open_sent = false;
  return Advance{};  // stop for one tick, then open
}

bool Executive::drop_points(const Activity& a) const {
  return p_.robust.drop && a.retargets <= kMaxDropRetargets;
}

// Robust variant (RobustParams::redrop): the law and every guide failed to reach a DISASSEMBLE's
// drop point; it is rejected with its surroundings (drop_point) and the action plans again with
// a fresh guide budget, up to kMaxRedrops per action. nullopt otherwise.
std::optional<Advance> Executive::redrop(Activity& a, double t) {
  if (a.kind != Kind::kDisassemble || !p_.robust.redrop || !p_.robust.drop || !a.target ||
      a.redrops >= kMaxRedrops) {
    return std::nullopt;
  }
  ++a.redrops;
  ++recoveries_.redrops;
  a.rejected_drops.push_back(*a.target);
  a.planned = false;
  a.target.reset();
  a.guide.clear();
  a.tracking = false;
  a.guides = 0;
  a.guide_base = 0;
  a.guide_best = std::numeric_limits<double>::infinity();
  a.monitor.reset(t);
  Advance out;
  out.kind = Advance::kRestart;
  return out;
}

// Robust variant (RobustParams::narrow): the law and every guide failed, yet the topology check
// finds x* reachable. With every movable object grown by kNarrowSlacks in turn (the fixed
// obstacles as they are), the first check that separates x* by objects names the objects that
// narrow the passage below what the law of [7] gets through: Fix mode moves them (paper §IV),
// then the action plans again. Once per action; nullopt when fixed obstacles alone narrow it.
std::optional<Advance> Executive::narrow(Activity& a, const Pose& pose) {
  if (!p_.robust.narrow || a.narrowed || !a.target) return std::nullopt;
  a.narrowed = true;
  const auto [rho, radius, center] = moving(ctx_, a, pose);
  const std::optional<Narrowing> n =
      grown_blockers(map_.familiar(), true, radius, center, *a.target);
  if (!n) return std::nullopt;
  std::optional<Advance> out =
      fix_mode_for(a, n->blocking,
                   "objects narrow the passage to x* below what the law got through (grown by " +
                       rearm::fixed(n->slack, 3) + " m): " + n->reason);
  if (out) ++recoveries_.narrows;
  return out;
}

// The topology check with `fixed` as the fixed obstacles (the topology cache only for the
// familiar ones) and every movable object grown by kNarrowSlacks in turn: the first slack whose
// verdict names objects, or whose grown objects cover the centre (then those whose grown
// dilation contains it); nullopt when fixed obstacles separate x* or no slack names any.
std::optional<Executive::Narrowing> Executive::grown_blockers(
    const std::vector<geometry::Polygon>& fixed, bool familiar_only, double radius,
    const Point& center, const Point& target) {
  for (double slack : kNarrowSlacks) {
    std::vector<geometry::Disk> grown = map_.movable();
    for (geometry::Disk& d : grown) d.radius += slack;
    Narrowing n{{}, "", slack};
    try {
      const ScopedStopwatch sw(times_.topology_s);
      const topology::TopologyResult res =
          familiar_only ? topology::check_topology(
                              topology::make_input(map_.workspace(), fixed, grown, radius, center,
                                                   target, std::nullopt, topology_cache_),
                              topology_cache_)
                        : topology::check_topology(topology::make_input(
                              map_.workspace(), fixed, grown, radius, center, target));
      ++topology_checks_;
      if (res.verdict == topology::Verdict::kBlockedByFixed) return std::nullopt;
      if (res.verdict != topology::Verdict::kBlockedByObjects) continue;
      n.blocking = res.blocking;
      n.reason = res.reason;
    } catch (const topology::CenterNotFree&) {
      // Grown objects cover the centre: those within `slack` of the robot's dilation squeeze it.
      for (std::size_t i = 0; i < grown.size(); ++i) {
        if ((grown[i].center - center).norm() < grown[i].radius + radius) n.blocking.push_back(i);
      }
      n.reason =
          "the robot's centre lies within " + rearm::fixed(slack, 3) + " m of their dilations";
    }
    return n;
  }
  return std::nullopt;
}

// Fix mode (paper §IV) for the objects `blocking` (indices into the map's movable objects) but
// the action's own object, with the action's recovery counts reset; nullopt when none is left.
std::optional<Advance> Executive::fix_mode_for(Activity& a,
                                               const std::vector<std::size_t>& blocking,
                                               std::string reason) {
  Advance out;
  const auto& ids = map_.movable_ids();
  for (std::size_t i : blocking) {
    if (ids[i] != a.object) out.blocking.push_back(ids[i]);  // GRASP's own object stays
  }
  if (out.blocking.empty()) return std::nullopt;
  out.kind = Advance::kBlocked;
  out.reason = std::move(reason);
  a.guides = 0;
  a.guide_base = 0;
  a.back_outs = 0;
  a.contact_outs = 0;
  return out;
}

// Robust variant (RobustParams::fragments): the reactive controller finds x* cut off from the
// centre where the topology check, which models the familiar obstacles and the objects only
// (paper Appendix III), did not: visible unknown fragments close the way, with objects or
// without. The check runs again with the fragments as fixed obstacles (mitered, a superset of
// the controller's round dilations); objects that close the way with them are moved by Fix mode
// (paper §IV), once per action. nullopt when fixed obstacles alone close it.
std::optional<Advance> Executive::fragment_blockers(Activity& a, double radius,
                                                    const Point& center) {
  if (!p_.robust.fragments || a.fragments_checked || !a.target) return std::nullopt;
  a.fragments_checked = true;
  return closing_with_fragments(a, radius, center);
}

// fragment_blockers' check, whichever recovery asks for it.
std::optional<Advance> Executive::closing_with_fragments(Activity& a, double radius,
                                                         const Point& center) {
  std::vector<geometry::Polygon> fixed = map_.familiar();
  fixed.insert(fixed.end(), map_.unknown().begin(), map_.unknown().end());
  if (p_.robust.memory) {
    // What has been seen of each unknown obstacle (a convex subset of it): the way the guide
    // found closed may run past obstacles out of sight now.
    for (const geometry::Polygon& h : map_.seen()) {
      if (h.size() >= 3) fixed.push_back(h);
    }
  }
  topology::TopologyResult res;
  try {
    const ScopedStopwatch sw(times_.topology_s);
    res = topology::check_topology(
        topology::make_input(map_.workspace(), fixed, map_.movable(), radius, center, *a.target));
    ++topology_checks_;
  } catch (const topology::CenterNotFree&) {
    return std::nullopt;
  }
  std::optional<Advance> out;
  if (res.verdict == topology::Verdict::kBlockedByObjects) {
    out = fix_mode_for(
        a, res.blocking,
        "objects close the way to x* together with visible unknown obstacles: " + res.reason);
  } else if (res.verdict == topology::Verdict::kReachable) {
    // The exact check finds a way that the mapped space (its polygonal dilations) closes: a gap
    // within millimetres of the pair's width. Objects that narrow it, as in `narrow`.
    if (const std::optional<Narrowing> n =
            grown_blockers(fixed, false, radius, center, *a.target)) {
      out = fix_mode_for(a, n->blocking,
                         "objects narrow the way to x* beside visible unknown obstacles (grown "
                         "by " +
                             rearm::fixed(n->slack, 3) + " m): " + n->reason);
    }
  }
  if (out) ++recoveries_.fragment_fixes;
  return out;
}

// Robust variant (RobustParams::memory with RobustParams::fragments): the last guide found a way
// only through what has been seen of the unknown obstacles, so objects may close every way
// together with them: fragment_blockers' check, once per action, beside (not instead of) its
// own once (sharing it left a RELEASE infeasible after the Fix mode this one started: measured).
// Not for DISASSEMBLE, whose drop point has alternatives (drop_point), as in rebuild: Fix mode
// for it drops the carried object by another DISASSEMBLE, which met the same hulls and nested
// Fix mode to its limit (measured).
std::optional<Advance> Executive::closed_by_memory(Activity& a, double radius,
                                                   const Point& center) {
  if (!a.memory_closed) return std::nullopt;
  a.memory_closed = false;
  if (!p_.robust.fragments || a.memory_checked || !a.target || a.kind == Kind::kDisassemble) {
    return std::nullopt;
  }
  a.memory_checked = true;
  return closing_with_fragments(a, radius, center);
}

// Robust variant (RobustParams::early_dock): within kEarlyDockReach of the approach circle, and
// the grasp from here passes grasp_candidates' checks with its pair centre in the exact pair
// freespace.
bool Executive::early_dock(const Activity& a, const Pose& pose) {
  if (map_.carried()) return false;
  const geometry::Disk m = *map_.object(a.object);
  const double gap = (pose.x - m.center).norm() - m.radius - p_.robot_radius;
  if (gap > p_.grasp.standoff + kEarlyDockReach) return false;
  const std::optional<GraspCandidate> g =
      grasp_from(map_, a.object, p_.robot_radius, pose.x, p_.grasp);
  return g && geometry::contains(pair_freespace(a.object), g->pair_center);
}

bool Executive::plan_guide(Activity& a, const Point& center, double t, std::string& note) {
  // Robust variant (RobustParams::persist): the budget starts again once the centre is
  // kPersistProgress closer to x* than at every earlier guide of the action (the guides counted
  // for widen go on).
  const double to_goal = (center - a.goal).norm();
  if (p_.robust.persist && to_goal <= a.guide_best - kPersistProgress) a.guide_base = a.guides;
  a.guide_best = std::min(a.guide_best, to_goal);
  if (a.guides - a.guide_base >= p_.guide.max_recoveries) {
    note = " (after " + std::to_string(a.guides) + " guide paths)";
    return false;
  }
  // Robust variant (RobustParams::widen): each guide after a failed one keeps kGuideWiden more
  // clearance than the last, so that it leaves the passage where the pair stalled for a wider
  // way round when there is one (the plain path otherwise).
  std::optional<std::vector<Point>> path;
  if (p_.robust.widen && a.guides > 0) {
    GuideParams wide = p_.guide;
    wide.avoid = kGuideWiden * a.guides;
    path = guide_to(a, center, wide);
  }
  if (!path) path = guide_to(a, center, p_.guide);
  if (!path || path->size() < 2) {
    if (path && p_.robust.track && !a.tracking) {
      // x* in sight (the segment to it keeps the guide's clearance in F_k), yet the law
      // stalled: drive straight at it (RobustParams::track), the pair centre as a fully
      // actuated point, which may back the robot in where the law of [7] would have to turn the
      // pair around.
      a.guide.clear();
      a.tracking = true;
      a.facing = Facing::kNo;
      ++a.guides;
      ++recoveries_.guides;
      a.monitor.reset(t);
      return true;
    }
    note = path ? " (x* is in sight: no guide helps)" : " (no guide path in the known freespace)";
    return false;
  }
  a.guide.assign(path->begin(), path->end() - 1);
  a.tracking = p_.robust.track;
  a.facing = p_.robust.face && !a.tracking ? Facing::kPending : Facing::kNo;
  ++a.guides;
  ++recoveries_.guides;
  a.monitor.reset(t);
  return true;
}

// A guide path from `center` to x* in F_k; with RobustParams::memory around what has been seen of
// the unknown obstacles too, in F_k alone when that finds none.
std::optional<std::vector<Point>> Executive::guide_to(Activity& a, const Point& center,
                                                      const GuideParams& gp) const {
  const geometry::Region& free = controller_.mapped().freespace;
  bool closed = false;
  if (p_.robust.memory) {
    const std::vector<geometry::Polygon> seen = seen_dilated(a.built_radius);
    if (!seen.empty()) {
      if (auto path = guide_path(free, center, a.goal, gp, seen)) return path;
      closed = true;
    }
  }
  std::optional<std::vector<Point>> path = guide_path(free, center, a.goal, gp);
  if (closed && path) a.memory_closed = true;
  return path;
}

// What has been seen of each unknown obstacle (perception::SemanticMap::seen) dilated by
// `radius`: the hull's Minkowski sum with the regular kSeenDilationSides-gon circumscribed about
// the disk of that radius (a convex superset of the round dilation F_k uses).
std::vector<geometry::Polygon> Executive::seen_dilated(double radius) const {
  const geometry::Polygon ring =
      geometry::regular_polygon({Point::Zero(), radius}, kSeenDilationSides, true);
  std::vector<geometry::Polygon> out;
  for (const geometry::Polygon& h : map_.seen()) {
    if (h.size() < 3) continue;
    std::vector<Point> points;
    points.reserve(h.size() * ring.size());
    for (const Point& v : h.vertices) {
      for (const Point& w : ring.vertices) points.push_back(v + w);
    }
    out.push_back(geometry::convex_hull(std::move(points)));
  }
  return out;
}

// Robust variant (RobustParams::face): after a back-up, turn in place toward the law's goal
// `nav` (kFaceTolerance), as far as the carried object stays clear; then the law resumes.
std::optional<Advance> Executive::face(Activity& a, const Pose& pose, const Point& nav, double t,
                                       double dt) {
  Advance out;
  out.u = reactive::align_command(pose.psi, pose.x, nav, p_.nav);
  if ((nav - pose.x).norm() <= p_.goal_tolerance ||
      reactive::aligned(pose.psi, pose.x, nav, kFaceTolerance) ||
      (map_.carried() && !step_clear(ctx_, pose, reactive::unicycle_step(pose, out.u, dt))) ||
      !centre_kept(ctx_, pose, reactive::unicycle_step(pose, out.u, dt))) {
    a.facing = Facing::kNo;
    a.monitor.reset(t);
    return std::nullopt;
  }
  if (a.facing == Facing::kPending) ++recoveries_.faces;
  a.facing = Facing::kTurning;
  return out;
}

// Robust variant (RobustParams::track): the next step along the guide toward `nav`
// (path_tracker.h) when it keeps the centre in F_k and everything clear; else the law takes over
// for the rest of this guide.
std::optional<Advance> Executive::track(Activity& a, const Pose& pose, const Point& nav, double rho,
                                        double dt) {
  Advance out;
  out.u = track_command(pose, rho, nav, p_.nav);
  const Pose next = reactive::unicycle_step(pose, out.u, dt);
  const Point next_center = rho > 0 ? reactive::pair_center(next.x, next.psi, rho) : next.x;
  if (reactive::in_freespace(controller_.mapped(), next_center) && step_clear(ctx_, pose, next)) {
    return out;
  }
  a.tracking = false;
  return std::nullopt;
}

// The reactive law's command; a singular Dh switches the action to convex pieces (robust
// variant) and rebuilds on the next transition.
Advance Executive::command(Activity& a, const Pose& pose, double rho, double t, double dt) {
  Advance out;
  try {
    out.u = map_.carried() ? controller_.pair(pose, rho, dt) : controller_.unicycle(pose, dt);
    law_command_ = true;
  } catch (const reactive::OutsideModelFreespace& e) {
    if (p_.robust.convex_fallback && !a.convex_all && centre_inside(ctx_, a, pose)) {
      // The centre lies inside F_k, clear of ∂F_k, yet h took it into a model obstacle: the
      // purge of a cluster deforms space across a convex obstacle near it (the separation of
      // [7] broken). Convex pieces keep h the identity there.
      a.convex_all = true;
      a.built = false;
      ++recoveries_.singular;
      out.kind = Advance::kRestart;
      return out;
    }
    // The centre touches a dilation (pressed into a corner): back up, then plan again.
    if (!p_.robust.back_out) throw;
    return start_back_out(a, pose, e.what(), t, dt);
  } catch (const reactive::SingularJacobian& e) {
    if (!p_.robust.convex_fallback || a.convex_all) throw;
    a.convex_all = true;
    a.built = false;
    ++recoveries_.singular;
    out.kind = Advance::kRestart;
  }
  return out;
}

std::optional<std::string> Executive::law_invariant_violation() const {
  if (!law_command_) return std::nullopt;
  const reactive::ReactiveController::LawSample& s = controller_.last_law_sample();
  if (!(s.det > 0)) return "det Dh = " + rearm::fixed(s.det, 3) + " <= 0 at x = " + point_text(s.x);
  if (std::optional<std::string> why =
          reactive::outside_model_freespace(controller_.diffeo().model(), s.y)) {
    return "the law's model point of x = " + point_text(s.x) + ": " + *why;
  }
  return std::nullopt;
}

Advance Executive::start_back_out(Activity& a, const Pose& pose, const std::string& why, double t,
                                  double dt, bool contact) {
  Advance out;
  out.kind = Advance::kStuck;
  out.reason = why;
  if (!p_.robust.back_out) return out;
  if (!contact && a.back_outs >= p_.robust.max_back_outs) {
    if (std::optional<Advance> d = drop_short(a, pose.x, t)) return *d;
    out.reason += " (after " + std::to_string(a.back_outs) + " back-ups)";
    return out;
  }
  if (!contact) ++a.back_outs;
  ++recoveries_.back_outs;
  a.backing = true;
  a.backing_travel = 0;
  a.backing_dir = -1;
  a.escape.reset();
  if (p_.robust.escape && !map_.carried()) a.escape = escape_line(pose.x);
  return back_out(a, pose, t, dt);
}

// Back-up of the robust variant: straight back, straight ahead, or (carrying) a turn in place
// either way: the first move whose next step keeps the robot, and the object it carries, clear
// of everything known and takes the centre (robot, or pair) farther from it, else the first that
// keeps them clear; kept while it stays clear, until the centre has moved back_out_step; then
// the action plans again from where it stopped.
Advance Executive::back_out(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const std::optional<std::string> carried = map_.carried();
  const double rho = carried ? object_radius(ctx_, *carried) : 0;
  auto finish_backing = [&] {
    a.backing = false;
    a.facing = p_.robust.face ? Facing::kPending : Facing::kNo;
    a.planned = false;
    a.built = false;
    a.monitor.reset(t);
    out.kind = Advance::kRestart;
    return out;
  };
  if (a.backing_travel >= p_.robust.back_out_step) return finish_backing();
  if (a.escape) {
    const std::optional<Twist> u = escape_step(a, pose, dt);
    if (!u) return finish_backing();
    out.u = *u;
    return out;
  }
  const double v = std::min(p_.backoff_speed, (p_.robust.back_out_step - a.backing_travel) / dt);
  const double w = carried ? std::min(p_.nav.omega_max, v / rho) : 0;
  const Twist moves[] = {{-v, 0},     {v, 0},       {0, w},     {0, -w},
                         {-v, w / 2}, {-v, -w / 2}, {v, w / 2}, {v, -w / 2}};
  // Without RobustParams::escape the pair's back-up has the first four moves; escape adds arcs,
  // and from the back-up after kPairLookaheadAfter looks all of them ahead.
  const int count = carried ? (p_.robust.escape ? 8 : 4) : 2;
  auto centre = [&](const Pose& q) {
    return carried ? reactive::pair_center(q.x, q.psi, rho) : q.x;
  };
  const double here = known_clearance(map_, centre(pose), carried.value_or(""));
  if (carried && p_.robust.escape && a.back_outs > kPairLookaheadAfter && a.backing_dir < 0 &&
      a.backing_travel == 0) {
    a.backing_dir = clearest_pair_move(pose, std::span(moves, count), rho, here, dt);
  }
  auto usable = [&](int k, bool away) {
    const Pose next = reactive::unicycle_step(pose, moves[k], dt);
    if (!step_clear(ctx_, pose, next)) return false;
    return !away || known_clearance(map_, centre(next), carried.value_or("")) > here;
  };
  if (a.backing_dir < 0 || !usable(a.backing_dir, false)) {
    a.backing_dir = -1;
    // A move away from what the centre touches first; any clear move otherwise.
    for (bool away : {true, false}) {
      for (int k = 0; k < count && a.backing_dir < 0; ++k) {
        if ((moves[k].v != 0 || moves[k].omega != 0) && usable(k, away)) a.backing_dir = k;
      }
    }
  }
  if (a.backing_dir < 0) {
    if (a.backing_travel > 0) return finish_backing();
    out.kind = Advance::kStuck;
    out.reason = "no room to back up from " + point_text(pose.x);
    return out;
  }
  out.u = moves[a.backing_dir];
  a.backing_travel += (std::abs(out.u.v) + rho * std::abs(out.u.omega)) * dt;
  return out;
}

// Robust variant (RobustParams::escape), carrying: each move of `moves` looked ahead for
// back_out_step of travel (or until a step would not keep the robot and the object clear of
// everything known), and the index of the one whose end leaves the pair's centre clearest, if
// clearer than `here`; -1 otherwise. The first move that takes the centre away at its first step
// (the back-up without escape) backs straight into the wedge between two obstacles as often as
// out of it: the pair centre must leave both dilations, and a turn or an arc often does.
int Executive::clearest_pair_move(const Pose& pose, std::span<const Twist> moves, double rho,
                                  double here, double dt) const {
  const std::string carried = *map_.carried();
  int best = -1;
  double best_clearance = here;
  for (std::size_t k = 0; k < moves.size(); ++k) {
    Pose q = pose;
    double travel = 0;
    while (travel < p_.robust.back_out_step) {
      const Pose next = reactive::unicycle_step(q, moves[k], dt);
      if (!step_clear(ctx_, pose, next) || !centre_kept(ctx_, q, next)) break;
      q = next;
      travel += (std::abs(moves[k].v) + rho * std::abs(moves[k].omega)) * dt;
    }
    if (travel == 0) continue;
    const double c = known_clearance(map_, reactive::pair_center(q.x, q.psi, rho), carried);
    if (c > best_clearance + kPairMoveGain) {
      best_clearance = c;
      best = static_cast<int>(k);
    }
  }
  return best;
}

// Robust variant (RobustParams::escape): along each of kEscapeHeadings straight lines from x,
// sampled every kEscapeSample up to back_out_step while nothing known comes closer than r (or
// than it is at x, if x is closer), the clearest sample; the clearest of all, if it is clearer
// than x: its heading and distance.
std::optional<Escape> Executive::escape_line(const Point& x) const {
  const double here = known_clearance(map_, x);
  const double floor = std::min(p_.robot_radius, here);
  const double step = p_.robust.back_out_step;
  std::optional<Escape> best;
  double best_clearance = here;
  for (int k = 0; k < kEscapeHeadings; ++k) {
    const double theta = 2 * std::numbers::pi * k / kEscapeHeadings;
    const Point d(std::cos(theta), std::sin(theta));
    for (double s = kEscapeSample; s <= step + 1e-9; s += kEscapeSample) {
      const double c = known_clearance(map_, x + s * d);
      if (c < floor) break;
      if (c > best_clearance) {
        best_clearance = c;
        best = Escape{theta, s};
      }
    }
  }
  return best;
}

// Turn in place to the escape heading or its reverse (the shorter turn), then drive along it
// for the escape's distance; each step keeps the robot no closer to anything known than r (or
// than it is now).
std::optional<Twist> Executive::escape_step(Activity& a, const Pose& pose, double dt) {
  const Escape& e = *a.escape;
  const double ahead = reactive::wrap_angle(e.heading - pose.psi);
  const double sign = std::abs(ahead) <= std::numbers::pi / 2 ? 1.0 : -1.0;
  const double error = sign > 0 ? ahead : reactive::wrap_angle(ahead + std::numbers::pi);
  const double omega = std::clamp(kTrackTurnGain * error, -p_.nav.omega_max, p_.nav.omega_max);
  if (std::abs(error) > kFaceTolerance) return Twist{0, omega};
  if (a.backing_travel >= e.distance) return std::nullopt;
  const double v = sign * std::min(p_.backoff_speed, (e.distance - a.backing_travel) / dt);
  const Twist u{v, omega};
  const Pose next = reactive::unicycle_step(pose, u, dt);
  const double floor = std::min(p_.robot_radius, known_clearance(map_, pose.x));
  if (known_clearance(map_, next.x) < floor) return std::nullopt;
  a.backing_travel += std::abs(v) * dt;
  return u;
}

// The exact freespace of the pair once `object` is gripped (the object carried, radius
// r + contact margin + ρ_i + pair_margin): F_list of Appendix III.
geometry::RegionSet Executive::pair_freespace(const std::string& object) {
  const auto& ids = map_.movable_ids();
  const auto it = std::find(ids.begin(), ids.end(), object);
  if (it == ids.end()) throw Error("executive: " + object + " is not a movable obstacle now");
  const std::size_t index = static_cast<std::size_t>(it - ids.begin());
  const Point c = map_.movable()[index].center;
  const ScopedStopwatch sw(times_.topology_s);
  ++topology_checks_;
  return topology::freespace_components(
      topology::make_input(map_.workspace(), map_.familiar(), map_.movable(),
                           plan_radius(ctx_) + object_radius(ctx_, object) + p_.grasp.pair_margin,
                           c, c, index, topology_cache_),
      topology_cache_);
}

// Robust drop rule: the paper's early-stop test (clear of every region, and 2(r + max ρ) from
// everything known), with kDropClearance (r + max ρ) instead of 2(r + max ρ), so that the
// dropped object leaves a passage for the pair between itself and anything else.
bool Executive::drop_clear(const Point& xc, double rho, double slack) const {
  const std::optional<std::string> carried = map_.carried();
  if (!carried) return false;
  if (!disassembly_done(xc, p_.robot_radius + rho + slack, p_.robot_radius, map_, *carried,
                        regions_)) {
    return false;
  }
  return known_clearance(map_, xc, *carried) >=
         kDropClearance * (p_.robot_radius + max_object_radius(ctx_)) + slack;
}

std::size_t Executive::restore_limit() const {
  return 2 * (map_.ground_truth().movable.size() + 1);
}

bool Executive::in_region(const std::string& object, const std::string& id) const {
  const auto d = map_.object(object);
  return d && geometry::contains(region(ctx_, id).polygon, d->center);
}

// Robust variant: the mission is accepting, but Fix mode moved objects that LTL actions had
// placed (the formula's "eventually release" held when they were released, the task's end state
// has them elsewhere). Each is released into its region again as an interface-layer action, at
// most 2 × (objects + 1) times per task.
bool Executive::restore_next(double t) {
  while (!displaced_.empty() && restores_ < restore_limit()) {
    const auto [object, region] = displaced_.front();
    displaced_.erase(displaced_.begin());
    const auto it = placed_.find(object);
    if (it == placed_.end() || it->second != region) continue;  // placed anew since
    if (in_region(object, region)) continue;
    ++restores_;
    ++recoveries_.restores;
    fix_.push_back(make(Kind::kRelease, object, region, true, t));
    return true;
  }
  return false;
}

// The mission is accepting and no restore is left to try. The objects an LTL RELEASE placed and
// Fix mode later moved, as the map locates them, are named. With the restores on, the task then
// ends stuck: the executive could not keep the end state it set out to restore (a restore that
// ended infeasible, or restores that ran out, two objects each in the other's way in turn).
// Without them (the paper variant) the formula, which speaks of actions only, holds: completed,
// with the objects named in the reason.
void Executive::finish_accepting(double t) {
  const std::string done = "mission complete: the automaton stays in an accepting state";
  std::string moved;
  for (const auto& [object, id] : placed_) {
    if (!in_region(object, id)) moved += (moved.empty() ? "" : ", ") + object + " not in " + id;
  }
  if (moved.empty()) return finish(TaskStatus::kCompleted, done, t);
  if (p_.robust.restore) {
    return finish(TaskStatus::kStuck,
                  "objects an LTL RELEASE placed and Fix mode moved are not back after " +
                      std::to_string(restores_) + " restore(s) (at most " +
                      std::to_string(restore_limit()) + "): " + moved + " (the formula holds)",
                  t);
  }
  finish(TaskStatus::kCompleted, done + "; Fix mode moved placed objects: " + moved, t);
}

RecoveryCounts Executive::recoveries() const {
  RecoveryCounts c = recoveries_;
  c.fallbacks = controller_.fallbacks();
  return c;
}

// The action's plan (paper §IV, §V): x* and the topology check's verdict; GRASP and
// DISASSEMBLE have their own.
Advance Executive::plan(Activity& a, const Pose& pose) {
  if (a.kind == Kind::kGrasp) return plan_grasp(a, pose);
  Advance out;
  const std::optional<std::string> carried = map_.carried();
  const auto [rho, radius, center] = moving(ctx_, a, pose);
  if (a.kind == Kind::kDisassemble) return plan_disassemble(a, radius, center, rho);

  const Point target = region_target(region(ctx_, a.region));
  const topology::TopologyResult res = timed_check(ctx_, radius, center, target);
  ++topology_checks_;
  a.target = target;
  if (a.kind == Kind::kRelease && p_.robust.release_point && carried == a.object &&
      res.verdict != topology::Verdict::kReachable) {
    // Robust variant: the centroid is cut off; anywhere in ℓ that the pair reaches now, as
    // clear as ℓ allows.
    const double inset = p_.robot_radius + p_.grasp.pair_margin + 2 * p_.goal_tolerance;
    const double enough = 2 * (p_.robot_radius + max_object_radius(ctx_));
    if (auto p = release_point(res.freespace, region(ctx_, a.region), map_, a.object, inset, enough,
                               kReleaseStep)) {
      a.target = *p;
      ++recoveries_.release_points;
      remember_plan(a);
      return out;
    }
  }
  switch (res.verdict) {
    case topology::Verdict::kReachable:
      remember_plan(a);
      return out;
    case topology::Verdict::kBlockedByFixed:
      if (!a.bare && plan_radius(ctx_, a) > p_.robot_radius) {
        // Robust variant: a passage only the contact margin closes is taken at the bare radius
        // (the paper's), for this action only.
        a.bare = true;
        return plan(a, pose);
      }
      out.kind = Advance::kInfeasible;
      out.reason = "fixed obstacles separate x* = " + point_text(target) + ": " + res.reason;
      return out;
    case topology::Verdict::kBlockedByObjects:
      out.kind = Advance::kBlocked;
      for (std::size_t i : res.blocking) out.blocking.push_back(map_.movable_ids()[i]);
      out.reason = res.reason;
      return out;
  }
  return out;
}

void Executive::remember_plan(Activity& a) const {
  a.planned = true;
  a.plan_familiar = map_.familiar().size();
  a.plan_movable = map_.movable();
  a.plan_carried = map_.carried();
}

// DISASSEMBLE's x* (paper §V-B): the midpoint of an edge of the pair's freespace F, kept while it
// stays in F so the target does not jump as the map grows. Robust variant: the nearest point of
// F where the object can be dropped clear of everything (drop_clear), when there is one.
Advance Executive::plan_disassemble(Activity& a, double radius, const Point& center, double rho) {
  Advance out;
  const topology::TopologyResult res = timed_check(ctx_, radius, center, center);
  ++topology_checks_;
  if (drop_points(a) && (!a.target || !geometry::contains(res.freespace, *a.target) ||
                         !drop_kept(a, *a.target, rho))) {
    a.target = drop_point(a, res.freespace, radius, center, rho);
  }
  if (!a.target || !geometry::contains(res.freespace, *a.target)) {
    a.target = disassemble_target(res.freespace, map_, a.object, regions_, radius);
    if (!a.target) {
      out.kind = Advance::kStuck;
      out.reason = "the pair's freespace has no edge to disassemble the object toward";
      return out;
    }
  }
  remember_plan(a);
  return out;
}

// As drop_clear for the first level; the lower levels keep the point while it meets their
// clearance and the region rule (both without the slack the point was chosen with, so that the
// target does not jump as the map grows).
bool Executive::drop_kept(const Activity& a, const Point& q, double rho) const {
  if (a.drop_level == 0) return drop_clear(q, rho);
  const std::optional<std::string> carried = map_.carried();
  if (!carried || !clear_of_regions(q, p_.robot_radius + rho, regions_)) return false;
  if (a.drop_level >= kDropLevels.size()) return true;
  return known_clearance(map_, q, *carried) >=
         kDropLevels[a.drop_level] * (p_.robot_radius + max_object_radius(ctx_));
}

// The robust variant's drop point: searched in the pair's mapped freespace F_k (the visible
// unknown fragments included, as the reactive controller will see it); in F when the centre is
// not in F_k. The nearest point clear of every region and kDropClearance (r + max ρ) from
// everything known; in a pocket where none is reachable, the nearest at the first of the lower
// kDropLevels that has one, then the clearest reachable point. Nearest, not clearest: the
// farther a point, the likelier an unseen fragment takes it (measured: clearest-first chose
// points 2–3 m away in unexplored space, eight of them taken in turn).
std::optional<Point> Executive::drop_point(Activity& a, const geometry::Region& free, double radius,
                                           const Point& center, double rho) {
  const double unit = p_.robot_radius + max_object_radius(ctx_);
  geometry::Region where = free;
  try {
    const ScopedStopwatch sw(times_.rebuild_s);
    where = reactive::build_mapped_space(semantic_input(ctx_), radius, center, drop_dilations_)
                .freespace;
  } catch (const reactive::NotInFreespace&) {
  }
  // Exact clearance of each level from everything known; the raster measures from ∂F_k, which
  // lies the pair radius closer.
  std::array<double, kDropLevels.size()> need{};
  std::array<double, kDropLevels.size()> raster_need{};
  for (std::size_t k = 0; k < need.size(); ++k) {
    need[k] = kDropLevels[k] * unit + kDropSlack;
    raster_need[k] = need[k] - radius;
  }
  // Points near a drop point a fragment took before are skipped: fragments are what the sensor
  // sees now, so a point can look clear from one side and not from another.
  const std::string carried = map_.carried().value_or("");
  auto accept = [&](const Point& q, std::size_t k) {
    for (const Point& x : a.rejected_drops) {
      if ((q - x).norm() < 2 * unit) return false;
    }
    return clear_of_regions(q, p_.robot_radius + rho + kDropSlack, regions_) &&
           (k == need.size() || known_clearance(map_, q, carried) >= need[k]);
  };
  const auto q = nearest_clear_point(where, center, raster_need, accept, p_.guide, true);
  a.drop_level = q ? q->level : kDropLevels.size();  // none: the paper's target, kept as is
  if (!q) return std::nullopt;
  if (q->level > 0) ++recoveries_.pocket_drops;
  return q->point;
}

Advance Executive::plan_grasp(Activity& a, const Pose& pose) {
  Advance out;
  const double r = p_.robot_radius;
  const std::vector<GraspCandidate> candidates =
      grasp_candidates(map_, a.object, r, pose.x, p_.grasp);
  if (candidates.empty()) {
    out.kind = Advance::kInfeasible;
    out.reason = "no side of " + a.object + " leaves room to dock and to carry it (" +
                 std::to_string(p_.grasp.samples) + " directions tried)";
    return out;
  }
  const auto& ids = map_.movable_ids();

  // Exact freespaces: the robot's (every object an obstacle) and the pair's once gripped (the
  // object carried, radius r + ρ_i + pair_margin).
  // F from the topology check with x* = x (throws when the robot is not in its freespace).
  const double rp = plan_radius(ctx_);
  const topology::TopologyResult here = timed_check(ctx_, rp, pose.x, pose.x);
  const geometry::Region* f = &here.freespace;
  const geometry::RegionSet pair_free = pair_freespace(a.object);
  topology_checks_ += 1;
  const auto [reachable, fallback] = choose_side(a, candidates, pair_free, *f);
  if (fallback == nullptr) {
    out.kind = Advance::kInfeasible;
    out.reason = "no side of " + a.object + " from which the robot–object pair would be free";
    return out;
  }
  a.target = (reachable != nullptr ? reachable : fallback)->approach;
  if (reachable == nullptr) {
    // Paper §IV: the approach point is not in F; the topology check says why.
    const topology::TopologyResult res = timed_check(ctx_, r, pose.x, *a.target);
    ++topology_checks_;
    if (res.verdict == topology::Verdict::kBlockedByFixed) {
      out.kind = Advance::kInfeasible;
      out.reason =
          "fixed obstacles separate the robot from every side of " + a.object + ": " + res.reason;
      return out;
    }
    if (res.verdict == topology::Verdict::kBlockedByObjects) {
      for (std::size_t i : res.blocking) {
        if (ids[i] != a.object) out.blocking.push_back(ids[i]);
      }
      if (out.blocking.empty()) {
        out.kind = Advance::kInfeasible;
        out.reason = "only " + a.object + " itself separates the robot from its free sides";
        return out;
      }
      out.kind = Advance::kBlocked;
      out.reason = res.reason;
      return out;
    }
  }
  remember_plan(a);
  return out;
}

// GRASP's side (paper §IV): the first candidate whose pair centre lies in the pair's freespace
// and whose approach point lies in F (reachable), and the first with the pair free alone
// (fallback, for the topology check). Robust variant (RobustParams::fragments): sides whose
// approach point or pair lies within the dilation of a visible unknown fragment (which the
// topology check does not model) come last.
std::pair<const GraspCandidate*, const GraspCandidate*> Executive::choose_side(
    const Activity& a, const std::vector<GraspCandidate>& candidates,
    const geometry::RegionSet& pair_free, const geometry::Region& f) const {
  const GraspCandidate* reachable = nullptr;
  const GraspCandidate* fallback = nullptr;
  const double pair_radius = p_.robot_radius + object_radius(ctx_, a.object) + p_.grasp.pair_margin;
  auto clear_of_fragments = [&](const GraspCandidate& g) {
    return known_clearance(map_, g.approach, a.object) >= plan_radius(ctx_, a) &&
           known_clearance(map_, g.pair_center, a.object) >= pair_radius;
  };
  for (bool clear : {true, false}) {
    if (clear && !p_.robust.fragments) continue;
    for (const GraspCandidate& g : candidates) {
      if (!geometry::contains(pair_free, g.pair_center) || (clear && !clear_of_fragments(g))) {
        continue;
      }
      if (fallback == nullptr) fallback = &g;
      if (geometry::contains(f, g.approach)) {
        reachable = &g;
        break;
      }
    }
    if (reachable != nullptr) break;
  }
  return {reachable, fallback};
}

void Executive::enter_fix(const std::vector<std::string>& blocking, double t) {
  Activity* a = current();
  a->interruptions++;
  a->planned = false;
  a->built = false;
  if (!a->fix) {
    ++fix_entries_;
    if (++fix_rounds_ > p_.max_fix_rounds) {
      const std::string why = "Fix mode entered " + std::to_string(p_.max_fix_rounds) +
                              " times for this action without clearing the way";
      const std::string what = a->name() + ": " + why;
      end_current(ActionOutcome::kStuck, why, t);
      finish(TaskStatus::kStuck, what, t);
      return;
    }
  }
  std::vector<Activity> exec;  // execution order
  const std::optional<std::string> carried = map_.carried();
  if (carried) exec.push_back(make(Kind::kDisassemble, *carried, "", true, t));
  for (auto it = blocking.rbegin(); it != blocking.rend(); ++it) {  // back() is B_M's top
    if (const auto p = placed_.find(*it); p != placed_.end() && p_.robust.restore) {
      displaced_.emplace_back(p->first, p->second);
    }
    exec.push_back(make(Kind::kGrasp, *it, "", true, t));
    exec.push_back(make(Kind::kDisassemble, *it, "", true, t));
  }
  if (carried) exec.push_back(make(Kind::kGrasp, *carried, "", true, t));
  const std::size_t limit = 2 * (map_.ground_truth().movable.size() + 1);
  if (fix_.size() + exec.size() > limit) {
    const std::string why = "Fix mode would stack " + std::to_string(fix_.size() + exec.size()) +
                            " actions (limit " + std::to_string(limit) +
                            "): the blocking objects keep blocking each other";
    const std::string what = a->name() + ": " + why;
    end_current(ActionOutcome::kStuck, why, t);
    finish(TaskStatus::kStuck, what, t);
    return;
  }
  for (auto it = exec.rbegin(); it != exec.rend(); ++it) fix_.push_back(std::move(*it));
}

// An action ended stuck. Paper §III-A: when the continuous controller fails at a sub-task, the
// symbolic controller is asked for an alternative; so an LTL action that ended stuck (itself, or
// in a Fix-mode action serving it) is reported infeasible to the mission controller, the Fix
// stack is dropped, and the next action is the controller's alternative, if any. A stuck
// interface-layer action with no LTL action behind it (a restore) ends the task stuck.
void Executive::end_stuck(const std::string& reason, double t) {
  Activity* a = current();
  const std::string what = a->name() + ": " + reason;
  if (!ltl_) {
    end_current(ActionOutcome::kStuck, reason, t);
    finish(TaskStatus::kStuck, what, t);
    return;
  }
  log_.push_back(ActionRecord{a->name(), a->fix, ActionOutcome::kStuck, reason, a->t_start, t,
                              a->interruptions, a->target});
  if (a->fix) {
    const std::string why = "gave up after " + what;
    fix_.pop_back();
    abandon_fix(why, t);
    log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kStuck, why, ltl_->t_start, t,
                                ltl_->interruptions, ltl_->target});
  }
  stuck_ = stuck_.empty() ? what : stuck_ + "; " + what;
  {
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_infeasible(ltl_->ltl);
  }
  ltl_.reset();
}

void Executive::abandon_fix(const std::string& why, double t) {
  for (auto it = fix_.rbegin(); it != fix_.rend(); ++it) {
    log_.push_back(ActionRecord{it->name(), true, ActionOutcome::kAbandoned, why, it->t_start, t,
                                it->interruptions, it->target});
  }
  fix_.clear();
}

void Executive::end_current(ActionOutcome outcome, const std::string& reason, double t) {
  Activity* a = current();
  if (a == nullptr) return;
  log_.push_back(
      ActionRecord{a->name(), a->fix, outcome, reason, a->t_start, t, a->interruptions, a->target});
  if (a->fix) {
    fix_.pop_back();
    if (outcome == ActionOutcome::kInfeasible) {
      // The Fix mode cannot clear the way: the LTL action it served is infeasible.
      const std::string why = "Fix mode failed: " + reason;
      abandon_fix(why, t);
      if (ltl_) {
        log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kInfeasible, why,
                                    ltl_->t_start, t, ltl_->interruptions, ltl_->target});
        {
          const ScopedStopwatch sw(times_.mission_s);
          mission_.report_infeasible(ltl_->ltl);
        }
        ltl_.reset();
      }
    }
    if (fix_.empty() && ltl_) {
      // Back to LTL mode: re-run the topology check (docs/executive.md, Fix mode).
      ltl_->planned = false;
      ltl_->built = false;
      ltl_->monitor.reset(t);
    }
    return;
  }
  if (outcome == ActionOutcome::kSucceeded) {
    // What the LTL actions placed (robust variant: restored if Fix mode moves it).
    if (a->kind == Kind::kRelease) placed_[a->object] = a->region;
    if (a->kind == Kind::kGrasp) placed_.erase(a->object);
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_success();
    ++ltl_done_;
  } else if (outcome == ActionOutcome::kInfeasible) {
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_infeasible(ltl_->ltl);
  }
  ltl_.reset();
}

void Executive::finish(TaskStatus status, const std::string& reason, double t) {
  if (finished()) return;
  status_ = status;
  reason_ = reason;
  const std::string why = "task ended: " + reason;
  abandon_fix(why, t);
  if (ltl_) {
    log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kAbandoned, why, ltl_->t_start,
                                t, ltl_->interruptions, ltl_->target});
    ltl_.reset();
  }
}

void Executive::abort(TaskStatus status, const std::string& reason, double t) {
  if (status == TaskStatus::kRunning) throw Error("executive: abort needs a final status");
  finish(status, reason, t);
}

}  // namespace rearm::executive
