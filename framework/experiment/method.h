// The plug point of the Monte Carlo runner (house style: inheritance only
// at real plug points): a method solves one scenario and reports a TrialOutcome. rearm itself
// is one (rearm_method.h); the OMPL baselines register theirs from baselines/ (nothing in
// framework/ includes baselines/: the command line wires them into the registry).
//
// A method is immutable and shared by every thread of a sweep: run() must keep all its mutable
// state in locals (one Box2D world per trial) and draw random numbers only from the seed it is
// given.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "experiment/trial.h"
#include "scenario/scenario.h"

namespace rearm::experiment {

struct MethodInput {
  std::uint64_t seed = 0;    // the planner seed
  double time_limit_s = 10;  // planning budget (baselines); rearm is bounded by simulated time
  long query_limit = 0;      // the baselines' deterministic search budget (0: none)
  // rearm: the closed loop's invariants checked on every tick (executive/task_runner.h,
  // TaskOptions::check_invariants); a violation throws, i.e. an `error` row with its message.
  bool checked = false;
};

class Method {
 public:
  virtual ~Method() = default;
  virtual std::string name() const = 0;
  // One line for `rearm sweep --help` and the OMPL log's planner settings.
  virtual std::string summary() const = 0;
  // Whether the method follows the order the task's formula imposes (rearm: its mission
  // controller reads the formula) or solves the final arrangement in any order (the
  // baselines): a sweep's goal orders multiply only the trials of the former.
  virtual bool follows_task_order() const { return false; }
  // Runs the scenario. Expected outcomes are values; a throw becomes an `error` row.
  virtual TrialOutcome run(const scenario::Scenario& s, const MethodInput& in) const = 0;
};

class MethodRegistry {
 public:
  // Throws rearm::Error when a method of that name is registered already.
  void add(std::unique_ptr<Method> m);
  // Throws rearm::Error naming the registered methods when there is none of that name.
  const Method& get(const std::string& name) const;
  bool contains(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::vector<std::unique_ptr<Method>> methods_;
};

}  // namespace rearm::experiment
