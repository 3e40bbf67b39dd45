#include "baselines/problem.h"

#include <cmath>
#include <functional>
#include <numbers>

#include "baselines/plan.h"
#include "core/error.h"
#include "experiment/goals.h"
#include "experiment/task_from_scenario.h"
#include "scenario/scenario_io.h"

namespace rearm::baselines {

Arrangement RearrangementProblem::goal_arrangement() const {
  Arrangement a = start;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (goals[i]) a[i] = *goals[i];
  return a;
}

bool RearrangementProblem::goals_reached(const Arrangement& a) const {
  REARM_DEMAND(a.size() == object_count(), "arrangement size");
  for (std::size_t i = 0; i < a.size(); ++i)
    if (goal_regions[i] && !geometry::contains(*goal_regions[i], a[i])) return false;
  return true;
}

RearrangementProblem problem_from_scenario(const scenario::Scenario& s) {
  experiment::check_task(s);  // parses, names only the scenario's objects and regions
  RearrangementProblem p;
  p.name = s.name;
  p.workspace = s.workspace;
  for (const auto& f : s.familiar) {
    p.obstacles.push_back(f.polygon);
    p.obstacle_names.push_back(f.name);
  }
  p.familiar_count = p.obstacles.size();
  for (const auto& u : s.unknown) {
    p.obstacles.push_back(u.polygon);
    p.obstacle_names.push_back(u.name);
  }
  p.robot_radius = s.robot.radius;
  p.robot_start = s.robot.start;
  p.robot_heading = s.robot.heading;
  p.v_max = s.robot.v_max;
  p.omega_max = s.robot.omega_max;
  for (const auto& o : s.objects) {
    p.object_names.push_back(o.name);
    p.object_radii.push_back(o.disk.radius);
    p.start.push_back(o.disk.center);
  }
  const std::size_t n = p.start.size();
  p.goals.assign(n, std::nullopt);
  p.goal_regions.assign(n, std::nullopt);
  p.goal_region_names.assign(n, "");

  const experiment::ReachabilityGoals g = experiment::reachability_goals(s);
  for (std::size_t i = 0; i < n; ++i) {
    if (!g.object_region[i]) continue;
    const scenario::NamedPolygon& r = s.regions[*g.object_region[i]];
    p.goals[i] = g.object_target[i];
    p.goal_regions[i] = r.polygon;
    p.goal_region_names[i] = r.name;
  }
  if (g.robot_region) {
    const scenario::NamedPolygon& r = s.regions[*g.robot_region];
    p.robot_goal = g.robot_target;
    p.robot_goal_region = r.polygon;
    p.robot_goal_name = r.name;
  }
  return p;
}

Point heading_vector(double psi) { return Point(std::cos(psi), std::sin(psi)); }

double wrap_angle(double a) {
  a = std::remainder(a, 2 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2 * std::numbers::pi : a;
}

double tracked_heading(const std::vector<Point>& path, double psi0, double ell) {
  REARM_DEMAND(ell > 0, "tracked_heading: the pair offset must be positive");
  double psi = psi0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Point d = path[k + 1] - path[k];
    const double s = d.norm();
    if (s == 0) continue;
    const double theta = std::atan2(d.y(), d.x());
    const double phi0 = wrap_angle(theta - psi);
    const double phi =
        2 * std::atan2(std::sin(0.5 * phi0) * std::exp(-s / ell), std::cos(0.5 * phi0));
    psi = wrap_angle(theta - phi);
  }
  return psi;
}

double pair_offset(double rho, const BaselineParams& p) { return rho + 0.5 * p.grip_gap; }

double pair_radius(double r, double rho, const BaselineParams& p) {
  return r + rho + 0.5 * p.grip_gap;
}

Point standoff_position(const Point& o, double r, double rho, double psi, const BaselineParams& p) {
  return o - (r + rho + p.standoff) * heading_vector(psi);
}

Point grip_position(const Point& o, double r, double rho, double psi, const BaselineParams& p) {
  return o - (r + rho + p.grip_gap) * heading_vector(psi);
}

const char* to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::kSolved:
      return "solved";
    case PlanStatus::kInfeasible:
      return "infeasible";
    case PlanStatus::kTimeout:
      return "timeout";
    case PlanStatus::kUnsolved:
      return "unsolved";
  }
  return "?";
}

}  // namespace rearm::baselines
