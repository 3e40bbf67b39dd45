// One polygon minus a union of polygons, traced along the crossings of their boundaries
// (declared in cgal_internal.h): the topology check's small window overlays without CGAL's
// arrangement. Exact: the predicates and the crossing points are Epeck's, as in CGAL's own
// Booleans; only inputs in general position are taken.
//
// Every cycle is walked with the result on its left (the material counter-clockwise as given,
// each cutter's outer boundary reversed) and cut at its crossings with the others. A piece of
// the material's boundary bounds the result when no cutter contains it; a piece of a cutter's
// boundary when the material contains it and no other cutter does. Containment is located once
// per pair of cycles, at a vertex, and toggled at each crossing along the walk (a proper
// crossing moves the walk into or out of the other cycle). At a crossing the result's boundary
// leaves the cycle it came along for the other one; at a vertex it goes on along its cycle.
// The traced cycles with the result on their left are outer boundaries when counter-clockwise,
// holes when clockwise; each hole goes to the innermost outer boundary around it.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/cgal_internal.h"

namespace rearm::geometry::internal {
namespace {

using Box = CGAL::Bbox_2;
using Segment = Kernel::Segment_2;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// A boundary cycle with the result on its left.
struct Cycle {
  std::vector<CPoint> v;
  std::vector<Box> edge;  // the box of edge i (v[i] to v[i + 1])
  Box box;
};

// A proper crossing of edge `edge[s]` of cycle `cycle[s]`, s = 0, 1; start[s]: the piece of
// that cycle's boundary that starts here.
struct Crossing {
  CPoint p;
  std::size_t cycle[2];
  std::size_t edge[2];
  std::size_t start[2] = {kNone, kNone};
};

// A piece of a cycle's boundary between two consecutive events (vertices and crossings).
struct Piece {
  std::size_t cycle = 0;
  CPoint from;
  std::size_t from_crossing = kNone;  // kNone: a vertex of the cycle
  bool kept = false;
  std::size_t next = kNone;  // the piece of the result's boundary that follows
};

Cycle make_cycle(std::vector<CPoint> v) {
  Cycle c;
  c.v = std::move(v);
  const std::size_t n = c.v.size();
  c.box = c.v.front().bbox();
  c.edge.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.edge.push_back(c.v[i].bbox() + c.v[(i + 1) % n].bbox());
    c.box += c.edge.back();
  }
  return c;
}

bool meet(const Box& a, const Box& b) { return CGAL::do_overlap(a, b); }

// The proper crossings of two cycles' edges; false at any contact that is not one.
bool cross(const std::vector<Cycle>& cs, std::size_t i, std::size_t j, std::vector<Crossing>& out) {
  const Cycle& a = cs[i];
  const Cycle& b = cs[j];
  for (std::size_t e = 0; e < a.v.size(); ++e) {
    if (!meet(a.edge[e], b.box)) continue;
    const CPoint& p = a.v[e];
    const CPoint& q = a.v[(e + 1) % a.v.size()];
    for (std::size_t f = 0; f < b.v.size(); ++f) {
      if (!meet(a.edge[e], b.edge[f])) continue;
      const CPoint& r = b.v[f];
      const CPoint& s = b.v[(f + 1) % b.v.size()];
      const CGAL::Orientation o1 = CGAL::orientation(p, q, r);
      const CGAL::Orientation o2 = CGAL::orientation(p, q, s);
      if (o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR) return false;
      if (o1 == o2) continue;
      const CGAL::Orientation o3 = CGAL::orientation(r, s, p);
      const CGAL::Orientation o4 = CGAL::orientation(r, s, q);
      if (o3 == CGAL::COLLINEAR || o4 == CGAL::COLLINEAR) return false;
      if (o3 == o4) continue;
      const auto x = CGAL::intersection(Segment(p, q), Segment(r, s));
      const CPoint* point = x ? boost::get<CPoint>(&*x) : nullptr;
      if (point == nullptr) return false;
      out.push_back(Crossing{*point, {i, j}, {e, f}});
    }
  }
  return true;
}

// Is vertex 0 of cycle c inside cycle d? Nullopt on d's boundary.
std::optional<bool> inside(const Cycle& c, const Cycle& d) {
  if (!meet(c.box, d.box)) return false;
  const CGAL::Bounded_side side =
      CGAL::bounded_side_2(d.v.begin(), d.v.end(), c.v.front(), Kernel());
  if (side == CGAL::ON_BOUNDARY) return std::nullopt;
  return side == CGAL::ON_BOUNDED_SIDE;
}

// The crossings on each edge of cycle c, in order along the edge; false when two coincide.
bool order_on_edges(std::size_t c, const Cycle& cycle, const std::vector<Crossing>& xs,
                    std::vector<std::vector<std::size_t>>& on_edge) {
  on_edge.assign(cycle.v.size(), {});
  for (std::size_t k = 0; k < xs.size(); ++k) {
    for (int s = 0; s < 2; ++s) {
      if (xs[k].cycle[s] == c) on_edge[xs[k].edge[s]].push_back(k);
    }
  }
  bool distinct = true;
  for (std::size_t e = 0; e < on_edge.size(); ++e) {
    if (on_edge[e].size() < 2) continue;
    const bool up =
        CGAL::compare_xy(cycle.v[e], cycle.v[(e + 1) % cycle.v.size()]) == CGAL::SMALLER;
    std::sort(on_edge[e].begin(), on_edge[e].end(), [&](std::size_t a, std::size_t b) {
      const CGAL::Comparison_result r = CGAL::compare_xy(xs[a].p, xs[b].p);
      if (r == CGAL::EQUAL) distinct = false;
      return up ? r == CGAL::SMALLER : r == CGAL::LARGER;
    });
  }
  return distinct;
}

// Walks cycle c (0: the material) from vertex 0 with `in` (per cycle: does it contain the walk
// there), appending its pieces; false when the walk does not come back to its start state.
bool walk(std::size_t c, const std::vector<Cycle>& cs, std::vector<Crossing>& xs,
          std::vector<char> in, std::vector<Piece>& pieces) {
  std::vector<std::vector<std::size_t>> on_edge;
  if (!order_on_edges(c, cs[c], xs, on_edge)) return false;
  const std::vector<char> start = in;
  auto kept = [&]() {
    for (std::size_t d = 1; d < cs.size(); ++d) {
      if (d != c && in[d]) return false;
    }
    return c == 0 || in[0] != 0;
  };
  for (std::size_t e = 0; e < cs[c].v.size(); ++e) {
    pieces.push_back(Piece{c, cs[c].v[e], kNone, kept()});
    for (std::size_t k : on_edge[e]) {
      Crossing& x = xs[k];
      const int s = x.cycle[0] == c ? 0 : 1;
      in[x.cycle[1 - s]] ^= 1;
      x.start[s] = pieces.size();
      pieces.push_back(Piece{c, x.p, k, kept()});
    }
  }
  return in == start;
}

// The successor of every kept piece; false when the boundary does not continue.
bool link(const std::vector<Crossing>& xs, std::vector<Piece>& pieces) {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!pieces[i].kept) continue;
    const bool last = i + 1 == pieces.size() || pieces[i + 1].cycle != pieces[i].cycle;
    std::size_t after = i + 1;
    if (last) {  // back to the cycle's first piece
      after = i;
      while (after > 0 && pieces[after - 1].cycle == pieces[i].cycle) --after;
    }
    std::size_t next = after;
    if (pieces[after].from_crossing != kNone) {
      const Crossing& x = xs[pieces[after].from_crossing];
      const int s = x.cycle[0] == pieces[i].cycle ? 0 : 1;
      next = x.start[1 - s];
    }
    if (next == kNone || !pieces[next].kept) return false;
    pieces[i].next = next;
  }
  return true;
}

