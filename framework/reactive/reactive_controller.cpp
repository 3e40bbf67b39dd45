#include "reactive/reactive_controller.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "geometry/distance.h"
#include "geometry/partition.h"

namespace rearm::reactive {
namespace {

// Documented fallback for a goal on an obstacle boundary: a goal outside the freespace by at
// most kGoalSnap (m) (the mapped space dilates by r plus a 1e-9 m contact slack, and rounding
// does the rest) moves to the nearest freespace boundary point, nudged kGoalNudge (m) outward.
constexpr double kGoalSnap = 1e-6;
constexpr double kGoalNudge = 1e-9;
// Model-heading turn (rad) always allowed in one step by the discrete-time guard.
constexpr double kHeadingGuardSlack = 0.02;

std::optional<Point> snap_goal(const MappedSpace& m, const Point& goal) {
  const geometry::Nearest best = geometry::nearest_on_boundary(m.freespace, goal);
  if (best.distance > kGoalSnap) return std::nullopt;
  const Point away = best.distance > 0 ? Point((best.point - goal) / best.distance) : Point::Zero();
  for (const Point& q : {Point(best.point + kGoalNudge * away), best.point}) {
    if (in_freespace(m, q)) return q;
  }
  return std::nullopt;
}

// Replaces the familiar components for which `pick` holds by their convex pieces, kept as
// convex obstacles of the model space (the unknown fragments' treatment).
template <typename Pick>
void convexify(MappedSpace& m, geometry::PartitionCache& cache, Pick pick) {
  std::vector<FamiliarComponent> kept;
  for (FamiliarComponent& c : m.familiar) {
    if (!pick(c)) {
      kept.push_back(std::move(c));
      continue;
    }
    for (Polygon& piece : cache.pieces(c.polygon)) m.unknown.push_back(std::move(piece));
  }
  m.familiar = std::move(kept);
}

}  // namespace

ReactiveController::ReactiveController(const DiffeoParams& diffeo, const NavParams& nav)
    : diffeo_params_(diffeo), nav_(nav) {
  validate(diffeo_params_);
  validate(nav_);
}

void ReactiveController::rebuild(const SemanticInput& map, double radius, const Point& center,
                                 const Point& goal) {
  const RebuildResult r = try_rebuild(map, radius, center, goal);
  if (r.status != RebuildStatus::kOk) throw Error(r.message);
}

RebuildResult ReactiveController::try_rebuild(const SemanticInput& map, double radius,
                                              const Point& center, const Point& goal) {
  if (!goal.allFinite()) throw Error("reactive controller: goal is not finite");
  MappedSpace mapped;
  try {
    mapped = mapped_builder_.build(map, radius, center);
  } catch (const NotInFreespace& e) {
    return {RebuildStatus::kCenterNotFree, e.what()};
  }
  Point target = goal;
  if (!in_freespace(mapped, goal)) {
    if (auto snapped = snap_goal(mapped, goal)) target = *snapped;
  }
  if (!in_freespace(mapped, target)) {
    return {RebuildStatus::kGoalNotFree,
            "reactive controller: the goal (" + std::to_string(goal.x()) + ", " +
                std::to_string(goal.y()) +
                ") is not in the freespace component of the robot (inside an obstacle, or "
                "disconnected from the robot)"};
  }
  if (fallback_ && convexify_all_)
    convexify(mapped, partitions_, [](const FamiliarComponent&) { return true; });
  Outcome<Diffeomorphism> diffeo =
      Diffeomorphism::try_build(mapped, diffeo_params_, decompositions_);
  if (!diffeo && fallback_) {
    // The fallback: the curved components as convex pieces, then every component.
    ++fallbacks_;
    convexify(mapped, partitions_, [](const FamiliarComponent& c) { return c.curved; });
    diffeo = Diffeomorphism::try_build(mapped, diffeo_params_, decompositions_);
    if (!diffeo) {
      convexify(mapped, partitions_, [](const FamiliarComponent&) { return true; });
      diffeo = Diffeomorphism::try_build(mapped, diffeo_params_, decompositions_);
    }
  }
  if (!diffeo) return {RebuildStatus::kNoDiffeomorphism, diffeo.reason()};
  if (fallback_ && convexify_all_) ++fallbacks_;
  model_goal_ = diffeo->map(target);
  mapped_ = std::move(mapped);
  diffeo_ = std::make_unique<Diffeomorphism>(std::move(*diffeo));
  goal_ = target;
  ++rebuilds_;
  return {};
}

bool ReactiveController::retarget(const Point& goal) {
  if (!diffeo_) throw Error("reactive controller: retarget requested before rebuild()");
  if (!goal.allFinite()) throw Error("reactive controller: goal is not finite");
  if (!in_freespace(mapped_, goal)) return false;
  goal_ = goal;
  model_goal_ = diffeo_->map(goal);
  return true;
}

Point ReactiveController::holonomic(const Point& x, double dt) {
  if (!diffeo_) throw Error("reactive controller: command requested before rebuild()");
  // The fully actuated law reads h and Dh only (§4): D²h is not computed.
  const DiffeoEval e = diffeo_->evaluate(x, DiffeoOrder::kJacobian);
  sample_ = LawSample{x, e.h, e.J.determinant()};
  Point u = fully_actuated_velocity(diffeo_->model(), e, model_goal_, nav_, scratch_);
  for (int k = 0; k < kSafetyHalvings; ++k, u /= 2) {
    if (geometry::convex_contains(scratch_.lf, diffeo_->map(holonomic_step(x, u, dt)))) return u;
  }
  return Point::Zero();
}

Twist ReactiveController::unicycle(const Pose& pose, double dt) {
  if (!diffeo_) throw Error("reactive controller: command requested before rebuild()");
  const DiffeoEval e = diffeo_->evaluate(pose.x);
  sample_ = LawSample{pose.x, e.h, e.J.determinant()};
  Twist u = unicycle_command(diffeo_->model(), e, pose.psi, model_goal_, nav_, scratch_);
  // Discrete-time guard: near sharp corners h is strongly anisotropic, dξ/dψ reaches 10–20
  // and D²h is large, so the two parts of ξ̇ (the turn, and the rotation the translation
  // causes, which ω compensates) nearly cancel in continuous time but not over a held step:
  // the model heading ξ then swings by tenths of a radian per step and the robot chatters.
  // v and ω are halved together until the predicted step keeps the model point in LF(y) (the
  // safety filter) and turns ξ by no more than twice the law's own turn k_ω|t_W| dt plus
  // kHeadingGuardSlack (an ordinary step turns ξ by at most ω_max dt = 0.01 rad).
  const Point e0 = e.J * Point(std::cos(pose.psi), std::sin(pose.psi));
  const double xi0 = std::atan2(e0.y(), e0.x());
  const double allowed = 2 * nav_.k_omega * std::abs(scratch_.t_w) * dt + kHeadingGuardSlack;
  for (int k = 0; k < kSafetyHalvings; ++k, u = Twist{u.v / 2, u.omega / 2}) {
    const Pose next = unicycle_step(pose, u, dt);
    const DiffeoEval en = diffeo_->evaluate(next.x, DiffeoOrder::kJacobian);
    if (!geometry::convex_contains(scratch_.lf, en.h)) continue;
    const Point e1 = en.J * Point(std::cos(next.psi), std::sin(next.psi));
    const double turn =
        std::abs(std::remainder(std::atan2(e1.y(), e1.x()) - xi0, 2 * std::numbers::pi));
    if (turn <= allowed) return u;
  }
  return Twist{};
}

Twist ReactiveController::pair(const Pose& pose, double rho_i, double dt) {
  if (!diffeo_) throw Error("reactive controller: command requested before rebuild()");
  const Point xc = pair_center(pose.x, pose.psi, rho_i);
  // The pair's law is the fully actuated one pulled through T(ψ) (§4): h and Dh only.
  const DiffeoEval e = diffeo_->evaluate(xc, DiffeoOrder::kJacobian);
  sample_ = LawSample{xc, e.h, e.J.determinant()};
  Twist u = pair_command(diffeo_->model(), e, pose.psi, rho_i, model_goal_, nav_, scratch_);
  for (int k = 0; k < kSafetyHalvings; ++k, u = Twist{u.v / 2, u.omega / 2}) {
    const Pose next = unicycle_step(pose, u, dt);
    if (geometry::convex_contains(scratch_.lf,
                                  diffeo_->map(pair_center(next.x, next.psi, rho_i)))) {
      return u;
    }
  }
  return Twist{};
}

}  // namespace rearm::reactive
