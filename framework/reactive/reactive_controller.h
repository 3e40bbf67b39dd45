// The reactive controller of the paper's reference [7] as one object: the mapped space and the
// diffeomorphism for the current semantic map, radius and goal, and the navigation law that
// turns a pose into a command (docs/reactive.md §2–4). Rebuilt only when the semantic map, the
// radius (grasp/release) or the goal changes, never inside an integration step.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "geometry/partition.h"
#include "reactive/diffeomorphism.h"
#include "reactive/kinematics.h"
#include "reactive/mapped_space.h"
#include "reactive/navigation.h"
#include "reactive/params.h"

namespace rearm::reactive {

enum class RobotModel { kHolonomic, kUnicycle };

// Halvings of a command before the discrete-time safety filter gives up and stops the robot.
inline constexpr int kSafetyHalvings = 30;

// Outcome of ReactiveController::try_rebuild: the two situations the executive expects and
// handles (docs/executive.md), as values.
enum class RebuildStatus {
  kOk,
  kCenterNotFree,  // the robot (or pair) centre is not in the freespace
  kGoalNotFree,    // the goal is inside an obstacle or in another freespace component
  // No purging diffeomorphism (Diffeomorphism::try_build's failure), with the convex fallback
  // off (the paper variant) or after its last stage (every component convexified).
  kNoDiffeomorphism,
};

struct RebuildResult {
  RebuildStatus status = RebuildStatus::kOk;
  std::string message;  // why, when not kOk
};

class ReactiveController {
 public:
  ReactiveController(const DiffeoParams& diffeo, const NavParams& nav);

  // Mapped space of `map` dilated by `radius` (the robot's r, or r + ρ_i for the robot–object
  // pair) seen from `center` (robot or pair centre), its diffeomorphism, and the goal's model
  // image. Throws rearm::Error when the centre is not in the freespace, or the goal is not in
  // the freespace component of the centre (blocked or inside an obstacle: the topology check
  // of the executive decides what to do then). A goal on an obstacle boundary (outside the
  // freespace by <= 1e-6 m) is snapped to the nearest freespace point (goal() returns it).
  void rebuild(const SemanticInput& map, double radius, const Point& center, const Point& goal);
  // The same, with a centre or goal outside the freespace reported as a value (the controller is
  // left as it was); malformed input still throws rearm::Error.
  RebuildResult try_rebuild(const SemanticInput& map, double radius, const Point& center,
                            const Point& goal);

  // Moves the goal within the current mapped space (no rebuild: h does not depend on the goal).
  // Returns false, leaving the goal as it was, when `goal` is not in the freespace F_k.
  bool retarget(const Point& goal);

  // Convex fallback of the robust variant (experiments/sweeps/README.md, "Variants"): when
  // Diffeomorphism::build rejects a cluster (no purging tree, a collar that cannot avoid another
  // obstacle), the clusters of mixed kind (FamiliarComponent::curved), then every familiar
  // component, are kept in the model space as their convex pieces (h is the identity there).
  // The law of Arslan & Koditschek stays safe with convex obstacles that overlap (LF(y) excludes
  // each one); what is lost near them is the convergence guarantee, which the interface layer's
  // guide recovers (executive/guide_path.h). Off (the paper's choice): the build error is thrown.
  void set_convex_fallback(bool on) { fallback_ = on; }
  // Every familiar component kept as its convex pieces from the next rebuild on (the executive
  // sets it for an action where Dh turned singular).
  void set_convexify_all(bool on) { convexify_all_ = on; }
  // The miter limit of the familiar obstacles' dilations (geometry::dilate_miter) from the next
  // rebuild on.
  void set_miter_limit(double limit) { mapped_builder_.dilations().set_miter_limit(limit); }
  // Rebuilds that used the convex fallback.
  int fallbacks() const { return fallbacks_; }

  bool ready() const { return diffeo_ != nullptr; }
  // Commands at the current state (docs/reactive.md §4), to be held for one step of `dt`.
  // Discrete-time safety: the law keeps the model point inside the local freespace LF(y) in
  // continuous time; a command held over a step moves the robot on an arc whose second-order
  // error can cross an obstacle a few millimetres away. The command is halved (v and ω alike,
  // so the path keeps its shape) until the predicted model point after the step lies in LF(y)
  // (at most kSafetyHalvings times, then zero). Throw rearm::Error when not ready or when the
  // state is outside the freespace.
  Point holonomic(const Point& x, double dt = kDefaultStep);
  Twist unicycle(const Pose& pose, double dt = kDefaultStep);
  // Gripper engaged: the pose is the robot's, the controller was rebuilt for the pair
  // (radius r + ρ_i, centre pair_center(x, ψ, ρ_i)).
  Twist pair(const Pose& pose, double rho_i, double dt = kDefaultStep);

  const MappedSpace& mapped() const { return mapped_; }
  const Diffeomorphism& diffeo() const { return *diffeo_; }
  const Point& goal() const { return goal_; }
  const Point& model_goal() const { return model_goal_; }
  const NavParams& nav() const { return nav_; }
  int rebuilds() const { return rebuilds_; }

  // The law's last evaluation (holonomic, unicycle or pair): the centre x, its model point
  // y = h(x) and det Dh(x), for the closed loop's checked mode (executive/task_runner.h).
  struct LawSample {
    Point x = Point::Zero();
    Point y = Point::Zero();
    double det = 0;
  };
  const LawSample& last_law_sample() const { return sample_; }

 private:
  DiffeoParams diffeo_params_;
  NavParams nav_;
  MappedSpace mapped_;
  MappedSpaceBuilder mapped_builder_;    // dilations, erosion and the last mapped space
  DecompositionCache decompositions_;    // components' candidate trees, kept across rebuilds
  geometry::PartitionCache partitions_;  // the convex fallback's pieces, kept across rebuilds
  std::unique_ptr<Diffeomorphism> diffeo_;
  Point goal_ = Point::Zero();
  Point model_goal_ = Point::Zero();
  NavScratch scratch_;
  int rebuilds_ = 0;
  bool fallback_ = false;
  bool convexify_all_ = false;
  int fallbacks_ = 0;
  LawSample sample_;
};

}  // namespace rearm::reactive
