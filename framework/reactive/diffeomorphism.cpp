// The purging diffeomorphism of docs/reactive.md §3 (Vasilopoulos & Koditschek, WAFR 2018;
// the paper's reference [7]). Construction: convex decomposition, trees, centres, collars
// (§3.1–3.4); evaluation: implicit functions (§3.5), switches (§3.6), deforming factors
// (§3.7) and one purge (§3.8), composed with first and second derivatives.
#include "reactive/diffeomorphism.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "core/error.h"
#include "geometry/dilation.h"
#include "geometry/partition.h"
#include "reactive/pth_root.h"

namespace rearm::reactive {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using geometry::HalfPlane;

// Shortest collar or piece edge kept as a half-plane of the implicit functions (m); shorter
// edges are clipping debris whose normals are numerically meaningless.
constexpr double kMinEdgeLength = 1e-10;
// Two points of adjacent pieces are the same vertex only when bit-identical (the partition
// copies input vertices), so no tolerance is needed for adjacency; this one (m) decides
// whether a piece lies inside its collar after the cuts.
constexpr double kCollarContainsTolerance = 1e-9;
// Points within this distance (m) of a piece count as on its boundary (σ = 1). Without it,
// the rounding of β on the boundary (~1e-15) meets a vanishing σ_γ near the corners of the
// adjacency edge, where σ = σ_γσ_β / (σ_γσ_β + 1 − σ_β) is 0/0 in the limit.
constexpr double kBoundarySnap = 1e-12;
// Collars are the augmented piece offset by ε with corners bevelled at ε (miter limit 1):
// the bevel lines are tangent to the round ε-dilation, so a collar reaches no farther than
// about ε from its piece (a longer miter would spread a sharp corner's switch 2ε away).
constexpr double kCollarMiterLimit = 1.0;
// Purge centres must lie at least this far (m) from the adjacency edge.
constexpr double kMinCenterDepth = 1e-9;

// A scalar function with gradient and Hessian at one point.
struct Scalar2 {
  double v = 0;
  Vector2d g = Vector2d::Zero();
  Matrix2d H = Matrix2d::Zero();
};

double ipow(double x, int k) {
  double r = 1;
  while (k > 0) {
    if (k & 1) r *= x;
    x *= x;
    k >>= 1;
  }
  return r;
}

// R-conjunction (§3.5) a ∧ b = a + b − (a^p + b^p)^{1/p} of inside-positive linear functions
// l_k(y) = offset_k − normal_k·y, folded left to right, with gradient and Hessian. Evaluated
// scaled by m = max(|a|, |b|) so that no power under- or overflows.
// R-conjunction of the negated half-plane values, to order O (the value alone, with the
// gradient, or with the Hessian too; the value and gradient are the same whichever).
template <DiffeoOrder O>
Scalar2 r_conjunction(const std::vector<HalfPlane>& planes, const Point& y, const PthRoot& root) {
  const int p = root.p();
  constexpr bool kGradient = O != DiffeoOrder::kValue;
  constexpr bool kHessian = O == DiffeoOrder::kHessian;
  Scalar2 acc;
  acc.v = -planes.front().value(y);
  if constexpr (kGradient) acc.g = -planes.front().normal;
  for (std::size_t k = 1; k < planes.size(); ++k) {
    const double b = -planes[k].value(y);
    const double a = acc.v;
    const double m = std::max(std::abs(a), std::abs(b));
    if (m == 0) {  // a corner point exactly: value 0, gradient of the sum (not differentiable)
      if constexpr (kGradient) acc.g += -planes[k].normal;
      continue;
    }
    // One of a/m, b/m is ±1 exactly, whose even power p − 2 is 1: only the other is raised.
    const bool a_is_max = std::abs(a) >= std::abs(b);
    const double as = a_is_max ? std::copysign(1.0, a) : a / m;
    const double bs = a_is_max ? b / m : std::copysign(1.0, b);
    const double ap2 = a_is_max ? 1.0 : ipow(as, p - 2);
    const double bp2 = a_is_max ? ipow(bs, p - 2) : 1.0;
    const double ap1 = ap2 * as, bp1 = bp2 * bs;
    const double s = ap1 * as + bp1 * bs;  // in [1, 2]
    const double t = root(s);
    if constexpr (kGradient) {
      const Vector2d bg = -planes[k].normal;
      const double t1 = t / s;  // s^{1/p − 1}
      const double ra = 1 - ap1 * t1;
      const double rb = 1 - bp1 * t1;
      if constexpr (kHessian) {
        const double t2 = t1 / s;  // s^{1/p − 2}
        const double c = (p - 1) / m;
        const double raa = c * (-ap2 * t1 + ap1 * ap1 * t2);
        const double rbb = c * (-bp2 * t1 + bp1 * bp1 * t2);
        const double rab = c * ap1 * bp1 * t2;
        const Matrix2d H = raa * acc.g * acc.g.transpose() +
                           rab * (acc.g * bg.transpose() + bg * acc.g.transpose()) +
                           rbb * bg * bg.transpose() + ra * acc.H;
        acc.H = H;
      }
      acc.g = ra * acc.g + rb * bg;
    }
    acc.v = a + b - m * t;
  }
  return acc;
}

// Is some half-plane's value at y at least eps (y that far outside one edge line)?
bool beyond_collar(const std::vector<HalfPlane>& planes, const Point& y, double eps) {
  return std::any_of(planes.begin(), planes.end(),
                     [&](const HalfPlane& h) { return h.value(y) >= eps; });
}

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

struct Node {
  int piece = -1;
  int parent = -1;
  int depth = 0;
  int edge = -1;  // index of the adjacency (or lid) edge v0→v1 in the piece's own order
};

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

// One component's tree (§3.2): pieces, nodes, and the purge order (deepest first, root last).
struct Tree {
  std::vector<Polygon> pieces;
  std::vector<Node> nodes;
  std::vector<int> order;
};

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

}  // namespace

