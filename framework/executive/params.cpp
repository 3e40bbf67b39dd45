#include "executive/params.h"

#include <cmath>
#include <utility>

#include "core/error.h"

namespace rearm::executive {

void validate(const ExecutiveParams& p) {
  const std::pair<const char*, double> positive[] = {
      {"robot_radius", p.robot_radius},
      {"goal_tolerance", p.goal_tolerance},
      {"grasp_goal_tolerance", p.grasp_goal_tolerance},
      {"align_tolerance", p.align_tolerance},
      {"dock_speed", p.dock_speed},
      {"backoff_speed", p.backoff_speed},
      {"backoff_margin", p.backoff_margin},
      {"phase_timeout", p.phase_timeout}};
  for (const auto& [name, v] : positive) {
    REARM_REQUIRE(std::isfinite(v) && v > 0, "executive: ", name, " must be finite and > 0, got ",
                  v);
  }
  if (p.max_fix_rounds < 1) throw Error("executive: max_fix_rounds must be >= 1");
  if (p.max_ltl_actions < 0) throw Error("executive: max_ltl_actions must be >= 0");
  if (p.grasp.samples < 1 || !(p.grasp.dock_gap > 0) || !(p.grasp.standoff > p.grasp.dock_gap) ||
      !std::isfinite(p.grasp.standoff) || !std::isfinite(p.grasp.pair_margin) ||
      !(p.grasp.pair_margin >= 0)) {
    throw Error("executive: grasp needs samples >= 1, standoff > dock_gap > 0, pair_margin >= 0");
  }
  reactive::validate(p.diffeo);
  reactive::validate(p.nav);
  validate(p.progress);
  validate(p.guide);
  if (!std::isfinite(p.robust.withdraw_clearance) || p.robust.withdraw_clearance < 0 ||
      !std::isfinite(p.robust.withdraw_max) || p.robust.withdraw_max < 0) {
    throw Error("executive: withdraw_clearance and withdraw_max must be finite and >= 0");
  }
  REARM_REQUIRE(std::isfinite(p.robust.rebuild_margin) && p.robust.rebuild_margin >= 0,
                "executive: rebuild_margin must be finite and >= 0, got ", p.robust.rebuild_margin);
  if (!std::isfinite(p.robust.back_out_step) || !(p.robust.back_out_step > 0) ||
      p.robust.max_back_outs < 0 || !std::isfinite(p.robust.contact_margin) ||
      p.robust.contact_margin < 0 || p.robust.contact_margin > p.robot_radius) {
    throw Error(
        "executive: back_out_step must be finite and > 0, max_back_outs >= 0, contact_margin in "
        "[0, robot_radius]");
  }
}

}  // namespace rearm::executive
