// Localized exact Booleans of the topology check; the contract and the reasoning are in
// freespace.h. The only CGAL translation unit of framework/topology.
#include "topology/freespace.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/cgal_internal.h"

namespace rearm::topology::detail {
namespace {

using geometry::Point;
using geometry::Polygon;
using geometry::Region;
using geometry::RegionSet;
using geometry::internal::CPoint;
using geometry::internal::CPolygon;
using geometry::internal::CPolygonWithHoles;
using geometry::internal::Kernel;
using FT = Kernel::FT;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;
using Box = CGAL::Bbox_2;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Window margin (freespace.h): the window around a group of interacting obstacles is their
// bounding box grown by this fraction of its larger side. When a loop vertex lies on the
// window's boundary or a loop edge passes through one of its corners, the window is grown by
// kWindowGrowth more, and vertically by kWindowAspect more still (so a corner leaves a line
// of slope 1 through it), for kWindowTries windows in all; then the plain overlay.
constexpr double kWindowMargin = 1.0 / 16;
constexpr double kWindowGrowth = 1.5;
constexpr double kWindowAspect = 1.3;
constexpr int kWindowTries = 4;

// Closed boxes meet (touching counts).
bool meet(const Box& a, const Box& b) { return CGAL::do_overlap(a, b); }

Box box_of(const Point& a, const Point& b) {
  return Box(std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()),
             std::max(a.y(), b.y()));
}

Box box_of(const Polygon& p) {
  Box b = box_of(p.vertices.front(), p.vertices.front());
  for (const Point& v : p.vertices) b += box_of(v, v);
  return b;
}

double box_area(const Box& b) { return (b.xmax() - b.xmin()) * (b.ymax() - b.ymin()); }

// One boundary cycle of an exact region, with its boxes and its rounding.
struct Loop {
  Box box;                 // encloses the exact cycle
  std::vector<Box> edges;  // encloses each exact edge
  // The cycle rounded to doubles and cut into simple loops, as geometry::subtract returns
  // them: loops bounding material (positive area) and holes (reversed to counter-clockwise).
  std::vector<Polygon> outers;
  std::vector<Polygon> holes;
  bool pinched = false;       // two rounded vertices coincide (so possibly two exact ones)
  bool from_doubles = false;  // given in doubles (double_loop): its rounding is the cycle

  // The exact cycle, material on the left: outer counter-clockwise, hole clockwise. A loop
  // given in doubles builds it on first use (most never take part in an overlay); a Loop
  // belongs to one TopologyCache, used by one thread.
  const CPolygon& exact() const {
    if (!exact_) {
      Polygon cycle = cycle_of_doubles();
      if (!holes.empty()) std::reverse(cycle.vertices.begin(), cycle.vertices.end());
      exact_ = geometry::internal::to_cgal(cycle);
    }
    return *exact_;
  }
  void set_exact(CPolygon p) { exact_ = std::move(p); }
  // A loop given in doubles: its cycle (either orientation).
  const Polygon& cycle_of_doubles() const {
    return outers.empty() ? holes.front() : outers.front();
  }

 private:
  mutable std::optional<CPolygon> exact_;
};
using LoopPtr = std::shared_ptr<const Loop>;

// An exact region: its outer boundary and holes, cycles that meet at most at points (CGAL
// returns a hole touching the outer cycle at a vertex as a separate cycle).
struct Piece {
  LoopPtr outer;
  std::vector<LoopPtr> holes;
};

bool has_duplicates(std::vector<Point> v) {
  std::sort(v.begin(), v.end(), [](const Point& a, const Point& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  return std::adjacent_find(v.begin(), v.end()) != v.end();
}

void split_rounded(std::vector<Polygon> loops, Loop& l) {
  for (Polygon& loop : loops) {
    if (loop.signed_area() > 0) {
      l.outers.push_back(std::move(loop));
    } else {
      std::reverse(loop.vertices.begin(), loop.vertices.end());
      l.holes.push_back(std::move(loop));
    }
  }
}

// geometry::internal::from_cgal without building the coordinates as lazy numbers: CGAL's
// to_double of a lazy number, applied to the point's own interval approximation (the point
// made exact first when an interval is too wide, as to_double does).
Point round_point(const CPoint& p) {
  auto narrow = [](const CGAL::Interval_nt<false>& c) {
    return c.inf() == c.sup() ||
           CGAL::has_smaller_relative_precision(c, FT::get_relative_precision_of_to_double());
  };
  if (!narrow(p.approx().x()) || !narrow(p.approx().y())) (void)CGAL::exact(p);
  const auto& a = p.approx();
  return Point(CGAL::to_double(a.x()), CGAL::to_double(a.y()));
}

// A cycle of exact points. settle: evaluate its exact coordinates now (freespace.h).
LoopPtr exact_loop(CPolygon p, bool settle) {
  auto l = std::make_shared<Loop>();
  if (settle) {
    // A point whose intervals are single doubles (an input vertex) is exact already.
    for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) {
      if (!geometry::internal::is_double(*it)) (void)CGAL::exact(*it);
    }
  }
  const std::size_t n = p.size();
  l->edges.reserve(n);
  l->box = p.vertex(0).bbox();
  std::vector<Point> rounded;
  rounded.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    l->edges.push_back(p.vertex(i).bbox() + p.vertex((i + 1) % n).bbox());
    l->box += l->edges.back();
    rounded.push_back(round_point(p.vertex(i)));
  }
  // Cutting at repeated vertices is quadratic; most cycles have none.
  l->pinched = has_duplicates(rounded);
  if (l->pinched) {
    split_rounded(geometry::simple_loops(rounded), *l);
  } else {
    split_rounded({Polygon{std::move(rounded)}}, *l);
  }
  l->set_exact(std::move(p));
  return l;
}

// A cycle given in doubles (a validated, counter-clockwise polygon), as an outer boundary or
// as a hole. Its rounding is itself; its exact cycle is built when first needed.
LoopPtr double_loop(const Polygon& p, bool hole) {
  auto l = std::make_shared<Loop>();
  (hole ? l->holes : l->outers).push_back(p);
  l->from_doubles = true;
  const std::size_t n = p.size();
  l->edges.reserve(n);
  l->box = box_of(p);
  // Edge i of the exact cycle: a hole runs clockwise, from vertex n − 1 − i to n − 2 − i.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = hole ? n - 1 - i : i;
    const std::size_t b = hole ? (2 * n - 2 - i) % n : (i + 1) % n;
    l->edges.push_back(box_of(p.vertices[a], p.vertices[b]));
  }
  return l;
}

Piece exact_piece(const CPolygonWithHoles& p, bool settle) {
  Piece out{exact_loop(p.outer_boundary(), settle), {}};
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
    out.holes.push_back(exact_loop(*h, settle));
  return out;
}