// Candidate trees by component (exact vertices, lid, curvature and sliver area). Entries are
// shared so that a build keeps its components' candidates when the cache is emptied midway.
struct DecompositionCache::Impl {
  std::vector<std::shared_ptr<Candidates>> entries;

  std::shared_ptr<Candidates> trees(const FamiliarComponent& c, double sliver_area) {
    for (const std::shared_ptr<Candidates>& e : entries) {
      if (e->comp.curved == c.curved && e->sliver_area == sliver_area && e->comp.lid == c.lid &&
          e->comp.polygon.vertices == c.polygon.vertices) {
        return e;
      }
    }
    if (entries.size() >= kDecompositionCacheEntries) entries.clear();
    entries.push_back(std::make_shared<Candidates>(candidate_trees(c, sliver_area)));
    return entries.back();
  }
};

DecompositionCache::DecompositionCache() : impl_(std::make_unique<Impl>()) {}
DecompositionCache::~DecompositionCache() = default;
DecompositionCache::DecompositionCache(DecompositionCache&&) noexcept = default;
DecompositionCache& DecompositionCache::operator=(DecompositionCache&&) noexcept = default;
std::size_t DecompositionCache::size() const { return impl_ ? impl_->entries.size() : 0; }

Diffeomorphism Diffeomorphism::build(const MappedSpace& m, const DiffeoParams& params) {
  DecompositionCache fresh;
  return build(m, params, fresh);
}

