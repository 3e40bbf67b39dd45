// The diffeomorphism's construction (docs/reactive.md §3.3–3.4; the paper's reference [7]):
// purge centres, collars cut clear of every other obstacle, the purges of each component over
// its first candidate tree whose collars can all be built, and Diffeomorphism::build.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/dilation.h"
#include "reactive/diffeo_internal.h"
#include "reactive/params.h"
#include "reactive/pth_root.h"

namespace rearm::reactive {

using namespace diffeo_detail;

Diffeomorphism Diffeomorphism::build(const MappedSpace& m, const DiffeoParams& params) {
  DecompositionCache fresh;
  return build(m, params, fresh);
}

namespace {

using Eigen::Vector2d;

// Two points of adjacent pieces are the same vertex only when bit-identical (the partition
// copies input vertices), so no tolerance is needed for adjacency; this one (m) decides
// whether a piece lies inside its collar after the cuts.
constexpr double kCollarContainsTolerance = 1e-9;
// Collars are the augmented piece offset by ε with corners bevelled at ε (miter limit 1):
// the bevel lines are tangent to the round ε-dilation, so a collar reaches no farther than
// about ε from its piece (a longer miter would spread a sharp corner's switch 2ε away).
constexpr double kCollarMiterLimit = 1.0;
// Purge centres must lie at least this far (m) from the adjacency edge.
constexpr double kMinCenterDepth = 1e-9;

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

}  // namespace rearm::reactive
