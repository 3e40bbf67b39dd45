// Seeded random static scenes of the kind used by the paper's reactive backbone (its reference
// [7], Vasilopoulos et al., and docs/reactive.md §7) for the reactive tests and benchmarks:
// a polygonal workspace, familiar non-convex obstacles (L, U, T, staircase, cross and random
// star-shaped polygons), unknown convex obstacles and, optionally, movable disks.
//
// Placement rule (random_scene): every obstacle dilated by r + margin/2 (mitered, as the
// mapped space dilates familiar obstacles) must be disjoint from every other one dilated the
// same way and lie inside the workspace eroded by r + margin/2, so the mapped-space obstacles
// (dilated by r) are at least `margin` apart from each other and from the eroded workspace
// boundary. Boundary-touching familiar obstacles (SceneOptions::boundary_touching) are the
// exception to the second half: they are clipped by the workspace and share part of its
// boundary (walls attached to the room, which the mapped space merges into ∂F_e as pockets).
// All decisions use the exact Booleans of geometry/boolean.h. Every draw comes from the given
// generator, so a scene is a function of the seed and the options.
#pragma once

#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "reactive/mapped_space.h"

namespace rearm::test_support {

struct ReactiveScene {
  geometry::Polygon workspace;              // counter-clockwise, possibly non-convex
  std::vector<geometry::Polygon> familiar;  // undilated, possibly non-convex
  std::vector<geometry::Polygon> unknown;   // undilated, convex
  std::vector<geometry::Disk> movable;      // undilated object disks
  double robot_radius = 0.2;
  double sensor_range = 5.0;
  geometry::Point goal = geometry::Point::Zero();  // free, with SceneOptions::goal_clearance
};

// The whole scene as perception would report it once everything has been seen.
reactive::SemanticInput to_semantic_input(const ReactiveScene& s);

// Familiar obstacle shapes. kStar is test_support::random_star (possibly convex).
enum class Shape { kL, kU, kT, kStaircase, kCross, kStar };
inline constexpr Shape kNonConvexShapes[] = {Shape::kL, Shape::kU, Shape::kT, Shape::kStaircase,
                                             Shape::kCross};
const char* to_string(Shape s);

// A shape of overall extent `size` (its axis-aligned bounding box is size × size before
// rotation, except the staircase, also size × size) and arm width `thickness`
// (0 < thickness < size/2 for U and cross, < size for the others; ignored by kStar),
// centred on its bounding box, rotated by `angle` about that centre, then moved to `center`.
// Counter-clockwise. kStar draws its vertices from rng (the only shape that does).
geometry::Polygon make_shape(Rng& rng, Shape s, double size, double thickness, double angle,
                             const geometry::Point& center);

// A random convex polygon of circumradius at most `radius` around `center`: either the hull
// of 5–9 points at sorted random angles and radii in [0.6, 1]·radius, or a regular polygon of
// 3–8 sides with jittered vertices (one of the two at random). Counter-clockwise.
geometry::Polygon random_convex(Rng& rng, const geometry::Point& center, double radius);

enum class WorkspaceShape {
  kSquare,  // size × size
  kLRoom,   // the square without its upper-right quadrant (non-convex)
};

struct SceneOptions {
  double workspace_size = 20.0;  // m
  WorkspaceShape workspace_shape = WorkspaceShape::kSquare;
  int familiar = 4;  // number of familiar (non-convex) obstacles K
  int unknown = 2;   // number of unknown convex obstacles
  int movable = 0;   // number of movable disks
  double robot_radius = 0.2;
  double sensor_range = 5.0;
  // Separation of the dilated obstacles from each other and from the eroded workspace
  // boundary (m). 2·ε with the default collar width ε = 1 leaves room for both collars.
  double margin = 2.0;
  double familiar_min_size = 1.5;  // extent of a familiar obstacle (m)
  double familiar_max_size = 3.0;
  double thickness_fraction_min = 0.25;  // arm width / extent
  double thickness_fraction_max = 0.35;
  // Unknown obstacles as regular 48-gons (nearly round) instead of random convex polygons: the
  // navigation law of Arslan & Koditschek converges when obstacles are sufficiently curved (its
  // curvature condition); a long flat face with the goal straight behind it is a stable
  // equilibrium of the law, which no reactive method of this family escapes.
  bool round_unknown = false;
  double unknown_min_radius = 0.4;  // circumradius of an unknown obstacle (m)
  double unknown_max_radius = 1.0;
  double movable_min_radius = 0.2;  // movable object radius (m)
  double movable_max_radius = 0.4;
  std::vector<Shape> shapes{std::begin(kNonConvexShapes), std::end(kNonConvexShapes)};
  // How many of the familiar obstacles are walls attached to the workspace boundary: the
  // first `boundary_touching` entries of ReactiveScene::familiar, clipped by the workspace,
  // away from its corners, never cutting the freespace in two.
  int boundary_touching = 0;
  // A free point at least this far from every dilated obstacle and the eroded boundary.
  double goal_clearance = 0.3;
  int max_attempts = 500;  // placement attempts per obstacle before starting over
  int max_restarts = 20;   // scenes started over before giving up
};

// Obstacles are placed one at a time (walls, familiar, unknown, movable, then the goal); when
// one cannot be placed within max_attempts the scene is started over (the generator's stream
// continues, so the result is still a function of the seed). Throws rearm::Error when the
// options are invalid or max_restarts scenes failed (too crowded for the margin).
ReactiveScene random_scene(Rng& rng, const SceneOptions& options = {});

// The workspace polygon of the options (counter-clockwise, lower-left corner at the origin).
geometry::Polygon make_workspace(WorkspaceShape shape, double size);

// Uniform in the freespace F_k of m (rejection sampling with reactive::in_freespace) at
// distance >= clearance from every boundary of F_k, every familiar component, unknown
// obstacle and movable disk. Throws rearm::Error after 100000 rejected draws.
geometry::Point random_free_point(Rng& rng, const reactive::MappedSpace& m, double clearance);

// The benchmark scene of docs/reactive.md §7: a 20 × 20 m workspace, K familiar non-convex
// obstacles cycling through L, U, T, staircase and cross (extent 1.8 m, arm width 0.6 m,
// rotations by multiples of 90° and a small seeded jitter), one per cell of a 5 × 4 grid
// (cells chosen by the seed), robot radius 0.2, no unknown obstacles, goal at (18.8, 18.8).
// 0 <= K <= 20, else rearm::Error.
ReactiveScene benchmark_scene(int K, std::uint64_t seed);

}  // namespace rearm::test_support