namespace {

// Convex obstacles a collar must avoid (§3.4): pieces of the other components (tagged by their
// component), unknown fragments and movable objects (circumscribed polygons, supersets of the
// disks).
struct Blocker {
  int component;  // -1: not familiar
  const Polygon* poly;
};

// What building the purges of one component reads.
struct PurgeBuild {
  const MappedSpace& m;
  const DiffeoParams& params;
  const std::vector<Blocker>& blockers;
};

// The edges of a piece around its adjacency edge `edge` (v0 -> v1), with the half-planes of the
// piece's edges next to it (extended beyond it): the centre keeps A convex inside them.
struct Adjacency {
  Point v0, v1, mid;
  HalfPlane h_prev, h_next;
};

Adjacency adjacency(const Polygon& piece, int edge) {
  const std::size_t s = piece.size();
  const std::size_t e = static_cast<std::size_t>(edge);
  const Point v0 = piece.vertices[e];
  const Point v1 = piece.vertices[(e + 1) % s];
  const Point vp = piece.vertices[(e + s - 1) % s];
  const Point vn = piece.vertices[(e + 2) % s];
  return Adjacency{v0, v1, (v0 + v1) / 2, geometry::left_of(vp, v0), geometry::left_of(v1, vn)};
}

// §3.3: ray from the piece vertex farthest from the adjacency edge through its midpoint into the
// (admissible part of the) parent; the centre halfway to the exit.
Outcome<Point> child_center(const Polygon& piece, const Polygon& parent, const Adjacency& a,
                            std::size_t ci) {
  const Vector2d t = (a.v1 - a.v0).normalized();
  const Vector2d inward(-t.y(), t.x());  // into the piece (left of v0→v1)
  Point far = piece.vertices.front();
  for (const Point& v : piece.vertices) {
    if ((v - a.v0).dot(inward) > (far - a.v0).dot(inward)) far = v;
  }
  const Vector2d dir = (a.mid - far).normalized();
  const Polygon admissible = geometry::clip(geometry::clip(parent, a.h_prev), a.h_next);
  const auto iv = geometry::line_interval(admissible, a.mid, dir);
  if (!iv || iv->hi <= kMinCenterDepth) {
    return Failure{
        "diffeomorphism: no admissible purge centre for a convex piece of familiar component " +
        std::to_string(ci)};
  }
  return Point(a.mid + (iv->hi / 2) * dir);
}

// Is the line of the half-plane through the lid's midpoint (the lid's own edge of F_e)?
bool on_line(const HalfPlane& h, const Point& mid) {
  return std::abs(h.value(mid)) <= 1e-9 * h.normal.norm();
}

// §3.3: boundary-touching root; the centre just outside ∂F_e beyond the lid, close enough that
// it stays inside every other edge of F_e and keeps A convex.
Point boundary_root_center(const Adjacency& a, const Polygon& enclosing,
                           const DiffeoParams& params) {
  const Vector2d t = (a.v1 - a.v0).normalized();
  const Vector2d out(t.y(), -t.x());
  double delta = params.boundary_center_offset;
  auto limit = [&](const HalfPlane& h) {
    const double along = h.normal.dot(out);
    const double room = -h.value(a.mid);
    if (along > 0 && room > kMinCenterDepth * h.normal.norm()) {
      delta = std::min(delta, 0.5 * room / along);
    }
  };
  limit(a.h_prev);
  limit(a.h_next);
  for (std::size_t e = 0, ne = enclosing.size(); e < ne; ++e) {
    const HalfPlane h = geometry::left_of(enclosing.vertices[e], enclosing.vertices[(e + 1) % ne]);
    if (on_line(h, a.mid)) continue;  // the lid's edge
    limit(h);
  }
  return a.mid + delta * out;
}

// §3.4: the collar of a child or boundary root: the augmented polygon A offset by ε, cut at the
// centre's two edges, and clipped to F_e (a boundary root's collar crosses its lid to reach c,
// γ(c) = 0).
Polygon attached_collar(const Polygon& shape, const Purge& pu, const Adjacency& a,
                        const Polygon& enclosing, double epsilon) {
  Polygon collar = geometry::offset_convex(shape, epsilon, kCollarMiterLimit);
  collar = geometry::clip(collar, geometry::left_of(a.v0, pu.center));
  collar = geometry::clip(collar, geometry::left_of(pu.center, a.v1));
  for (std::size_t e = 0, ne = enclosing.size(); e < ne; ++e) {
    const HalfPlane h = geometry::left_of(enclosing.vertices[e], enclosing.vertices[(e + 1) % ne]);
    if (pu.kind == Purge::Kind::kBoundaryRoot && on_line(h, a.mid)) continue;
    collar = geometry::clip(collar, h);
  }
  return collar;
}

// §3.4: the collar avoids every obstacle in `present`: each overlapping one is cut off by a line
// separating it from A; the collar must still contain the piece. The cut collar, or why there
// is none.
Outcome<Polygon> avoid(Polygon collar, const Polygon& shape, const Polygon& piece,
                       const std::vector<const Polygon*>& present, std::size_t ci) {
  for (const Polygon* blocker : present) {
    if (!geometry::convex_overlap(collar, *blocker)) continue;
    const auto cut = geometry::separating_half_plane(shape, *blocker, 1e-9);
    if (!cut) {
      return Failure{"diffeomorphism: a convex piece of familiar component " + std::to_string(ci) +
                     " overlaps another obstacle; obstacles must be consolidated first"};
    }
    collar = geometry::clip(collar, *cut);
  }
  for (const Point& v : piece.vertices) {
    if (!geometry::convex_contains(collar, v, kCollarContainsTolerance)) {
      return Failure{"diffeomorphism: the collar of a convex piece of familiar component " +
                     std::to_string(ci) + " cannot contain the piece (touching obstacles?)"};
    }
  }
  return collar;
}

// §3.3: free root: c = vertex mean, model disk of radius 0.8·dist(c, ∂root); its collar is the
// piece offset by ε within F_e.
Polygon free_root(Purge& pu, const Polygon& piece, const Polygon& enclosing,
                  const DiffeoParams& params) {
  Point c = Point::Zero();
  for (const Point& v : piece.vertices) c += v;
  c /= static_cast<double>(piece.size());
  double dist = std::numeric_limits<double>::infinity();
  for (const HalfPlane& h : edge_planes(piece)) dist = std::min(dist, -h.value(c));
  pu.kind = Purge::Kind::kDiskRoot;
  pu.center = c;
  pu.radius = params.root_radius_fraction * dist;
  return geometry::intersect_convex(
      geometry::offset_convex(piece, params.epsilon, kCollarMiterLimit), enclosing);
}

// The purge of piece k (the i-th in purge order) of component ci over `tree` (§3.3–3.7);
// first_purge is the index of the component's first purge. A failure when a centre or a collar
// cannot be built (the caller tries the component's next candidate tree).
Outcome<Purge> purge_of(const PurgeBuild& b, std::size_t ci, const Tree& tree,
                        const std::vector<int>& rank, int i, int first_purge,
                        std::vector<Disk>& disks) {
  const int k = tree.order[i];
  const Node& node = tree.nodes[k];
  const Polygon& piece = tree.pieces[k];
  const Polygon& enclosing = b.m.enclosing;
  Purge pu;
  pu.component = static_cast<int>(ci);
  pu.depth = node.depth;
  pu.piece = piece;
  pu.epsilon = b.params.epsilon;
  Polygon shape = piece;  // the augmented polygon A (§3.4)
  Polygon collar;
  if (node.parent >= 0 || b.m.familiar[ci].lid) {
    const Adjacency a = adjacency(piece, node.edge);
    if (node.parent >= 0) {
      const Outcome<Point> center = child_center(piece, tree.pieces[node.parent], a, ci);
      if (!center) return Failure{center.reason()};
      pu.center = *center;
      pu.kind = Purge::Kind::kChild;
      pu.parent = first_purge + rank[node.parent];
    } else {
      pu.center = boundary_root_center(a, enclosing, b.params);
      pu.kind = Purge::Kind::kBoundaryRoot;
    }
    pu.v0 = a.v0;
    pu.v1 = a.v1;
    shape = augmented(piece, node.edge, pu.center);
    collar = attached_collar(shape, pu, a, enclosing, b.params.epsilon);
  } else {
    collar = free_root(pu, piece, enclosing, b.params);
    disks.push_back(Disk{pu.center, pu.radius});
  }
  // Obstacles still present when this piece is purged: later pieces of its component except
  // its parent, every other component, unknown and movable obstacles.
  std::vector<const Polygon*> present;
  for (int j = 0, n = static_cast<int>(tree.pieces.size()); j < n; ++j) {
    if (j != k && j != node.parent && rank[j] > i) present.push_back(&tree.pieces[j]);
  }
  for (const Blocker& blocker : b.blockers) {
    if (blocker.component != static_cast<int>(ci)) present.push_back(blocker.poly);
  }
  Outcome<Polygon> cut = avoid(std::move(collar), shape, piece, present, ci);
  if (!cut) return Failure{cut.reason()};
  pu.collar = std::move(*cut);
  pu.beta_planes = edge_planes(piece);
  pu.gamma_planes = edge_planes(pu.collar);
  pu.collar_box = Eigen::AlignedBox2d();
  for (const Point& v : pu.collar.vertices) pu.collar_box.extend(v);
  return pu;
}

// The purges of component ci over one candidate tree, in purge order, or why one of them cannot
// be built.
Outcome<std::vector<Purge>> purges_of(const PurgeBuild& b, std::size_t ci, const Tree& tree,
                                      int first_purge, std::vector<Disk>& disks) {
  const int n = static_cast<int>(tree.pieces.size());
  std::vector<int> rank(n);
  for (int i = 0; i < n; ++i) rank[tree.order[i]] = i;
  std::vector<Purge> out;
  for (int i = 0; i < n; ++i) {
    Outcome<Purge> pu = purge_of(b, ci, tree, rank, i, first_purge, disks);
    if (!pu) return Failure{pu.reason()};
    out.push_back(std::move(*pu));
  }
  return out;
}

}  // namespace

