#include "experiment/generated_job.h"

#include <exception>

namespace rearm::experiment {

GeneratedJob generate_job(const InstanceJob& job) {
  GeneratedJob out;
  try {
    out.instance = scenario::generate_instance(job.spec);
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace rearm::experiment
