#include "experiment/method.h"

#include "core/error.h"

namespace rearm::experiment {

void MethodRegistry::add(std::unique_ptr<Method> m) {
  REARM_DEMAND(m != nullptr, "MethodRegistry::add: null method");
  if (contains(m->name())) throw Error("method '" + m->name() + "' is registered twice");
  methods_.push_back(std::move(m));
}

bool MethodRegistry::contains(const std::string& name) const {
  for (const auto& m : methods_) {
    if (m->name() == name) return true;
  }
  return false;
}

const Method& MethodRegistry::get(const std::string& name) const {
  for (const auto& m : methods_) {
    if (m->name() == name) return *m;
  }
  std::string known;
  for (const auto& m : methods_) known += (known.empty() ? "" : ", ") + m->name();
  throw Error("unknown method '" + name + "' (known: " + known + ")");
}

std::vector<std::string> MethodRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& m : methods_) out.push_back(m->name());
  return out;
}

}  // namespace rearm::experiment
