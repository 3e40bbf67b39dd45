// The recovery policy as data (docs/executive.md, "Recoveries: causes, units and the policy
// table"): the units, each with the switch that turns it on and the counter that shows it ran,
// and for each cause and action kind the ordered steps, each a unit with the switches it
// requires beyond its own (today's couplings, kept so that an ablation `rearm-no<key>` still
// turns off what it measured). The paper variant turns every switch off: no step is enabled,
// the empty table.
#pragma once

#include <array>
#include <span>

#include "executive/action.h"
#include "executive/params.h"
#include "executive/recovery.h"

namespace rearm::executive {

enum class Unit {
  kReleaseInRegion,
  kEarlyDock,
  kContactBackUp,
  kGuide,
  kRedrop,
  kNarrow,
  kBackUp,
  kConvex,
  kFragmentBlockers,
  kMemoryBlockers,
  kRetarget,
  kDropShort,
  kObjectBlockers,
  kPlanAmongFragments,
};
inline constexpr std::size_t kUnitCount = 14;

using Switch = bool RobustParams::*;

struct UnitInfo {
  Unit unit;
  const char* name;     // as in docs/executive.md's table
  Switch turned_on_by;  // its RobustParams switch
  const char* counter;  // the RecoveryCounts field (kRecoveryFields name) it counts in, or ""
};
const UnitInfo& unit_info(Unit unit);

struct Step {
  Unit unit;
  std::array<Switch, 2> needs{};  // further switches it requires (null: none)
};
// The steps for a cause and an action kind, in the order they are tried.
std::span<const Step> policy(Cause cause, ActionKind kind);
// The step's unit switch and every switch it requires are on.
bool enabled(const RobustParams& r, const Step& step);

}  // namespace rearm::executive
