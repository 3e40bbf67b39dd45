// The diffeomorphism's construction phases shared by its translation units (docs/reactive.md
// §3.1–3.4; the paper's reference [7]): convex pieces and their trees, a component's candidate
// trees, and the decomposition cache. Internal to framework/reactive: included only by
// diffeo_trees.cpp (decompositions and trees) and diffeo_build.cpp (centres, collars, purges
// and Diffeomorphism::build); diffeomorphism.cpp keeps the per-tick evaluation.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "reactive/diffeomorphism.h"

namespace rearm::reactive {
namespace diffeo_detail {

using geometry::HalfPlane;

// Half-planes (unit normals) of a convex counter-clockwise polygon's edges.
std::vector<HalfPlane> edge_planes(const Polygon& poly);
// The piece's vertices with c inserted after edge e's start: [.., v0, c, v1, ..].
Polygon augmented(const Polygon& piece, int e, const Point& c);

struct Node {
  int piece = -1;
  int parent = -1;
  int depth = 0;
  int edge = -1;  // index of the adjacency (or lid) edge v0→v1 in the piece's own order
};

// One component's tree (§3.2): pieces, nodes, and the purge order (deepest first, root last).
struct Tree {
  std::vector<Polygon> pieces;
  std::vector<Node> nodes;
  std::vector<int> order;
};

// A component's candidate trees (§3.1–3.2) in order of preference (see build()). The
// triangulation's tree, the last resort, is built only when every candidate before it has
// failed: ear clipping is cubic in the vertices, and curved components have hundreds.
struct Candidates {
  FamiliarComponent comp;
  double sliver_area;
  std::vector<Tree> trees;
  std::size_t triangulation_at = 0;  // where the triangulation's tree goes in `trees`
  bool triangulation_pending = true;

  // The k-th candidate, or nullptr past the last.
  const Tree* at(std::size_t k);
};

// The candidates of one component: extension cuts, then CGAL's partition, then (lazily) the
// triangulation.
Candidates candidate_trees(const FamiliarComponent& comp, double sliver_area);

}  // namespace diffeo_detail

// Candidate trees by component (exact vertices, lid, curvature and sliver area). Entries are
// shared so that a build keeps its components' candidates when the cache is emptied midway.
struct DecompositionCache::Impl {
  std::vector<std::shared_ptr<diffeo_detail::Candidates>> entries;

  std::shared_ptr<diffeo_detail::Candidates> trees(const FamiliarComponent& c, double sliver_area);
};

}  // namespace rearm::reactive
