// The change of coordinates h from the mapped space to the model space (docs/reactive.md §3;
// Vasilopoulos & Koditschek, WAFR 2018; paper Appendix II): every familiar component is
// decomposed into convex pieces arranged in a tree; each piece is purged into its parent by
//   h_i(x) = σ_i(x)(c_i + ν_i(x)(x − c_i)) + (1 − σ_i(x)) x                       (§3.8)
// and the root is deformed into a disk (free component) or merged into ∂F_e (pocket). h is
// the composition of all purges, deepest first; evaluate() returns h, Dh and D²h by the chain
// rule. h is the identity outside the collars, and a C∞ diffeomorphism of the freespace away
// from sharp corners.
//
// Choices where reactive.md leaves room, or departs from the authors' code (each argued at its
// place in diffeomorphism.cpp):
//  - Decomposition: cuts along reflex-vertex extensions first (rectangles for L, U, T,
//    staircase and cross shapes; no sharp angles), then CGAL's partition, then a
//    triangulation; the first whose collars can all be built is used. A piece whose side runs
//    on past a shared edge (a flat corner) must be the parent of that adjacency, or is split.
//  - Centres: c_i is taken on reactive.md's ray but inside the parent *and* the half-planes of
//    the piece's two edges next to the adjacency edge, so [v0, c_i, v1, ...] is convex and the
//    piece lies in the cone of c_i (both needed for det Dh > 0 and for the boundary to map
//    onto the adjacency edge).
//  - Collars: the augmented piece offset by ε with bevelled corners (reach ≈ ε), clipped by
//    the cone at c_i and by F_e; an obstacle still present is cut off by a line separating it
//    from the augmented piece (collars stay convex, so γ is exact), not by subtraction.
//  - β: over the piece's own edges (reactive.md §3.5). Points within 1e-12 m of a piece count
//    as on it (σ = 1), which fixes the 0/0 of σ at the adjacency corners on the boundary.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

#include "core/outcome.h"
#include "geometry/convex.h"
#include "reactive/mapped_space.h"
#include "reactive/model_space.h"
#include "reactive/params.h"

namespace rearm::reactive {

class PthRoot;

// h(x), its Jacobian J = Dh(x) and second derivatives H[k](i, j) = ∂²h_k / ∂x_i ∂x_j.
// How much of an evaluation to compute: h alone, h and Dh, or h, Dh and D²h (the fields not
// computed keep their defaults). h and Dh are the same, bit for bit, at every order.
enum class DiffeoOrder { kValue, kJacobian, kHessian };

struct DiffeoEval {
  Point h = Point::Zero();
  Eigen::Matrix2d J = Eigen::Matrix2d::Identity();
  std::array<Eigen::Matrix2d, 2> H{Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
};

// One purging transformation (one convex piece), in the coordinates of the space it acts on
// (all earlier purges applied).
struct Purge {
  enum class Kind { kChild, kDiskRoot, kBoundaryRoot };
  Kind kind = Kind::kChild;
  int component = 0;             // index into MappedSpace::familiar
  int parent = -1;               // index into purges(), -1 for a root
  int depth = 0;                 // 0 for a root
  Polygon piece;                 // the convex piece (counter-clockwise)
  Polygon collar;                // convex switch domain (σ > 0 only inside)
  Point center = Point::Zero();  // c_i
  Point v0 = Point::Zero();      // adjacency (or lid) edge; unused for a disk root
  Point v1 = Point::Zero();
  double radius = 0;   // disk root: model disk radius ρ
  double epsilon = 0;  // the collar width used for this piece
  // Flat evaluation data: unit normals pointing into the piece / collar.
  std::vector<geometry::HalfPlane> beta_planes;
  std::vector<geometry::HalfPlane> gamma_planes;
  Eigen::AlignedBox2d collar_box;
};

// Components remembered by DecompositionCache before it is emptied.
inline constexpr std::size_t kDecompositionCacheEntries = 256;

// The convex decompositions and candidate trees of familiar components (§3.1–3.2), remembered
// between rebuilds: they depend on the component's polygon, lid and curvature only, and a
// rebuild often changes few components (a new fragment, a moved object), while the
// decompositions (CGAL's optimal convex partition above all) were about a quarter of a rebuild
// at N = 8 (docs/reactive.md §2). Keyed by the exact vertices; the result of build() is
// identical. Not thread-safe (one per controller).
class DecompositionCache {
 public:
  DecompositionCache();
  ~DecompositionCache();
  DecompositionCache(DecompositionCache&&) noexcept;
  DecompositionCache& operator=(DecompositionCache&&) noexcept;
  std::size_t size() const;

 private:
  friend class Diffeomorphism;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class Diffeomorphism {
 public:
  // Builds the trees of every familiar component of m (docs/reactive.md §3.1–3.7). Throws
  // rearm::Error on invalid parameters or geometry that admits no construction (a collar
  // that cannot avoid another obstacle).
  static Diffeomorphism build(const MappedSpace& m, const DiffeoParams& params = {});
  // The same, the components' candidate trees taken from (and added to) `cache`.
  static Diffeomorphism build(const MappedSpace& m, const DiffeoParams& params,
                              DecompositionCache& cache);
  // The same with the expected failure as a value: a component that admits no purging tree,
  // or none of whose candidate trees admits every centre and collar (obstacles too close to
  // separate, §3.4); the reactive controller then falls back to convex pieces. Invalid
  // parameters or a non-convex enclosing freespace are bad input: rearm::Error.
  static Outcome<Diffeomorphism> try_build(const MappedSpace& m, const DiffeoParams& params,
                                           DecompositionCache& cache);

  // h, Dh, D²h at x. x must be a finite point of the freespace (not checked on this path;
  // inside an obstacle the value is defined but meaningless). No allocation.
  DiffeoEval evaluate(const Point& x, DiffeoOrder order = DiffeoOrder::kHessian) const {
    return evaluate(x, purges_.size(), order);
  }
  // The composition of the first `count` purges only (the intermediate spaces of §3.8).
  DiffeoEval evaluate(const Point& x, std::size_t count,
                      DiffeoOrder order = DiffeoOrder::kHessian) const;
  Point map(const Point& x) const { return evaluate(x, DiffeoOrder::kValue).h; }

  const ModelSpace& model() const { return model_; }
  const std::vector<Purge>& purges() const { return purges_; }
  const DiffeoParams& params() const { return params_; }

 private:
  DiffeoParams params_;
  const PthRoot* root_ = nullptr;  // s^{1/p} of the R-conjunctions (shared table of p)
  ModelSpace model_;
  std::vector<Purge> purges_;  // in composition order
};

}  // namespace rearm::reactive