// Where q lies relative to the cycle (exact), after a box filter; a cycle and a point given in
// doubles by exact predicates on the doubles, without building lazy exact points.
CGAL::Bounded_side side_of(const Loop& l, const CPoint& q) {
  if (!meet(l.box, q.bbox())) return CGAL::ON_UNBOUNDED_SIDE;
  if (l.from_doubles && geometry::internal::is_double(q)) {
    const int side = geometry::side_of(l.cycle_of_doubles(), geometry::internal::double_point(q));
    return side > 0    ? CGAL::ON_BOUNDED_SIDE
           : side == 0 ? CGAL::ON_BOUNDARY
                       : CGAL::ON_UNBOUNDED_SIDE;
  }
  const CPolygon& e = l.exact();
  return CGAL::bounded_side_2(e.vertices_begin(), e.vertices_end(), q, Kernel());
}

// Is q strictly inside the cycle? The callers know q is on no boundary.
bool strictly_inside(const Loop& l, const CPoint& q) {
  const CGAL::Bounded_side side = side_of(l, q);
  REARM_DEMAND(side != CGAL::ON_BOUNDARY, "topology: a located point lies on a boundary");
  return side == CGAL::ON_BOUNDED_SIDE;
}

bool in_piece(const Piece& p, const CPoint& q) {
  if (!strictly_inside(*p.outer, q)) return false;
  return std::none_of(p.holes.begin(), p.holes.end(),
                      [&q](const LoopPtr& h) { return strictly_inside(*h, q); });
}

std::vector<Box> edge_boxes(const std::vector<Piece>& pieces) {
  std::vector<Box> out;
  for (const Piece& p : pieces) {
    out.insert(out.end(), p.outer->edges.begin(), p.outer->edges.end());
    for (const LoopPtr& h : p.holes) out.insert(out.end(), h->edges.begin(), h->edges.end());
  }
  return out;
}

// geometry::subtract's rounding of one exact region (boolean.cpp, from_set_exact): usually one
// outer loop; otherwise a hole goes to the smallest loop containing the midpoint of one of its
// edges.
void append_rounded(const Piece& p, RegionSet& out) {
  const std::size_t first = out.size();
  std::vector<const Polygon*> holes;
  auto add = [&](const Loop& l) {
    for (const Polygon& o : l.outers) out.push_back(Region{o, {}});
    for (const Polygon& h : l.holes) holes.push_back(&h);
  };
  add(*p.outer);
  for (const LoopPtr& h : p.holes) add(*h);
  for (const Polygon* h : holes) {
    std::size_t best = first;
    if (out.size() - first > 1) {
      const Point probe = (h->vertices[0] + h->vertices[1]) / 2;
      double best_area = std::numeric_limits<double>::infinity();
      for (std::size_t k = first; k < out.size(); ++k) {
        const double a = out[k].outer.area();
        if (a < best_area && geometry::contains(out[k].outer, probe)) {
          best = k;
          best_area = a;
        }
      }
    }
    REARM_DEMAND(best < out.size(), "a Boolean result has a hole but no outer boundary");
    out[best].holes.push_back(*h);
  }
}

RegionSet rounded(const std::vector<Piece>& pieces) {
  RegionSet out;
  for (const Piece& p : pieces) append_rounded(p, out);
  return out;
}

// Isolation (freespace.h) of each polygon among `boxes` and against the edge boxes `walls`.
std::vector<char> isolated(const std::vector<Box>& boxes, const std::vector<Box>& walls) {
  const std::size_t n = boxes.size();
  std::vector<char> iso(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (meet(boxes[i], boxes[j])) iso[i] = iso[j] = 0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (iso[i] &&
        std::any_of(walls.begin(), walls.end(), [&](const Box& w) { return meet(boxes[i], w); })) {
      iso[i] = 0;
    }
  }
  return iso;
}

// Groups of the non-isolated polygons whose boxes meet (transitively).
std::vector<std::vector<std::size_t>> box_groups(const std::vector<Box>& boxes,
                                                 const std::vector<std::size_t>& members) {
  std::vector<std::size_t> parent(members.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < members.size(); ++i) {
    for (std::size_t j = i + 1; j < members.size(); ++j) {
      if (meet(boxes[members[i]], boxes[members[j]])) parent[root(i)] = root(j);
    }
  }
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> index(members.size(), kNone);
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::size_t r = root(i);
    if (index[r] == kNone) {
      index[r] = groups.size();
      groups.emplace_back();
    }
    groups[index[r]].push_back(members[i]);
  }
  return groups;
}

// The points by which a loop is located: its vertices, then its edge midpoints (a hole of a
// CGAL result may touch the outer cycle, or another hole, at vertices).
std::vector<CPoint> probes(const Loop& l) {
  std::vector<CPoint> out(l.exact().vertices_begin(), l.exact().vertices_end());
  const std::size_t n = l.exact().size();
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(CGAL::midpoint(l.exact().vertex(i), l.exact().vertex((i + 1) % n)));
  }
  return out;
}

// Outer cycles and holes into pieces: each hole goes to the innermost outer cycle containing
// it. Outer cycles of disjoint pieces are nested or disjoint, so among the candidates whose
// box holds a probe point of the hole, ordered by box area, the first that contains it
// (exact) is the innermost, and the last needs no test. A probe on a tested outer cycle is
// replaced by the next. Nullopt when no probe works.
std::optional<std::vector<Piece>> assemble(std::vector<LoopPtr> outers,
                                           std::vector<LoopPtr> holes) {
  std::vector<Piece> out;
  out.reserve(outers.size());
  for (LoopPtr& o : outers) out.push_back(Piece{std::move(o), {}});
  if (out.empty()) {
    if (!holes.empty()) return std::nullopt;
    return out;
  }
  std::vector<std::size_t> order(out.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&out](std::size_t a, std::size_t b) {
    return box_area(out[a].outer->box) < box_area(out[b].outer->box);
  });
  for (LoopPtr& h : holes) {
    std::size_t at = out.size() == 1 ? 0 : kNone;
    const std::vector<CPoint> qs = at == kNone ? probes(*h) : std::vector<CPoint>{};
    for (std::size_t p = 0; p < qs.size() && at == kNone; ++p) {
      const CPoint& q = qs[p];
      std::vector<std::size_t> candidates;
      for (std::size_t k : order) {
        if (meet(out[k].outer->box, q.bbox())) candidates.push_back(k);
      }
      bool on_boundary = false;
      for (std::size_t c = 0; c < candidates.size() && at == kNone && !on_boundary; ++c) {
        if (c + 1 == candidates.size()) {
          at = candidates[c];
          break;
        }
        const CGAL::Bounded_side side = side_of(*out[candidates[c]].outer, q);
        on_boundary = side == CGAL::ON_BOUNDARY;
        if (side == CGAL::ON_BOUNDED_SIDE) at = candidates[c];
      }
    }
    if (at == kNone) return std::nullopt;
    out[at].holes.push_back(std::move(h));
  }
  return out;
}

