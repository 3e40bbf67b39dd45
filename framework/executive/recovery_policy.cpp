#include "executive/recovery_policy.h"

#include "core/error.h"
#include "executive/recovery_units.h"

namespace rearm::executive {
namespace {

using R = RobustParams;

// docs/executive.md, "Recoveries": the unit table.
constexpr UnitInfo kUnits[kUnitCount] = {
    {Unit::kReleaseInRegion, "release in region", &R::early_release, "early_releases"},
    {Unit::kEarlyDock, "early dock", &R::early_dock, "early_docks"},
    {Unit::kContactBackUp, "contact back-up", &R::back_out, "back_outs"},
    {Unit::kGuide, "guide", &R::guide, "guides"},
    {Unit::kRedrop, "redrop", &R::redrop, "redrops"},
    {Unit::kNarrow, "narrow", &R::narrow, "narrows"},
    {Unit::kBackUp, "back-up", &R::back_out, "back_outs"},
    {Unit::kConvex, "convex", &R::convex_fallback, "singular_switches"},
    {Unit::kFragmentBlockers, "fragment blockers", &R::fragments, "fragment_fixes"},
    {Unit::kMemoryBlockers, "memory blockers", &R::fragments, "fragment_fixes"},
    {Unit::kRetarget, "retarget", &R::drop, ""},
    {Unit::kDropShort, "drop short", &R::early_release, "early_releases"},
    {Unit::kObjectBlockers, "object blockers", &R::object_blockers, "object_fixes"},
    {Unit::kPlanAmongFragments, "plan among fragments", &R::fragments, ""},
};

constexpr units::UnitFunction* kFunctions[kUnitCount] = {
    units::release_in_region,
    units::early_dock,
    units::contact_back_up,
    units::guide,
    units::redrop,
    units::narrow,
    units::back_up,
    units::convex,
    units::fragment_blockers,
    units::memory_blockers,
    units::retarget,
    units::drop_short,
    units::object_blockers,
    units::plan_among_fragments,
};

// The steps. Requirements are today's couplings (docs/executive.md): the contact back-up,
// redrop and narrow ran only after the guide's switch was checked; redrop needs the drop points
// it rejects; drop short at a cut-off goal ran only with the drop points on.
constexpr Step kReleaseInRegion{Unit::kReleaseInRegion};
constexpr Step kEarlyDock{Unit::kEarlyDock};
constexpr Step kContactBackUp{Unit::kContactBackUp, {&R::guide}};
constexpr Step kGuide{Unit::kGuide};
constexpr Step kRedrop{Unit::kRedrop, {&R::guide, &R::drop}};
constexpr Step kNarrow{Unit::kNarrow, {&R::guide}};
constexpr Step kBackUp{Unit::kBackUp};
constexpr Step kConvex{Unit::kConvex};
constexpr Step kFragmentBlockers{Unit::kFragmentBlockers};
constexpr Step kMemoryBlockers{Unit::kMemoryBlockers, {&R::memory}};
constexpr Step kRetarget{Unit::kRetarget};
constexpr Step kDropShortAtGoal{Unit::kDropShort, {&R::drop}};
constexpr Step kDropShort{Unit::kDropShort};
constexpr Step kObjectBlockers{Unit::kObjectBlockers};
constexpr Step kPlanAmongFragments{Unit::kPlanAmongFragments};

constexpr Step kStalledMove[] = {kContactBackUp, kGuide, kNarrow};
constexpr Step kStalledGrasp[] = {kEarlyDock, kContactBackUp, kGuide, kNarrow};
constexpr Step kStalledRelease[] = {kReleaseInRegion, kContactBackUp, kGuide, kNarrow};
constexpr Step kStalledDisassemble[] = {kContactBackUp, kGuide, kRedrop, kNarrow};
constexpr Step kCentreNotFree[] = {kBackUp};
constexpr Step kNoLaw[] = {kConvex};
constexpr Step kGoalCutOffMove[] = {kFragmentBlockers};
constexpr Step kGoalCutOff[] = {kFragmentBlockers, kPlanAmongFragments};
constexpr Step kGoalCutOffDisassemble[] = {kRetarget, kDropShortAtGoal};
constexpr Step kClosedByMemory[] = {kMemoryBlockers};
constexpr Step kBackUpsSpentDisassemble[] = {kDropShort};
constexpr Step kClosedByObjects[] = {kObjectBlockers};

// [cause][kind]: MOVE, GRASP, RELEASE, DISASSEMBLE.
constexpr std::span<const Step> kTable[kCauseCount][4] = {
    {kStalledMove, kStalledGrasp, kStalledRelease, kStalledDisassemble},
    {kCentreNotFree, kCentreNotFree, kCentreNotFree, kCentreNotFree},
    {kNoLaw, kNoLaw, kNoLaw, kNoLaw},
    {kGoalCutOffMove, kGoalCutOff, kGoalCutOff, kGoalCutOffDisassemble},
    {kClosedByMemory, kClosedByMemory, kClosedByMemory, {}},
    {{}, {}, {}, kBackUpsSpentDisassemble},
    {{}, kClosedByObjects, kClosedByObjects, {}},
};

}  // namespace

const char* to_string(Cause cause) {
  switch (cause) {
    case Cause::kStalled:
      return "stalled";
    case Cause::kCentreNotFree:
      return "centre not free";
    case Cause::kNoLaw:
      return "no law";
    case Cause::kGoalCutOff:
      return "goal cut off";
    case Cause::kClosedByMemory:
      return "closed by memory";
    case Cause::kBackUpsSpent:
      return "back-ups spent";
    case Cause::kClosedByObjects:
      return "closed by objects";
  }
  return "?";
}

const UnitInfo& unit_info(Unit unit) { return kUnits[static_cast<std::size_t>(unit)]; }

std::span<const Step> policy(Cause cause, ActionKind kind) {
  return kTable[static_cast<std::size_t>(cause)][static_cast<std::size_t>(kind)];
}

bool enabled(const RobustParams& r, const Step& step) {
  if (!(r.*(unit_info(step.unit).turned_on_by))) return false;
  for (Switch s : step.needs) {
    if (s != nullptr && !(r.*s)) return false;
  }
  return true;
}

std::optional<Advance> recover(const Context& c, ActionState& a, const Pose& pose, Trigger& trigger,
                               Tick tick) {
  for (const Step& step : policy(trigger.cause, a.kind)) {
    if (!enabled(c.p.robust, step)) continue;
    if (std::optional<Advance> next =
            kFunctions[static_cast<std::size_t>(step.unit)](c, a, pose, trigger, tick)) {
      return next;
    }
  }
  return std::nullopt;
}

}  // namespace rearm::executive
