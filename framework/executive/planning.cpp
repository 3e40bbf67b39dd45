#include "executive/planning.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/stopwatch.h"
#include "executive/blockers.h"
#include "executive/interface_layer.h"
#include "executive/release_pose.h"
#include "executive/targets.h"
#include "topology/topology_check.h"

namespace rearm::executive {
namespace {

bool same_disks(const std::vector<geometry::Disk>& a, const std::vector<geometry::Disk>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].center != b[i].center || a[i].radius != b[i].radius) return false;
  }
  return true;
}

// What the action's plan counts as fixed, for its messages.
const char* fixed_obstacles(const ActionState& a) {
  return a.fragment_plan.on ? "fixed obstacles and visible unknown obstacles" : "fixed obstacles";
}

// B_M of a verdict kBlockedByObjects; RobustParams::object_blockers: a minimal subset of it
// (blockers.h, minimal_blockers).
std::vector<std::size_t> blockers(const Context& c, const ActionState& a,
                                  const topology::TopologyResult& res, double radius,
                                  const Point& center, const Point& target) {
  if (!c.p.robust.object_blockers || a.fragment_plan.on) return res.blocking;
  return minimal_blockers(c, res.blocking, radius, center, target);
}

// GRASP's side (paper §IV): the first candidate whose pair centre lies in the pair's freespace
// and whose approach point lies in F (reachable), and the first with the pair free alone
// (fallback, for the topology check). Robust variant (RobustParams::fragments): sides whose
// approach point or pair lies within the dilation of a visible unknown fragment (which the
// topology check does not model) come last.
std::pair<const GraspCandidate*, const GraspCandidate*> choose_side(
    const Context& c, const ActionState& a, const std::vector<GraspCandidate>& candidates,
    const geometry::RegionSet& pair_free, const geometry::Region& f) {
  const GraspCandidate* reachable = nullptr;
  const GraspCandidate* fallback = nullptr;
  const double pair_radius = c.p.robot_radius + object_radius(c, a.object) + c.p.grasp.pair_margin;
  auto clear_of_fragments = [&](const GraspCandidate& g) {
    return known_clearance(c.map, g.approach, a.object) >= plan_radius(c, a) &&
           known_clearance(c.map, g.pair_center, a.object) >= pair_radius;
  };
  for (bool clear : {true, false}) {
    if (clear && !c.p.robust.fragments) continue;
    for (const GraspCandidate& g : candidates) {
      if (!geometry::contains(pair_free, g.pair_center) || (clear && !clear_of_fragments(g))) {
        continue;
      }
      if (fallback == nullptr) fallback = &g;
      if (geometry::contains(f, g.approach)) {
        reachable = &g;
        break;
      }
    }
    if (reachable != nullptr) break;
  }
  return {reachable, fallback};
}

// The disks the paper's disassembly target keeps away from: Context::keep_clear, and the drop
// points a recovery rejected (the retarget and redrop units: a target cut off by a fragment the
// topology check does not model would be chosen again, tick after tick, until the units' budget
// is spent on one point), with the clearance drop_point keeps from them.
std::vector<geometry::Disk> keep_off_rejected(const Context& c, const ActionState& a) {
  std::vector<geometry::Disk> keep = c.keep_clear;
  const double unit = c.p.robot_radius + max_object_radius(c);
  for (const Point& x : a.drop.rejected)
    keep.push_back(geometry::Disk{x, kRejectedDropRadius * unit});
  return keep;
}

// DISASSEMBLE's x* (paper §V-B): the midpoint of an edge of the pair's freespace F, kept while it
// stays in F so the target does not jump as the map grows. Robust variant: the nearest point of
// F where the object can be dropped clear of everything (drop_clear), when there is one.
Advance plan_disassemble(const Context& c, ActionState& a, double radius, const Point& center,
                         double rho) {
  Advance out;
  const topology::TopologyResult res = timed_check(c, radius, center, center);
  ++c.topology_checks;
  if (drop_points(c, a) && (!a.target || !geometry::contains(res.freespace, *a.target) ||
                            !drop_kept(c, a, *a.target, rho))) {
    a.target = drop_point(c, a, res.freespace, radius, center, rho);
  }
  if (!a.target || !geometry::contains(res.freespace, *a.target)) {
    a.target = disassemble_target(res.freespace, c.map, a.object, c.regions, radius,
                                  kDisassembleInset, keep_off_rejected(c, a));
    if (!a.target) {
      out.kind = Advance::kStuck;
      out.reason = "the pair's freespace has no edge to disassemble the object toward";
      return out;
    }
  }
  remember_plan(c, a);
  return out;
}

// The cause "closed by objects" (docs/executive.md, "Recoveries"), met where the plan would
// end the action infeasible: the recovery policy's next step, else infeasible with `reason`.
Advance closed_by_objects(const Context& c, ActionState& a, const Pose& pose, Tick tick,
                          std::string reason, double radius, const Point& center) {
  Trigger closed{Cause::kClosedByObjects, std::move(reason), radius, center};
  if (std::optional<Advance> next = recover(c, a, pose, closed, tick)) return *next;
  return infeasible(closed.reason);
}

