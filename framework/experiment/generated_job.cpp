#include "experiment/generated_job.h"

#include <exception>

namespace rearm::experiment {

GeneratedJob generate_job(const InstanceJob& job, const InstanceGenerators& generators) {
  GeneratedJob out;
  try {
    if (job.spec.goal_class != scenario::GoalClass::kConstructive) {
      out.instance = scenario::generate_instance(job.spec);
    } else if (generators.constructive) {
      out.instance = generators.constructive(job.spec);
    } else {
      out.error =
          "class constructive: no generator (the rearm program supplies "
          "baselines::generate_constructive)";
    }
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace rearm::experiment
