#include "experiment/provenance.h"

#include <unistd.h>

#include <ctime>
#include <fstream>
#include <string>

namespace rearm::experiment {

// Defined in the build tree's generated revision.cpp (revision.cmake).
extern const char* const kBuildRevision;

const char* build_revision() { return kBuildRevision; }

std::string host_name() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "unknown";
  return buf;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string model = line.substr(colon + 1);
    const std::size_t first = model.find_first_not_of(" \t");
    return first == std::string::npos ? "unknown" : model.substr(first);
  }
  return "unknown";
}

Provenance this_process() { return Provenance{build_revision(), host_name(), cpu_model(), ""}; }

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

}  // namespace rearm::experiment
