#include "executive/action.h"

#include <utility>

namespace rearm::executive {

std::string ActionState::name() const {
  switch (kind) {
    case ActionKind::kMove:
      return "move(" + region + ")";
    case ActionKind::kGrasp:
      return "grasp(" + object + ")";
    case ActionKind::kRelease:
      return "release(" + object + "," + region + ")";
    case ActionKind::kDisassemble:
      return "disassemble(" + object + ")";
  }
  return "?";
}

ActionState make_action(ActionKind kind, std::string object, std::string region, bool fix, double t,
                        const ProgressParams& progress) {
  ActionState a;
  a.kind = kind;
  a.object = std::move(object);
  a.region = std::move(region);
  a.fix = fix;
  a.t_start = a.phase_start = t;
  a.monitor = ProgressMonitor(progress);
  a.monitor.reset(t);
  return a;
}

Advance stuck(std::string reason) {
  Advance out;
  out.kind = Advance::kStuck;
  out.reason = std::move(reason);
  return out;
}

Advance infeasible(std::string reason) {
  Advance out;
  out.kind = Advance::kInfeasible;
  out.reason = std::move(reason);
  return out;
}

Advance restart() {
  Advance out;
  out.kind = Advance::kRestart;
  return out;
}

}  // namespace rearm::executive
