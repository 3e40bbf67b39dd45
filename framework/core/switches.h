// The one registry of the robust variant's switches (docs/executive.md, "Recoveries: causes,
// units and the policy table"): each switch's scenario key, what kind of thing it turns on,
// where it acts, the recovery counter that shows its code ran, and a summary. Everything else
// is derived from it: the scenario keys (scenario_io.cpp), the ablation methods `rearm-no<key>`
// (experiment/rearm_method.cpp), the executive's parameters (executive::kRobustFlags, checked
// against this list by tests/core/switches_test), and the behaviour gate's cases
// (scripts/behaviour_gate.py reads this file). Adding a switch: a row here, its field and
// kRobustFlags row in executive/params.h, and the code where it acts.
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace rearm {

enum class SwitchKind {
  kRecovery,  // a recovery unit of the policy table
  kOption,    // shapes a recovery (the guide's or the back-up's)
  kPolicy,    // acts where it is (geometry, rebuilds, targets, phases, perception)
};

enum class SwitchHome { kExecutive, kPerception };

struct SwitchInfo {
  const char* key;
  SwitchKind kind;
  SwitchHome home;
  // The metrics.json / trials.csv recovery counter that shows the switch's code ran (an
  // option names the recovery it shapes; a policy acting in every run, the guide's).
  const char* evidence;
  const char* summary;
};

// In the scenario files' and the sweep's order.
inline constexpr SwitchInfo kSwitches[] = {
    {"guide", SwitchKind::kRecovery, SwitchHome::kExecutive, "guides",
     "guide paths after the progress monitor fires"},
    {"convex_fallback", SwitchKind::kRecovery, SwitchHome::kExecutive, "singular_switches",
     "convex pieces where h cannot be built"},
    {"back_out", SwitchKind::kRecovery, SwitchHome::kExecutive, "back_outs",
     "back up when the centre is not free"},
    {"restore", SwitchKind::kPolicy, SwitchHome::kExecutive, "restores",
     "re-place objects Fix mode moved off their goal"},
    {"drop", SwitchKind::kPolicy, SwitchHome::kExecutive, "pocket_drops",
     "drop disassembled objects clear of everything"},
    {"early_release", SwitchKind::kRecovery, SwitchHome::kExecutive, "early_releases",
     "release once the object is inside its region"},
    {"withdraw", SwitchKind::kPolicy, SwitchHome::kExecutive, "withdrawals",
     "back the pair out of a narrow place after a grasp"},
    {"release_point", SwitchKind::kPolicy, SwitchHome::kExecutive, "release_points",
     "release where in the region it is clearest"},
    {"release_pose", SwitchKind::kPolicy, SwitchHome::kExecutive, "release_poses",
     "set the object down in a narrow region from a pose"},
    {"object_blockers", SwitchKind::kRecovery, SwitchHome::kExecutive, "object_fixes",
     "Fix mode for objects on a grasp side or release pose"},
    {"bevel", SwitchKind::kPolicy, SwitchHome::kExecutive, "guides",
     "familiar corners bevelled on the disk's tangent"},
    {"early_dock", SwitchKind::kRecovery, SwitchHome::kExecutive, "early_docks",
     "dock from where the robot stalls beside the object"},
    {"face", SwitchKind::kOption, SwitchHome::kExecutive, "faces",
     "turn toward the goal after a back-up"},
    {"narrow", SwitchKind::kRecovery, SwitchHome::kExecutive, "narrows",
     "Fix mode for objects narrowing a failed passage"},
    {"track", SwitchKind::kOption, SwitchHome::kExecutive, "guides",
     "follow guide paths straight, segment by segment"},
    {"escape", SwitchKind::kOption, SwitchHome::kExecutive, "back_outs",
     "back up along the clearest straight line"},
    {"widen", SwitchKind::kOption, SwitchHome::kExecutive, "guides",
     "each failed guide's successor keeps more clearance"},
    {"scan", SwitchKind::kPolicy, SwitchHome::kPerception, "guides",
     "read unknown fragments every scan_spacing"},
    {"fragments", SwitchKind::kRecovery, SwitchHome::kExecutive, "fragment_fixes",
     "Fix mode for objects closing x* off with fragments"},
    {"memory", SwitchKind::kOption, SwitchHome::kExecutive, "guides",
     "guide paths avoid what was seen of unknown obstacles"},
    {"persist", SwitchKind::kOption, SwitchHome::kExecutive, "guides",
     "guides that bring the robot closer renew the budget"},
    {"redrop", SwitchKind::kRecovery, SwitchHome::kExecutive, "redrops",
     "an unreachable drop point is chosen again"},
    {"defer", SwitchKind::kPolicy, SwitchHome::kExecutive, "guides",
     "rebuild once the map's news comes near"},
};
inline constexpr std::size_t kSwitchCount = std::size(kSwitches);

// The registry index of `key`, nullopt for an unknown one.
constexpr std::optional<std::size_t> switch_index(std::string_view key) {
  for (std::size_t i = 0; i < kSwitchCount; ++i) {
    if (key == kSwitches[i].key) return i;
  }
  return std::nullopt;
}

// The sweep method that runs the robust variant with switch `s` off: "rearm-no" and the key
// without underscores (early_release: rearm-noearlyrelease).
inline std::string ablation_method(const SwitchInfo& s) {
  std::string name = "rearm-no";
  for (const char* c = s.key; *c != '\0'; ++c) {
    if (*c != '_') name += *c;
  }
  return name;
}

// A sweep file's methods entry that stands for every ablation method, in registry order.
inline constexpr std::string_view kAblationGroup = "rearm-no*";

// One value per registry switch (all on: the robust variant).
class SwitchSet {
 public:
  SwitchSet() { bits_.set(); }
  bool on(std::size_t i) const { return bits_.test(i); }
  void set(std::size_t i, bool value) { bits_.set(i, value); }
  // By key; throws rearm::Error naming an unknown one.
  bool on(std::string_view key) const { return on(index(key)); }
  void set(std::string_view key, bool value) { set(index(key), value); }
  void set_all(bool value) { value ? bits_.set() : bits_.reset(); }
  bool operator==(const SwitchSet&) const = default;

 private:
  static std::size_t index(std::string_view key) {
    if (const auto i = switch_index(key)) return *i;
    throw Error("unknown robust switch '" + std::string(key) + "'");
  }
  std::bitset<kSwitchCount> bits_;
};

}  // namespace rearm