Advance plan_grasp(const Context& c, ActionState& a, const Pose& pose, Tick tick) {
  Advance out;
  const double r = c.p.robot_radius;
  const double rp = plan_radius(c);
  auto closed = [&](std::string reason) {
    return closed_by_objects(c, a, pose, tick, std::move(reason), rp, pose.x);
  };
  const std::vector<GraspCandidate> candidates =
      grasp_candidates(c.map, a.object, r, pose.x, c.p.grasp);
  if (candidates.empty()) {
    return closed("no side of " + a.object + " leaves room to dock and to carry it (" +
                  std::to_string(c.p.grasp.samples) + " directions tried)");
  }
  const auto& ids = c.map.movable_ids();

  // Exact freespaces: the robot's (every object an obstacle) and the pair's once gripped (the
  // object carried, radius r + ρ_i + pair_margin).
  // F from the topology check with x* = x (throws when the robot is not in its freespace).
  const topology::TopologyResult here = check_target(c, a, rp, pose.x, pose.x);
  const geometry::Region* f = &here.freespace;
  const geometry::RegionSet pair_free = pair_freespace(c, a.object, a.fragment_plan.on);
  c.topology_checks += 1;
  const auto [reachable, fallback] = choose_side(c, a, candidates, pair_free, *f);
  if (fallback == nullptr) {
    return closed("no side of " + a.object + " from which the robot–object pair would be free");
  }
  a.target = (reachable != nullptr ? reachable : fallback)->approach;
  if (reachable == nullptr) {
    // Paper §IV: the approach point is not in F; the topology check says why.
    const topology::TopologyResult res = check_target(c, a, r, pose.x, *a.target);
    ++c.topology_checks;
    if (res.verdict == topology::Verdict::kBlockedByFixed) {
      return closed(std::string(fixed_obstacles(a)) + " separate the robot from every side of " +
                    a.object + ": " + res.reason);
    }
    if (res.verdict == topology::Verdict::kBlockedByObjects) {
      for (std::size_t i : blockers(c, a, res, r, pose.x, *a.target)) {
        if (ids[i] != a.object) out.blocking.push_back(ids[i]);
      }
      if (out.blocking.empty()) {
        return closed("only " + a.object + " itself separates the robot from its free sides");
      }
      out.kind = Advance::kBlocked;
      out.reason = res.reason;
      a.blocked_way = Way{pose.x, *a.target, r, a.fragment_plan.on, {}, {}, {}, 0};
      return out;
    }
  }
  remember_plan(c, a);
  return out;
}

// Objects cut ℓ's centroid off and one of them lies in ℓ: Fix mode clears ℓ, as in the paper
// (Fig. 5), rather than setting the object down beside the occupant.
bool occupied(const Context& c, const topology::TopologyResult& res, const RegionOfInterest& l) {
  if (res.verdict != topology::Verdict::kBlockedByObjects) return false;
  for (std::size_t i : res.blocking) {
    if (geometry::contains(l.polygon, c.map.movable()[i].center)) return true;
  }
  return false;
}

// RELEASE, robust variant, the centroid cut off: anywhere in ℓ that the pair reaches now, as
// clear as ℓ allows (release_point); else a pose from which the object is set down in ℓ
// (release_pose), ties going to the lead-in nearest the pair's centre. Sets x*; false when
// neither applies (the centroid's verdict stands).
bool release_elsewhere(const Context& c, ActionState& a, const topology::TopologyResult& res,
                       double radius, const Point& center) {
  const RegionOfInterest& l = region(c, a.region);
  const ReleasePoseParams pp = pose_params(c, radius);
  if (c.p.robust.release_point) {
    const double inset = c.p.robot_radius + c.p.grasp.pair_margin + 2 * c.p.goal_tolerance;
    if (auto p = release_point(res.freespace, l, c.map, a.object, inset, pp.enough, pp.step)) {
      a.target = *p;
      a.pose.reset();
      ++c.recoveries.release_points;
      return true;
    }
  }
  if (!c.p.robust.release_pose || occupied(c, res, l)) return false;
  const std::optional<ReleasePose> pose =
      release_pose({res.freespace}, l, c.map, a.object, center, pp);
  if (!pose) return false;
  // The pose is chosen again whenever the plan is (the map changed); the stage is kept while
  // the pose is the same.
  if (!a.pose || a.pose->pair != pose->pair || a.pose->lead_in != pose->lead_in) {
    a.pose_stretch = false;
    ++c.recoveries.release_poses;
  }
  a.pose = pose;
  a.target = a.pose_stretch ? pose->pair : pose->lead_in;
  return true;
}

}  // namespace

