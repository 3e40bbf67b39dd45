#include "experiment/run_scenario.h"

#include <utility>

#include "core/error.h"
#include "executive/kinematic_plant.h"
#include "experiment/json_internal.h"
#include "experiment/sim_plant.h"
#include "experiment/task_from_scenario.h"
#include "perception/sensor.h"
#include "sim/sim_config.h"

namespace rearm::experiment {
namespace {

using json::clearance_by_kind;
using json::Json;
using json::kIndent;
using json::named_polygons;
using json::point;
using json::polygon;
using json::text;

}  // namespace

const char* to_string(PlantKind k) { return k == PlantKind::kBox2d ? "box2d" : "kinematic"; }

double RunRecord::real_time_factor() const {
  return result.wall_time > 0 ? result.sim_time / result.wall_time : 0;
}

RunRecord run_scenario(const scenario::Scenario& s, const RunOptions& o) {
  const executive::TaskSpec spec = task_spec(s);
  executive::TaskOptions topt;
  topt.dt = s.simulation.dt;
  topt.max_time = s.simulation.time_budget;
  topt.record_path = o.record;
  topt.clearance_by_kind = o.record;
  topt.record_spaces = o.record && o.spaces;
  topt.check_invariants = o.checked;
  RunRecord r;
  r.scenario = s.name;
  r.seed = o.seed;
  r.plant = o.plant;
  for (const auto& obj : s.objects) r.objects_start.push_back(obj.disk.center);
  if (o.plant == PlantKind::kBox2d) {
    SimPlant plant(s, sim::config_for(s));
    r.result = executive::run_task(spec, plant, topt);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
      r.objects_end.push_back(plant.object_center(i));
  } else {
    executive::KinematicPlant plant(spec.world, s.robot.radius, start_pose(s));
    r.result = executive::run_task(spec, plant, topt);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
      r.objects_end.push_back(plant.object_center(i));
  }
  // Localization times (paper §II: a familiar obstacle is localized whole once it is within
  // the sensor range), from the recorded path.
  const perception::Sensor sensor(perception::SensorParams{s.robot.sensor_range});
  r.localized_at.assign(s.familiar.size(), -1);
  for (std::size_t i = 0; i < s.familiar.size(); ++i) {
    for (std::size_t k = 0; k < r.result.path.size(); ++k) {
      if (sensor.sees(s.familiar[i].polygon, r.result.path[k].x)) {
        r.localized_at[i] = static_cast<double>(k) * s.simulation.dt;
        break;
      }
    }
  }
  return r;
}

namespace {

Json actions_json(const std::vector<executive::ActionRecord>& actions) {
  Json a = Json::array();
  for (const executive::ActionRecord& r : actions) {
    a.push_back({{"action", r.action},
                 {"fix_mode", r.fix},
                 {"outcome", executive::to_string(r.outcome)},
                 {"reason", r.reason},
                 {"t_start_s", r.t_start},
                 {"t_end_s", r.t_end}});
  }
  return a;
}

Json objects_json(const scenario::Scenario& s, const RunRecord& r) {
  Json a = Json::array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    a.push_back({{"name", s.objects[i].name},
                 {"start", point(r.objects_start[i])},
                 {"end", point(r.objects_end[i])}});
  }
  return a;
}

}  // namespace

std::string metrics_json(const scenario::Scenario& s, const RunRecord& r) {
  const executive::TaskResult& t = r.result;
  Json recoveries = Json::object();
  for (const executive::RecoveryField& f : executive::kRecoveryFields)
    recoveries[f.name] = t.recoveries.*f.count;
  const Json j = {{"scenario", s.name},
                  {"source", s.source},
                  {"plant", to_string(r.plant)},
                  {"seed", r.seed},
                  {"task", s.task},
                  {"status", executive::to_string(t.status)},
                  {"reason", t.reason},
                  {"collisions", t.collisions},
                  {"collision_events", t.collision_events},
                  {"min_clearance", t.min_clearance},
                  {"min_clearance_by_kind", clearance_by_kind(t.clearance_by_kind)},
                  {"sim_time_s", t.sim_time},
                  {"steps", t.steps},
                  {"dt_s", s.simulation.dt},
                  {"wall_time_s", t.wall_time},
                  {"controller_time_s", t.controller_time},
                  {"first_action_time_s", t.first_action_time},
                  {"real_time_factor", r.real_time_factor()},
                  {"fix_mode_entries", t.fix_mode_entries},
                  {"recoveries", recoveries},
                  {"robot_path_length_m", t.robot_path_length},
                  {"object_path_length_m", t.object_path_length},
                  {"rebuilds", t.rebuilds},
                  {"topology_checks", t.topology_checks},
                  {"topology_time_s", t.topology_time},
                  {"actions", actions_json(t.actions)},
                  {"objects", objects_json(s, r)}};
  return text(j, kIndent);
}

