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
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
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

// The orientation of a simple cycle, from the sign of its area in interval arithmetic when that
// decides (it does unless the area is nearly zero); else CGAL's exact test, whose leftmost-vertex
// search compares coordinates that are often equal (window sides) and so exact.
CGAL::Orientation orientation_of(const CPolygon& c) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    CGAL::Interval_nt<false> twice_area = 0;
    for (std::size_t i = 0, n = c.size(); i < n; ++i) {
      const auto& p = c.vertex(i).approx();
      const auto& q = c.vertex((i + 1) % n).approx();
      twice_area += p.x() * q.y() - q.x() * p.y();
    }
    if (twice_area.inf() > 0) return CGAL::COUNTERCLOCKWISE;
    if (twice_area.sup() < 0) return CGAL::CLOCKWISE;
  }
  return c.orientation();
}

// The crossing point of segments pq and rs (a proper crossing) whose ends are doubles,
// c = (p, q, r, s) coordinate by coordinate: X = p + t (q − p), t = ((r − p) × (s − r)) /
// ((q − p) × (s − r)), computed in integers (every coordinate an integer multiple of 2^lo, lo
// the smallest binary exponent among them) and made an exact point directly, its
// approximation the tight interval of its value: what the lazy construction evaluates to when
// settled, without its node and the rationals' normalization at every step.
CPoint crossing_of_doubles(const std::array<double, 8>& c) {
  constexpr int kMantissa = std::numeric_limits<double>::digits;
  int lo = std::numeric_limits<int>::max();
  std::array<double, 8> mantissa{};
  std::array<int, 8> exponent{};
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] == 0) continue;
    mantissa[i] = std::frexp(c[i], &exponent[i]);
    lo = std::min(lo, exponent[i] - kMantissa);
  }
  std::array<mpz_class, 8> z;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] == 0) continue;
    z[i] = mpz_class(std::ldexp(mantissa[i], kMantissa));  // an integer below 2^53
    z[i] <<= static_cast<mp_bitcnt_t>(exponent[i] - kMantissa - lo);
  }
  const mpz_class dx = z[2] - z[0], dy = z[3] - z[1], ex = z[6] - z[4], ey = z[7] - z[5];
  const mpz_class den = dx * ey - dy * ex;
  const mpz_class num = (z[4] - z[0]) * ey - (z[5] - z[1]) * ex;
  auto coordinate = [&](const mpz_class& start, const mpz_class& d) {
    mpq_class q(start * den + num * d, den);
    q.canonicalize();
    if (lo < 0) {
      mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-lo));
    } else {
      mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(lo));
    }
    return Kernel::Exact_kernel::FT(q.get_mpq_t());
  };
  return CPoint(
      CPoint::Rep(Kernel::Exact_kernel::Point_2(coordinate(z[0], dx), coordinate(z[1], dy))));
}

// The crossing point of the properly crossing segments pq and rs, exact.
std::optional<CPoint> crossing_point(const CPoint& p, const CPoint& q, const CPoint& r,
                                     const CPoint& s) {
  if (is_double(p) && is_double(q) && is_double(r) && is_double(s)) {
    std::array<double, 8> c;
    std::size_t k = 0;
    for (const CPoint* v : {&p, &q, &r, &s}) {
      const Point d = double_point(*v);
      c[k++] = d.x();
      c[k++] = d.y();
    }
    return crossing_of_doubles(c);
  }
  const auto x = CGAL::intersection(Segment(p, q), Segment(r, s));
  const CPoint* point = x ? boost::get<CPoint>(&*x) : nullptr;
  if (point == nullptr) return std::nullopt;
  return *point;
}

// The proper crossings of two cycles' edges; false at any contact that is not one (and,
// conservatively, whenever an end of one edge lies on the other's line while their boxes meet).
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
      const std::optional<CPoint> x = crossing_point(p, q, r, s);
      if (!x) return false;
      out.push_back(Crossing{*x, {i, j}, {e, f}});
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
    // Points of one edge are ordered by either coordinate that differs between its ends; the
    // one that differs more leaves the interval filters room (a window side has one coordinate
    // equal at all its crossings, which only the exact numbers could compare).
    const CPoint& a = cycle.v[e];
    const CPoint& b = cycle.v[(e + 1) % cycle.v.size()];
    const auto& ia = a.approx();
    const auto& ib = b.approx();
    bool by_x = std::abs(ib.x().inf() - ia.x().inf()) >= std::abs(ib.y().inf() - ia.y().inf());
    CGAL::Comparison_result dir = by_x ? CGAL::compare_x(a, b) : CGAL::compare_y(a, b);
    if (dir == CGAL::EQUAL) {
      by_x = !by_x;
      dir = by_x ? CGAL::compare_x(a, b) : CGAL::compare_y(a, b);
    }
    std::sort(on_edge[e].begin(), on_edge[e].end(), [&](std::size_t i, std::size_t j) {
      const CGAL::Comparison_result r =
          by_x ? CGAL::compare_x(xs[i].p, xs[j].p) : CGAL::compare_y(xs[i].p, xs[j].p);
      if (r == CGAL::EQUAL) distinct = false;
      return r == dir;
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
    if (orientation_of(c) == CGAL::COUNTERCLOCKWISE) {
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
  if (material.size() < 3 || orientation_of(material) != CGAL::COUNTERCLOCKWISE) {
    return std::nullopt;
  }
  std::vector<Cycle> cs;
  cs.reserve(cutters.size() + 1);
  cs.push_back(make_cycle(std::vector<CPoint>(material.vertices_begin(), material.vertices_end())));
  for (const CPolygonWithHoles& c : cutters) {
    if (c.has_holes() || c.outer_boundary().size() < 3 ||
        orientation_of(c.outer_boundary()) != CGAL::COUNTERCLOCKWISE) {
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
