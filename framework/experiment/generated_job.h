// One instance of a sweep generated from its spec (scenario::generate_instance), or why it could
// not be. The cell check (cell_check.h) generates every instance of the cells a shard touches and
// keeps them by canonical instance index; the runner (sweep_runner.h) takes those and generates
// only the ones the check did not. Generation is a function of the spec, so a kept instance is
// the one the runner would have generated.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "experiment/sweep_plan.h"
#include "scenario/random_instance.h"

namespace rearm::experiment {

// Generators of the classes framework/ cannot build itself: kConstructive scatters its objects
// with the baselines' move planner (baselines::generate_constructive), which the command line
// wires in (nothing in framework/ includes baselines/).
struct InstanceGenerators {
  std::function<scenario::GeneratedInstance(const scenario::InstanceSpec&)> constructive;
};

struct GeneratedJob {
  std::optional<scenario::GeneratedInstance> instance;
  std::string error;  // the generator's message when it threw; empty otherwise
};

// Generates the job's instance; a generator exception becomes `error`, as does class
// kConstructive without its generator.
GeneratedJob generate_job(const InstanceJob& job, const InstanceGenerators& generators = {});

// Generated instances by canonical instance index (InstanceJob::index).
using GeneratedJobs = std::map<std::size_t, GeneratedJob>;

}  // namespace rearm::experiment
