#include "executive/action.h"

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

}  // namespace rearm::executive
