#include "executive/guide_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <span>
#include <string>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

using geometry::Point;
using geometry::Polygon;
using geometry::Region;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kFar = 1e20;  // "no blocked cell" in the distance transform (finite)
// Cells searched around an endpoint whose own cell centre is outside F_k.
constexpr int kEndpointSearchCells = 6;

struct Raster {
  double x0 = 0, y0 = 0, res = 0;
  int nx = 0, ny = 0;
  std::vector<unsigned char> free;  // cell centre in F_k
  std::vector<float> clear;         // m, from the distance transform
  Point center(int i, int j) const { return {x0 + (i + 0.5) * res, y0 + (j + 0.5) * res}; }
  int index(int i, int j) const { return j * nx + i; }
};

template <typename F>
void for_each_edge(const Region& r, F&& f) {
  auto ring = [&](const Polygon& p) {
    for (std::size_t k = 0; k < p.size(); ++k) f(p.vertices[k], p.vertices[(k + 1) % p.size()]);
  };
  ring(r.outer);
  for (const Polygon& h : r.holes) ring(h);
}

// The space a path runs through: the region F_k less convex polygons it does not model
// (guide_path's `blocked`, already dilated).
struct Space {
  const Region& free;
  std::span<const Polygon> blocked;
  // Is [a, b] in the space, at distance >= c from its boundary?
  bool segment_clear(const Point& a, const Point& b, double c) const;
  // Distance from x to the space's boundary; 0 outside.
  double clearance(const Point& x) const;
};

// Scanline fill: a cell is free when its centre lies inside an odd number of rings (the holes
// lie inside the outer ring and are disjoint, so even-odd is F_k's membership).
void fill(const Region& r, Raster& g) {
  std::vector<double> xs;
  for (int j = 0; j < g.ny; ++j) {
    const double y = g.y0 + (j + 0.5) * g.res;
    xs.clear();
    for_each_edge(r, [&](const Point& a, const Point& b) {
      if ((a.y() > y) != (b.y() > y))
        xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    });
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int lo = std::max(0, static_cast<int>(std::ceil((xs[k] - g.x0) / g.res - 0.5)));
      const int hi =
          std::min(g.nx - 1, static_cast<int>(std::floor((xs[k + 1] - g.x0) / g.res - 0.5)));
      for (int i = lo; i <= hi; ++i) g.free[g.index(i, j)] = 1;
    }
  }
}

// One-dimensional squared Euclidean distance transform (Felzenszwalb & Huttenlocher, 2012) of
// f into d: d[q] = min_p (q − p)² + f[p] (z[0] = −∞ in the original: a value below every
// intersection).

void edt_1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
            std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  auto meet = [&](int q, int p) {
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
  };
  int k = 0;
  v[0] = 0;
  z[0] = -kFar * 10;
  z[1] = kFar * 10;
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (k > 0 && s <= z[k]) s = meet(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kFar * 10;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
  }
}

// Clearance of every free cell: distance (m) from its centre to the nearest blocked cell centre,
// less half a cell (the boundary lies between them); cells outside the raster count as blocked.
void clearance(Raster& g) {
  const int w = g.nx + 2, h = g.ny + 2;  // a blocked frame around the raster
  std::vector<double> grid(static_cast<std::size_t>(w) * h, 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) grid[(j + 1) * w + i + 1] = g.free[g.index(i, j)] ? kFar : 0.0;
  std::vector<double> f(w), d(w), z(w + 1);
  std::vector<int> v(w);
  for (int j = 0; j < h; ++j) {
    f.assign(grid.begin() + j * w, grid.begin() + (j + 1) * w);
    edt_1d(f, d, v, z);
    std::copy(d.begin(), d.end(), grid.begin() + j * w);
  }
  f.resize(h), d.resize(h), v.resize(h), z.resize(h + 1);
  for (int i = 0; i < w; ++i) {
    for (int j = 0; j < h; ++j) f[j] = grid[j * w + i];
    edt_1d(f, d, v, z);
    for (int j = 0; j < h; ++j) grid[j * w + i] = d[j];
  }
  g.clear.assign(g.free.size(), 0.0f);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      g.clear[g.index(i, j)] =
          std::max(0.0f, float((std::sqrt(grid[(j + 1) * w + i + 1]) - 0.5) * g.res));
}

