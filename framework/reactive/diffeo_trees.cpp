// Convex decompositions and purging trees of the familiar components (docs/reactive.md
// §3.1–3.2; the paper's reference [7]), and the cache of a component's candidate trees.
#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/partition.h"
#include "reactive/diffeo_internal.h"

namespace rearm::reactive {
namespace diffeo_detail {

using Eigen::Vector2d;

// Shortest collar or piece edge kept as a half-plane of the implicit functions (m); shorter
// edges are clipping debris whose normals are numerically meaningless.
constexpr double kMinEdgeLength = 1e-10;

// Half-planes (unit normals) of a convex counter-clockwise polygon's edges.
std::vector<HalfPlane> edge_planes(const Polygon& poly) {
  std::vector<HalfPlane> out;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Point& a = poly.vertices[i];
    const Point& b = poly.vertices[(i + 1) % n];
    const double len = (b - a).norm();
    if (len < kMinEdgeLength) continue;
    HalfPlane h = geometry::left_of(a, b);
    h.normal /= len;
    h.offset /= len;
    if (!out.empty() && (out.back().normal - h.normal).norm() < 1e-12 &&
        std::abs(out.back().offset - h.offset) < 1e-12) {
      continue;  // collinear continuation: the same half-plane
    }
    out.push_back(h);
  }
  return out;
}

bool same_edge(const Point& a, const Point& b, const Point& p, const Point& q) {
  return (a == p && b == q) || (a == q && b == p);
}

// Index of the edge (i, i+1) of poly equal to {a, b}, or -1.
int find_edge(const Polygon& poly, const Point& a, const Point& b) {
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    if (same_edge(poly.vertices[i], poly.vertices[(i + 1) % n], a, b)) return static_cast<int>(i);
  }
  return -1;
}

// The piece's vertices with c inserted after edge e's start: [.., v0, c, v1, ..].
Polygon augmented(const Polygon& piece, int e, const Point& c) {
  Polygon a;
  const std::size_t n = piece.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (static_cast<std::size_t>(e) + 1 + k) % n;  // start at v1
    a.vertices.push_back(piece.vertices[i]);
  }
  a.vertices.push_back(c);  // after v0 (the last one pushed), before v1 (the first)
  return a;
}

// A piece's corners at the ends of its edge e are strictly convex (sine of the turn above
// this), so a centre beyond the edge keeps the augmented polygon convex (§3.3).
constexpr double kMinCornerSine = 1e-9;

// Sine of the turn a → b → c (positive to the left).
double turn_sine(const Point& a, const Point& b, const Point& c) {
  const Vector2d u = b - a, w = c - b;
  return (u.x() * w.y() - u.y() * w.x()) / (u.norm() * w.norm());
}

bool corners_convex(const Polygon& piece, int e) {
  const std::size_t s = piece.size();
  const Point& vp = piece.vertices[(e + s - 1) % s];
  const Point& v0 = piece.vertices[e];
  const Point& v1 = piece.vertices[(e + 1) % s];
  const Point& vn = piece.vertices[(e + 2) % s];
  return turn_sine(vp, v0, v1) > kMinCornerSine && turn_sine(v0, v1, vn) > kMinCornerSine;
}

// A vertex of the component lying on a piece's edge (a T-junction left by a partition that
// dropped a 180° vertex) is inserted into that edge, so that adjacent pieces share whole,
// bit-identical edges. Relative collinearity tolerance:
constexpr double kJunctionTolerance = 1e-9;

void insert_junctions(std::vector<Polygon>& pieces, const std::vector<Point>& points) {
  // The points by x, so that each edge tests only those in its x-range: a point within the
  // collinearity tolerance of an edge (a, b) strictly between its ends lies within
  // kJunctionTolerance·|b − a| of the segment, hence of its x-range (twice that, and a
  // rounding margin, are searched). Candidates are taken in the points' own order.
  std::vector<std::size_t> by_x(points.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(),
            [&](std::size_t l, std::size_t r) { return points[l].x() < points[r].x(); });
  std::vector<double> xs(by_x.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) xs[i] = points[by_x[i]].x();
  std::vector<std::size_t> near;
  std::vector<std::pair<double, Point>> on_edge;
  for (Polygon& piece : pieces) {
    std::vector<Point> out;
    const std::size_t n = piece.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = piece.vertices[i];
      const Point& b = piece.vertices[(i + 1) % n];
      out.push_back(a);
      const Vector2d d = b - a;
      const double len2 = d.squaredNorm();
      const double margin = 2 * kJunctionTolerance * std::sqrt(len2) +
                            1e-12 * (std::abs(a.x()) + std::abs(b.x()) + 1);
      const auto lo = std::lower_bound(xs.begin(), xs.end(), std::min(a.x(), b.x()) - margin);
      const auto hi = std::upper_bound(lo, xs.end(), std::max(a.x(), b.x()) + margin);
      near.assign(by_x.begin() + (lo - xs.begin()), by_x.begin() + (hi - xs.begin()));
      std::sort(near.begin(), near.end());
      on_edge.clear();
      for (std::size_t k : near) {
        const Point& v = points[k];
        if (v == a || v == b) continue;
        const Vector2d w = v - a;
        const double t = w.dot(d) / len2;
        if (t <= 0 || t >= 1) continue;
        if (std::abs(d.x() * w.y() - d.y() * w.x()) <= kJunctionTolerance * len2) {
          on_edge.emplace_back(t, v);
        }
      }
      std::sort(on_edge.begin(), on_edge.end(),
                [](const auto& l, const auto& r) { return l.first < r.first; });
      for (const auto& [t, v] : on_edge) out.push_back(v);
    }
    piece.vertices = std::move(out);
  }
}

