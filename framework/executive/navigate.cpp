#include "executive/navigate.h"

#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "core/stopwatch.h"
#include "core/text.h"
#include "executive/back_up.h"
#include "executive/guides.h"
#include "executive/interface_layer.h"
#include "executive/motion_checks.h"
#include "executive/path_tracker.h"
#include "executive/planning.h"
#include "executive/recovery.h"
#include "executive/release_pose.h"
#include "executive/targets.h"
#include "reactive/grasp.h"
#include "reactive/navigation.h"
#include "topology/topology_check.h"

namespace rearm::executive {
namespace {

// The cause "centre not free" met with `reason`: the recoveries' next step, else stuck.
Advance centre_not_free(const Context& c, ActionState& a, const Pose& pose, std::string reason,
                        const Moving& m, Tick tick) {
  Trigger not_free{Cause::kCentreNotFree, std::move(reason), m.radius, m.center};
  if (std::optional<Advance> r = recover(c, a, pose, not_free, tick)) return *r;
  return stuck(not_free.reason);
}

// A map version newer than the build: stale at once in the paper variant, else once the news
// (map_news.h) comes within rebuild_margin of the centre's disk. The news is measured once per
// map version; as the centre moves, its distance shrinks by at most the centre's travel.
bool stale(const Context& c, ActionState& a, double radius, const Point& center) {
  if (a.built_version == c.map.version()) return false;
  if (!c.p.robust.defer) return true;
  if (a.news_version != c.map.version()) {
    a.news_version = c.map.version();
    a.news = news_distance(a.built_map, c.map, center);
    a.news_at = center;
  }
  return a.news - (center - a.news_at).norm() <= radius + c.p.robust.rebuild_margin;
}

// The diffeomorphism for the current map, radius and x* (reactive controller of [7]); a guide
// whose next waypoint left the new mapped space is planned again. center_not_free: the centre
// is not in the freespace (the caller backs out, or ends stuck in the paper variant).
Advance rebuild(const Context& c, ActionState& a, const Pose& pose, double radius,
                const Point& center, double t, double dt) {
  Advance out;
  const Point target = *a.target;
  c.controller.set_convexify_all(a.once.convex_all);
  reactive::RebuildResult rr;
  {
    const ScopedStopwatch sw(c.times.rebuild_s);
    rr = c.controller.try_rebuild(semantic_input(c), radius, center, target);
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
    // The cause "goal cut off" (docs/executive.md, "Recoveries"): a newly seen unknown fragment
    // took x*, which the topology check does not model.
    Trigger cut{Cause::kGoalCutOff, rr.message, radius, center};
    if (std::optional<Advance> r = recover(c, a, pose, cut, Tick{t, dt})) return *r;
    if (a.kind == ActionKind::kDisassemble) {
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
  if (a.built && (a.built_target - target).norm() > c.p.progress.progress_step) {
    a.monitor.reset(t);
    a.guide.best = std::numeric_limits<double>::infinity();  // distances to another x*
  }
  a.built = true;
  a.built_version = c.map.version();
  a.checked_version = c.map.version();
  if (c.p.robust.defer) a.built_map = MapSnapshot::of(c.map);
  a.built_target = target;
  a.built_radius = radius;
  a.goal = c.controller.goal();
  if (a.guide.pending) {
    a.guide.pending = false;
    std::string note;
    plan_guide(c, a, center, t, note);
  }
  // A guide in use stays while its next waypoint is still free (a path costs tens of ms; the
  // map changes every few ticks as fragments grow), else it is planned again.
  if (!a.guide.path.empty() &&
      !reactive::in_freespace(c.controller.mapped(), a.guide.path.front())) {
    replan_guide(c, a, center);
  }
  return out;
}

// RELEASE from a pose (RobustParams::release_pose, release_pose.h): once the carried object's
// centre lies goal_tolerance within ℓ (the predicate holds, §II-B), stop for one tick, then open
// (ActionPhase::kOpen); nullopt before.
std::optional<Advance> set_down_inside(const Context& c, ActionState& a, double t) {
  const geometry::Disk m = *c.map.object(a.object);
  if (!object_inside(region(c, a.region), m.center, c.p.goal_tolerance)) return std::nullopt;
  a.note = "set " + a.object + " down inside " + a.region + " from a pose";
  a.phase = ActionPhase::kOpen;
  a.phase_start = t;
  a.open_sent = false;
  return Advance{};
}

// RELEASE from a pose, on the law's way to the lead-in: set down once the object is inside ℓ;
// at the lead-in the straight last stretch (set_down) begins. nullopt while still on the way.
std::optional<Advance> arrive_posed(const Context& c, ActionState& a, const Point& center,
                                    double t) {
  if (std::optional<Advance> open = set_down_inside(c, a, t)) return open;
  if (!a.guide.path.empty() || (center - a.goal).norm() > c.p.goal_tolerance) return std::nullopt;
  a.pose_stretch = true;
  a.phase_start = t;
  a.target = a.pose->pair;
  a.guide.drop();
  a.monitor.reset(t);
  return restart();
}

// RELEASE from a pose, the last stretch: from the lead-in the robot turns in place toward the
// object point o and drives straight at it (track_command of the robot's centre), every step
// checked against everything known (step_clear), until the object's centre lies goal_tolerance
// within ℓ; a step that is not clear, or the phase timeout, ends the action stuck.
Advance set_down(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  if (std::optional<Advance> open = set_down_inside(c, a, t)) return *open;
  const geometry::Disk m = *c.map.object(a.object);
  Advance out;
  out.u = track_command(pose, 0, a.pose->object, c.p.nav);
  if (t - a.phase_start > c.p.phase_timeout) {
    return stuck("the last stretch to " + a.region + "'s release pose took longer than " +
                 rearm::fixed(c.p.phase_timeout, 3) + " s");
  }
  if (!step_clear(c, pose, reactive::unicycle_step(pose, out.u, dt))) {
    return stuck("the last stretch to " + a.region + "'s release pose is not clear at " +
                 point_text(pose.x) + " (" + a.object + " at " + point_text(m.center) + ")");
  }
  return out;
}

// Reached x* (MOVE: done; GRASP: align; RELEASE, DISASSEMBLE: stop and open), or the early stop
// of DISASSEMBLE (paper §V-B); nullopt while still on the way.
std::optional<Advance> arrive(const Context& c, ActionState& a, const Point& center, double rho,
                              double t) {
  if (a.kind == ActionKind::kRelease && a.pose) return arrive_posed(c, a, center, t);
  Advance out;
  const double tol = a.kind == ActionKind::kGrasp ? c.p.grasp_goal_tolerance : c.p.goal_tolerance;
  bool reached = a.guide.path.empty() && (center - a.goal).norm() <= tol;
  std::string why;  // written only once reached (formatting every tick cost 3% of a trial)
  auto early = [&] {
    return drop_points(c, a) ? drop_clear(c, center, rho)
                             : disassembly_done(center, c.p.robot_radius + rho, c.p.robot_radius,
                                                c.map, *c.map.carried(), c.regions);
  };
  if (!reached && a.kind == ActionKind::kDisassemble && c.map.carried() && early()) {
    reached = true;
    why = "early stop at " + point_text(center) + " (clear of regions and of every obstacle)";
  }
  if (!reached) return std::nullopt;
  if (why.empty()) why = "reached x* = " + point_text(a.goal);
  switch (a.kind) {
    case ActionKind::kMove:
      out.kind = Advance::kDone;
      out.reason = why;
      return out;
    case ActionKind::kGrasp:
      a.phase = ActionPhase::kAlign;
      a.phase_start = t;
      out.kind = Advance::kRestart;
      return out;
    case ActionKind::kRelease:
    case ActionKind::kDisassemble:
      a.note = why;
      a.phase = ActionPhase::kOpen;
      a.phase_start = t;
      a.open_sent = false;
      return out;  // stop for one tick, then open (ActionPhase::kOpen)
  }
  return out;
}

// Robust variant (RobustParams::face): after a back-up, turn in place toward the law's goal
// `nav` (kFaceTolerance), as far as the carried object stays clear; then the law resumes.
std::optional<Advance> face(const Context& c, ActionState& a, const Pose& pose, const Point& nav,
                            double t, double dt) {
  Advance out;
  out.u = reactive::align_command(pose.psi, pose.x, nav, c.p.nav);
  if ((nav - pose.x).norm() <= c.p.goal_tolerance ||
      reactive::aligned(pose.psi, pose.x, nav, kFaceTolerance) ||
      (c.map.carried() && !step_clear(c, pose, reactive::unicycle_step(pose, out.u, dt))) ||
      !centre_kept(c, pose, reactive::unicycle_step(pose, out.u, dt))) {
    a.back_up.facing = Facing::kNo;
    a.monitor.reset(t);
    return std::nullopt;
  }
  if (a.back_up.facing == Facing::kPending) ++c.recoveries.faces;
  a.back_up.facing = Facing::kTurning;
  return out;
}

// Robust variant (RobustParams::track): the next step along the guide toward `nav`
// (path_tracker.h) when it keeps the centre in F_k and everything clear; else the law takes over
// for the rest of this guide.
std::optional<Advance> track(const Context& c, ActionState& a, const Pose& pose, const Point& nav,
                             double rho, double dt) {
  Advance out;
  out.u = track_command(pose, rho, nav, c.p.nav);
  const Pose next = reactive::unicycle_step(pose, out.u, dt);
  const Point next_center = rho > 0 ? reactive::pair_center(next.x, next.psi, rho) : next.x;
  if (reactive::in_freespace(c.controller.mapped(), next_center) && step_clear(c, pose, next)) {
    return out;
  }
  a.guide.tracking = false;
  return std::nullopt;
}

// The reactive law's command of [7]; where the law has none (a singular Dh, or a model point
// outside the model freespace), the recoveries of those causes, else the action ends stuck.
Advance command(const Context& c, ActionState& a, const Pose& pose, double rho, double t,
                double dt) {
  Advance out;
  try {
    out.u = c.map.carried() ? c.controller.pair(pose, rho, dt) : c.controller.unicycle(pose, dt);
    out.law = true;
  } catch (const reactive::OutsideModelFreespace& e) {
    // The cause "no law" (h took the centre into a model obstacle), then "centre not free": the
    // centre touches a dilation (pressed into a corner).
    const Moving m = moving(c, a, pose);
    Trigger no_law{Cause::kNoLaw, e.what(), m.radius, m.center, true};
    if (std::optional<Advance> r = recover(c, a, pose, no_law, Tick{t, dt})) return *r;
    return centre_not_free(c, a, pose, e.what(), m, Tick{t, dt});
  } catch (const reactive::SingularJacobian& e) {
    const Moving m = moving(c, a, pose);
    Trigger no_law{Cause::kNoLaw, e.what(), m.radius, m.center};
    if (std::optional<Advance> r = recover(c, a, pose, no_law, Tick{t, dt})) return *r;
    return stuck(e.what());
  }
  return out;
}

// A plan among the fragments (recovery_plan_among_fragments.cpp) chose its side against them;
// a side that loses its clearance to them later is chosen again within that unit's budget
// only (measured: sides chosen in turn as fragments came into and out of sight, each choice
// restarting the progress monitor, kept a GRASP going for 4,500 s of simulated time).
bool lost_side_replan(ActionState& a) {
  if (!a.fragment_plan.on) return true;
  if (a.fragment_plan.retargets >= kMaxFragmentRetargets) return false;
  ++a.fragment_plan.retargets;
  return true;
}

}  // namespace

Advance navigate(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  const auto [rho, radius, center] = moving(c, a, pose);
  if (a.back_up.active) return back_out(c, a, pose, t, dt);

  // A grasp approach point chosen earlier may have lost its clearance to a newly seen unknown
  // fragment (the topology knowledge is unchanged then).
  if (a.planned && a.kind == ActionKind::kGrasp && a.built &&
      a.checked_version != c.map.version()) {
    a.checked_version = c.map.version();
    if (known_clearance(c.map, *a.target) < plan_radius(c, a) && lost_side_replan(a)) {
      a.planned = false;
    }
  }
  if (!a.planned || knowledge_changed(c, a)) {
    Advance p;
    try {
      p = plan(c, a, pose, Tick{t, dt});
    } catch (const topology::CenterNotFree& e) {
      return centre_not_free(c, a, pose, e.what(), {rho, radius, center}, Tick{t, dt});
    }
    if (p.kind != Advance::kCommand) return p;
  }
  if (a.kind == ActionKind::kRelease && a.pose && a.pose_stretch) {
    return set_down(c, a, pose, t, dt);
  }
  if (!a.built || a.built_target != *a.target || a.built_radius != radius ||
      stale(c, a, radius, center)) {
    Advance b = rebuild(c, a, pose, radius, center, t, dt);
    if (b.center_not_free) {
      return centre_not_free(c, a, pose, b.reason, {rho, radius, center}, Tick{t, dt});
    }
    // Not built, yet a command: a recovery's stop tick (drop short opens the gripper next);
    // there is no law, guide or radius to go on with.
    if (b.kind != Advance::kCommand || !a.built) return b;
  }
  // The guide's waypoints (robust variant): passed ones are dropped, the next is the law's goal.
  const double reach = a.guide.tracking ? kTrackReach : c.p.guide.reach;
  while (!a.guide.path.empty() && (center - a.guide.path.front()).norm() <= reach) {
    a.guide.path.erase(a.guide.path.begin());
    a.monitor.reset(t);
  }
  Point nav = a.guide.path.empty() ? a.goal : a.guide.path.front();
  if (c.controller.goal() != nav && !c.controller.retarget(nav)) {
    // The next waypoint has left F_k since the guide was planned (the map changed under it): the
    // guide is planned again from here (kMaxGuideReplans per action) rather than dropped for a
    // straight run at x*.
    if (a.guide.replans < kMaxGuideReplans) {
      ++a.guide.replans;
      replan_guide(c, a, center);
    } else {
      a.guide.path.clear();
    }
    nav = a.guide.path.empty() ? a.goal : a.guide.path.front();
    if (!c.controller.retarget(nav)) {
      a.guide.path.clear();
      nav = a.goal;
      c.controller.retarget(nav);
    }
  }
  if (a.guide.memory_closed) {
    // The cause "closed by memory": the last guide found a way only through what has been seen
    // of the unknown obstacles (RobustParams::memory).
    a.guide.memory_closed = false;
    Trigger memory{Cause::kClosedByMemory, "", radius, center};
    if (std::optional<Advance> f = recover(c, a, pose, memory, Tick{t, dt})) return *f;
  }
  if (std::optional<Advance> done = arrive(c, a, center, rho, t)) return *done;
  if (a.back_up.facing != Facing::kNo) {
    if (std::optional<Advance> f = face(c, a, pose, c.controller.goal(), t, dt)) return *f;
  }
  if (auto stuck =
          a.monitor.observe(t, pose, (center - c.controller.goal()).norm(), c.map.version())) {
    // The cause "stalled": a rest point, saddle or limit cycle of [7]'s law.
    Trigger stalled{Cause::kStalled, *stuck, radius, center};
    if (std::optional<Advance> r = recover(c, a, pose, stalled, Tick{t, dt})) return *r;
    return executive::stuck(stalled.reason);
  }
  if (a.guide.tracking) {
    if (std::optional<Advance> step = track(c, a, pose, nav, rho, dt)) return *step;
  }
  return command(c, a, pose, rho, t, dt);
}

}  // namespace rearm::executive
