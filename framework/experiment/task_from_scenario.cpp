#include "experiment/task_from_scenario.h"

#include <algorithm>
#include <utility>

#include "perception/semantic_map.h"

namespace rearm::experiment {

perception::World world_of(const scenario::Scenario& s) {
  perception::World w;
  w.workspace = s.workspace;
  for (const auto& f : s.familiar) w.familiar.push_back({f.name, f.polygon});
  for (const auto& u : s.unknown) w.unknown.push_back({u.name, u.polygon});
  for (const auto& o : s.objects) w.movable.push_back({o.name, o.disk});
  return w;
}

reactive::DiffeoParams diffeo_params(const scenario::Scenario& s) {
  reactive::DiffeoParams d;
  d.p = s.controller.p;
  d.epsilon = s.controller.epsilon;
  d.mu1 = s.controller.mu1;
  d.mu2 = s.controller.mu2;
  return d;
}

reactive::NavParams nav_params(const scenario::Scenario& s) {
  reactive::NavParams n;
  n.k_v = s.controller.k_v;
  n.k_omega = s.controller.k_omega;
  n.v_max = s.robot.v_max;
  n.omega_max = s.robot.omega_max;
  n.sensor_range = s.robot.sensor_range;
  return n;
}

executive::Pose start_pose(const scenario::Scenario& s) {
  return executive::Pose{s.robot.start, s.robot.heading};
}

executive::TaskSpec task_spec(const scenario::Scenario& s) {
  ScenarioTask task = parse_task(s);
  executive::TaskSpec t;
  t.world = world_of(s);
  for (const auto& r : s.regions) t.regions.push_back({r.name, r.polygon});
  t.formula = std::move(task.formula);
  t.initial = std::move(task.initial);
  t.sensor.range = s.robot.sensor_range;
  t.map_tolerances.fragment = s.controller.fragment_tolerance;
  // At most a quarter of the sensing range (the semantic map's bound): a short-range sensor
  // reads at least four times per R of travel.
  t.map_tolerances.scan_spacing =
      s.controller.switches.on("scan")
          ? std::min(s.controller.scan_spacing,
                     s.robot.sensor_range / perception::kMaxScanSpacingFraction)
          : 0;
  executive::ExecutiveParams& e = t.executive;
  e.robot_radius = s.robot.radius;
  e.diffeo = diffeo_params(s);
  e.nav = nav_params(s);
  e.goal_tolerance = s.controller.goal_tolerance;
  for (const executive::RobustFlag& f : executive::kRobustFlags) {
    e.robust.*f.flag = s.controller.switches.on(f.key);
  }
  e.robust.rebuild_margin = s.controller.rebuild_margin;
  if (s.controller.variant == "paper") e.robust.contact_margin = 0;
  e.max_ltl_actions = s.simulation.max_actions;
  return t;
}

}  // namespace rearm::experiment
