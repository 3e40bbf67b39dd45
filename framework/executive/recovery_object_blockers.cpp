// Recovery unit "object blockers" (RobustParams::object_blockers; closed by objects, GRASP,
// RELEASE; docs/executive.md, "Crowded rooms"): the plan found no grasp side of M, or no pose
// from which the pair sets M down in ℓ, that the movable objects leave free. In the paper,
// movable objects are never a reason for infeasibility: clearing them is Fix mode's job
// (§III-A, §IV, Appendix III); but the topology check names only the objects that separate x*
// from the robot, not those lying on x* or beside it. The unit asks what the fixed obstacles
// alone allow:
//  - GRASP: of the sides (grasp_candidates with the objects ignored) whose pair centre lies in
//    the pair's freespace among the fixed obstacles and whose approach point lies in the
//    robot's component of it, the one with the fewest objects in its way, then the nearest;
//  - RELEASE: a pose in a component of the pair's freespace that objects separate from the
//    robot, else a pose among the fixed obstacles alone (release_pose).
// The objects within that side's or pose's clearances, else those the topology check finds
// separating it from the robot, go to Fix mode (fix_mode_for), and Fix mode's drop points keep
// clear of it (Context::keep_clear). When the fixed obstacles alone leave none, the unit does
// not apply and the action is infeasible, as the paper says. Budget: kMaxObjectFixes per
// action, within Fix mode's own (max_fix_rounds per LTL action, the stack limit); past it the
// action ends stuck (objects, not the fixed obstacles, keep it from its target).
#include <string>
#include <vector>

#include "executive/blockers.h"
#include "executive/interface_layer.h"
#include "executive/planning.h"
#include "executive/recovery_units.h"
#include "executive/release_pose.h"
#include "topology/topology_check.h"

namespace rearm::executive::units {
namespace {

// The objects the topology check finds separating `target` from the centre (the action's check:
// with the visible unknown fragments when its plan counts them, planning.h).
std::vector<std::size_t> separating(const Context& c, const ActionState& a, double radius,
                                    const Point& center, const Point& target) {
  const topology::TopologyResult res = check_target(c, a, radius, center, target);
  ++c.topology_checks;
  if (res.verdict != topology::Verdict::kBlockedByObjects) return {};
  return res.blocking;
}

// Fix mode for `blocking`, its drop points kept clear of the disks `keep` and of where each
// blocking object lies now (an object that separates a side, dropped at the nearest clear point
// to where it was gripped, would separate it again); counted. Past kMaxObjectFixes, stuck.
std::optional<Advance> fix_for(const Context& c, ActionState& a, std::vector<std::size_t> blocking,
                               std::vector<geometry::Disk> keep, std::string reason) {
  std::erase_if(blocking, [&](std::size_t i) { return c.map.movable_ids()[i] == a.object; });
  if (blocking.empty()) return std::nullopt;
  if (a.blockers.fixes >= kMaxObjectFixes) {
    return stuck(reason + ", still after " + std::to_string(kMaxObjectFixes) +
                 " Fix-mode entries for them");
  }
  std::optional<Advance> out = fix_mode_for(c, a, blocking, std::move(reason));
  if (!out) return std::nullopt;
  for (std::size_t i : blocking) keep.push_back(c.map.movable()[i]);
  c.keep_clear.insert(c.keep_clear.end(), keep.begin(), keep.end());
  ++a.blockers.fixes;
  ++c.recoveries.object_fixes;
  return out;
}

// GRASP: of the sides the fixed obstacles leave (header), the one with the fewest objects in its
// way, then the nearest.
std::optional<Advance> side_blockers(const Context& c, ActionState& a, const Pose& pose) {
  const double r = c.p.robot_radius;
  const double rp = plan_radius(c);
  const double pair = rp + object_radius(c, a.object) + c.p.grasp.pair_margin;
  const std::optional<geometry::Region> robot_free = fixed_component(c, rp, pose.x);
  const geometry::RegionSet pair_free = fixed_components(c, pair);
  const GraspCandidate* best = nullptr;
  std::vector<std::size_t> best_way;
  const std::vector<GraspCandidate> sides =
      grasp_candidates(c.map, a.object, r, pose.x, c.p.grasp, Objects::kIgnored);
  for (const GraspCandidate& g : sides) {  // nearest first
    if (robot_free && !geometry::contains(*robot_free, g.approach)) continue;
    if (!geometry::contains(pair_free, g.pair_center)) continue;
    std::vector<std::size_t> in_way;
    add_intruders(c, g.approach, rp, a.object, in_way);
    add_intruders(c, g.contact, rp, a.object, in_way);
    add_intruders(c, g.pair_center, pair, a.object, in_way);
    if (in_way.empty()) in_way = separating(c, a, rp, pose.x, g.approach);
    std::erase_if(in_way, [&](std::size_t i) { return c.map.movable_ids()[i] == a.object; });
    if (in_way.empty()) continue;
    if (best == nullptr || in_way.size() < best_way.size()) {
      best = &g;
      best_way = std::move(in_way);
    }
  }
  if (best == nullptr) return std::nullopt;
  return fix_for(c, a, best_way, {{best->approach, rp}, {best->pair_center, pair}},
                 "objects close the side of " + a.object + " at " + point_text(best->approach) +
                     " that the fixed obstacles leave");
}

// RELEASE: a pose objects separate, else one among the fixed obstacles alone (header).
std::optional<Advance> pose_blockers(const Context& c, ActionState& a, const Trigger& trigger) {
  if (c.map.carried() != a.object) return std::nullopt;
  const RegionOfInterest& l = region(c, a.region);
  ReleasePoseParams pp = pose_params(c, trigger.radius);
  // The action's own check (with the visible unknown fragments when its plan counts them): a
  // pose the objects leave but the fragments close is no pose.
  const topology::TopologyResult here =
      check_target(c, a, trigger.radius, trigger.center, trigger.center);
  ++c.topology_checks;
  std::optional<ReleasePose> pose =
      release_pose(here.components, l, c.map, a.object, trigger.center, pp);
  std::vector<std::size_t> in_way;
  if (!pose) {
    const std::optional<geometry::Region> free =
        fixed_component(c, trigger.radius, trigger.center, a.fragment_plan.on);
    if (!free) return std::nullopt;
    pp.objects = Objects::kIgnored;
    pose = release_pose({*free}, l, c.map, a.object, trigger.center, pp);
    if (!pose) return std::nullopt;
    for (int s = 0; s <= kPoseSamples; ++s) {
      const Point x = pose->lead_in + (pose->pair - pose->lead_in) * (double(s) / kPoseSamples);
      add_intruders(c, x, pp.stretch, a.object, in_way);
    }
    add_intruders(c, pose->pair, pp.clearance, a.object, in_way);
  }
  if (in_way.empty()) in_way = separating(c, a, trigger.radius, trigger.center, pose->lead_in);
  return fix_for(c, a, in_way, {{pose->lead_in, trigger.radius}, {pose->pair, trigger.radius}},
                 "objects close the release pose of " + a.object + " in " + a.region + " at " +
                     point_text(pose->pair) + " that the fixed obstacles leave");
}

}  // namespace

std::optional<Advance> object_blockers(const Context& c, ActionState& a, const Pose& pose,
                                       Trigger& trigger, Tick /*tick*/) {
  switch (a.kind) {
    case ActionKind::kGrasp:
      return side_blockers(c, a, pose);
    case ActionKind::kRelease:
      return pose_blockers(c, a, trigger);
    case ActionKind::kMove:
    case ActionKind::kDisassemble:
      break;
  }
  return std::nullopt;
}

}  // namespace rearm::executive::units