// Cells whose centre lies in a blocked convex polygon are not free (scanline, as in fill).
void unfill(const Polygon& convex, Raster& g) {
  double lo = kInf, hi = -kInf;
  for (const Point& v : convex.vertices) lo = std::min(lo, v.y()), hi = std::max(hi, v.y());
  const int j0 = std::max(0, static_cast<int>(std::ceil((lo - g.y0) / g.res - 0.5)));
  const int j1 = std::min(g.ny - 1, static_cast<int>(std::floor((hi - g.y0) / g.res - 0.5)));
  for (int j = j0; j <= j1; ++j) {
    const double y = g.y0 + (j + 0.5) * g.res;
    double x_lo = kInf, x_hi = -kInf;
    for (std::size_t k = 0; k < convex.size(); ++k) {
      const Point& a = convex.vertices[k];
      const Point& b = convex.vertices[(k + 1) % convex.size()];
      if ((a.y() > y) == (b.y() > y)) continue;
      const double x = a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
    }
    if (!(x_lo <= x_hi)) continue;
    const int lo_i = std::max(0, static_cast<int>(std::ceil((x_lo - g.x0) / g.res - 0.5)));
    const int hi_i = std::min(g.nx - 1, static_cast<int>(std::floor((x_hi - g.x0) / g.res - 0.5)));
    for (int i = lo_i; i <= hi_i; ++i) g.free[g.index(i, j)] = 0;
  }
}

Raster rasterize(const Space& s, const GuideParams& p) {
  const Region& r = s.free;
  Raster g;
  double lo_x = kInf, lo_y = kInf, hi_x = -kInf, hi_y = -kInf;
  for (const Point& v : r.outer.vertices) {
    lo_x = std::min(lo_x, v.x()), lo_y = std::min(lo_y, v.y());
    hi_x = std::max(hi_x, v.x()), hi_y = std::max(hi_y, v.y());
  }
  g.res = p.resolution;
  const double cells = (hi_x - lo_x) * (hi_y - lo_y) / (g.res * g.res);
  if (cells > double(p.max_cells)) g.res *= std::sqrt(cells / double(p.max_cells));
  g.x0 = lo_x, g.y0 = lo_y;
  g.nx = std::max(1, static_cast<int>(std::ceil((hi_x - lo_x) / g.res)));
  g.ny = std::max(1, static_cast<int>(std::ceil((hi_y - lo_y) / g.res)));
  g.free.assign(static_cast<std::size_t>(g.nx) * g.ny, 0);
  fill(r, g);
  for (const Polygon& b : s.blocked) unfill(b, g);
  clearance(g);
  return g;
}

// The free cell nearest to x among those within kEndpointSearchCells whose centre x sees in the
// space.
std::optional<int> endpoint_cell(const Raster& g, const Space& r, const Point& x) {
  const int ci = static_cast<int>(std::floor((x.x() - g.x0) / g.res));
  const int cj = static_cast<int>(std::floor((x.y() - g.y0) / g.res));
  std::optional<int> best;
  double best_d = kInf;
  for (int j = cj - kEndpointSearchCells; j <= cj + kEndpointSearchCells; ++j) {
    for (int i = ci - kEndpointSearchCells; i <= ci + kEndpointSearchCells; ++i) {
      if (i < 0 || j < 0 || i >= g.nx || j >= g.ny || !g.free[g.index(i, j)]) continue;
      const double d = (g.center(i, j) - x).norm();
      if (d < best_d && r.segment_clear(x, g.center(i, j), 0)) best_d = d, best = g.index(i, j);
    }
  }
  return best;
}