// The piece whose interior holds the loop (a loop disjoint from the pieces' interiors' other
// boundaries, possibly touching them at points): the first probe point on no boundary of any
// piece decides. kNone when none is in a piece.
std::size_t piece_holding(const std::vector<Piece>& pieces, const Loop& l) {
  for (const CPoint& q : probes(l)) {
    std::size_t at = kNone;
    bool on_boundary = false;
    for (std::size_t k = 0; k < pieces.size() && !on_boundary; ++k) {
      CGAL::Bounded_side side = side_of(*pieces[k].outer, q);
      on_boundary = side == CGAL::ON_BOUNDARY;
      if (side != CGAL::ON_BOUNDED_SIDE) continue;
      bool in_hole = false;
      for (const LoopPtr& h : pieces[k].holes) {
        side = side_of(*h, q);
        on_boundary = on_boundary || side == CGAL::ON_BOUNDARY;
        in_hole = in_hole || side == CGAL::ON_BOUNDED_SIDE;
      }
      if (!in_hole && at == kNone) at = k;
    }
    if (!on_boundary) return at;
  }
  return kNone;
}

// --- Windows (freespace.h): axis-parallel rectangles around the groups of interacting
// obstacles, pairwise disjoint. A piece's loops are cut where they cross a window's boundary;
// the part of the piece inside each window goes through one small exact overlay with that
// window's obstacles, and the loops' chains outside the windows are spliced back onto the
// overlays' chains at the crossing points. ---

struct Window {
  std::array<double, 2> lo;
  std::array<double, 2> hi;
  Box box() const { return Box(lo[0], lo[1], hi[0], hi[1]); }
  // Corner k starts side k: 0 (x0, y0), 1 (x1, y0), 2 (x1, y1), 3 (x0, y1).
  CPoint corner(int k) const {
    return CPoint(k == 1 || k == 2 ? hi[0] : lo[0], k >= 2 ? hi[1] : lo[1]);
  }
  // Side s (0 bottom, 1 right, 2 top, 3 left, counter-clockwise) lies on the line
  // coordinate[fixed_axis(s)] = value(s).
  static int fixed_axis(int s) { return s % 2 == 0 ? 1 : 0; }
  double value(int s) const { return s == 0 ? lo[1] : s == 1 ? hi[0] : s == 2 ? hi[1] : lo[0]; }
  // The comparison of a coordinate with value(s) that means "inside W".
  static CGAL::Comparison_result inward(int s) {
    return s == 0 || s == 3 ? CGAL::LARGER : CGAL::SMALLER;
  }
};

// The window of attempt t (0, 1, ...) around box b.
Window window_around(const Box& b, int t) {
  const double m = kWindowMargin * std::pow(kWindowGrowth, t) *
                   std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
  const double my = t == 0 ? m : m * kWindowAspect;
  return Window{{b.xmin() - m, b.ymin() - my}, {b.xmax() + m, b.ymax() + my}};
}

// Windows of attempt t around groups of obstacles (their boxes `group_box`); groups whose
// windows meet are merged until the windows are pairwise disjoint. members[w]: the groups in
// window w.
std::vector<Window> windows_for(const std::vector<Box>& group_box, int t,
                                std::vector<std::vector<std::size_t>>& members) {
  std::vector<Box> boxes = group_box;
  members.clear();
  for (std::size_t g = 0; g < group_box.size(); ++g) members.push_back({g});
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < boxes.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < boxes.size() && !merged; ++j) {
        if (meet(window_around(boxes[i], t).box(), window_around(boxes[j], t).box())) {
          boxes[i] += boxes[j];
          members[i].insert(members[i].end(), members[j].begin(), members[j].end());
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          members.erase(members.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
        }
      }
    }
  }
  std::vector<Window> out;
  for (const Box& b : boxes) out.push_back(window_around(b, t));
  return out;
}

const FT& coord(const CPoint& p, int axis, FT& scratch) {
  scratch = axis == 0 ? p.x() : p.y();
  return scratch;
}

// Exact comparison of a coordinate of p with v, on the interval approximation when it decides.
CGAL::Comparison_result compare_coord(const CPoint& p, int axis, double v) {
  const auto& a = p.approx();
  const CGAL::Interval_nt<false> c = axis == 0 ? a.x() : a.y();
  if (c.sup() < v) return CGAL::SMALLER;
  if (c.inf() > v) return CGAL::LARGER;
  if (c.inf() == c.sup()) return CGAL::EQUAL;  // the coordinate is the double v
  FT s;
  return CGAL::compare(coord(p, axis, s), FT(v));
}

// Sides of W whose line passes through p (p assumed in the closed window).
unsigned sides_through(const CPoint& p, const Window& w) {
  unsigned mask = 0;
  for (int s = 0; s < 4; ++s) {
    if (compare_coord(p, Window::fixed_axis(s), w.value(s)) == CGAL::EQUAL) mask |= 1u << s;
  }
  return mask;
}

bool on_boundary(const CPoint& p, const Window& w) {
  for (int s = 0; s < 4; ++s) {
    const int f = Window::fixed_axis(s);
    if (compare_coord(p, f, w.value(s)) != CGAL::EQUAL) continue;
    if (compare_coord(p, 1 - f, w.lo[1 - f]) != CGAL::SMALLER &&
        compare_coord(p, 1 - f, w.hi[1 - f]) != CGAL::LARGER) {
      return true;
    }
  }
  return false;
}

// Is the point strictly inside W (exact)?
bool inside_window(const CPoint& p, const Window& w) {
  return compare_coord(p, 0, w.lo[0]) == CGAL::LARGER &&
         compare_coord(p, 0, w.hi[0]) == CGAL::SMALLER &&
         compare_coord(p, 1, w.lo[1]) == CGAL::LARGER &&
         compare_coord(p, 1, w.hi[1]) == CGAL::SMALLER;
}

CPolygon window_polygon(const Window& w) {
  CPolygon p;
  for (int k = 0; k < 4; ++k) p.push_back(w.corner(k));
  return p;
}

// No vertex of the loop on ∂W, no edge through a corner of W (exact).
bool general_position(const Loop& l, const Window& w) {
  const Box wb = w.box();
  const std::size_t n = l.exact().size();
  std::array<std::optional<CPoint>, 4> corners;
  for (std::size_t i = 0; i < n; ++i) {
    if (!meet(l.edges[i], wb)) continue;
    const CPoint& a = l.exact().vertex(i);
    const CPoint& b = l.exact().vertex((i + 1) % n);
    if (on_boundary(a, w) || on_boundary(b, w)) return false;
    for (int k = 0; k < 4; ++k) {
      const Box cb =
          box_of(Point(k == 1 || k == 2 ? w.hi[0] : w.lo[0], k >= 2 ? w.hi[1] : w.lo[1]),
                 Point(k == 1 || k == 2 ? w.hi[0] : w.lo[0], k >= 2 ? w.hi[1] : w.lo[1]));
      if (!meet(l.edges[i], cb)) continue;
      if (!corners[k]) corners[k] = w.corner(k);
      if (CGAL::collinear(a, b, *corners[k]) &&
          CGAL::collinear_are_ordered_along_line(a, *corners[k], b)) {
        return false;
      }
    }
  }
  return true;
}

struct Crossing {
  CPoint p;
  FT along;  // the coordinate along its side
  int side = 0;
  bool entry = false;  // the loop enters the window here, in its own direction
  std::size_t window = 0;
  std::size_t edge = 0;
  std::size_t loop = 0;  // index among the piece's loops (0: the outer boundary)
};

