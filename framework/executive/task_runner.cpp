#include "executive/task_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/text.h"
#include "perception/semantic_map.h"
#include "symbolic/mission_controller.h"

namespace rearm::executive {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// TaskOptions::check_invariants: throws InvariantViolation on the first broken invariant.
// `clearance` is the plant's at this tick (the command has not acted yet), `previous` the command
// of the tick before.
void check_tick(const Command& cmd, const Twist& previous, double clearance, const Executive& exec,
                double t) {
  auto fail = [&](const std::string& what) {
    throw InvariantViolation("invariant broken at t = " + significant(t, 6) + " s during " +
                             exec.current_action() + ": " + what);
  };
  if (!std::isfinite(cmd.u.v) || !std::isfinite(cmd.u.omega)) {
    fail("non-finite command (v, omega) = (" + significant(cmd.u.v, 6) + ", " +
         significant(cmd.u.omega, 6) + ")");
  }
  if (!(clearance >= -kInvariantSlop)) {
    fail("the robot or the object it holds overlaps an obstacle, an object or the boundary by " +
         significant(-clearance, 6) + " m (beyond the slop " + significant(kInvariantSlop, 6) +
         " m)");
  }
  if (std::optional<std::string> why = exec.law_invariant_violation()) fail(*why);
  if (cmd.gripper == GripperAction::kOpen && (previous.v != 0 || previous.omega != 0)) {
    fail("the gripper opened after a tick in motion, (v, omega) = (" + significant(previous.v, 6) +
         ", " + significant(previous.omega, 6) + ")");
  }
}

// TaskOptions::record_spaces: a snapshot when the controller built a new diffeomorphism, and the
// law's model point of this tick.
void record_spaces(const Executive& exec, double t, TaskResult& res) {
  const reactive::ReactiveController& c = exec.controller();
  const int builds = c.rebuilds();
  if (builds > 0 && (res.spaces.empty() || res.spaces.back().build != builds)) {
    res.spaces.push_back(
        SpacesSnapshot{t, builds, c.mapped().freespace, c.mapped().enclosing, c.diffeo().model()});
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  res.model_path.push_back(exec.law_commanded() ? c.last_law_sample().y : Point(nan, nan));
}

// TaskOptions::clearance_by_kind: the world's obstacles (familiar first) and objects, the
// objects' centres refreshed each tick.
struct KindScene {
  std::vector<geometry::Polygon> obstacles;
  std::size_t familiar_count = 0;
  std::vector<geometry::Disk> objects;
};

KindScene kind_scene(const perception::World& world) {
  KindScene k;
  for (const auto& f : world.familiar) k.obstacles.push_back(f.polygon);
  k.familiar_count = k.obstacles.size();
  for (const auto& u : world.unknown) k.obstacles.push_back(u.polygon);
  for (const auto& m : world.movable) k.objects.push_back(m.disk);
  return k;
}

// The robot's disk and the held object's at this tick.
void lower_by_kind(const perception::World& world, KindScene& k, const Plant& plant,
                   const Pose& pose, double robot_radius, TaskResult& res) {
  for (std::size_t i = 0; i < k.objects.size(); ++i) k.objects[i].center = plant.object_center(i);
  const std::optional<std::size_t> held = plant.held();
  geometry::ClearanceByKind& c = res.clearance_by_kind;
  c.lower(world.workspace, k.obstacles, k.familiar_count, k.objects, pose.x, robot_radius, held);
  if (held) {
    c.lower(world.workspace, k.obstacles, k.familiar_count, k.objects, k.objects[*held].center,
            k.objects[*held].radius, held);
  }
}

// The gripper acts; perception records what it holds (a failed grip holds nothing, and the
// executive ends the grasp stuck on the next tick).
void apply_gripper(const Command& cmd, const perception::World& world, Plant& plant,
                   perception::SemanticMap& map) {
  if (cmd.gripper == GripperAction::kClose) {
    std::size_t i = 0;
    const std::size_t n = world.movable.size();
    while (i < n && world.movable[i].id != cmd.object) ++i;
    if (i < n && plant.grip(i)) map.set_carried(cmd.object);
  } else if (cmd.gripper == GripperAction::kOpen) {
    plant.release();
    map.set_carried(std::nullopt);
  }
}

// Whether the command acts: the robot moves or the gripper closes or opens.
bool acts(const Command& cmd) {
  return cmd.u.v != 0 || cmd.u.omega != 0 || cmd.gripper != GripperAction::kNone;
}

// The task's outcome, counters and compute split from the executive and the plant.
void finish(const Executive& exec, const Plant& plant, double mission_setup, TaskResult& res) {
  res.status = exec.status();
  res.reason = exec.reason();
  res.actions = exec.actions();
  res.fix_mode_entries = exec.fix_mode_entries();
  res.recoveries = exec.recoveries();
  res.collisions = plant.collisions();
  res.collision_events = plant.collision_events();
  res.rebuilds = exec.rebuilds();
  res.topology_checks = exec.topology_checks();
  const ComputeTimes& ct = exec.compute_times();
  res.mission_time = mission_setup + ct.mission_s;
  res.topology_time = ct.topology_s;
  res.rebuild_time = ct.rebuild_s;
  res.control_time =
      std::max(0.0, res.controller_time - ct.mission_s - ct.topology_s - ct.rebuild_s);
}

}  // namespace

TaskResult run_task(const TaskSpec& spec, Plant& plant, const TaskOptions& o) {
  const Clock::time_point wall_start = Clock::now();
  if (!std::isfinite(o.dt) || !(o.dt > 0)) throw Error("task: dt must be finite and > 0");
  if (!std::isfinite(o.max_time) || !(o.max_time > 0)) {
    throw Error("task: max_time must be finite and > 0");
  }
  const perception::World world = perception::validated(spec.world);
  if (plant.object_count() != world.movable.size()) {
    throw Error("task: the plant has " + std::to_string(plant.object_count()) +
                " objects, the world " + std::to_string(world.movable.size()));
  }
  symbolic::MissionOptions mo;
  for (const auto& m : world.movable) mo.vocabulary.objects.push_back(m.id);
  for (const auto& r : spec.regions) mo.vocabulary.regions.push_back(r.id);
  mo.translate = spec.translate;
  mo.initial = spec.initial;
  const Clock::time_point mission_start = Clock::now();
  symbolic::MissionController mission(spec.formula, mo);
  const double mission_setup = seconds_since(mission_start);
  perception::SemanticMap map(world, perception::Sensor(spec.sensor), spec.map_tolerances);
  Executive exec(spec.executive, spec.regions, mission, map);

  TaskResult res;
  res.min_clearance = std::numeric_limits<double>::infinity();
  const std::size_t n = world.movable.size();
  std::vector<Point> last_center(n);
  for (std::size_t i = 0; i < n; ++i) last_center[i] = plant.object_center(i);
  if (o.record_path) res.object_paths.resize(n);
  double t = 0;
  Twist previous;  // the last tick's command
  KindScene kinds = o.clearance_by_kind ? kind_scene(world) : KindScene{};
  const long max_steps = static_cast<long>(std::ceil(o.max_time / o.dt));
  for (long k = 0;; ++k) {
    const Pose pose = plant.pose();
    const double clearance = plant.clearance();
    res.min_clearance = std::min(res.min_clearance, clearance);
    if (o.clearance_by_kind) {
      lower_by_kind(world, kinds, plant, pose, spec.executive.robot_radius, res);
    }
    if (o.record_path) {
      res.path.push_back(pose);
      for (std::size_t i = 0; i < n; ++i) res.object_paths[i].push_back(plant.object_center(i));
    }
    // Perception (paper §II): object positions known at all times, the sensor disk at x.
    for (std::size_t i = 0; i < n; ++i)
      map.move_object(world.movable[i].id, plant.object_center(i));
    map.update(pose.x);

    const Clock::time_point c0 = Clock::now();
    const Command cmd = exec.step(pose, t, o.dt);
    res.controller_time += seconds_since(c0);
    if (std::isnan(res.first_action_time) && acts(cmd)) {
      res.first_action_time = mission_setup + res.controller_time;
    }
    if (o.check_invariants) check_tick(cmd, previous, clearance, exec, t);
    if (o.record_spaces && o.record_path) record_spaces(exec, t, res);
    previous = cmd.u;
    apply_gripper(cmd, world, plant, map);
    if (exec.finished()) break;
    if (k >= max_steps) {
      exec.abort(TaskStatus::kTimeout,
                 "time budget of " + std::to_string(o.max_time) + " s exhausted at " +
                     exec.current_action(),
                 t);
      break;
    }
    plant.step(cmd.u, o.dt);
    t += o.dt;
    ++res.steps;
    res.robot_path_length += (plant.pose().x - pose.x).norm();
    for (std::size_t i = 0; i < n; ++i) {
      const Point c = plant.object_center(i);
      res.object_path_length += (c - last_center[i]).norm();
      last_center[i] = c;
    }
  }
  res.min_clearance = std::min(res.min_clearance, plant.clearance());
  res.sim_time = t;
  finish(exec, plant, mission_setup, res);
  res.wall_time = seconds_since(wall_start);
  return res;
}

}  // namespace rearm::executive
