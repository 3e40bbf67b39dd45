#include "baselines/move_planner.h"

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace rearm::baselines {

namespace {

// Candidate headings tried per move: a transit is posed for at most this many grasp headings,
// a transfer for at most this many release headings per grasp (the rest would mostly repeat
// the same failed query through the same corridors).
constexpr int kMaxGraspTries = 2;
constexpr int kMaxReleaseTries = 2;

// Headings base + 2πk/n in the order 0, +1, −1, +2, −2, ... (nearest to `base` first).
std::vector<double> candidate_headings(double base, int n) {
  std::vector<double> out;
  out.push_back(wrap_angle(base));
  for (int k = 1; static_cast<int>(out.size()) < n; ++k) {
    out.push_back(wrap_angle(base + 2 * std::numbers::pi * k / n));
    if (static_cast<int>(out.size()) < n)
      out.push_back(wrap_angle(base - 2 * std::numbers::pi * k / n));
  }
  return out;
}

double bearing(const Point& from, const Point& to) {
  const Point d = to - from;
  return d.squaredNorm() == 0 ? 0.0 : std::atan2(d.y(), d.x());
}

}  // namespace

const char* to_string(MoveFailure f) {
  switch (f) {
    case MoveFailure::kNone:
      return "none";
    case MoveFailure::kTargetOccupied:
      return "target occupied by another object";
    case MoveFailure::kTargetBlocked:
      return "target blocked (no free release approach)";
    case MoveFailure::kNoGrasp:
      return "no free grasp heading";
    case MoveFailure::kTransitFailed:
      return "no transit path found";
    case MoveFailure::kTransferFailed:
      return "no transfer path found";
    case MoveFailure::kTimeout:
      return "time budget exhausted";
  }
  return "?";
}

MovePlanner::MovePlanner(const RearrangementProblem& problem, const BaselineParams& params)
    : problem_(problem), params_(params), world_(problem.workspace, problem.obstacles) {
  if (params.directions < 1) throw Error("baseline parameters: directions must be >= 1");
}

std::vector<geometry::Disk> MovePlanner::disks(const Arrangement& a) const {
  std::vector<geometry::Disk> out;
  out.reserve(a.size());
  for (std::size_t j = 0; j < a.size(); ++j) out.push_back({a[j], problem_.object_radii[j]});
  return out;
}

bool MovePlanner::overlaps_object(const Arrangement& a, std::size_t i, const Point& p) const {
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (j == i) continue;
    if ((a[j] - p).norm() <
        problem_.object_radii[i] + problem_.object_radii[j] + params_.placement_margin)
      return true;
  }
  return false;
}

bool MovePlanner::placement_free(const Arrangement& a, std::size_t i, const Point& p) const {
  const double rho = problem_.object_radii[i], r = problem_.robot_radius;
  if (overlaps_object(a, i, p)) return false;
  if (!world_.disk_free(p, rho, params_.placement_margin, {})) return false;
  Arrangement b = a;
  b[i] = p;
  const auto d = disks(b);
  for (double psi : candidate_headings(0, params_.directions)) {
    const Point xs = standoff_position(p, r, rho, psi, params_);
    if (world_.disk_free(xs, r, params_.transit_margin, d)) return true;
  }
  return false;
}

QueryResult MovePlanner::transit(const Arrangement& a, const Point& from, const Point& to,
                                 QueryContext& ctx) const {
  return plan_motion(world_, disks(a), std::nullopt, problem_.robot_radius, params_.transit_margin,
                     from, to, ctx, params_.range);
}