// A* over 8-neighbours; returns cell indices from start to goal.
std::optional<std::vector<int>> search(const Raster& g, int start, int goal, const GuideParams& p) {
  const Point target = g.center(goal % g.nx, goal / g.nx);
  const Point source = g.center(start % g.nx, start / g.nx);
  std::vector<float> cost(g.free.size(), kInf);
  std::vector<int> parent(g.free.size(), -1);
  using Entry = std::pair<float, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[start] = 0;
  open.push({float((g.center(start % g.nx, start / g.nx) - target).norm()), start});
  constexpr int kDi[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  constexpr int kDj[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    const auto [f, c] = open.top();
    open.pop();
    if (c == goal) break;
    const int i = c % g.nx, j = c / g.nx;
    const Point pc = g.center(i, j);
    if (f - float((pc - target).norm()) > cost[c] + 1e-4f) continue;  // stale entry
    for (int k = 0; k < 8; ++k) {
      const int ni = i + kDi[k], nj = j + kDj[k];
      if (ni < 0 || nj < 0 || ni >= g.nx || nj >= g.ny) continue;
      const int n = g.index(ni, nj);
      if (!g.free[n]) continue;
      if (g.clear[n] < p.avoid && (g.center(ni, nj) - source).norm() > kAvoidExempt &&
          (g.center(ni, nj) - target).norm() > kAvoidExempt) {
        continue;
      }
      // A diagonal step needs both orthogonal neighbours free (no corner cutting).
      if (k >= 4 && (!g.free[g.index(ni, j)] || !g.free[g.index(i, nj)])) continue;
      const double shortfall = std::max(0.0, 1.0 - g.clear[n] / p.comfort);
      const float step =
          float((k < 4 ? 1.0 : std::sqrt(2.0)) * g.res * (1 + p.comfort_weight * shortfall));
      if (cost[c] + step < cost[n]) {
        cost[n] = cost[c] + step;
        parent[n] = c;
        open.push({cost[n] + float((g.center(ni, nj) - target).norm()), n});
      }
    }
  }
  if (cost[goal] == kInf) return std::nullopt;
  std::vector<int> cells;
  for (int c = goal; c != -1; c = parent[c]) cells.push_back(c);
  std::reverse(cells.begin(), cells.end());
  return cells;
}

// Shortcuts the polyline: from each anchor, the farthest point reached by clear segments before
// the first that is not (a narrow stretch keeps the raster's own steps). A segment must keep the
// clearance of the raster path it replaces (the least clearance of its points, less one cell,
// capped at `comfort`, never below `floor`): the A* search prefers cells `comfort` from ∂F_k,
// and a shortcut that hugs a corner again would bring the law back to the corners where
// clusters stop it.
std::vector<Point> shortcut(const Space& r, const std::vector<Point>& line,
                            const std::vector<double>& clear, double res, double floor,
                            double comfort) {
  std::vector<Point> out;
  std::size_t anchor = 0;
  while (anchor + 1 < line.size()) {
    std::size_t next = anchor + 1;
    double least = std::min(clear[anchor], clear[anchor + 1]);
    for (std::size_t k = anchor + 2; k < line.size(); ++k) {
      least = std::min(least, clear[k]);
      const double need = std::clamp(least - res, floor, std::max(floor, comfort));
      if (!r.segment_clear(line[anchor], line[k], need)) break;
      next = k;
    }
    out.push_back(line[next]);
    anchor = next;
  }
  return out;
}

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
         d4 != 0;
}

double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (segments_cross(a, b, c, d)) return 0;
  return std::min({(geometry::nearest_on_segment(c, d, a) - a).norm(),
                   (geometry::nearest_on_segment(c, d, b) - b).norm(),
                   (geometry::nearest_on_segment(a, b, c) - c).norm(),
                   (geometry::nearest_on_segment(a, b, d) - d).norm()});
}

}  // namespace

void validate(const GuideParams& p) {
  const std::pair<const char*, double> positive[] = {{"resolution", p.resolution},
                                                     {"comfort", p.comfort},
                                                     {"comfort_weight", p.comfort_weight},
                                                     {"clearance", p.clearance},
                                                     {"reach", p.reach}};
  for (const auto& [name, v] : positive) {
    if (!std::isfinite(v) || !(v > 0)) {
      throw Error(std::string("guide: ") + name + " must be finite and > 0");
    }
  }
  if (!std::isfinite(p.avoid) || p.avoid < 0) {
    throw Error("guide: avoid must be finite and >= 0");
  }
  if (p.max_cells < 16) throw Error("guide: max_cells must be at least 16");
  if (p.max_recoveries < 0) throw Error("guide: max_recoveries must be >= 0");
}

bool segment_clear(const Region& free, const Point& a, const Point& b, double c) {
  if (!geometry::contains(free, a) || !geometry::contains(free, b)) return false;
  bool ok = true;
  for_each_edge(free, [&](const Point& p, const Point& q) {
    if (ok && (segments_cross(a, b, p, q) || (c > 0 && segment_distance(a, b, p, q) < c))) {
      ok = false;
    }
  });
  return ok && geometry::contains(free, Point((a + b) / 2));
}