// ∂W order, counter-clockwise from corner 0 (crossings of one window).
bool before_on_boundary(const Crossing& a, const Crossing& b) {
  if (a.side != b.side) return a.side < b.side;
  const CGAL::Comparison_result c = CGAL::compare(a.along, b.along);
  return a.side < 2 ? c == CGAL::SMALLER : c == CGAL::LARGER;
}

// Appends the crossings of edge (a, b) with the boundary of window w (general position).
void edge_crossings(const CPoint& a, const CPoint& b, const Window& w, Crossing proto,
                    std::vector<Crossing>& out) {
  for (int s = 0; s < 4; ++s) {
    const int f = Window::fixed_axis(s);
    const double v = w.value(s);
    const CGAL::Comparison_result ca = compare_coord(a, f, v);
    const CGAL::Comparison_result cb = compare_coord(b, f, v);
    if (ca == CGAL::EQUAL || cb == CGAL::EQUAL || ca == cb) continue;
    FT sa, sb, ta, tb;
    const FT& af = coord(a, f, sa);
    const FT& bf = coord(b, f, sb);
    const FT& aa = coord(a, 1 - f, ta);
    const FT& ba = coord(b, 1 - f, tb);
    FT along = aa + (FT(v) - af) * (ba - aa) / (bf - af);
    if (CGAL::compare(along, FT(w.lo[1 - f])) != CGAL::LARGER ||
        CGAL::compare(along, FT(w.hi[1 - f])) != CGAL::SMALLER) {
      continue;
    }
    Crossing c = proto;
    c.p = f == 0 ? CPoint(FT(v), along) : CPoint(along, FT(v));
    c.along = std::move(along);
    c.side = s;
    c.entry = ca != Window::inward(s);
    out.push_back(std::move(c));
  }
}

// The crossings of a piece's loops with the windows, and the chains between them.
struct Cut {
  std::vector<Crossing> x;
  std::vector<std::vector<CPoint>> chain;  // from crossing i to next[i]: interior vertices
  std::vector<std::size_t> next;           // the crossing that ends chain i
};

// Appends the loop's crossings with the windows `ws` (in loop order) and its chains; false
// when they do not alternate (entry into a window, exit from the same window, entry, ...).
bool cut_loop(const Loop& l, std::size_t loop, const std::vector<Window>& windows,
              const std::vector<std::size_t>& ws, Cut& cut) {
  const std::size_t first = cut.x.size();
  const std::size_t n = l.exact().size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t edge_first = cut.x.size();
    const CPoint& a = l.exact().vertex(i);
    const CPoint& b = l.exact().vertex((i + 1) % n);
    for (std::size_t w : ws) {
      if (!meet(l.edges[i], windows[w].box())) continue;
      Crossing proto;
      proto.window = w;
      proto.edge = i;
      proto.loop = loop;
      edge_crossings(a, b, windows[w], proto, cut.x);
    }
    if (cut.x.size() - edge_first > 1) {  // order them along the edge
      const int axis = CGAL::compare(a.x(), b.x()) != CGAL::EQUAL ? 0 : 1;
      FT sa, sb;
      const bool increasing =
          CGAL::compare(coord(a, axis, sa), coord(b, axis, sb)) == CGAL::SMALLER;
      std::sort(cut.x.begin() + static_cast<std::ptrdiff_t>(edge_first), cut.x.end(),
                [axis, increasing](const Crossing& u, const Crossing& v) {
                  FT su, sv;
                  const CGAL::Comparison_result c =
                      CGAL::compare(coord(u.p, axis, su), coord(v.p, axis, sv));
                  return increasing ? c == CGAL::SMALLER : c == CGAL::LARGER;
                });
    }
  }
  const std::size_t m = cut.x.size() - first;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = first + k;
    const std::size_t j = first + (k + 1) % m;
    const Crossing& u = cut.x[i];
    const Crossing& v = cut.x[j];
    if (u.entry == v.entry || (u.entry && u.window != v.window)) return false;
    std::size_t count = (v.edge + n - u.edge) % n;
    if (count == 0 && !(v.edge == u.edge && k + 1 < m)) count = n;
    std::vector<CPoint> pts;
    pts.reserve(count);
    for (std::size_t t = 1; t <= count; ++t) pts.push_back(l.exact().vertex((u.edge + t) % n));
    cut.chain.push_back(std::move(pts));
    cut.next.push_back(j);
  }
  return true;
}

// Weiler–Atherton against a rectangle: the polygons (counter-clockwise) of the loop's material
// side inside the window (right = false: the left of the loop as it runs; true: its right),
// from the loop's crossings `ids` with that window. Nullopt when they do not alternate along
// the window's boundary.
std::optional<std::vector<CPolygon>> clip(const Cut& cut, std::vector<std::size_t> ids, bool right,
                                          const Window& w) {
  std::vector<std::size_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end(), [&cut](std::size_t a, std::size_t b) {
    return before_on_boundary(cut.x[a], cut.x[b]);
  });
  std::vector<std::size_t> pos(cut.x.size(), kNone), prev(cut.x.size(), kNone);
  for (std::size_t k = 0; k < sorted.size(); ++k) pos[sorted[k]] = k;
  for (std::size_t i : ids) {
    if (cut.x[i].entry) prev[cut.next[i]] = i;  // the inside chain ending at exit next[i]
  }
  // The material-left way: inside chains start at entries; the right way: at exits, backwards.
  auto starts = [&](std::size_t i) { return cut.x[i].entry != right; };
  std::vector<char> used(cut.x.size(), 0);
  std::vector<CPolygon> out;
  for (std::size_t s : ids) {
    if (!starts(s) || used[s]) continue;
    CPolygon poly;
    std::size_t cur = s;
    for (std::size_t guard = 0;; ++guard) {
      if (guard > ids.size()) return std::nullopt;
      used[cur] = 1;
      poly.push_back(cut.x[cur].p);
      std::size_t end;
      if (!right) {
        for (const CPoint& q : cut.chain[cur]) poly.push_back(q);
        end = cut.next[cur];
      } else {
        end = prev[cur];
        if (end == kNone) return std::nullopt;
        const auto& c = cut.chain[end];
        for (auto it = c.rbegin(); it != c.rend(); ++it) poly.push_back(*it);
      }
      if (pos[end] == kNone) return std::nullopt;
      poly.push_back(cut.x[end].p);
      const std::size_t nxt = sorted[(pos[end] + 1) % sorted.size()];
      if (!starts(nxt)) return std::nullopt;
      const int s0 = cut.x[end].side;
      const int s1 = cut.x[nxt].side;
      int corners = (s1 - s0 + 4) % 4;
      if (corners == 0 && !before_on_boundary(cut.x[end], cut.x[nxt])) corners = 4;
      for (int k = 1; k <= corners; ++k) poly.push_back(w.corner((s0 + k) % 4));
      if (nxt == s) break;
      if (used[nxt]) return std::nullopt;
      cur = nxt;
    }
    out.push_back(std::move(poly));
  }
  return out;
}