// The result's boundary cycles, traced along the kept pieces.
std::optional<std::vector<CPolygon>> trace(std::vector<Piece>& pieces) {
  std::vector<CPolygon> out;
  std::vector<char> used(pieces.size(), 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!pieces[i].kept || used[i]) continue;
    CPolygon cycle;
    std::size_t k = i;
    do {
      if (used[k]) return std::nullopt;  // joins another cycle: not a boundary
      used[k] = 1;
      cycle.push_back(pieces[k].from);
      k = pieces[k].next;
    } while (k != i);
    out.push_back(std::move(cycle));
  }
  return out;
}

// Outer boundaries (counter-clockwise) with their holes (clockwise), each hole in the
// innermost outer boundary holding one of its vertices.
std::optional<std::vector<CPolygonWithHoles>> assemble(std::vector<CPolygon> cycles) {
  std::vector<CPolygonWithHoles> out;
  std::vector<CPolygon> holes;
  for (CPolygon& c : cycles) {
    if (c.size() < 3) return std::nullopt;
    if (c.orientation() == CGAL::COUNTERCLOCKWISE) {
      out.emplace_back(std::move(c));
    } else {
      holes.push_back(std::move(c));
    }
  }
  for (CPolygon& h : holes) {
    std::size_t best = kNone;
    for (std::size_t k = 0; k < out.size(); ++k) {
      const CPolygon& o = out[k].outer_boundary();
      if (out.size() > 1 && o.bounded_side(h.vertex(0)) != CGAL::ON_BOUNDED_SIDE) continue;
      if (best == kNone || o.area() < out[best].outer_boundary().area()) best = k;
    }
    if (best == kNone) return std::nullopt;
    out[best].add_hole(std::move(h));
  }
  return out;
}

}  // namespace

std::optional<std::vector<CPolygonWithHoles>> crossing_difference(
    const CPolygon& material, const std::vector<CPolygonWithHoles>& cutters) {
  if (material.size() < 3 || material.orientation() != CGAL::COUNTERCLOCKWISE) return std::nullopt;
  std::vector<Cycle> cs;
  cs.reserve(cutters.size() + 1);
  cs.push_back(make_cycle(std::vector<CPoint>(material.vertices_begin(), material.vertices_end())));
  for (const CPolygonWithHoles& c : cutters) {
    if (c.has_holes() || c.outer_boundary().size() < 3 ||
        c.outer_boundary().orientation() != CGAL::COUNTERCLOCKWISE) {
      return std::nullopt;
    }
    std::vector<CPoint> v(c.outer_boundary().vertices_begin(), c.outer_boundary().vertices_end());
    std::reverse(v.begin(), v.end());
    cs.push_back(make_cycle(std::move(v)));
  }
  std::vector<Crossing> xs;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    for (std::size_t j = i + 1; j < cs.size(); ++j) {
      if (meet(cs[i].box, cs[j].box) && !cross(cs, i, j, xs)) return std::nullopt;
    }
  }
  std::vector<Piece> pieces;
  for (std::size_t c = 0; c < cs.size(); ++c) {
    std::vector<char> in(cs.size(), 0);
    for (std::size_t d = 0; d < cs.size(); ++d) {
      if (d == c) continue;
      const std::optional<bool> is_in = inside(cs[c], cs[d]);
      if (!is_in) return std::nullopt;
      in[d] = *is_in;
    }
    if (!walk(c, cs, xs, std::move(in), pieces)) return std::nullopt;
  }
  if (!link(xs, pieces)) return std::nullopt;
  std::optional<std::vector<CPolygon>> cycles = trace(pieces);
  if (!cycles) return std::nullopt;
  return assemble(std::move(*cycles));
}

}  // namespace rearm::geometry::internal