Diffeomorphism Diffeomorphism::build(const MappedSpace& m, const DiffeoParams& params,
                                     DecompositionCache& cache) {
  return try_build(m, params, cache).or_throw();
}

Outcome<Diffeomorphism> Diffeomorphism::try_build(const MappedSpace& m, const DiffeoParams& params,
                                                  DecompositionCache& cache) {
  if (!cache.impl_) cache.impl_ = std::make_unique<DecompositionCache::Impl>();  // moved from
  validate(params);
  if (m.enclosing.size() < 3 || !m.enclosing.is_convex()) {
    throw Error(
        "diffeomorphism: the enclosing freespace must be a convex counter-clockwise polygon");
  }
  Diffeomorphism d;
  d.params_ = params;
  d.root_ = &PthRoot::of(params.p);
  d.model_.boundary = m.enclosing;
  d.model_.convex = m.unknown;

  // §3.1–3.2: convex decompositions of every component (slivers dropped) with their trees,
  // in order of preference: cuts along reflex-vertex extensions (rectangles for orthogonal
  // shapes, no sharp angles), with flat corners split if needed; CGAL's partition (fewest
  // pieces), likewise; a triangulation (no flat corners at all). A curved component (one that
  // merges a movable disk or an unknown obstacle, FamiliarComponent::curved) takes the fewest
  // pieces first instead: the reflex vertices along its arcs make extension cuts leave
  // slivers, and purging a large piece into a sliver's centre drives det Dh towards 0 (the
  // robot then turns in place, or Dh is singular). The first candidate whose collars can all
  // be built (§3.4) is used.
  std::vector<std::shared_ptr<Candidates>> candidates(m.familiar.size());
  std::vector<std::vector<Polygon>> pieces(m.familiar.size());
  for (std::size_t ci = 0; ci < m.familiar.size(); ++ci) {
    const FamiliarComponent& comp = m.familiar[ci];
    candidates[ci] = cache.impl_->trees(comp, params.sliver_area);
    const Tree* first = candidates[ci]->at(0);
    if (first == nullptr) {
      if (comp.polygon.area() <= params.sliver_area) continue;  // a sliver: nothing to purge
      return Failure{"diffeomorphism: familiar component " + std::to_string(ci) +
                     " admits no purging tree (its convex pieces are not edge-connected)"};
    }
    pieces[ci] = first->pieces;  // what other components' collars avoid
  }

  std::vector<Polygon> extra;
  for (const Disk& disk : m.movable) extra.push_back(geometry::disk_polygon(disk));
  std::vector<Blocker> blockers;
  for (std::size_t ci = 0; ci < pieces.size(); ++ci) {
    for (const Polygon& p : pieces[ci]) blockers.push_back({static_cast<int>(ci), &p});
  }
  for (const Polygon& u : m.unknown) blockers.push_back({-1, &u});
  for (const Polygon& e : extra) blockers.push_back({-1, &e});

  // Each component over its first candidate tree whose purges can all be built.
  const PurgeBuild b{m, params, blockers};
  std::vector<Disk> root_disks;
  for (std::size_t ci = 0; ci < candidates.size(); ++ci) {
    std::string failure;
    bool built = false;
    const Tree* tree = nullptr;
    for (std::size_t k = 0; (tree = candidates[ci]->at(k)) != nullptr; ++k) {
      std::vector<Disk> disks;
      Outcome<std::vector<Purge>> purges =
          purges_of(b, ci, *tree, static_cast<int>(d.purges_.size()), disks);
      if (!purges) {
        failure = purges.reason();
        continue;
      }
      d.purges_.insert(d.purges_.end(), std::make_move_iterator(purges->begin()),
                       std::make_move_iterator(purges->end()));
      root_disks.insert(root_disks.end(), disks.begin(), disks.end());
      built = true;
      break;
    }
    if (!built && candidates[ci]->at(0) != nullptr) return Failure{failure};
  }
  d.model_.disks = root_disks;
  d.model_.disks.insert(d.model_.disks.end(), m.movable.begin(), m.movable.end());
  return d;
}

