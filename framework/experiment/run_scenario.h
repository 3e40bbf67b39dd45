// One run of a scenario (docs/architecture.md "A control tick"): the executive's task
// loop (executive/task_runner.h) on the Box2D world of sim/ (or on the kinematic plant, for
// comparison), and the files a run leaves: metrics.json and the trajectory that the figure and
// the animation are drawn from.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "executive/task_runner.h"
#include "geometry/clearance_by_kind.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

enum class PlantKind { kBox2d, kKinematic };
const char* to_string(PlantKind k);  // "box2d", "kinematic"

struct RunOptions {
  PlantKind plant = PlantKind::kBox2d;
  // Recorded in the metrics. A run of a fixed scenario draws no random number (Box2D, the
  // executive and the controllers are deterministic); the seed identifies the run in sweeps.
  std::uint64_t seed = 0;
  bool record = true;  // keep the paths (needed for the trajectory, figure and animation)
  // Check the closed loop's invariants on every tick (executive::TaskOptions::check_invariants).
  bool checked = false;
  // Record the mapped and model spaces for trajectory.json (TaskOptions::record_spaces).
  bool spaces = false;
};

struct RunRecord {
  std::string scenario;
  std::uint64_t seed = 0;
  PlantKind plant = PlantKind::kBox2d;
  executive::TaskResult result;
  // Per familiar obstacle (scenario order): the first simulated time (s) it was within sensor
  // range (localized whole, paper §II), or a negative number if never.
  std::vector<double> localized_at;
  std::vector<geometry::Point> objects_start, objects_end;
  double real_time_factor() const;  // simulated / wall time
};

// Validates the task (check_task) and runs it. Bad input throws (scenario::ScenarioError or
// rearm::Error); every outcome of the run itself is in the record.
RunRecord run_scenario(const scenario::Scenario& s, const RunOptions& o = {});

// The entries of "min_clearance_by_kind" in rearm run's and the baselines' metrics.json, in file
// order: {familiar, unknown, objects, boundary} (null for a kind never measured, +infinity).
struct ClearanceKind {
  const char* name;
  double geometry::ClearanceByKind::*value;
};
inline constexpr ClearanceKind kClearanceKinds[] = {
    {"familiar", &geometry::ClearanceByKind::familiar},
    {"unknown", &geometry::ClearanceByKind::unknown},
    {"objects", &geometry::ClearanceByKind::objects},
    {"boundary", &geometry::ClearanceByKind::boundary}};

// metrics.json: status, reason, collisions, min_clearance, sim_time_s, wall_time_s,
// controller_time_s, real_time_factor, actions (with Fix-mode marks), fix_mode_entries,
// robot_path_length_m, object_path_length_m and more. Identical bytes for identical runs apart
// from the three timing fields (wall_time_s, controller_time_s, real_time_factor).
std::string metrics_json(const scenario::Scenario& s, const RunRecord& r);

// trajectory.json: the scenario's geometry, localization times, the robot's poses and the
// objects' centres every `stride` steps, and the action intervals (for the figure and the
// animation, experiments/plot/run.py).
std::string trajectory_json(const scenario::Scenario& s, const RunRecord& r, int stride = 10);

}  // namespace rearm::experiment