namespace {

// Does [a, b] keep the distance c from the closed convex polygon?
bool clear_of(const Polygon& convex, const Point& a, const Point& b, double c) {
  if (geometry::convex_contains(convex, a) || geometry::convex_contains(convex, b) ||
      geometry::convex_contains(convex, Point((a + b) / 2))) {
    return false;
  }
  for (std::size_t k = 0; k < convex.size(); ++k) {
    const Point& p = convex.vertices[k];
    const Point& q = convex.vertices[(k + 1) % convex.size()];
    if (segments_cross(a, b, p, q) || (c > 0 && segment_distance(a, b, p, q) < c)) return false;
  }
  return true;
}

bool Space::segment_clear(const Point& a, const Point& b, double c) const {
  if (!executive::segment_clear(free, a, b, c)) return false;
  return std::all_of(blocked.begin(), blocked.end(),
                     [&](const Polygon& p) { return clear_of(p, a, b, c); });
}

double Space::clearance(const Point& x) const {
  if (!geometry::contains(free, x)) return 0;
  double d = geometry::nearest_on_boundary(free, x).distance;
  for (const Polygon& p : blocked) d = std::min(d, geometry::distance(p, x));
  return d;
}

// Dijkstra over the raster's 8-neighbours from the cell of `from` (diagonals only where both
// side cells are free): `visit(cell, cost)` in order of cost until it returns true. False when
// `from` has no cell or the walk ends unstopped.
template <typename Visit>
bool walk(const Raster& g, const Space& free, const Point& from, Visit&& visit) {
  const std::optional<int> s = endpoint_cell(g, free, from);
  if (!s) return false;
  std::vector<float> cost(g.free.size(), kInf);
  using Entry = std::pair<float, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[*s] = 0;
  open.push({0.0f, *s});
  constexpr int kDi[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  constexpr int kDj[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    const auto [d, c] = open.top();
    open.pop();
    if (d > cost[c]) continue;
    if (visit(c, d)) return true;
    const int i = c % g.nx, j = c / g.nx;
    for (int k = 0; k < 8; ++k) {
      const int ni = i + kDi[k], nj = j + kDj[k];
      if (ni < 0 || nj < 0 || ni >= g.nx || nj >= g.ny) continue;
      const int n = g.index(ni, nj);
      if (!g.free[n] || (k >= 4 && (!g.free[g.index(ni, j)] || !g.free[g.index(i, nj)]))) continue;
      const float step = float((k < 4 ? 1.0 : std::sqrt(2.0)) * g.res);
      if (cost[c] + step < cost[n]) {
        cost[n] = cost[c] + step;
        open.push({cost[n], n});
      }
    }
  }
  return false;
}

void check_search(const Point& from, double clearance) {
  if (!from.allFinite() || !std::isfinite(clearance)) {
    throw Error("drop point: the start and the clearance must be finite");
  }
}

}  // namespace

std::optional<ClearPoint> nearest_clear_point(
    const Region& free, const Point& from, std::span<const double> clearances,
    const std::function<bool(const Point&, std::size_t)>& accept, const GuideParams& p,
    bool clearest_last) {
  validate(p);
  check_search(from, 0.0);
  for (double c : clearances) check_search(from, c);
  const Space space{free, {}};
  const Raster g = rasterize(space, p);
  const std::size_t last = clearances.size();  // the clearest-point level
  std::optional<ClearPoint> out;
  std::size_t open_levels = last;  // levels that can still improve on `out`
  float best = -kInf;              // the clearest accepted cell so far (clearest_last)
  walk(g, space, from, [&](int c, float) {
    const Point q = g.center(c % g.nx, c / g.nx);
    for (std::size_t k = 0; k < open_levels; ++k) {
      if (g.clear[c] >= clearances[k] && accept(q, k)) {
        out = ClearPoint{q, k};
        open_levels = k;
        return open_levels == 0;
      }
    }
    // The walk is by cost: the first of equally clear cells is the nearest.
    if (clearest_last && open_levels == last && g.clear[c] > best && accept(q, last)) {
      best = g.clear[c];
      out = ClearPoint{q, last};
    }
    return false;
  });
  return out;
}

std::optional<Point> clearest_point(const Region& free, const Point& from,
                                    const std::function<bool(const Point&)>& accept,
                                    const GuideParams& p) {
  const auto q = nearest_clear_point(
      free, from, {}, [&](const Point& x, std::size_t) { return accept(x); }, p, true);
  if (!q) return std::nullopt;
  return q->point;
}

std::optional<std::vector<Point>> guide_path(const Region& free, const Point& from, const Point& to,
                                             const GuideParams& p,
                                             std::span<const Polygon> blocked) {
  validate(p);
  if (!from.allFinite() || !to.allFinite()) throw Error("guide: endpoints must be finite");
  // A blocked polygon holding an endpoint is left out: the robot stands there, or x* lies there.
  std::vector<Polygon> kept;
  for (const Polygon& b : blocked) {
    if (b.size() < 3) throw Error("guide: a blocked polygon needs at least 3 vertices");
    if (!geometry::convex_contains(b, from) && !geometry::convex_contains(b, to)) kept.push_back(b);
  }
  const Space space{free, kept};
  const Raster g = rasterize(space, p);
  const std::optional<int> s = endpoint_cell(g, space, from);
  const std::optional<int> t = endpoint_cell(g, space, to);
  if (!s || !t) return std::nullopt;
  const std::optional<std::vector<int>> cells = search(g, *s, *t, p);
  if (!cells) return std::nullopt;
  std::vector<Point> line{from};
  std::vector<double> clear{space.clearance(from)};
  for (int c : *cells) {
    line.push_back(g.center(c % g.nx, c / g.nx));
    clear.push_back(g.clear[c]);
  }
  line.push_back(to);
  clear.push_back(space.clearance(to));
  return shortcut(space, line, clear, g.res, p.clearance, p.comfort);
}

}  // namespace rearm::executive
