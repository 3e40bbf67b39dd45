// Progress monitor of one action (docs/executive.md, "Termination and failure"): the action
// ends "stuck", with the reason, when the distance to its target x* has not improved for a
// named time, or when the robot revisits a configuration it held earlier without having come
// closer since (a limit cycle or an equilibrium short of the target). Either way a trial
// never loops forever.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "reactive/kinematics.h"

namespace rearm::executive {

struct ProgressParams {
  // No progress: the best distance to x* has not dropped by progress_step (m) for
  // stall_time (s).
  double stall_time = 60;
  double progress_step = 0.02;
  // Revisits: a configuration is recorded every revisit_period (s); the robot revisits one
  // when it is within revisit_distance (m) and revisit_heading (rad) of a record at least
  // revisit_min_age (s) old, taken with the same semantic map version, and the best distance
  // to x* has not dropped by progress_step since that record.
  double revisit_period = 1.0;
  double revisit_distance = 0.01;
  double revisit_heading = 0.05;
  double revisit_min_age = 5.0;
};

// Throws rearm::Error naming the first field that is not finite and > 0.
void validate(const ProgressParams& p);

class ProgressMonitor {
 public:
  explicit ProgressMonitor(const ProgressParams& p = {});

  // Starts monitoring an action at time t (forgets everything before).
  void reset(double t);
  // Observes the robot at time t (non-decreasing) with distance `distance` to x*, under semantic
  // map version `map_version`. Returns the reason when the action is stuck, nullopt otherwise.
  // Throws rearm::Error on non-finite input or time going backwards.
  std::optional<std::string> observe(double t, const reactive::Pose& pose, double distance,
                                     std::uint64_t map_version);

  double best_distance() const { return best_; }

 private:
  struct Record {
    double t;
    reactive::Pose pose;
    std::uint64_t version;
    double best;  // best distance when recorded
  };
  ProgressParams p_;
  bool started_ = false;
  double t0_ = 0;
  double last_t_ = 0;
  double best_ = 0;
  double best_t_ = 0;  // when best_ last dropped by progress_step
  double best_mark_ = 0;
  std::vector<Record> records_;
};

}  // namespace rearm::executive