// The vertices of an overlay cycle of window `wi` on its boundary: the sides through each
// (on), and which crossing each is (kNone for a corner or a vertex off the boundary). False
// when a vertex on one side only is none of the window's crossings.
bool match_crossings(const CPolygon& cycle, const Window& w, std::size_t wi, const Cut& cut,
                     std::vector<unsigned>& on, std::vector<std::size_t>& which) {
  const std::size_t n = cycle.size();
  on.assign(n, 0);
  which.assign(n, kNone);
  for (std::size_t i = 0; i < n; ++i) {
    const CPoint& v = cycle.vertex(i);
    on[i] = sides_through(v, w);
    if (on[i] == 0 || (on[i] & (on[i] - 1)) != 0) continue;  // off the boundary, or a corner
    const int s = std::countr_zero(on[i]);
    const int f = Window::fixed_axis(s);
    // Usually the overlay hands back the crossing's own point; else compare exactly.
    for (std::size_t k = 0; k < cut.x.size() && which[i] == kNone; ++k) {
      if (cut.x[k].window == wi && cut.x[k].side == s && CGAL::identical(cut.x[k].p, v)) {
        which[i] = k;
      }
    }
    for (std::size_t k = 0; k < cut.x.size() && which[i] == kNone; ++k) {
      FT sv;
      if (cut.x[k].window == wi && cut.x[k].side == s &&
          CGAL::compare(cut.x[k].along, coord(v, 1 - f, sv)) == CGAL::EQUAL) {
        which[i] = k;
      }
    }
    if (which[i] == kNone) return false;
  }
  return true;
}

// (∪material) − ∪cutters, exact: material polygons interior-disjoint, cutters overlapping
// freely. One polygon minus cutters in general position (the usual window: the bound's wall
// and dilated obstacles) is traced along the boundaries' crossings
// (geometry::internal::crossing_difference); otherwise one polygon minus one goes through
// CGAL's free function, which skips building the polygon sets (about a third faster).
std::vector<CPolygonWithHoles> boolean_difference(const std::vector<CPolygon>& material,
                                                  const std::vector<CPolygonWithHoles>& cutters) {
  if (material.size() == 1) {
    auto traced = geometry::internal::crossing_difference(material.front(), cutters);
    if (traced) return std::move(*traced);
  }
  std::vector<CPolygonWithHoles> out;
  if (material.size() == 1 && cutters.size() == 1) {
    CGAL::difference(material.front(), cutters.front(), std::back_inserter(out));
    return out;
  }
  PolygonSet s;
  if (material.size() == 1) {
    s = PolygonSet(material.front());
  } else {
    s.join(material.begin(), material.end());
  }
  if (cutters.size() == 1) {
    s.difference(cutters.front());
  } else {
    PolygonSet u;
    u.join(cutters.begin(), cutters.end());
    s.difference(u);
  }
  s.polygons_with_holes(std::back_inserter(out));
  return out;
}

enum class Outcome { kDone, kUnchanged, kDegenerate, kFallback };

// The state of windowed()'s three phases: the piece's loops cut by the windows (cut_loops), the
// chains inside the windows that the windows' overlays give (overlay_windows), and the loops
// spliced from them (splice).
struct WindowedState {
  std::vector<std::size_t> near;   // the windows whose boxes meet the piece's
  std::vector<const Loop*> loops;  // the piece's outer boundary, then its holes
  std::vector<std::vector<CPolygon>> material, removed;  // per window
  std::vector<char> dead;  // per window: it lies in a hole, nothing of the piece in it
  std::vector<char> kept;  // per loop: it meets no window and stays as it is
  Cut cut;
  std::vector<LoopPtr> outers, holes;
  std::vector<std::vector<CPoint>> inner;  // per entry crossing: its inner chain
  std::vector<std::size_t> inner_end;      // per entry crossing: the exit crossing it ends at
};

// Phase 1: each loop cut at the window boundaries it crosses; what lies inside each window (of
// the piece's material, or of its holes) goes to that window's overlay.
Outcome cut_loops(const std::vector<Window>& windows, WindowedState& s) {
  for (std::size_t k = 0; k < s.loops.size(); ++k) {
    const Loop& l = *s.loops[k];
    std::vector<std::size_t> ws;
    for (std::size_t w : s.near) {
      if (meet(l.box, windows[w].box())) ws.push_back(w);
    }
    for (std::size_t w : ws) {
      if (!general_position(l, windows[w])) return Outcome::kDegenerate;
    }
    Cut& cut = s.cut;
    const std::size_t first = cut.x.size();
    if (!ws.empty() && !cut_loop(l, k, windows, ws, cut)) return Outcome::kFallback;
    if (cut.x.size() > first) {
      if (l.pinched) return Outcome::kFallback;
      s.kept[k] = 0;
    }
    const bool hole = k != 0;
    for (std::size_t w : ws) {
      std::vector<std::size_t> ids;
      for (std::size_t i = first; i < cut.x.size(); ++i) {
        if (cut.x[i].window == w) ids.push_back(i);
      }
      if (!ids.empty()) {
        auto parts = clip(cut, std::move(ids), hole, windows[w]);
        if (!parts) return Outcome::kFallback;
        auto& to = hole ? s.removed[w] : s.material[w];
        to.insert(to.end(), parts->begin(), parts->end());
      } else if (cut.x.size() == first && inside_window(l.exact().vertex(0), windows[w])) {
        s.kept[k] = 0;  // wholly inside the window: the overlay returns it
        CPolygon p = l.exact();
        if (hole) p.reverse_orientation();
        (hole ? s.removed[w] : s.material[w]).push_back(std::move(p));
      } else if (side_of(l, windows[w].corner(0)) == CGAL::ON_BOUNDED_SIDE) {
        if (hole) {
          s.dead[w] = 1;
        } else {
          s.material[w].push_back(window_polygon(windows[w]));
        }
      }
    }
  }
  return Outcome::kDone;
}

// One cycle of window w's overlay: whole when off the window's boundary, else its inner chains
// (entry crossing to exit crossing of that window). False when it cannot be matched.
bool take_cycle(const CPolygon& c, bool is_outer, const Window& win, std::size_t w, bool settle,
                WindowedState& s) {
  if (c.is_empty()) return true;
  std::vector<unsigned> on;
  std::vector<std::size_t> which;
  const Cut& cut = s.cut;
  if (!match_crossings(c, win, w, cut, on, which)) return false;
  const std::size_t n = c.size();
  auto boundary_edge = [&](std::size_t i) { return (on[i] & on[(i + 1) % n]) != 0; };
  bool touches = false;
  for (std::size_t i = 0; i < n && !touches; ++i) touches = boundary_edge(i);
  if (!touches) {
    (is_outer ? s.outers : s.holes).push_back(exact_loop(c, settle));
    return true;
  }
  std::vector<Point> check;
  check.reserve(n);
  for (std::size_t i = 0; i < n; ++i) check.push_back(round_point(c.vertex(i)));
  if (has_duplicates(std::move(check))) return false;  // pinched on the boundary
  for (std::size_t i = 0; i < n; ++i) {
    if (!(boundary_edge((i + n - 1) % n) && !boundary_edge(i))) continue;
    // An inner chain from vertex i (an entry crossing) to the next vertex that starts a
    // boundary edge (an exit crossing); a cycle wholly on the boundary has none.
    const std::size_t from = which[i];
    if (from == kNone || !cut.x[from].entry || s.inner_end[from] != kNone) return false;
    std::vector<CPoint> pts;
    std::size_t j = (i + 1) % n;
    while (!boundary_edge(j)) {
      pts.push_back(c.vertex(j));
      j = (j + 1) % n;
      if (j == i) return false;
    }
    const std::size_t to = which[j];
    if (to == kNone || cut.x[to].entry) return false;
    s.inner[from] = std::move(pts);
    s.inner_end[from] = to;
  }
  return true;
}

