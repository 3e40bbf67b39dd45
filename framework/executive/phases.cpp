#include "executive/phases.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/text.h"
#include "executive/motion_checks.h"
#include "geometry/dilation.h"
#include "reactive/grasp.h"
#include "reactive/navigation.h"

namespace rearm::executive {
namespace {

// GRASP, robust variant (RobustParams::withdraw): how far to reverse along the docking line.
// The line is sampled every kWithdrawSample (m) up to withdraw_max, as long as the robot and the
// gripped object stay clear of everything known: the first sample where the pair's centre is
// withdraw_clearance clear of its dilated surroundings, else the sample where it is clearest
// (0 when that is where it stands). A pocket's mouth narrows before it widens, so the clearance
// is looked ahead along the line, not followed step by step.
double withdraw_distance(const Context& c, const ActionState& a, const Pose& pose) {
  constexpr double kWithdrawSample = 0.01;
  const geometry::Disk m = *c.map.object(a.object);
  const double pair_radius = plan_radius(c) + m.radius + c.p.grasp.pair_margin;
  const Point back = -Point(std::cos(pose.psi), std::sin(pose.psi));
  const Point xc = reactive::pair_center(pose.x, pose.psi, m.radius);
  double best = known_clearance(c.map, xc, a.object);
  double best_s = 0;
  const int samples = static_cast<int>(std::floor(c.p.robust.withdraw_max / kWithdrawSample));
  for (int k = 0; k <= samples; ++k) {
    const double s = k * kWithdrawSample;
    if (!reverse_clear(c, m, a.object, pose.x + s * back, m.center + s * back)) break;
    const double clear = known_clearance(c.map, xc + s * back, a.object);
    if (clear >= pair_radius + c.p.robust.withdraw_clearance) return s;
    if (clear > best) {
      best = clear;
      best_s = s;
    }
  }
  return best_s;
}

}  // namespace

// GRASP: turn in place until the gripper faces the object (paper §V-B).
Advance align(const Context& c, ActionState& a, const Pose& pose, double t) {
  Advance out;
  const geometry::Disk m = *c.map.object(a.object);
  if (reactive::aligned(pose.psi, pose.x, m.center, c.p.align_tolerance)) {
    a.phase = ActionPhase::kDock;
    a.phase_start = t;
    out.kind = Advance::kRestart;
    return out;
  }
  if (t - a.phase_start > c.p.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not turn the gripper toward the object within " +
                 rearm::fixed(c.p.phase_timeout, 3) + " s";
    return out;
  }
  out.u = reactive::align_command(pose.psi, pose.x, m.center, c.p.nav);
  return out;
}

// GRASP: drive straight in to dock_gap from contact, then close the gripper.
Advance dock(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *c.map.object(a.object);
  const double gap = (m.center - pose.x).norm() - c.p.robot_radius - m.radius;
  if (gap <= c.p.grasp.dock_gap) {
    out.gripper = GripperAction::kClose;
    out.grip_object = a.object;
    a.phase = ActionPhase::kGrip;
    a.phase_start = t;
    a.note = "gripped at gap " + rearm::fixed(gap * 1000, 3) + " mm";
    return out;  // stand still while the gripper closes
  }
  if (t - a.phase_start > c.p.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not dock to the object within " + rearm::fixed(c.p.phase_timeout, 3) + " s";
    return out;
  }
  // Straight in, never closer than half the gap allowance in one step, steering to keep
  // facing the centre.
  out.u.v = std::min(c.p.dock_speed, (gap - c.p.grasp.dock_gap / 2) / dt);
  out.u.omega = reactive::align_command(pose.psi, pose.x, m.center, c.p.nav).omega;
  return out;
}

// GRASP: the tick after the close command, the map must report the object carried.
Advance grip(const Context& c, ActionState& a, const Pose& pose, double t) {
  Advance out;
  if (c.map.carried() != a.object) {
    out.kind = Advance::kStuck;
    out.reason = "the gripper did not close on " + a.object;
    return out;
  }
  if (c.p.robust.withdraw) {
    a.phase = ActionPhase::kWithdraw;
    a.phase_start = t;
    a.withdrawn = 0;
    a.withdraw_goal = withdraw_distance(c, a, pose);
    out.kind = Advance::kRestart;
    return out;
  }
  out.kind = Advance::kDone;
  out.reason = a.note;
  return out;
}

// GRASP, robust variant: reverse straight to withdraw_distance(), each step checked again
// against the map (a fragment seen on the way ends it).
Advance withdraw(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *c.map.object(a.object);
  auto done = [&](const std::string& how) {
    if (a.withdrawn > 0) {
      ++c.recoveries.withdrawals;
      a.note += "; withdrew " + rearm::fixed(a.withdrawn, 3) + " m" + how;
    }
    out.kind = Advance::kDone;
    out.reason = a.note;
    return out;
  };
  if (a.withdrawn >= a.withdraw_goal || t - a.phase_start > c.p.phase_timeout) return done("");
  const double v = std::min(c.p.backoff_speed, (a.withdraw_goal - a.withdrawn) / dt);
  out.u.v = -v;
  const Pose next = reactive::unicycle_step(pose, out.u, dt);
  if (!reverse_clear(c, m, a.object, next.x, m.center + (next.x - pose.x))) {
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
Advance open(const Context& c, ActionState& a, double t) {
  Advance out;
  if (c.map.carried()) {
    if (c.last_u.v != 0 || c.last_u.omega != 0) return out;  // stop this tick, open the next
    if (!a.open_sent) {
      out.gripper = GripperAction::kOpen;
      a.open_sent = true;
      return out;
    }
    out.kind = Advance::kStuck;
    out.reason = "the gripper did not open";
    return out;
  }
  a.phase = ActionPhase::kBackOff;
  a.phase_start = t;
  out.kind = Advance::kRestart;
  return out;
}

// RELEASE, DISASSEMBLE: back off straight until the robot is clear of the released object's
// dilation, so the next action starts in the freespace.
Advance back_off(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  Advance out;
  const geometry::Disk m = *c.map.object(a.object);
  const double need =
      geometry::disk_polygon_circumradius(m.radius + plan_radius(c) + geometry::kContactSlack) +
      c.p.backoff_margin;
  const double d = (m.center - pose.x).norm();
  if (d >= need) {
    out.kind = Advance::kDone;
    out.reason = a.note + "; released " + a.object + " at " + point_text(m.center);
    return out;
  }
  if (t - a.phase_start > c.p.phase_timeout) {
    out.kind = Advance::kStuck;
    out.reason = "could not back off from the released object";
    return out;
  }
  out.u.v = -std::min(c.p.backoff_speed, (need - d) / dt + 1e-3);
  const Point next = reactive::unicycle_step(pose, out.u, dt).x;
  if (known_clearance(c.map, next) < c.p.robot_radius) {
    out.kind = Advance::kStuck;
    out.reason = "no room to back off from the released object at " + point_text(pose.x);
    return out;
  }
  return out;
}

Advance advance(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  switch (a.phase) {
    case ActionPhase::kNavigate:
      break;  // the executive's: its prerequisites push Fix-mode actions (navigate.h)
    case ActionPhase::kAlign:
      return align(c, a, pose, t);
    case ActionPhase::kDock:
      return dock(c, a, pose, t, dt);
    case ActionPhase::kGrip:
      return grip(c, a, pose, t);
    case ActionPhase::kWithdraw:
      return withdraw(c, a, pose, t, dt);
    case ActionPhase::kOpen:
      return open(c, a, t);
    case ActionPhase::kBackOff:
      return back_off(c, a, pose, t, dt);
  }
  Advance out;
  out.kind = Advance::kStuck;
  out.reason = "unknown phase";
  return out;
}

}  // namespace rearm::executive
