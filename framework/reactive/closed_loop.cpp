#include "reactive/closed_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace rearm::reactive {

ClosedLoopResult run_closed_loop(ReactiveController& controller, const Pose& start,
                                 const Point& goal, const MapUpdate& sense,
                                 const Clearance& clearance, const ClosedLoopOptions& o) {
  REARM_REQUIRE(o.dt > 0 && std::isfinite(o.dt), "closed loop: dt must be finite and > 0, got ",
                o.dt);
  REARM_REQUIRE(o.max_time > 0 && std::isfinite(o.max_time),
                "closed loop: max_time must be finite and > 0, got ", o.max_time);
  REARM_REQUIRE(o.goal_tolerance > 0, "closed loop: goal_tolerance must be > 0, got ",
                o.goal_tolerance);
  REARM_REQUIRE(o.radius > 0, "closed loop: radius must be > 0, got ", o.radius);
  REARM_REQUIRE(o.carried_radius >= 0, "closed loop: carried_radius must be >= 0, got ",
                o.carried_radius);
  if (!start.x.allFinite() || !std::isfinite(start.psi) || !goal.allFinite()) {
    throw Error("closed loop: start pose and goal must be finite");
  }
  const bool carrying = o.carried_radius > 0;
  const double radius = o.radius + o.carried_radius;
  auto centre = [&](const Pose& p) {
    return carrying ? pair_center(p.x, p.psi, o.carried_radius) : p.x;
  };

  ClosedLoopResult r;
  r.min_clearance = std::numeric_limits<double>::infinity();
  Pose pose = start;
  SemanticInput map;
  bool have_map = false;
  const int max_steps = static_cast<int>(std::ceil(o.max_time / o.dt));
  const int rebuilds_before = controller.rebuilds();
  try {
    for (;;) {
      if (auto update = sense(pose)) {
        map = std::move(*update);
        have_map = true;
        controller.rebuild(map, radius, centre(pose), goal);
      } else if (!have_map) {
        throw Error("closed loop: the first map update returned no map");
      }
      r.min_clearance = std::min(r.min_clearance, clearance(pose));
      if (o.record_path) r.path.push_back(pose);
      if ((centre(pose) - goal).norm() <= o.goal_tolerance) {
        r.status = ClosedLoopResult::Status::kReached;
        break;
      }
      if (r.steps >= max_steps) break;
      if (o.model == RobotModel::kHolonomic && !carrying) {
        const Point v = controller.holonomic(pose.x, o.dt);
        r.max_v = std::max(r.max_v, v.norm());
        pose.x = holonomic_step(pose.x, v, o.dt);
      } else {
        const Twist u = carrying ? controller.pair(pose, o.carried_radius, o.dt)
                                 : controller.unicycle(pose, o.dt);
        r.max_v = std::max(r.max_v, std::abs(u.v));
        r.max_omega = std::max(r.max_omega, std::abs(u.omega));
        pose = unicycle_step(pose, u, o.dt);
      }
      ++r.steps;
    }
  } catch (const Error& e) {
    r.status = ClosedLoopResult::Status::kError;
    r.message = e.what();
  }
  r.time = r.steps * o.dt;
  r.rebuilds = controller.rebuilds() - rebuilds_before;
  return r;
}

}  // namespace rearm::reactive