// Phase 2: the exact overlays, one per window holding material, and their cycles.
Outcome overlay_windows(const std::vector<Window>& windows,
                        const std::vector<std::vector<CPolygonWithHoles>>& cutters, bool settle,
                        WindowedState& s) {
  s.inner.assign(s.cut.x.size(), {});
  s.inner_end.assign(s.cut.x.size(), kNone);
  bool any = false;
  for (std::size_t w : s.near) {
    if (s.dead[w] || s.material[w].empty()) continue;
    any = true;
    std::vector<CPolygonWithHoles> subtract(cutters[w].begin(), cutters[w].end());
    for (CPolygon& p : s.removed[w]) subtract.emplace_back(std::move(p));
    const std::vector<CPolygonWithHoles> local = boolean_difference(s.material[w], subtract);
    for (const CPolygonWithHoles& p : local) {
      if (p.is_unbounded()) return Outcome::kFallback;
      if (!take_cycle(p.outer_boundary(), true, windows[w], w, settle, s)) {
        return Outcome::kFallback;
      }
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
        if (!take_cycle(*h, false, windows[w], w, settle, s)) return Outcome::kFallback;
      }
    }
  }
  return any ? Outcome::kDone : Outcome::kUnchanged;
}

// Phase 3: inner chains and the loops' outer chains (exit crossing to the next entry, outside
// every window), alternately. The crossing points themselves are dropped: each lies inside an
// edge of the piece, which the result follows straight through it.
Outcome splice(const Piece& piece, bool settle, WindowedState& s, std::vector<Piece>& result) {
  const Cut& cut = s.cut;
  std::vector<char> used(cut.x.size(), 0);
  for (std::size_t e = 0; e < cut.x.size(); ++e) {
    if (!cut.x[e].entry || used[e]) continue;
    std::vector<CPoint> pts;
    bool has_outer_chain = false;
    for (std::size_t cur = e, guard = 0;; ++guard) {
      if (guard > cut.x.size() || used[cur] || s.inner_end[cur] == kNone) {
        return Outcome::kFallback;
      }
      used[cur] = 1;
      pts.insert(pts.end(), s.inner[cur].begin(), s.inner[cur].end());
      const std::size_t x = s.inner_end[cur];
      if (used[x]) return Outcome::kFallback;
      used[x] = 1;
      pts.insert(pts.end(), cut.chain[x].begin(), cut.chain[x].end());
      has_outer_chain = has_outer_chain || cut.x[x].loop == 0;
      cur = cut.next[x];
      if (cur == e) break;
    }
    if (pts.size() < 3) return Outcome::kFallback;
    LoopPtr loop = exact_loop(CPolygon(pts.begin(), pts.end()), settle);
    // A cycle through the outer boundary's chains keeps the piece's exterior outside it, so it
    // is an outer boundary; otherwise its orientation says, when it is simple (two holes of
    // the piece touching outside the windows would make it pass one point twice).
    bool is_outer = has_outer_chain;
    if (!is_outer) {
      if (loop->pinched) return Outcome::kFallback;
      const CGAL::Orientation o = CGAL::orientation_2(pts.begin(), pts.end(), Kernel());
      if (o == CGAL::COLLINEAR) return Outcome::kFallback;
      is_outer = o == CGAL::COUNTERCLOCKWISE;
    }
    (is_outer ? s.outers : s.holes).push_back(std::move(loop));
  }
  if (std::find(used.begin(), used.end(), 0) != used.end()) return Outcome::kFallback;
  for (std::size_t k = 0; k < s.loops.size(); ++k) {
    if (!s.kept[k]) continue;
    if (k == 0) {
      s.outers.push_back(piece.outer);
    } else {
      s.holes.push_back(piece.holes[k - 1]);
    }
  }
  auto pieces = assemble(std::move(s.outers), std::move(s.holes));
  if (!pieces) return Outcome::kFallback;
  result.insert(result.end(), std::make_move_iterator(pieces->begin()),
                std::make_move_iterator(pieces->end()));
  return Outcome::kDone;
}

// The piece minus the windows' obstacles (each window's obstacles lie strictly inside it).
// kDegenerate: a window is not in general position with the piece's loops (retry with other
// windows); kFallback: the splice met something it does not handle (use the plain overlay);
// kUnchanged: no window holds material of the piece.
Outcome windowed(const Piece& piece, const std::vector<Window>& windows,
                 const std::vector<std::vector<CPolygonWithHoles>>& cutters, bool settle,
                 std::vector<Piece>& result) {
  WindowedState s;
  for (std::size_t w = 0; w < windows.size(); ++w) {
    if (meet(windows[w].box(), piece.outer->box)) s.near.push_back(w);
  }
  if (s.near.empty()) return Outcome::kUnchanged;
  s.loops.push_back(piece.outer.get());
  for (const LoopPtr& h : piece.holes) s.loops.push_back(h.get());
  s.material.resize(windows.size());
  s.removed.resize(windows.size());
  s.dead.assign(windows.size(), 0);
  s.kept.assign(s.loops.size(), 1);
  if (const Outcome o = cut_loops(windows, s); o != Outcome::kDone) return o;
  if (const Outcome o = overlay_windows(windows, cutters, settle, s); o != Outcome::kDone) {
    return o;
  }
  return splice(piece, settle, s, result);
}

// The piece minus the obstacles in one overlay with the piece's outer boundary and the holes
// whose boxes meet an obstacle's (the others are disjoint from every obstacle and go back to
// the result piece holding them).
std::vector<Piece> plain(const Piece& piece, const std::vector<Box>& boxes,
                         const std::vector<std::size_t>& touching,
                         const std::vector<CPolygonWithHoles>& exact, bool settle) {
  CPolygonWithHoles kept(piece.outer->exact());
  std::vector<LoopPtr> untouched;
  for (const LoopPtr& h : piece.holes) {
    const bool touched = std::any_of(touching.begin(), touching.end(),
                                     [&](std::size_t i) { return meet(boxes[i], h->box); });
    if (touched) {
      kept.add_hole(h->exact());
    } else {
      untouched.push_back(h);
    }
  }
  PolygonSet s(kept);
  if (touching.size() == 1) {
    s.difference(exact[touching.front()]);
  } else {
    std::vector<CPolygonWithHoles> parts;
    parts.reserve(touching.size());
    for (std::size_t i : touching) parts.push_back(exact[i]);
    PolygonSet u;
    u.join(parts.begin(), parts.end());
    s.difference(u);
  }
  std::vector<CPolygonWithHoles> result;
  s.polygons_with_holes(std::back_inserter(result));
  std::vector<Piece> out;
  for (const CPolygonWithHoles& p : result) {
    REARM_DEMAND(!p.is_unbounded(), "a bounded Boolean operation gave an unbounded region");
    out.push_back(exact_piece(p, settle));
  }
  for (LoopPtr& h : untouched) {
    const std::size_t at = out.size() == 1 ? 0 : piece_holding(out, *h);
    REARM_DEMAND(at != kNone, "topology: an untouched hole lies in no piece of the overlay");
    out[at].holes.push_back(std::move(h));
  }
  return out;
}