namespace {

Json region_json(const geometry::Region& r) {
  Json holes = Json::array();
  for (const geometry::Polygon& h : r.holes) holes.push_back(polygon(h));
  return {{"outer", polygon(r.outer)}, {"holes", holes}};
}

// "model_path": the law's model point at the robot samples (null where the command was not the
// law's); "spaces": each build's F_k, F_e and model space (boundary, disks [x, y, r], convex).
void spaces_json(Json& j, const executive::TaskResult& t, std::size_t stride) {
  Json& model_path = j["model_path"] = Json::array();
  for (std::size_t k = 0; k < t.model_path.size(); k += stride)
    model_path.push_back(t.model_path[k].allFinite() ? point(t.model_path[k]) : Json());
  Json& spaces = j["spaces"] = Json::array();
  for (const executive::SpacesSnapshot& s : t.spaces) {
    Json disks = Json::array(), convex = Json::array();
    for (const geometry::Disk& d : s.model.disks)
      disks.push_back({d.center.x(), d.center.y(), d.radius});
    for (const geometry::Polygon& c : s.model.convex) convex.push_back(polygon(c));
    spaces.push_back(
        {{"t", s.t},
         {"freespace", region_json(s.freespace)},
         {"enclosing", polygon(s.enclosing)},
         {"model",
          {{"boundary", polygon(s.model.boundary)}, {"disks", disks}, {"convex", convex}}}});
  }
}

}  // namespace

std::string trajectory_json(const scenario::Scenario& s, const RunRecord& r, int stride) {
  if (stride < 1) throw Error("trajectory: stride must be >= 1");
  const auto st = static_cast<std::size_t>(stride);
  const executive::TaskResult& t = r.result;
  Json j = {{"scenario", s.name},
            {"task", s.task},
            {"status", executive::to_string(t.status)},
            {"robot_radius", s.robot.radius},
            {"sensor_range", s.robot.sensor_range},
            {"workspace", polygon(s.workspace)},
            {"familiar", named_polygons(s.familiar)},
            {"unknown", named_polygons(s.unknown)},
            {"regions", named_polygons(s.regions)},
            {"objects", Json::array()},
            {"dt", s.simulation.dt * stride},
            {"robot", Json::array()},
            {"object_paths", Json::array()}};
  for (std::size_t i = 0; i < s.familiar.size(); ++i)
    j["familiar"][i]["localized_at"] = r.localized_at[i];
  for (const auto& o : s.objects)
    j["objects"].push_back({{"name", o.name}, {"radius", o.disk.radius}});
  for (std::size_t k = 0; k < t.path.size(); k += st)
    j["robot"].push_back({t.path[k].x.x(), t.path[k].x.y(), t.path[k].psi});
  for (const auto& path : t.object_paths) {
    Json& p = j["object_paths"].emplace_back(Json::array());
    for (std::size_t k = 0; k < path.size(); k += st) p.push_back(point(path[k]));
  }
  if (!t.spaces.empty()) spaces_json(j, t, st);
  Json& actions = j["actions"] = Json::array();
  for (const executive::ActionRecord& a : t.actions) {
    actions.push_back({{"action", a.action},
                       {"fix_mode", a.fix},
                       {"outcome", executive::to_string(a.outcome)},
                       {"t_start", a.t_start},
                       {"t_end", a.t_end}});
  }
  return text(j);
}

}  // namespace rearm::experiment