namespace {

// The switch σ of one purge (§3.6) at y with its derivatives to order O, from β (negated: below
// zero inside the piece, 0 < β < ε in the collar) and γ > 0.
struct Switch {
  double sigma = 0;
  Vector2d d = Vector2d::Zero();
  Matrix2d dd = Matrix2d::Zero();
};

template <DiffeoOrder O>
Switch switch_of(const Purge& pu, const Point& y, const Scalar2& beta, const Scalar2& gamma,
                 const DiffeoParams& prm) {
  const double eps = prm.epsilon, mu1 = prm.mu1, mu2 = prm.mu2;
  // σ_β = exp(−μ1/(ε−β)) / exp(−μ1/ε); 1 − σ_β by expm1 to keep it accurate near β = 0.
  const double q = eps - beta.v;
  const double expo = -mu1 * beta.v / (eps * q);  // −μ1/(ε−β) + μ1/ε
  const double sb = std::exp(expo);
  const double one_minus_sb = -std::expm1(expo);
  // σ_γ = exp(−μ2/α), α = γ/‖y − c‖.
  const Vector2d w = y - pu.center;
  const double r = w.norm();
  const double alpha = gamma.v / r;
  const double sg = std::exp(-mu2 / alpha);
  // σ = σ_γσ_β / (σ_γσ_β + 1 − σ_β), with u = σ_γ, b = σ_β.
  const double u = sg, b = sb;
  const double den = u * b + one_minus_sb;
  Switch out;
  out.sigma = u * b / den;
  if constexpr (O == DiffeoOrder::kValue) return out;
  const double sb1 = -mu1 * sb / (q * q);
  const Vector2d gb = sb1 * beta.g;
  const Vector2d dr = w / r;
  const Vector2d dalpha = gamma.g / r - gamma.v * dr / (r * r);
  const double sg1 = mu2 * sg / (alpha * alpha);
  const Vector2d gg = sg1 * dalpha;
  const double su = b * one_minus_sb / (den * den);
  const double sbb_ = u / (den * den);
  out.d = su * gg + sbb_ * gb;
  if constexpr (O == DiffeoOrder::kHessian) {
    const double sb2 = sb * (mu1 * mu1 / (q * q * q * q) - 2 * mu1 / (q * q * q));
    const Matrix2d Hb = sb2 * beta.g * beta.g.transpose() + sb1 * beta.H;
    const Matrix2d ddr = (Matrix2d::Identity() - dr * dr.transpose()) / r;
    const Matrix2d ddalpha =
        gamma.H / r - (gamma.g * dr.transpose() + dr * gamma.g.transpose()) / (r * r) +
        2 * gamma.v * dr * dr.transpose() / (r * r * r) - gamma.v * ddr / (r * r);
    const double sg2 = sg * (mu2 * mu2 / std::pow(alpha, 4) - 2 * mu2 / std::pow(alpha, 3));
    const Matrix2d Hg = sg2 * dalpha * dalpha.transpose() + sg1 * ddalpha;
    const double suu = -2 * b * b * one_minus_sb / (den * den * den);
    const double sbb2 = -2 * u * (u - 1) / (den * den * den);
    const double sub =
        (1 - 2 * b) / (den * den) - 2 * b * one_minus_sb * (u - 1) / (den * den * den);
    out.dd = suu * gg * gg.transpose() + sub * (gg * gb.transpose() + gb * gg.transpose()) +
             sbb2 * gb * gb.transpose() + su * Hg + sbb_ * Hb;
  }
  return out;
}

// §3.7: the deforming factor ν (homogeneous of degree −1 in w = y − c) to order O.
struct Factor {
  double nu = 0;
  Vector2d d = Vector2d::Zero();
  Matrix2d dd = Matrix2d::Zero();
};

template <DiffeoOrder O>
Factor factor_of(const Purge& pu, const Vector2d& w) {
  Factor out;
  if (pu.kind == Purge::Kind::kDiskRoot) {
    const double r = w.norm();
    out.nu = pu.radius / r;
    if constexpr (O != DiffeoOrder::kValue) out.d = -pu.radius * w / (r * r * r);
    if constexpr (O == DiffeoOrder::kHessian) {
      out.dd = 3 * pu.radius * w * w.transpose() / std::pow(r, 5) -
               pu.radius / (r * r * r) * Matrix2d::Identity();
    }
  } else {
    const Vector2d t = (pu.v1 - pu.v0).normalized();
    const Vector2d n(-t.y(), t.x());
    const double num = (pu.v0 - pu.center).dot(n);
    const double den = w.dot(n);
    out.nu = num / den;
    if constexpr (O != DiffeoOrder::kValue) out.d = -num / (den * den) * n;
    if constexpr (O == DiffeoOrder::kHessian)
      out.dd = 2 * num / (den * den * den) * n * n.transpose();
  }
  return out;
}

// §3.8: h_i(y) = y + f(y)(y − c), f = σ(ν − 1), composed onto `out` (h, Dh and D²h of the
// purges before it) by the chain rule, to order O.
template <DiffeoOrder O>
void compose(DiffeoEval& out, const Vector2d& w, const Switch& sw, const Factor& fa) {
  const double f = sw.sigma * (fa.nu - 1);
  if constexpr (O != DiffeoOrder::kValue) {
    const Vector2d df = (fa.nu - 1) * sw.d + sw.sigma * fa.d;
    const Matrix2d Ji = (1 + f) * Matrix2d::Identity() + w * df.transpose();
    if constexpr (O == DiffeoOrder::kHessian) {
      const Matrix2d ddf = (fa.nu - 1) * sw.dd + sw.d * fa.d.transpose() + fa.d * sw.d.transpose() +
                           sw.sigma * fa.dd;
      std::array<Matrix2d, 2> Hi;
      for (int k = 0; k < 2; ++k) {
        Hi[k] = w[k] * ddf;
        Hi[k].row(k) += df.transpose();
        Hi[k].col(k) += df;
      }
      // Chain rule: D²(h_i ∘ g)[k] = Jgᵀ Hi[k] Jg + Σ_a Ji(k, a) Hg[a].
      std::array<Matrix2d, 2> H;
      for (int k = 0; k < 2; ++k) {
        H[k] = out.J.transpose() * Hi[k] * out.J + Ji(k, 0) * out.H[0] + Ji(k, 1) * out.H[1];
      }
      out.H = H;
    }
    out.J = Ji * out.J;
  }
  out.h = out.h + f * w;
}

template <DiffeoOrder O>
DiffeoEval evaluate_to(const std::vector<Purge>& purges, const DiffeoParams& prm,
                       const PthRoot& root, const Point& x, std::size_t count) {
  DiffeoEval out;
  out.h = x;
  count = std::min(count, purges.size());
  for (std::size_t index = 0; index < count; ++index) {
    const Purge& pu = purges[index];
    const Point y = out.h;
    if (!pu.collar_box.contains(y)) continue;  // identity outside the collar (σ = 0)
    // The R-conjunction lies below each of its arguments (a + b − ‖(a, b)‖_p <= min(a, b)), so
    // β >= max_i of the half-plane values: at least ε there, and σ_β = 0 without evaluating it.
    if (beyond_collar(pu.beta_planes, y, prm.epsilon)) continue;
    // §3.5–3.6: β (negative inside the piece) and its switch.
    Scalar2 beta = r_conjunction<O>(pu.beta_planes, y, root);
    beta.v = -beta.v;
    beta.g = -beta.g;
    beta.H = -beta.H;
    if (beta.v >= prm.epsilon) continue;
    Switch sw;
    if (beta.v <= kBoundarySnap) {
      sw.sigma = 1;  // on or inside the piece: fully purged (its interior is not freespace)
    } else {
      const Scalar2 gamma = r_conjunction<O>(pu.gamma_planes, y, root);
      if (gamma.v <= 0) continue;
      sw = switch_of<O>(pu, y, beta, gamma, prm);
    }
    const Vector2d w = y - pu.center;
    compose<O>(out, w, sw, factor_of<O>(pu, w));
  }
  return out;
}

}  // namespace

DiffeoEval Diffeomorphism::evaluate(const Point& x, std::size_t count, DiffeoOrder order) const {
  // A default-constructed Diffeomorphism (no purges) has no table yet.
  const PthRoot& root = root_ ? *root_ : PthRoot::of(params_.p);
  switch (order) {
    case DiffeoOrder::kValue:
      return evaluate_to<DiffeoOrder::kValue>(purges_, params_, root, x, count);
    case DiffeoOrder::kJacobian:
      return evaluate_to<DiffeoOrder::kJacobian>(purges_, params_, root, x, count);
    case DiffeoOrder::kHessian:
      break;
  }
  return evaluate_to<DiffeoOrder::kHessian>(purges_, params_, root, x, count);
}

}  // namespace rearm::reactive