MoveOutcome MovePlanner::plan(const Arrangement& a, std::optional<Point> robot, std::size_t i,
                              const Point& target,
                              const std::optional<geometry::Polygon>& goal_region,
                              QueryContext& ctx) const {
  REARM_DEMAND(i < a.size(), "MovePlanner::plan: object index");
  MoveOutcome out;
  const double r = problem_.robot_radius, rho = problem_.object_radii[i];
  const double ell = pair_offset(rho, params_), pr = pair_radius(r, rho, params_);
  const double reach = r + 0.5 * params_.grip_gap;  // pair centre to object centre
  const double approach = std::max(params_.approach_min, params_.approach_factor * ell);
  const Point o = a[i];
  const auto d = disks(a);

  if (overlaps_object(a, i, target)) {
    out.failure = MoveFailure::kTargetOccupied;
    return out;
  }
  if (!world_.disk_free(target, rho, params_.placement_margin, {})) {
    out.failure = MoveFailure::kTargetBlocked;
    return out;
  }
  // Release approaches whose straight final segment is free (exact geometry).
  std::vector<double> releases;
  for (double psi : candidate_headings(bearing(o, target), params_.directions)) {
    const Point u = heading_vector(psi);
    const Point p_goal = target - reach * u, p_pre = p_goal - approach * u;
    if (world_.segment_free(p_pre, p_goal, pr, params_.transfer_margin, d, i))
      releases.push_back(psi);
  }
  if (releases.empty()) {
    out.failure = MoveFailure::kTargetBlocked;
    return out;
  }
  // Grasp headings with a free pre-grasp pose, dock and gripped pair.
  std::vector<double> grasps;
  for (double psi :
       candidate_headings(robot ? bearing(*robot, o) : bearing(target, o), params_.directions)) {
    const Point u = heading_vector(psi);
    const Point xs = standoff_position(o, r, rho, psi, params_);
    const Point xg = grip_position(o, r, rho, psi, params_);
    if (world_.disk_free(xs, r, params_.transit_margin, d) &&
        world_.segment_free(xs, xg, r, params_.transit_margin, d, i) &&
        world_.disk_free(xg + ell * u, pr, params_.transfer_margin, d, i))
      grasps.push_back(psi);
  }
  if (grasps.empty()) {
    out.failure = MoveFailure::kNoGrasp;
    return out;
  }

  out.failure = MoveFailure::kTransitFailed;
  for (int g = 0; g < std::min<int>(kMaxGraspTries, static_cast<int>(grasps.size())); ++g) {
    const double psi_g = grasps[static_cast<std::size_t>(g)];
    const Point xs = standoff_position(o, r, rho, psi_g, params_);
    ObjectMove m;
    m.object = i;
    m.from = o;
    m.grasp_heading = psi_g;
    if (robot) {
      const QueryResult t = transit(a, *robot, xs, ctx);
      if (t.status == QueryStatus::kTimeout) {
        out.failure = MoveFailure::kTimeout;
        return out;
      }
      if (t.status != QueryStatus::kSolved) continue;
      m.transit = t.path;
    }
    const Point p0 = grip_position(o, r, rho, psi_g, params_) + ell * heading_vector(psi_g);
    MoveOutcome t = transfer(a, i, p0, psi_g, target, goal_region, ctx);
    out.failure = t.failure;
    if (t.failure == MoveFailure::kTimeout) return out;
    if (!t.move.has_value()) continue;
    m.to = t.move->to;
    m.transfer = std::move(t.move->transfer);
    m.release_heading = t.move->release_heading;
    out.move = std::move(m);
    out.failure = MoveFailure::kNone;
    out.robot_after = t.robot_after;
    return out;
  }
  return out;
}

MoveOutcome MovePlanner::transfer(const Arrangement& a, std::size_t i, const Point& p0, double psi0,
                                  const Point& target,
                                  const std::optional<geometry::Polygon>& goal_region,
                                  QueryContext& ctx) const {
  REARM_DEMAND(i < a.size(), "MovePlanner::transfer: object index");
  MoveOutcome out;
  const double r = problem_.robot_radius, rho = problem_.object_radii[i];
  const double ell = pair_offset(rho, params_), pr = pair_radius(r, rho, params_);
  const double reach = r + 0.5 * params_.grip_gap;
  const double approach = std::max(params_.approach_min, params_.approach_factor * ell);
  const auto d = disks(a);
  if (overlaps_object(a, i, target)) {
    out.failure = MoveFailure::kTargetOccupied;
    return out;
  }
  out.failure = MoveFailure::kTargetBlocked;
  int tries = 0;
  for (double psi_r : candidate_headings(bearing(p0, target), params_.directions)) {
    if (tries == kMaxReleaseTries) break;
    const Point u = heading_vector(psi_r);
    const Point p_goal = target - reach * u, p_pre = p_goal - approach * u;
    if (!world_.segment_free(p_pre, p_goal, pr, params_.transfer_margin, d, i)) continue;
    ++tries;
    out.failure = MoveFailure::kTransferFailed;
    const QueryResult q =
        plan_motion(world_, d, i, pr, params_.transfer_margin, p0, p_pre, ctx, params_.range);
    if (q.status == QueryStatus::kTimeout) {
      out.failure = MoveFailure::kTimeout;
      return out;
    }
    if (q.status != QueryStatus::kSolved) continue;
    std::vector<Point> path = q.path;
    if ((path.back() - p_goal).norm() > 0) path.push_back(p_goal);
    const double psi_end = tracked_heading(path, psi0, ell);
    const Point to = p_goal + reach * heading_vector(psi_end);
    if (goal_region && !geometry::contains(*goal_region, to)) continue;
    if (overlaps_object(a, i, to)) continue;
    Arrangement after = a;
    after[i] = to;
    const Point xr = grip_position(to, r, rho, psi_end, params_);
    const Point xb = standoff_position(to, r, rho, psi_end, params_);
    if (!world_.segment_free(xr, xb, r, params_.transit_margin, disks(after), i)) continue;
    ObjectMove m;
    m.object = i;
    m.from = a[i];
    m.to = to;
    m.transfer = std::move(path);
    m.release_heading = psi_end;
    out.move = std::move(m);
    out.failure = MoveFailure::kNone;
    out.robot_after = xb;
    return out;
  }
  return out;
}

}  // namespace rearm::baselines