// base − ∪obstacles, localized (freespace.h). settle: the result is kept (cache level), so its
// exact coordinates are evaluated now (loops given in doubles make their CGAL cycles on first use).
std::vector<Piece> difference(const std::vector<Piece>& base, const std::vector<Box>& walls,
                              const std::vector<Region>& obstacles, bool settle) {
  const std::size_t n = obstacles.size();
  std::vector<Box> boxes;
  boxes.reserve(n);
  for (const Region& o : obstacles) boxes.push_back(box_of(o.outer));
  const std::vector<char> iso = isolated(boxes, walls);
  std::vector<std::size_t> home(n, kNone);  // the base piece holding an isolated obstacle
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < n; ++i) {
    if (!iso[i]) {
      others.push_back(i);
      continue;
    }
    const CPoint q = geometry::internal::to_cgal(obstacles[i].outer.vertices.front());
    for (std::size_t r = 0; r < base.size() && home[i] == kNone; ++r) {
      if (in_piece(base[r], q)) home[i] = r;
    }
  }
  std::vector<CPolygonWithHoles> exact(n);
  for (std::size_t i : others) exact[i] = geometry::internal::to_cgal(obstacles[i]);
  const std::vector<std::vector<std::size_t>> groups = box_groups(boxes, others);
  std::vector<Box> group_box;
  for (const auto& g : groups) {
    Box b = boxes[g.front()];
    for (std::size_t i : g) b += boxes[i];
    group_box.push_back(b);
  }
  // Windows per attempt (grown after a degenerate one), built when first needed.
  struct Attempt {
    std::vector<Window> windows;
    std::vector<std::vector<CPolygonWithHoles>> cutters;
  };
  std::vector<std::optional<Attempt>> attempts(kWindowTries);
  auto attempt = [&](int t) -> const Attempt& {
    if (!attempts[t]) {
      Attempt a;
      std::vector<std::vector<std::size_t>> members;
      a.windows = windows_for(group_box, t, members);
      for (const auto& m : members) {
        a.cutters.emplace_back();
        for (std::size_t g : m) {
          for (std::size_t i : groups[g]) a.cutters.back().push_back(exact[i]);
        }
      }
      attempts[t] = std::move(a);
    }
    return *attempts[t];
  };

  std::vector<Piece> out;
  for (std::size_t r = 0; r < base.size(); ++r) {
    std::vector<std::size_t> inside, touching;
    for (std::size_t i = 0; i < n; ++i) {
      if (iso[i] && home[i] == r) inside.push_back(i);
      if (!iso[i] && meet(boxes[i], base[r].outer->box)) touching.push_back(i);
    }
    std::vector<Piece> pieces;
    if (touching.empty()) {
      pieces.push_back(base[r]);
    } else {
      Outcome o = Outcome::kDegenerate;
      for (int t = 0; t < kWindowTries && o == Outcome::kDegenerate; ++t) {
        pieces.clear();
        const Attempt& a = attempt(t);
        o = windowed(base[r], a.windows, a.cutters, settle, pieces);
      }
      if (o == Outcome::kUnchanged) pieces = {base[r]};
      if (o == Outcome::kDegenerate || o == Outcome::kFallback) {
        pieces = plain(base[r], boxes, touching, exact, settle);
      }
    }
    // The isolated obstacles, each in the interior of one piece.
    for (std::size_t i : inside) {
      std::size_t at = pieces.size() == 1 ? 0 : kNone;
      if (at == kNone) {
        const CPoint q = geometry::internal::to_cgal(obstacles[i].outer.vertices.front());
        for (std::size_t k = 0; k < pieces.size() && at == kNone; ++k) {
          if (in_piece(pieces[k], q)) at = k;
        }
      }
      REARM_DEMAND(at != kNone, "topology: an isolated obstacle lies in no piece");
      pieces[at].holes.push_back(double_loop(obstacles[i].outer, true));
    }
    out.insert(out.end(), std::make_move_iterator(pieces.begin()),
               std::make_move_iterator(pieces.end()));
  }
  // The holes of isolated obstacles inside the base: freespace islands.
  for (std::size_t i = 0; i < n; ++i) {
    if (home[i] == kNone) continue;
    for (const Polygon& h : obstacles[i].holes) {
      out.push_back(Piece{double_loop(h, false), {}});
    }
  }
  return out;
}

}  // namespace

struct ExactFreespace::Impl {
  std::vector<Piece> pieces;  // bound − ∪fixed, settled
  std::vector<Box> walls;     // every edge box of `pieces`
  RegionSet components;       // `pieces` rounded
};

ExactFreespace::ExactFreespace(const RegionSet& bound, const RegionSet& fixed) {
  auto impl = std::make_unique<Impl>();
  std::vector<Piece> base;
  if (bound.size() == 1 && bound.front().holes.empty()) {
    base.push_back(Piece{double_loop(bound.front().outer, false), {}});
  } else {
    // Overlapping regions united, and the loops normalized to CGAL's disjoint cycles.
    std::vector<CPolygonWithHoles> parts;
    parts.reserve(bound.size());
    for (const Region& r : bound) parts.push_back(geometry::internal::to_cgal(r));
    PolygonSet s;
    s.join(parts.begin(), parts.end());
    std::vector<CPolygonWithHoles> result;
    s.polygons_with_holes(std::back_inserter(result));
    for (const CPolygonWithHoles& p : result) base.push_back(exact_piece(p, true));
  }
  impl->pieces = difference(base, edge_boxes(base), fixed, true);
  impl->walls = edge_boxes(impl->pieces);
  impl->components = rounded(impl->pieces);
  impl_ = std::move(impl);
}

ExactFreespace::~ExactFreespace() = default;

const RegionSet& ExactFreespace::components() const { return impl_->components; }

RegionSet ExactFreespace::subtract(const std::vector<Polygon>& movable) const {
  std::vector<Region> obstacles;
  obstacles.reserve(movable.size());
  for (const Polygon& p : movable) obstacles.push_back(Region{p, {}});
  return rounded(difference(impl_->pieces, impl_->walls, obstacles, false));
}