std::vector<Point> all_vertices(const std::vector<Polygon>& pieces) {
  std::vector<Point> out;
  for (const Polygon& p : pieces) out.insert(out.end(), p.vertices.begin(), p.vertices.end());
  std::sort(out.begin(), out.end(), [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A piece whose side runs straight on past the end v of an edge it shares with a neighbour
// (a flat corner, as a T's bar under its stem) cannot be that neighbour's child. Such a piece
// is cut by the line through v that continues the neighbour's other edge at v (the stem's
// side), which leaves convex pieces sharing whole edges and corners that are not flat. Rounds
// of cuts repeat until no flat corner is left at a shared edge (bounded); Steiner points of the
// cuts are inserted into the edges they split.
constexpr int kMaxSplitRounds = 16;

std::vector<Polygon> split_flat_corners(std::vector<Polygon> P, double sliver_area) {
  for (int round = 0; round < kMaxSplitRounds; ++round) {
    bool cut = false;
    for (std::size_t x = 0; x < P.size() && !cut; ++x) {
      const std::size_t n = P[x].size();
      for (std::size_t i = 0; i < n && !cut; ++i) {
        const Point& prev = P[x].vertices[(i + n - 1) % n];
        const Point& v = P[x].vertices[i];
        const Point& next = P[x].vertices[(i + 1) % n];
        if (std::abs(turn_sine(prev, v, next)) > kMinCornerSine) continue;
        // A neighbour y sharing the edge (v, prev) or (v, next) with x.
        for (std::size_t y = 0; y < P.size() && !cut; ++y) {
          if (y == x) continue;
          const int e1 = find_edge(P[y], v, prev);
          const int e2 = find_edge(P[y], v, next);
          if (e1 < 0 && e2 < 0) continue;
          const Point& w = e1 >= 0 ? prev : next;  // the shared edge is (v, w)
          const std::size_t m = P[y].size();
          std::size_t j = 0;
          while (P[y].vertices[j] != v) ++j;
          const Point& a = P[y].vertices[(j + m - 1) % m];
          const Point& b = P[y].vertices[(j + 1) % m];
          const Point u = (a == w) ? b : a;  // y's other neighbour of v
          const Vector2d d = v - u;
          if (d.norm() <= 0) continue;
          const geometry::HalfPlane h{Vector2d(-d.y(), d.x()), Vector2d(-d.y(), d.x()).dot(v)};
          Polygon left = geometry::clip(P[x], h);
          Polygon right = geometry::clip(P[x], geometry::HalfPlane{-h.normal, -h.offset});
          if (left.area() <= sliver_area || right.area() <= sliver_area) continue;
          P[x] = std::move(left);
          P.push_back(std::move(right));
          cut = true;
        }
      }
    }
    if (!cut) break;
    insert_junctions(P, all_vertices(P));
  }
  return P;
}

// Breadth-first tree of the pieces from `root` (root_edge: its lid, or -1). Fails (nullopt)
// when the pieces are not edge-connected, or some child (or the boundary root) has a flat
// corner at its adjacency edge: a convex partition may leave a piece whose side runs on past
// the edge it shares (a T-junction); that piece must be the parent of that adjacency.
std::optional<Tree> plan_tree(const std::vector<Polygon>& P, int root, int root_edge) {
  const int n = static_cast<int>(P.size());
  Tree t;
  t.nodes.assign(n, Node{});
  std::vector<bool> seen(n, false);
  std::deque<int> queue{root};
  seen[root] = true;
  t.nodes[root] = Node{root, -1, 0, root_edge};
  if (root_edge >= 0 && !corners_convex(P[root], root_edge)) return std::nullopt;
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop_front();
    t.order.push_back(u);
    for (int v = 0; v < n; ++v) {
      if (seen[v]) continue;
      for (std::size_t i = 0, s = P[v].size(); i < s; ++i) {
        const Point& a = P[v].vertices[i];
        const Point& b = P[v].vertices[(i + 1) % s];
        if (find_edge(P[u], a, b) >= 0) {
          if (!corners_convex(P[v], static_cast<int>(i))) return std::nullopt;
          seen[v] = true;
          t.nodes[v] = Node{v, u, t.nodes[u].depth + 1, static_cast<int>(i)};
          queue.push_back(v);
          break;
        }
      }
    }
  }
  if (static_cast<int>(t.order.size()) != n) return std::nullopt;
  std::reverse(t.order.begin(), t.order.end());
  t.pieces = P;
  return t;
}

// A tree over pieces P: rooted at the lid's piece (pocket) or at the largest piece that
// admits one (free component).
std::optional<Tree> choose_tree(const std::vector<Polygon>& P,
                                const std::optional<std::pair<Point, Point>>& lid) {
  if (P.empty()) return std::nullopt;
  if (lid) {
    for (int k = 0; k < static_cast<int>(P.size()); ++k) {
      const int e = find_edge(P[k], lid->first, lid->second);
      if (e >= 0) return plan_tree(P, k, e);
    }
    return std::nullopt;
  }
  std::vector<int> by_area(P.size());
  for (std::size_t k = 0; k < P.size(); ++k) by_area[k] = static_cast<int>(k);
  std::stable_sort(by_area.begin(), by_area.end(),
                   [&](int a, int b) { return P[a].area() > P[b].area(); });
  for (int root : by_area) {
    if (auto t = plan_tree(P, root, -1)) return t;
  }
  return std::nullopt;
}

// The tree over P (or over P with its flat corners split), if one exists.
std::optional<Tree> tree_over(const std::vector<Polygon>& P, const FamiliarComponent& comp,
                              double sliver_area) {
  if (P.empty()) return std::nullopt;
  if (auto t = choose_tree(P, comp.lid)) return t;
  return choose_tree(split_flat_corners(P, sliver_area), comp.lid);
}

const Tree* Candidates::at(std::size_t k) {
  if (triangulation_pending && k == triangulation_at) {
    triangulation_pending = false;
    const Outcome<std::vector<Polygon>> triangles = geometry::triangulate(comp.polygon);
    if (triangles) {  // else not simple enough to triangulate: no such candidate
      if (auto t = tree_over(*triangles, comp, sliver_area)) {
        trees.insert(trees.begin() + static_cast<std::ptrdiff_t>(k), std::move(*t));
      }
    }
  }
  return k < trees.size() ? &trees[k] : nullptr;
}

// The candidates of one component: extension cuts, then CGAL's partition, then (lazily) the
// triangulation; a curved component's fewest pieces first. The triangulation has n − 2
// triangles (no flat corners to split), which fixes its place without computing it.
Candidates candidate_trees(const FamiliarComponent& comp, double sliver_area) {
  Candidates out{comp, sliver_area, {}};
  auto usable = [&](std::vector<Polygon> raw) {
    std::vector<Polygon> kept;
    for (Polygon& p : raw) {
      if (p.area() > sliver_area) kept.push_back(std::move(p));
    }
    insert_junctions(kept, comp.polygon.vertices);
    return kept;
  };
  auto add = [&](const std::vector<Polygon>& P) {
    if (auto t = tree_over(P, comp, sliver_area)) out.trees.push_back(std::move(*t));
  };
  // Not simple enough for extension cuts (a failure): the other decompositions remain.
  if (Outcome<std::vector<Polygon>> cuts = geometry::decompose_by_extensions(comp.polygon)) {
    add(usable(std::move(*cuts)));
  }
  add(usable(geometry::convex_partition(comp.polygon)));
  out.triangulation_at = out.trees.size();
  // Curved: fewest convex pieces first (stable: the preference order above breaks ties).
  if (comp.curved) {
    std::stable_sort(out.trees.begin(), out.trees.end(), [](const Tree& a, const Tree& b) {
      return a.pieces.size() < b.pieces.size();
    });
    const std::size_t triangles = comp.polygon.size() - 2;
    out.triangulation_at = static_cast<std::size_t>(
        std::count_if(out.trees.begin(), out.trees.end(),
                      [&](const Tree& t) { return t.pieces.size() <= triangles; }));
  }
  return out;
}

}  // namespace diffeo_detail

std::shared_ptr<diffeo_detail::Candidates> DecompositionCache::Impl::trees(
    const FamiliarComponent& c, double sliver_area) {
  for (const std::shared_ptr<diffeo_detail::Candidates>& e : entries) {
    if (e->comp.curved == c.curved && e->sliver_area == sliver_area && e->comp.lid == c.lid &&
        e->comp.polygon.vertices == c.polygon.vertices) {
      return e;
    }
  }
  if (entries.size() >= kDecompositionCacheEntries) entries.clear();
  entries.push_back(
      std::make_shared<diffeo_detail::Candidates>(diffeo_detail::candidate_trees(c, sliver_area)));
  return entries.back();
}

DecompositionCache::DecompositionCache() : impl_(std::make_unique<Impl>()) {}
DecompositionCache::~DecompositionCache() = default;
DecompositionCache::DecompositionCache(DecompositionCache&&) noexcept = default;
DecompositionCache& DecompositionCache::operator=(DecompositionCache&&) noexcept = default;
std::size_t DecompositionCache::size() const { return impl_ ? impl_->entries.size() : 0; }

}  // namespace rearm::reactive