// The topology check of the action's x* (Appendix III); a RELEASE the plan-among-fragments
// unit sent on checks with the visible unknown fragments as fixed obstacles (without the topology
// cache, which holds the familiar obstacles only).
topology::TopologyResult check_target(const Context& c, const ActionState& a, double radius,
                                      const Point& center, const Point& target) {
  if (!a.fragment_plan.on) return timed_check(c, radius, center, target);
  const topology::TopologyInput in =
      input_with_fragments(c, c.map.movable(), radius, center, target);
  const ScopedStopwatch sw(c.times.topology_s);
  return topology::check_topology(in);
}

ReleasePoseParams pose_params(const Context& c, double radius) {
  ReleasePoseParams pp;
  pp.lead = c.p.robot_radius + c.p.grasp.dock_gap;
  pp.clearance = radius + kPoseSlack;
  pp.stretch = radius;
  pp.inside = kPoseInside;
  pp.approach = kPoseApproach;
  pp.enough = 2 * (c.p.robot_radius + max_object_radius(c));
  pp.step = kReleaseStep;
  pp.headings = kPoseHeadings;
  return pp;
}

bool knowledge_changed(const Context& c, const ActionState& a) {
  return c.map.familiar().size() != a.plan_familiar || c.map.carried() != a.plan_carried ||
         !same_disks(c.map.movable(), a.plan_movable);
}

// The action's plan (paper §IV, §V): x* and the topology check's verdict; GRASP and
// DISASSEMBLE have their own.
Advance plan(const Context& c, ActionState& a, const Pose& pose, Tick tick) {
  if (a.kind == ActionKind::kGrasp) return plan_grasp(c, a, pose, tick);
  Advance out;
  const std::optional<std::string> carried = c.map.carried();
  const auto [rho, radius, center] = moving(c, a, pose);
  if (a.kind == ActionKind::kDisassemble) return plan_disassemble(c, a, radius, center, rho);

  const Point target = region_target(region(c, a.region));
  const topology::TopologyResult res = check_target(c, a, radius, center, target);
  ++c.topology_checks;
  a.target = target;
  if (a.kind == ActionKind::kRelease && carried == a.object &&
      res.verdict != topology::Verdict::kReachable) {
    if (release_elsewhere(c, a, res, radius, center)) {
      remember_plan(c, a);
      return out;
    }
  }
  a.pose.reset();
  switch (res.verdict) {
    case topology::Verdict::kReachable:
      remember_plan(c, a);
      return out;
    case topology::Verdict::kBlockedByFixed:
      if (!a.bare && plan_radius(c, a) > c.p.robot_radius) {
        // Robust variant: a passage only the contact margin closes is taken at the bare radius
        // (the paper's), for this action only.
        a.bare = true;
        return plan(c, a, pose, tick);
      }
      if (a.kind == ActionKind::kRelease && carried == a.object) {
        return closed_by_objects(c, a, pose, tick,
                                 std::string(fixed_obstacles(a)) +
                                     " separate x* = " + point_text(target) + ": " + res.reason,
                                 radius, center);
      }
      out.kind = Advance::kInfeasible;
      out.reason = "fixed obstacles separate x* = " + point_text(target) + ": " + res.reason;
      return out;
    case topology::Verdict::kBlockedByObjects:
      out.kind = Advance::kBlocked;
      a.blocked_way = Way{center, target, radius, a.fragment_plan.on, {}, {}, {}, 0};
      for (std::size_t i : blockers(c, a, res, radius, center, target)) {
        out.blocking.push_back(c.map.movable_ids()[i]);
      }
      out.reason = res.reason;
      return out;
  }
  return out;
}

void remember_plan(const Context& c, ActionState& a) {
  a.planned = true;
  a.plan_familiar = c.map.familiar().size();
  a.plan_movable = c.map.movable();
  a.plan_carried = c.map.carried();
}

// The exact freespace of the pair once `object` is gripped (the object carried, radius
// r + contact margin + ρ_i + pair_margin): F_list of Appendix III.
geometry::RegionSet pair_freespace(const Context& c, const std::string& object,
                                   bool with_fragments) {
  const auto& ids = c.map.movable_ids();
  const auto it = std::find(ids.begin(), ids.end(), object);
  if (it == ids.end()) throw Error("executive: " + object + " is not a movable obstacle now");
  const std::size_t index = static_cast<std::size_t>(it - ids.begin());
  const Point at = c.map.movable()[index].center;
  const double radius = plan_radius(c) + object_radius(c, object) + c.p.grasp.pair_margin;
  const ScopedStopwatch sw(c.times.topology_s);
  ++c.topology_checks;
  if (with_fragments) {
    topology::TopologyCache none;  // bound − ∪fixed changes as the fragments grow
    return topology::freespace_components(
        input_with_fragments(c, c.map.movable(), radius, at, at, index), none);
  }
  return topology::freespace_components(
      topology::make_input(c.map.workspace(), c.map.familiar(), c.map.movable(), radius, at, at,
                           index, c.topology_cache),
      c.topology_cache);
}

}  // namespace rearm::executive