namespace {

// The clusters of `result` (pieces of a union clipped to the region), each with the polygons of
// `from` whose boxes meet it as its candidates.
void add_clusters(const std::vector<CPolygonWithHoles>& result,
                  const std::vector<std::size_t>& from, const std::vector<Box>& boxes,
                  Clusters& out) {
  for (const CPolygonWithHoles& p : result) {
    REARM_DEMAND(!p.is_unbounded(), "a bounded Boolean operation gave an unbounded region");
    const Piece piece = exact_piece(p, false);
    std::vector<std::size_t> near;
    for (std::size_t i : from) {
      if (meet(boxes[i], piece.outer->box)) near.push_back(i);
    }
    const std::size_t first = out.regions.size();
    append_rounded(piece, out.regions);
    for (std::size_t k = first; k < out.regions.size(); ++k) {
      out.candidates.push_back(near);
      out.sole.push_back(false);
    }
  }
}

// The region's loops clipped to window w: its material (`material`) and the holes' parts inside
// it (`removed`); `dead` when the window lies in a hole.
Outcome clip_region_to_window(const std::vector<LoopPtr>& loops, const std::vector<Window>& windows,
                              std::size_t w, std::vector<CPolygon>& material,
                              std::vector<CPolygon>& removed, bool& dead) {
  for (std::size_t k = 0; k < loops.size() && !dead; ++k) {
    if (!meet(loops[k]->box, windows[w].box())) continue;
    const Loop& l = *loops[k];
    if (!general_position(l, windows[w])) return Outcome::kDegenerate;
    Cut cut;
    if (!cut_loop(l, k, windows, {w}, cut)) return Outcome::kFallback;
    std::vector<std::size_t> ids(cut.x.size());
    std::iota(ids.begin(), ids.end(), 0);
    if (!ids.empty()) {
      auto parts = clip(cut, std::move(ids), k != 0, windows[w]);
      if (!parts) return Outcome::kFallback;
      auto& to = k == 0 ? material : removed;
      to.insert(to.end(), parts->begin(), parts->end());
    } else if (inside_window(l.exact().vertex(0), windows[w])) {
      CPolygon p = l.exact();
      if (k != 0) p.reverse_orientation();
      (k == 0 ? material : removed).push_back(std::move(p));
    } else if (side_of(l, windows[w].corner(0)) == CGAL::ON_BOUNDED_SIDE) {
      if (k != 0) {
        dead = true;
      } else {
        material.push_back(window_polygon(windows[w]));
      }
    }
  }
  return Outcome::kDone;
}

// (∪ parts) ∩ (∪ material) minus (∪ removed), exactly.
std::vector<CPolygonWithHoles> clipped_union(const std::vector<CPolygon>& parts,
                                             const std::vector<CPolygon>& material,
                                             const std::vector<CPolygon>& removed) {
  std::vector<CPolygonWithHoles> result;
  if (parts.size() == 1 && material.size() == 1 && removed.empty()) {
    CGAL::intersection(parts.front(), material.front(), std::back_inserter(result));
    return result;
  }
  PolygonSet s;
  s.join(parts.begin(), parts.end());
  PolygonSet m;
  m.join(material.begin(), material.end());
  s.intersection(m);
  if (!removed.empty()) {
    PolygonSet u;
    u.join(removed.begin(), removed.end());
    s.difference(u);
  }
  s.polygons_with_holes(std::back_inserter(result));
  return result;
}

// Windowed: (∪ group) ∩ region = (∪ group) ∩ (region ∩ W), the region clipped to each window
// (freespace.h); the groups' unions are disjoint, so are their clusters. False when every try
// of windows was degenerate or one met what the splice does not handle.
bool windowed_union(const std::vector<Polygon>& polygons, const std::vector<LoopPtr>& loops,
                    const std::vector<Box>& boxes, const std::vector<std::size_t>& touching,
                    Clusters& out) {
  const std::vector<std::vector<std::size_t>> groups = box_groups(boxes, touching);
  std::vector<Box> group_box;
  for (const auto& g : groups) {
    Box b = boxes[g.front()];
    for (std::size_t i : g) b += boxes[i];
    group_box.push_back(b);
  }
  for (int t = 0; t < kWindowTries; ++t) {
    std::vector<std::vector<std::size_t>> members;
    const std::vector<Window> windows = windows_for(group_box, t, members);
    std::vector<std::pair<std::vector<CPolygonWithHoles>, std::vector<std::size_t>>> found;
    Outcome o = Outcome::kDone;
    for (std::size_t w = 0; w < windows.size() && o == Outcome::kDone; ++w) {
      std::vector<CPolygon> material, removed;
      bool dead = false;
      o = clip_region_to_window(loops, windows, w, material, removed, dead);
      if (o != Outcome::kDone || dead || material.empty()) continue;
      std::vector<std::size_t> from;
      std::vector<CPolygon> parts;
      for (std::size_t g : members[w]) {
        for (std::size_t i : groups[g]) {
          from.push_back(i);
          parts.push_back(geometry::internal::to_cgal(polygons[i]));
        }
      }
      found.emplace_back(clipped_union(parts, material, removed), std::move(from));
    }
    if (o == Outcome::kDegenerate) continue;
    if (o != Outcome::kDone) return false;  // fallback
    for (const auto& [result, from] : found) add_clusters(result, from, boxes, out);
    return true;
  }
  return false;
}

}  // namespace

Clusters clip_union(const std::vector<Polygon>& polygons, const Region& region) {
  const std::size_t n = polygons.size();
  std::vector<Box> boxes;
  boxes.reserve(n);
  for (const Polygon& p : polygons) boxes.push_back(box_of(p));
  std::vector<LoopPtr> loops{double_loop(region.outer, false)};
  std::vector<Box> walls = loops.front()->edges;
  for (const Polygon& h : region.holes) {
    loops.push_back(double_loop(h, true));
    walls.insert(walls.end(), loops.back()->edges.begin(), loops.back()->edges.end());
  }
  const std::vector<char> iso = isolated(boxes, walls);

  Clusters out;
  std::vector<std::size_t> touching;
  for (std::size_t i = 0; i < n; ++i) {
    if (!iso[i]) {
      if (meet(boxes[i], loops.front()->box)) touching.push_back(i);
      continue;
    }
    // Wholly inside the region or wholly outside; the vertex is on no boundary (exact test).
    if (geometry::contains(region, polygons[i].vertices.front())) {
      out.regions.push_back(Region{polygons[i], {}});
      out.candidates.push_back({i});
      out.sole.push_back(true);
    }
  }
  if (touching.empty()) return out;
  if (windowed_union(polygons, loops, boxes, touching, out)) return out;

  // Plain: one overlay with the region's outer boundary and the holes the polygons reach.
  Region kept{region.outer, {}};
  for (std::size_t k = 1; k < loops.size(); ++k) {
    if (std::any_of(touching.begin(), touching.end(),
                    [&](std::size_t i) { return meet(boxes[i], loops[k]->box); })) {
      kept.holes.push_back(region.holes[k - 1]);
    }
  }
  std::vector<CPolygon> parts;
  parts.reserve(touching.size());
  for (std::size_t i : touching) parts.push_back(geometry::internal::to_cgal(polygons[i]));
  PolygonSet s;
  s.join(parts.begin(), parts.end());
  s.intersection(PolygonSet(geometry::internal::to_cgal(kept)));
  std::vector<CPolygonWithHoles> result;
  s.polygons_with_holes(std::back_inserter(result));
  add_clusters(result, touching, boxes, out);
  return out;
}

}  // namespace rearm::topology::detail
