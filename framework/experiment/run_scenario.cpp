#include "experiment/run_scenario.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "executive/kinematic_plant.h"
#include "experiment/json_writer.h"
#include "experiment/sim_plant.h"
#include "experiment/task_from_scenario.h"
#include "perception/sensor.h"
#include "sim/sim_config.h"

namespace rearm::experiment {
namespace {

void point(JsonWriter& j, const geometry::Point& p) {
  j.begin_array().value(p.x()).value(p.y()).end_array();
}

void polygon(JsonWriter& j, const geometry::Polygon& p) {
  j.begin_array();
  for (const auto& v : p.vertices) point(j, v);
  j.end_array();
}

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

void clearance_by_kind_json(JsonWriter& j, const geometry::ClearanceByKind& c) {
  j.key("min_clearance_by_kind").begin_object();
  for (const auto& [name, value] : {std::pair<const char*, double>{"familiar", c.familiar},
                                    {"unknown", c.unknown},
                                    {"objects", c.objects},
                                    {"boundary", c.boundary}}) {
    j.key(name);
    if (std::isfinite(value)) {
      j.value(value);
    } else {
      j.null();
    }
  }
  j.end_object();
}

std::string metrics_json(const scenario::Scenario& s, const RunRecord& r) {
  const executive::TaskResult& t = r.result;
  JsonWriter j(true);
  j.begin_object();
  j.key("scenario").value(s.name);
  j.key("source").value(s.source);
  j.key("plant").value(to_string(r.plant));
  j.key("seed").value(r.seed);
  j.key("task").value(s.task);
  j.key("status").value(executive::to_string(t.status));
  j.key("reason").value(t.reason);
  j.key("collisions").value(t.collisions);
  j.key("collision_events").begin_array();
  for (const std::string& e : t.collision_events) j.value(e);
  j.end_array();
  j.key("min_clearance").value(t.min_clearance);
  clearance_by_kind_json(j, t.clearance_by_kind);
  j.key("sim_time_s").value(t.sim_time);
  j.key("steps").value(t.steps);
  j.key("dt_s").value(s.simulation.dt);
  j.key("wall_time_s").value(t.wall_time);
  j.key("controller_time_s").value(t.controller_time);
  j.key("real_time_factor").value(r.real_time_factor());
  j.key("fix_mode_entries").value(t.fix_mode_entries);
  j.key("recoveries").begin_object();
  for (const executive::RecoveryField& f : executive::kRecoveryFields) {
    j.key(f.name).value(t.recoveries.*f.count);
  }
  j.end_object();
  j.key("robot_path_length_m").value(t.robot_path_length);
  j.key("object_path_length_m").value(t.object_path_length);
  j.key("rebuilds").value(t.rebuilds);
  j.key("topology_checks").value(t.topology_checks);
  j.key("actions").begin_array();
  for (const executive::ActionRecord& a : t.actions) {
    j.begin_object();
    j.key("action").value(a.action);
    j.key("fix_mode").value(a.fix);
    j.key("outcome").value(executive::to_string(a.outcome));
    j.key("reason").value(a.reason);
    j.key("t_start_s").value(a.t_start);
    j.key("t_end_s").value(a.t_end);
    j.end_object();
  }
  j.end_array();
  j.key("objects").begin_array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    j.begin_object();
    j.key("name").value(s.objects[i].name);
    j.key("start")
        .begin_array()
        .value(r.objects_start[i].x())
        .value(r.objects_start[i].y())
        .end_array();
    j.key("end").begin_array().value(r.objects_end[i].x()).value(r.objects_end[i].y()).end_array();
    j.end_object();
  }
  j.end_array();
  j.end_object();
  return j.str();
}

namespace {

void region_json(JsonWriter& j, const geometry::Region& r) {
  j.begin_object().key("outer");
  polygon(j, r.outer);
  j.key("holes").begin_array();
  for (const geometry::Polygon& h : r.holes) polygon(j, h);
  j.end_array().end_object();
}

// "model_path": the law's model point at the robot samples (null where the command was not the
// law's); "spaces": each build's F_k, F_e and model space (boundary, disks [x, y, r], convex).
void spaces_json(JsonWriter& j, const executive::TaskResult& t, int stride) {
  j.key("model_path").begin_array();
  for (std::size_t k = 0; k < t.model_path.size(); k += static_cast<std::size_t>(stride)) {
    if (t.model_path[k].allFinite()) {
      point(j, t.model_path[k]);
    } else {
      j.null();
    }
  }
  j.end_array();
  j.key("spaces").begin_array();
  for (const executive::SpacesSnapshot& s : t.spaces) {
    j.begin_object().key("t").value(s.t).key("freespace");
    region_json(j, s.freespace);
    j.key("enclosing");
    polygon(j, s.enclosing);
    j.key("model").begin_object().key("boundary");
    polygon(j, s.model.boundary);
    j.key("disks").begin_array();
    for (const geometry::Disk& d : s.model.disks) {
      j.begin_array().value(d.center.x()).value(d.center.y()).value(d.radius).end_array();
    }
    j.end_array().key("convex").begin_array();
    for (const geometry::Polygon& c : s.model.convex) polygon(j, c);
    j.end_array().end_object().end_object();
  }
  j.end_array();
}

}  // namespace

std::string trajectory_json(const scenario::Scenario& s, const RunRecord& r, int stride) {
  if (stride < 1) throw Error("trajectory: stride must be >= 1");
  const executive::TaskResult& t = r.result;
  JsonWriter j;
  j.begin_object();
  j.key("scenario").value(s.name);
  j.key("task").value(s.task);
  j.key("status").value(executive::to_string(t.status));
  j.key("robot_radius").value(s.robot.radius);
  j.key("sensor_range").value(s.robot.sensor_range);
  j.key("workspace");
  polygon(j, s.workspace);
  j.key("familiar").begin_array();
  for (std::size_t i = 0; i < s.familiar.size(); ++i) {
    j.begin_object().key("name").value(s.familiar[i].name).key("polygon");
    polygon(j, s.familiar[i].polygon);
    j.key("localized_at").value(r.localized_at[i]).end_object();
  }
  j.end_array();
  j.key("unknown").begin_array();
  for (const auto& u : s.unknown) {
    j.begin_object().key("name").value(u.name).key("polygon");
    polygon(j, u.polygon);
    j.end_object();
  }
  j.end_array();
  j.key("regions").begin_array();
  for (const auto& g : s.regions) {
    j.begin_object().key("name").value(g.name).key("polygon");
    polygon(j, g.polygon);
    j.end_object();
  }
  j.end_array();
  j.key("objects").begin_array();
  for (const auto& o : s.objects) {
    j.begin_object().key("name").value(o.name).key("radius").value(o.disk.radius).end_object();
  }
  j.end_array();
  j.key("dt").value(s.simulation.dt * stride);
  j.key("robot").begin_array();
  for (std::size_t k = 0; k < t.path.size(); k += static_cast<std::size_t>(stride)) {
    j.begin_array().value(t.path[k].x.x()).value(t.path[k].x.y()).value(t.path[k].psi).end_array();
  }
  j.end_array();
  j.key("object_paths").begin_array();
  for (const auto& path : t.object_paths) {
    j.begin_array();
    for (std::size_t k = 0; k < path.size(); k += static_cast<std::size_t>(stride))
      point(j, path[k]);
    j.end_array();
  }
  j.end_array();
  if (!t.spaces.empty()) spaces_json(j, t, stride);
  j.key("actions").begin_array();
  for (const executive::ActionRecord& a : t.actions) {
    j.begin_object().key("action").value(a.action).key("fix_mode").value(a.fix);
    j.key("outcome").value(executive::to_string(a.outcome));
    j.key("t_start").value(a.t_start).key("t_end").value(a.t_end).end_object();
  }
  j.end_array();
  j.end_object();
  return j.str();
}

}  // namespace rearm::experiment
