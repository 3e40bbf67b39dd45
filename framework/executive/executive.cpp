#include "executive/executive.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/stopwatch.h"
#include "geometry/dilation.h"
#include "reactive/grasp.h"
#include "reactive/navigation.h"
#include "topology/topology_check.h"

namespace rearm::executive {
namespace {

// Phase changes allowed in one tick before the executive gives up (each action takes a handful:
// plan, reach, align, dock, …); more means a bug, reported as stuck rather than a hang.
constexpr int kMaxTransitionsPerTick = 64;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

std::string point_text(const Point& p) { return "(" + fmt(p.x()) + ", " + fmt(p.y()) + ")"; }

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
    if (!std::isfinite(v) || !(v > 0)) {
      throw Error(std::string("executive: ") + name + " must be finite and > 0, got " +
                  std::to_string(v));
    }
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

std::string Executive::Activity::name() const {
  switch (kind) {
    case Kind::kMove:
      return "move(" + region + ")";
    case Kind::kGrasp:
      return "grasp(" + object + ")";
    case Kind::kRelease:
      return "release(" + object + "," + region + ")";
    case Kind::kDisassemble:
      return "disassemble(" + object + ")";
  }
  return "?";
}

Executive::Executive(const ExecutiveParams& params, const std::vector<RegionOfInterest>& regions,
                     symbolic::MissionController& mission, const perception::SemanticMap& map)
    : p_(params),
      regions_(validated(regions, map.workspace())),
      mission_(mission),
      map_(map),
      controller_(params.diffeo, params.nav) {
  validate(p_);
}

Executive::Activity Executive::make(Kind kind, std::string object, std::string region, bool fix,
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

Executive::Activity* Executive::current() {
  if (!fix_.empty()) return &fix_.back();
  return ltl_ ? &*ltl_ : nullptr;
}

std::string Executive::current_action() const {
  if (!fix_.empty()) return fix_.back().name();
  return ltl_ ? ltl_->name() : std::string();
}

const RegionOfInterest& Executive::region(const std::string& id) const {
  for (const RegionOfInterest& r : regions_) {
    if (r.id == id) return r;
  }
  throw Error("executive: unknown region of interest '" + id + "'");
}

double Executive::object_radius(const std::string& id) const {
  const auto d = map_.object(id);
  if (!d) throw Error("executive: unknown object '" + id + "'");
  return d->radius;
}

reactive::SemanticInput Executive::semantic_input() const {
  return reactive::SemanticInput{map_.workspace(), map_.familiar(), map_.unknown(), map_.movable()};
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
        finish(TaskStatus::kInfeasible, "mission infeasible: " + mission_.reason(), t);
        break;
      case symbolic::MissionStatus::Accepting:
        finish(TaskStatus::kCompleted,
               "mission complete: the automaton stays in an accepting state", t);
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
  if (!ltl_->region.empty()) region(ltl_->region);
  if (!ltl_->object.empty()) object_radius(ltl_->object);
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
      case Advance::kStuck: {
        const std::string what = a->name() + ": " + r.reason;
        end_current(ActionOutcome::kStuck, r.reason, t);
        finish(TaskStatus::kStuck, what, t);
        break;
      }
    }
  }
  if (!finished()) {
    finish(TaskStatus::kStuck,
           "no motion command after " + std::to_string(kMaxTransitionsPerTick) +
               " action transitions in one tick (at " + current_action() + ")",
           t);
  }
  return Command{Twist{}, gripper_, gripper_object_};
}

Executive::Advance Executive::advance(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const double r = p_.robot_radius;
  switch (a.phase) {
    case Phase::kNavigate: {
      // Gripper prerequisites (interface-layer steps, beyond the paper; see the header).
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
    case Phase::kAlign: {
      const geometry::Disk m = *map_.object(a.object);
      if (reactive::aligned(pose.psi, pose.x, m.center, p_.align_tolerance)) {
        a.phase = Phase::kDock;
        a.phase_start = t;
        out.kind = Advance::kRestart;
        return out;
      }
      if (t - a.phase_start > p_.phase_timeout) {
        out.kind = Advance::kStuck;
        out.reason =
            "could not turn the gripper toward the object within " + fmt(p_.phase_timeout) + " s";
        return out;
      }
      out.u = reactive::align_command(pose.psi, pose.x, m.center, p_.nav);
      return out;
    }
    case Phase::kDock: {
      const geometry::Disk m = *map_.object(a.object);
      const double gap = (m.center - pose.x).norm() - r - m.radius;
      if (gap <= p_.grasp.dock_gap) {
        gripper_ = GripperAction::kClose;
        gripper_object_ = a.object;
        a.phase = Phase::kGrip;
        a.phase_start = t;
        a.note = "gripped at gap " + fmt(gap * 1000) + " mm";
        return out;  // stand still while the gripper closes
      }
      if (t - a.phase_start > p_.phase_timeout) {
        out.kind = Advance::kStuck;
        out.reason = "could not dock to the object within " + fmt(p_.phase_timeout) + " s";
        return out;
      }
      // Straight in, never closer than half the gap allowance in one step, steering to keep
      // facing the centre.
      out.u.v = std::min(p_.dock_speed, (gap - p_.grasp.dock_gap / 2) / dt);
      out.u.omega = reactive::align_command(pose.psi, pose.x, m.center, p_.nav).omega;
      return out;
    }
    case Phase::kGrip:
      if (map_.carried() == a.object) {
        out.kind = Advance::kDone;
        out.reason = a.note;
      } else {
        out.kind = Advance::kStuck;
        out.reason = "the gripper did not close on " + a.object;
      }
      return out;
    case Phase::kOpen:
      if (map_.carried()) {
        // The robot stood still for one tick (so the object is at rest when it is let go);
        // now the gripper opens, and the map must say so on the next tick.
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
    case Phase::kBackOff: {
      const geometry::Disk m = *map_.object(a.object);
      const double need =
          geometry::disk_polygon_circumradius(m.radius + r + geometry::kContactSlack) +
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
      if (known_clearance(map_, next) < r) {
        out.kind = Advance::kStuck;
        out.reason = "no room to back off from the released object at " + point_text(pose.x);
        return out;
      }
      return out;
    }
  }
  out.kind = Advance::kStuck;
  out.reason = "unknown phase";
  return out;
}

Executive::Advance Executive::navigate(Activity& a, const Pose& pose, double t, double dt) {
  Advance out;
  const double r = p_.robot_radius;
  const std::optional<std::string> carried = map_.carried();
  const double rho = carried ? object_radius(*carried) : 0;
  const double radius = carried ? r + rho + p_.grasp.pair_margin : r;
  const Point center = carried ? reactive::pair_center(pose.x, pose.psi, rho) : pose.x;

  // A grasp approach point chosen earlier may have lost its clearance to a newly seen unknown
  // fragment (the topology knowledge is unchanged then).
  if (a.planned && a.kind == Kind::kGrasp && a.built && a.built_version != map_.version() &&
      known_clearance(map_, *a.target) < r) {
    a.planned = false;
  }
  if (!a.planned || knowledge_changed(a)) {
    Advance p = plan(a, pose);
    if (p.kind != Advance::kCommand) return p;
  }
  const Point target = *a.target;
  if (!a.built || a.built_version != map_.version() || a.built_target != target ||
      a.built_radius != radius) {
    reactive::RebuildResult rr;
    {
      const ScopedStopwatch sw(times_.rebuild_s);
      rr = controller_.try_rebuild(semantic_input(), radius, center, target);
    }
    if (rr.status == reactive::RebuildStatus::kCenterNotFree) {
      out.kind = Advance::kStuck;
      out.reason = rr.message;
      return out;
    }
    if (rr.status == reactive::RebuildStatus::kGoalNotFree) {
      if (a.kind == Kind::kDisassemble) {
        out.kind = Advance::kStuck;
        out.reason =
            "the disassembly target " + point_text(target) + " is not reachable: " + rr.message;
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
    }
    a.built = true;
    a.built_version = map_.version();
    a.built_target = target;
    a.built_radius = radius;
  }

  const double tol = a.kind == Kind::kGrasp ? p_.grasp_goal_tolerance : p_.goal_tolerance;
  const double dist = (center - controller_.goal()).norm();
  bool reached = dist <= tol;
  std::string why = "reached x* = " + point_text(controller_.goal());
  if (!reached && a.kind == Kind::kDisassemble &&
      disassembly_done(center, r + rho, r, map_, *carried, regions_)) {
    reached = true;
    why = "early stop at " + point_text(center) + " (clear of regions and of every obstacle)";
  }
  if (reached) {
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
  }
  if (auto stuck = a.monitor.observe(t, pose, dist, map_.version())) {
    out.kind = Advance::kStuck;
    out.reason = *stuck;
    return out;
  }
  out.u = carried ? controller_.pair(pose, rho, dt) : controller_.unicycle(pose, dt);
  return out;
}

Executive::Advance Executive::plan(Activity& a, const Pose& pose) {
  if (a.kind == Kind::kGrasp) return plan_grasp(a, pose);
  Advance out;
  const double r = p_.robot_radius;
  const std::optional<std::string> carried = map_.carried();
  const double rho = carried ? object_radius(*carried) : 0;
  const double radius = carried ? r + rho + p_.grasp.pair_margin : r;
  const Point center = carried ? reactive::pair_center(pose.x, pose.psi, rho) : pose.x;
  auto remember = [&] {
    a.planned = true;
    a.plan_familiar = map_.familiar().size();
    a.plan_movable = map_.movable();
    a.plan_carried = carried;
  };

  if (a.kind == Kind::kDisassemble) {
    // Paper §V-B: x* is the midpoint of an edge of the pair's freespace F; kept while it stays
    // in F so the target does not jump as the map grows.
    const topology::TopologyResult res = timed_check(radius, center, center);
    ++topology_checks_;
    if (!a.target || !geometry::contains(res.freespace, *a.target)) {
      a.target = disassemble_target(res.freespace, map_, a.object, regions_, radius);
      if (!a.target) {
        out.kind = Advance::kStuck;
        out.reason = "the pair's freespace has no edge to disassemble the object toward";
        return out;
      }
    }
    remember();
    return out;
  }

  const Point target = region_target(region(a.region));
  const topology::TopologyResult res = timed_check(radius, center, target);
  ++topology_checks_;
  a.target = target;
  switch (res.verdict) {
    case topology::Verdict::kReachable:
      remember();
      return out;
    case topology::Verdict::kBlockedByFixed:
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

Executive::Advance Executive::plan_grasp(Activity& a, const Pose& pose) {
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
  const auto it = std::find(ids.begin(), ids.end(), a.object);
  if (it == ids.end()) throw Error("executive: " + a.object + " is not a movable obstacle now");
  const std::size_t index = static_cast<std::size_t>(it - ids.begin());
  const double rho = object_radius(a.object);

  // Exact freespaces: the robot's (every object an obstacle) and the pair's once gripped (the
  // object carried, radius r + ρ_i + pair_margin).
  // F from the topology check with x* = x (throws when the robot is not in its freespace).
  const topology::TopologyResult here = timed_check(r, pose.x, pose.x);
  const geometry::Region* f = &here.freespace;
  const Point c = map_.movable()[index].center;
  const geometry::RegionSet pair_free = [&] {
    const ScopedStopwatch sw(times_.topology_s);
    return freespace_of(topology::make_input(map_.workspace(), map_.familiar(), map_.movable(),
                                             r + rho + p_.grasp.pair_margin, c, c, index,
                                             topology_cache_));
  }();
  topology_checks_ += 2;
  const GraspCandidate* reachable = nullptr;
  const GraspCandidate* fallback = nullptr;
  for (const GraspCandidate& g : candidates) {
    if (!geometry::contains(pair_free, g.pair_center)) continue;
    if (fallback == nullptr) fallback = &g;
    if (geometry::contains(*f, g.approach)) {
      reachable = &g;
      break;
    }
  }
  if (fallback == nullptr) {
    out.kind = Advance::kInfeasible;
    out.reason = "no side of " + a.object + " from which the robot–object pair would be free";
    return out;
  }
  a.target = (reachable != nullptr ? reachable : fallback)->approach;
  if (reachable == nullptr) {
    // Paper §IV: the approach point is not in F; the topology check says why.
    const topology::TopologyResult res = timed_check(r, pose.x, *a.target);
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
  a.planned = true;
  a.plan_familiar = map_.familiar().size();
  a.plan_movable = map_.movable();
  a.plan_carried = map_.carried();
  return out;
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
      for (auto it = fix_.rbegin(); it != fix_.rend(); ++it) {
        log_.push_back(ActionRecord{it->name(), true, ActionOutcome::kAbandoned, why, it->t_start,
                                    t, it->interruptions, it->target});
      }
      fix_.clear();
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
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_success();
    ++ltl_done_;
  } else if (outcome == ActionOutcome::kInfeasible) {
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_infeasible(ltl_->ltl);
  }
  ltl_.reset();
}

topology::TopologyResult Executive::timed_check(double radius, const Point& x,
                                                const Point& target) {
  const ScopedStopwatch sw(times_.topology_s);
  const topology::TopologyInput in =
      topology::make_input(map_.workspace(), map_.familiar(), map_.movable(), radius, x, target,
                           std::nullopt, topology_cache_);
  return topology::check_topology(in, topology_cache_);
}

void Executive::finish(TaskStatus status, const std::string& reason, double t) {
  if (finished()) return;
  status_ = status;
  reason_ = reason;
  const std::string why = "task ended: " + reason;
  for (auto it = fix_.rbegin(); it != fix_.rend(); ++it) {
    log_.push_back(ActionRecord{it->name(), true, ActionOutcome::kAbandoned, why, it->t_start, t,
                                it->interruptions, it->target});
  }
  fix_.clear();
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
