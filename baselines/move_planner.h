// One object move, the primitive both baselines build plans from (Krontiris & Bekris's
// "transit" and "transfer" paths): the robot drives alone to a pre-grasp pose at the object
// (a transit query), docks and grips, carries the object as the pair disk to a target (a
// transfer query ending with a straight approach), and releases it. Grasp and release
// headings are tried from `directions` evenly spaced candidates, nearest to the straight line
// first.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "baselines/motion_query.h"
#include "baselines/plan.h"

namespace rearm::baselines {

// Why a move could not be planned. The first three are decided by exact geometry (no sampling):
// they prove the move impossible in this arrangement, which is what lets B1 report an instance
// non-monotone; the others are the sampling planner's failures.
enum class MoveFailure {
  kNone,
  kTargetOccupied,  // the object at the target would overlap another object
  kTargetBlocked,   // ... or an obstacle / the boundary (or no release heading fits)
  kNoGrasp,         // no candidate heading has a free pre-grasp pose, dock and pair disk
  kTransitFailed,   // RRTConnect found no transit path (iteration cap)
  kTransferFailed,  // ... no transfer path
  kTimeout,         // the trial's time budget ran out
};
const char* to_string(MoveFailure f);
inline bool proves_impossible(MoveFailure f) {
  return f == MoveFailure::kTargetOccupied || f == MoveFailure::kTargetBlocked ||
         f == MoveFailure::kNoGrasp;
}

struct MoveOutcome {
  std::optional<ObjectMove> move;  // set when planned
  MoveFailure failure = MoveFailure::kNone;
  Point robot_after = Point::Zero();  // robot centre after backing off the release
};

class MovePlanner {
 public:
  MovePlanner(const RearrangementProblem& problem, const BaselineParams& params);

  // Plans moving object i from its place in `a` to `target`, the robot starting at `robot`
  // (its centre; nullopt: the transit is left empty, to be planned when the plan is assembled).
  // `goal_region`: the object must end inside it (the planned landing is checked).
  MoveOutcome plan(const Arrangement& a, std::optional<Point> robot, std::size_t i,
                   const Point& target, const std::optional<geometry::Polygon>& goal_region,
                   QueryContext& ctx) const;

  // The transfer part of a move: object i (at a[i], held) carried from pair centre p0 with the
  // robot's heading psi0 to `target`: a transfer query to the start of a free straight approach,
  // the landing predicted by tracked_heading, the back-off checked. `move->transit` is empty.
  MoveOutcome transfer(const Arrangement& a, std::size_t i, const Point& p0, double psi0,
                       const Point& target, const std::optional<geometry::Polygon>& goal_region,
                       QueryContext& ctx) const;

  // A transit of the robot alone in arrangement a (robot disk, transit margin).
  QueryResult transit(const Arrangement& a, const Point& from, const Point& to,
                      QueryContext& ctx) const;

  // True when object i fits at p in arrangement a (placement margin to the other objects,
  // clearance for the pair to handle it: the robot disk at some standoff pose is free).
  bool placement_free(const Arrangement& a, std::size_t i, const Point& p) const;
  bool overlaps_object(const Arrangement& a, std::size_t i, const Point& p) const;

  const DiskWorld& world() const { return world_; }
  const RearrangementProblem& problem() const { return problem_; }
  const BaselineParams& params() const { return params_; }
  std::vector<geometry::Disk> disks(const Arrangement& a) const;

 private:
  const RearrangementProblem& problem_;
  BaselineParams params_;
  DiskWorld world_;
};

}  // namespace rearm::baselines
