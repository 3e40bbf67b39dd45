#include "executive/back_up.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "executive/interface_layer.h"
#include "executive/motion_checks.h"
#include "executive/path_tracker.h"
#include "reactive/grasp.h"

namespace rearm::executive {
namespace {

// Robust variant (RobustParams::escape), carrying: each move of `moves` looked ahead for
// back_out_step of travel (or until a step would not keep the robot and the object clear of
// everything known), and the index of the one whose end leaves the pair's centre clearest, if
// clearer than `here`; -1 otherwise. The first move that takes the centre away at its first step
// (the back-up without escape) backs straight into the wedge between two obstacles as often as
// out of it: the pair centre must leave both dilations, and a turn or an arc often does.
int clearest_pair_move(const Context& c, const Pose& pose, std::span<const Twist> moves, double rho,
                       double here, double dt) {
  const std::string carried = *c.map.carried();
  int best = -1;
  double best_clearance = here;
  for (std::size_t k = 0; k < moves.size(); ++k) {
    Pose q = pose;
    double travel = 0;
    while (travel < c.p.robust.back_out_step) {
      const Pose next = reactive::unicycle_step(q, moves[k], dt);
      if (!step_clear(c, pose, next) || !centre_kept(c, q, next)) break;
      q = next;
      travel += (std::abs(moves[k].v) + rho * std::abs(moves[k].omega)) * dt;
    }
    if (travel == 0) continue;
    const double clear = known_clearance(c.map, reactive::pair_center(q.x, q.psi, rho), carried);
    if (clear > best_clearance + kPairMoveGain) {
      best_clearance = clear;
      best = static_cast<int>(k);
    }
  }
  return best;
}

// Robust variant (RobustParams::escape): along each of kEscapeHeadings straight lines from x,
// sampled every kEscapeSample up to back_out_step while nothing known comes closer than r (or
// than it is at x, if x is closer), the clearest sample; the clearest of all, if it is clearer
// than x: its heading and distance.
std::optional<Escape> escape_line(const Context& c, const Point& x) {
  const double here = known_clearance(c.map, x);
  const double floor = std::min(c.p.robot_radius, here);
  const double step = c.p.robust.back_out_step;
  std::optional<Escape> best;
  double best_clearance = here;
  for (int k = 0; k < kEscapeHeadings; ++k) {
    const double theta = 2 * std::numbers::pi * k / kEscapeHeadings;
    const Point d(std::cos(theta), std::sin(theta));
    for (double s = kEscapeSample; s <= step + 1e-9; s += kEscapeSample) {
      const double clear = known_clearance(c.map, x + s * d);
      if (clear < floor) break;
      if (clear > best_clearance) {
        best_clearance = clear;
        best = Escape{theta, s};
      }
    }
  }
  return best;
}

// Turn in place to the escape heading or its reverse (the shorter turn), then drive along it
// for the escape's distance; each step keeps the robot no closer to anything known than r (or
// than it is now).
std::optional<Twist> escape_step(const Context& c, ActionState& a, const Pose& pose, double dt) {
  const Escape& e = *a.back_up.escape;
  const double ahead = reactive::wrap_angle(e.heading - pose.psi);
  const double sign = std::abs(ahead) <= std::numbers::pi / 2 ? 1.0 : -1.0;
  const double error = sign > 0 ? ahead : reactive::wrap_angle(ahead + std::numbers::pi);
  const double omega = std::clamp(kTrackTurnGain * error, -c.p.nav.omega_max, c.p.nav.omega_max);
  if (std::abs(error) > kFaceTolerance) return Twist{0, omega};
  if (a.back_up.travel >= e.distance) return std::nullopt;
  const double v = sign * std::min(c.p.backoff_speed, (e.distance - a.back_up.travel) / dt);
  const Twist u{v, omega};
  const Pose next = reactive::unicycle_step(pose, u, dt);
  const double floor = std::min(c.p.robot_radius, known_clearance(c.map, pose.x));
  if (known_clearance(c.map, next.x) < floor) return std::nullopt;
  a.back_up.travel += std::abs(v) * dt;
  return u;
}

}  // namespace

Advance begin_back_up(const Context& c, ActionState& a, const Pose& pose, double t, double dt,
                      bool contact) {
  if (!contact) ++a.back_up.count;
  ++c.recoveries.back_outs;
  a.back_up.begin();
  if (c.p.robust.escape && !c.map.carried()) a.back_up.escape = escape_line(c, pose.x);
  return back_out(c, a, pose, t, dt);
}

// Back-up of the robust variant: straight back, straight ahead, or (carrying) a turn in place
// either way: the first move whose next step keeps the robot, and the object it carries, clear
// of everything known and takes the centre (robot, or pair) farther from it, else the first that
// keeps them clear; kept while it stays clear, until the centre has moved back_out_step; then
// the action plans again from where it stopped.
Advance back_out(const Context& c, ActionState& a, const Pose& pose, double t, double dt) {
  Advance out;
  const std::optional<std::string> carried = c.map.carried();
  const double rho = carried ? object_radius(c, *carried) : 0;
  auto finish_backing = [&] {
    a.back_up.active = false;
    a.back_up.facing = c.p.robust.face ? Facing::kPending : Facing::kNo;
    a.planned = false;
    a.built = false;
    a.monitor.reset(t);
    out.kind = Advance::kRestart;
    return out;
  };
  if (a.back_up.travel >= c.p.robust.back_out_step) return finish_backing();
  if (a.back_up.escape) {
    const std::optional<Twist> u = escape_step(c, a, pose, dt);
    if (!u) return finish_backing();
    out.u = *u;
    return out;
  }
  const double v = std::min(c.p.backoff_speed, (c.p.robust.back_out_step - a.back_up.travel) / dt);
  const double w = carried ? std::min(c.p.nav.omega_max, v / rho) : 0;
  const Twist moves[] = {{-v, 0},     {v, 0},       {0, w},     {0, -w},
                         {-v, w / 2}, {-v, -w / 2}, {v, w / 2}, {v, -w / 2}};
  // Without RobustParams::escape the pair's back-up has the first four moves; escape adds arcs,
  // and from the back-up after kPairLookaheadAfter looks all of them ahead.
  const int count = carried ? (c.p.robust.escape ? 8 : 4) : 2;
  auto centre = [&](const Pose& q) {
    return carried ? reactive::pair_center(q.x, q.psi, rho) : q.x;
  };
  const double here = known_clearance(c.map, centre(pose), carried.value_or(""));
  if (carried && c.p.robust.escape && a.back_up.count > kPairLookaheadAfter && a.back_up.dir < 0 &&
      a.back_up.travel == 0) {
    a.back_up.dir = clearest_pair_move(c, pose, std::span(moves, count), rho, here, dt);
  }
  auto usable = [&](int k, bool away) {
    const Pose next = reactive::unicycle_step(pose, moves[k], dt);
    if (!step_clear(c, pose, next)) return false;
    return !away || known_clearance(c.map, centre(next), carried.value_or("")) > here;
  };
  if (a.back_up.dir < 0 || !usable(a.back_up.dir, false)) {
    a.back_up.dir = -1;
    // A move away from what the centre touches first; any clear move otherwise.
    for (bool away : {true, false}) {
      for (int k = 0; k < count && a.back_up.dir < 0; ++k) {
        if ((moves[k].v != 0 || moves[k].omega != 0) && usable(k, away)) a.back_up.dir = k;
      }
    }
  }
  if (a.back_up.dir < 0) {
    if (a.back_up.travel > 0) return finish_backing();
    out.kind = Advance::kStuck;
    out.reason = "no room to back up from " + point_text(pose.x);
    return out;
  }
  out.u = moves[a.back_up.dir];
  a.back_up.travel += (std::abs(out.u.v) + rho * std::abs(out.u.omega)) * dt;
  return out;
}

}  // namespace rearm::executive
