// Convex-polygon helpers in doubles (see convex.h).
#include "geometry/convex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"

namespace rearm::geometry {
namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Edges shorter than this (m) are rounding debris of clipping (a vertex re-created a few ulps
// away from itself); their normals carry no direction, so they are skipped or merged.
constexpr double kDegenerateEdge = 1e-12;

}  // namespace

HalfPlane left_of(const Point& a, const Point& b) {
  const Point t = b - a;
  const Point outward(t.y(), -t.x());  // right-hand normal points out of a CCW polygon
  return HalfPlane{outward, outward.dot(a)};
}

Polygon clip(const Polygon& convex, const HalfPlane& h) {
  Polygon out;
  const std::size_t n = convex.size();
  out.vertices.reserve(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = convex.vertices[i];
    const Point& q = convex.vertices[(i + 1) % n];
    const double fp = h.value(p);
    const double fq = h.value(q);
    auto emit = [&](const Point& x) {
      if (out.vertices.empty() || (x - out.vertices.back()).norm() > kDegenerateEdge) {
        out.vertices.push_back(x);
      }
    };
    if (fp <= 0) emit(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const double t = fp / (fp - fq);
      emit(p + t * (q - p));
    }
  }
  while (out.vertices.size() > 1 &&
         (out.vertices.front() - out.vertices.back()).norm() <= kDegenerateEdge) {
    out.vertices.pop_back();
  }
  if (out.vertices.size() < 3) out.vertices.clear();  // touching only: no area
  return out;
}

Polygon intersect_convex(const Polygon& a, const Polygon& b) {
  Polygon r = a;
  for (std::size_t i = 0, n = b.size(); i < n && r.size() > 0; ++i) {
    r = clip(r, left_of(b.vertices[i], b.vertices[(i + 1) % n]));
  }
  return r;
}

bool convex_contains(const Polygon& convex, const Point& q, double tol) {
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    const Point& a = convex.vertices[i];
    const Point& b = convex.vertices[(i + 1) % n];
    const Point t = b - a;
    const double len = t.norm();
    if (len <= kDegenerateEdge) continue;
    if (cross(t, q - a) / len < -tol) return false;
  }
  return convex.size() > 0;
}

Point project_onto_convex(const Polygon& convex, const Point& q) {
  if (convex.size() == 0) throw Error("project_onto_convex: empty polygon");
  if (convex_contains(convex, q)) return q;
  Point best = convex.vertices.front();
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    const Point& a = convex.vertices[i];
    const Point& b = convex.vertices[(i + 1) % n];
    const Point d = b - a;
    const double len2 = d.squaredNorm();
    double t = len2 > 0 ? (q - a).dot(d) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const Point p = a + t * d;
    const double dist = (p - q).squaredNorm();
    if (dist < best_d) {
      best_d = dist;
      best = p;
    }
  }
  return best;
}

std::optional<Interval> line_interval(const Polygon& convex, const Point& o, const Point& d,
                                      double inset) {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    HalfPlane h = left_of(convex.vertices[i], convex.vertices[(i + 1) % n]);
    const double len = h.normal.norm();
    if (len <= kDegenerateEdge) continue;
    h.normal /= len;
    h.offset = h.offset / len - inset;
    // h.value(o + t d) = h.value(o) + t (normal·d) <= 0
    const double f0 = h.value(o);
    const double fd = h.normal.dot(d);
    if (fd == 0) {
      if (f0 > 0) return std::nullopt;
      continue;
    }
    const double t = -f0 / fd;
    if (fd > 0) {
      hi = std::min(hi, t);
    } else {
      lo = std::max(lo, t);
    }
  }
  if (convex.size() == 0 || lo > hi) return std::nullopt;
  return Interval{lo, hi};
}

std::optional<double> ray_exit(const Polygon& convex, const Point& o, const Point& d) {
  const auto iv = line_interval(convex, o, d);
  if (!iv || iv->lo > 0 || iv->hi < 0) return std::nullopt;
  return iv->hi;
}

Polygon convex_hull(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  Polygon hull;
  if (pts.size() < 3) {
    hull.vertices = pts;
    return hull;
  }
  std::vector<Point> h(2 * pts.size());
  std::size_t k = 0;
  for (const Point& p : pts) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p - h[k - 2]) <= 0) --k;
    h[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    const Point& p = pts[i];
    while (k >= t && cross(h[k - 1] - h[k - 2], p - h[k - 2]) <= 0) --k;
    h[k++] = p;
  }
  h.resize(k - 1);
  hull.vertices = std::move(h);
  return hull;
}

Polygon regular_polygon(const Disk& d, int n, bool circumscribed) {
  REARM_REQUIRE(n >= 3, "regular_polygon: need at least 3 vertices, got ", n);
  REARM_REQUIRE(d.radius > 0 && std::isfinite(d.radius) && d.center.allFinite(),
                "regular_polygon: disk radius must be finite and positive, centre finite, got "
                "radius ",
                d.radius, " at (", d.center.x(), ", ", d.center.y(), ")");
  const double pi = std::numbers::pi;
  const double r = circumscribed ? d.radius / std::cos(pi / n) : d.radius;
  Polygon p;
  p.vertices.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n;
    p.vertices.emplace_back(d.center + r * Point(std::cos(a), std::sin(a)));
  }
  return p;
}

Polygon remove_collinear(const Polygon& p, double tol) {
  std::vector<Point> v;
  v.reserve(p.size());
  for (const Point& q : p.vertices) {
    if (v.empty() || q != v.back()) v.push_back(q);
  }
  while (v.size() > 1 && v.front() == v.back()) v.pop_back();
  bool changed = true;
  while (changed && v.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < v.size() && v.size() > 3; ++i) {
      const Point& a = v[(i + v.size() - 1) % v.size()];
      const Point& b = v[i];
      const Point& c = v[(i + 1) % v.size()];
      const double la = (b - a).norm();
      const double lc = (c - b).norm();
      if (std::abs(cross(b - a, c - b)) <= tol * la * lc && (b - a).dot(c - b) > 0) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        --i;
      }
    }
  }
  return Polygon{std::move(v)};
}

namespace {

// Largest separation of b from a along the outward normals of a's edges: max over edges of
// (min over b's vertices of the signed distance outside that edge); also returns the edge.
std::pair<double, HalfPlane> best_axis(const Polygon& a, const Polygon& b) {
  double best = -std::numeric_limits<double>::infinity();
  HalfPlane best_h;
  for (std::size_t i = 0, n = a.size(); i < n; ++i) {
    const Point& p = a.vertices[i];
    const Point& q = a.vertices[(i + 1) % n];
    const double len = (q - p).norm();
    if (len <= kDegenerateEdge) continue;
    HalfPlane h = left_of(p, q);
    h.normal /= len;
    h.offset /= len;
    double m = std::numeric_limits<double>::infinity();
    for (const Point& v : b.vertices) m = std::min(m, h.value(v));
    if (m > best) {
      best = m;
      best_h = h;
    }
  }
  return {best, best_h};
}

}  // namespace

bool convex_overlap(const Polygon& a, const Polygon& b, double tol) {
  if (a.size() < 3 || b.size() < 3) return false;
  return best_axis(a, b).first < -tol && best_axis(b, a).first < -tol;
}

std::optional<HalfPlane> separating_half_plane(const Polygon& a, const Polygon& b, double tol) {
  if (a.size() < 3 || b.size() < 3) return std::nullopt;
  auto [sa, ha] = best_axis(a, b);  // b outside a's edge: the half-plane a's edge bounds
  auto [sb, hb] = best_axis(b, a);  // a outside b's edge
  if (sa < -tol && sb < -tol) return std::nullopt;
  const HalfPlane pushed{ha.normal, ha.offset + sa};  // a's edge line moved out to touch b
  const HalfPlane flipped{-hb.normal, -hb.offset};    // b's edge line, a on the inside
  if (sa > tol || sb > tol) return sa >= sb ? pushed : flipped;  // a clear gap
  if (sa < -tol) return flipped;
  if (sb < -tol) return pushed;
  // Touching at a point: both lines pass through the contact. Either alone may run along an
  // edge of a (then a's boundary would lie on the cut); the bisecting line through the
  // contact keeps a strictly inside away from the contact, and b outside.
  const Point n = pushed.normal + flipped.normal;
  const double len = n.norm();
  if (len < 1e-9) return flipped;  // parallel edges touching along a segment
  return HalfPlane{n / len, (pushed.offset + flipped.offset) / len};
}

}  // namespace rearm::geometry

namespace rearm::geometry {

Polygon offset_convex(const Polygon& convex, double d, double miter_limit) {
  REARM_REQUIRE(d > 0 && std::isfinite(d), "offset_convex: distance must be finite and > 0, got ",
                d);
  REARM_REQUIRE(miter_limit >= 1, "offset_convex: miter limit must be >= 1, got ", miter_limit);
  const std::size_t n = convex.size();
  Polygon out;
  out.vertices.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point& prev = convex.vertices[(i + n - 1) % n];
    const Point& v = convex.vertices[i];
    const Point& next = convex.vertices[(i + 1) % n];
    const Point t0 = (v - prev).normalized();
    const Point t1 = (next - v).normalized();
    const Point n0(t0.y(), -t0.x());  // outward normals of a counter-clockwise polygon
    const Point n1(t1.y(), -t1.x());
    const Point bis = n0 + n1;
    const double cos_half = bis.norm() / 2;  // cos of half the turning angle
    if (cos_half < 1e-9) {  // a spike (turn of 180°): square cap through both normals
      out.vertices.push_back(v + d * n0);
      out.vertices.push_back(v + d * n1);
    } else if (1 / cos_half > miter_limit && cos_half < 1 - 1e-12) {
      // Bevel: the line perpendicular to the bisector at distance miter_limit·d from v meets
      // offset line 0 at v + d n0 + s t0 (and line 1 symmetrically), with, for the turn φ,
      // s = d (L − cos(φ/2)) / sin(φ/2) = d (L − 1 + 2 sin²(φ/4)) / sin(φ/2), the second form
      // exact for small φ (L = 1 gives the tangent to the round corner, s = d tan(φ/4)).
      const double phi = std::atan2(n0.x() * n1.y() - n0.y() * n1.x(), n0.dot(n1));
      const double q = std::sin(phi / 4);
      const double s = d * (miter_limit - 1 + 2 * q * q) / std::sin(phi / 2);
      out.vertices.push_back(v + d * n0 + s * t0);
      out.vertices.push_back(v + d * n1 - s * t1);
    } else {
      out.vertices.push_back(v + d * bis / (2 * cos_half * cos_half));
    }
  }
  return out;
}

}  // namespace rearm::geometry

namespace rearm::geometry {

Outcome<std::vector<Polygon>> triangulate(const Polygon& simple) {
  std::vector<Point> v = simple.vertices;
  std::vector<Polygon> out;
  auto orient = [](const Point& a, const Point& b, const Point& c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  };
  // Smallest sine of the triangle's angles: the ear clipped is the fattest one, so nearly
  // collinear runs of the boundary are joined to far vertices instead of making slivers.
  auto quality = [&](const Point& a, const Point& b, const Point& c) {
    const double twice = orient(a, b, c);
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    return twice / std::max({ab * bc, bc * ca, ca * ab});
  };
  while (v.size() > 3) {
    const std::size_t n = v.size();
    std::size_t best = n;
    double best_q = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = v[(i + n - 1) % n];
      const Point& b = v[i];
      const Point& c = v[(i + 1) % n];
      if (orient(a, b, c) <= 0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const Point& q = v[k];
        if (q == a || q == b || q == c) continue;
        // Closed triangle test: a vertex on the ear's boundary also blocks it.
        empty = !(orient(a, b, q) >= 0 && orient(b, c, q) >= 0 && orient(c, a, q) >= 0);
      }
      if (!empty) continue;
      const double q = quality(a, b, c);
      if (best == n || q > best_q) {
        best = i;
        best_q = q;
      }
    }
    if (best == n) return Failure{"triangulate: no ear found (the polygon is not simple)"};
    out.push_back(Polygon{{v[(best + n - 1) % n], v[best], v[(best + 1) % n]}});
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(best));
  }
  if (v.size() == 3) out.push_back(Polygon{v});
  return out;
}

}  // namespace rearm::geometry

namespace rearm::geometry {
namespace {

// Relative turn (sine) below which a vertex counts as flat in the extension decomposition.
constexpr double kFlatTurn = 1e-9;

double orient2(const Point& a, const Point& b, const Point& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// First boundary point of q hit by the ray v + t·d (t > 0), skipping the edges incident to
// vertex i: the edge index k (the hit lies on (q[k], q[k+1])), the parameter and the point.
struct RayHit {
  std::size_t edge = 0;
  double t = std::numeric_limits<double>::infinity();
  Point point = Point::Zero();
};

std::optional<RayHit> first_hit(const Polygon& q, std::size_t i, const Point& d) {
  const std::size_t n = q.size();
  const Point& v = q.vertices[i];
  std::optional<RayHit> best;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == i || (k + 1) % n == i) continue;
    const Point& a = q.vertices[k];
    const Point& b = q.vertices[(k + 1) % n];
    const Point e = b - a;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (den == 0) continue;
    const Point w = a - v;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;  // along the ray
    const double s = (w.x() * d.y() - w.y() * d.x()) / den;  // along the edge
    if (t <= 0 || s < 0 || s > 1) continue;
    if (!best || t < best->t) {
      Point hit = s == 0 ? a : (s == 1 ? b : Point(v + t * d));
      best = RayHit{k, t, hit};
    }
  }
  return best;
}

}  // namespace

Outcome<std::vector<Polygon>> decompose_by_extensions(const Polygon& simple,
                                                      std::size_t max_pieces) {
  std::vector<Polygon> stack{simple};
  std::vector<Polygon> out;
  while (!stack.empty()) {
    Polygon q = std::move(stack.back());
    stack.pop_back();
    const std::size_t n = q.size();
    // Extension cuts of every reflex vertex, shortest first; the first that splits q into
    // two proper polygons is made.
    std::vector<std::pair<std::size_t, RayHit>> cuts;
    bool reflex = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Point& prev = q.vertices[(i + n - 1) % n];
      const Point& v = q.vertices[i];
      const Point& next = q.vertices[(i + 1) % n];
      // Reflex beyond rounding: the cut points are rounded onto their lines, which can turn a
      // 180° vertex into a reflex one by an ulp (relative turn tolerance kFlatTurn).
      if (orient2(prev, v, next) >= -kFlatTurn * (v - prev).norm() * (next - v).norm()) continue;
      reflex = true;
      for (const Point& d : {Point(v - prev), Point(v - next)}) {
        if (const auto hit = first_hit(q, i, d.normalized())) cuts.emplace_back(i, *hit);
      }
    }
    if (!reflex) {
      out.push_back(std::move(q));
      continue;
    }
    std::sort(cuts.begin(), cuts.end(),
              [](const auto& l, const auto& r) { return l.second.t < r.second.t; });
    Polygon a, b;
    bool split = false;
    for (const auto& [i, hit] : cuts) {
      // Split q at v = q[i] and the hit point h on edge (k, k+1): one side runs v → ... →
      // q[k] → h, the other h → q[k+1] → ... → v (h is a vertex already when it hit one).
      const std::size_t k = hit.edge;
      const Point& h = hit.point;
      a.vertices.clear();
      b.vertices.clear();
      for (std::size_t j = i;; j = (j + 1) % n) {
        a.vertices.push_back(q.vertices[j]);
        if (j == k) break;
      }
      if (a.vertices.back() != h) a.vertices.push_back(h);
      if (q.vertices[(k + 1) % n] != h) b.vertices.push_back(h);
      for (std::size_t j = (k + 1) % n;; j = (j + 1) % n) {
        b.vertices.push_back(q.vertices[j]);
        if (j == i) break;
      }
      if (a.size() >= 3 && b.size() >= 3 && a.signed_area() > 0 && b.signed_area() > 0) {
        split = true;
        break;
      }
    }
    if (!split) {
      return Failure{
          "decompose_by_extensions: no extension cut splits a piece (is the polygon simple?)"};
    }
    if (out.size() + stack.size() + 2 > max_pieces) {
      return Failure{"decompose_by_extensions: more than " + std::to_string(max_pieces) +
                     " pieces"};
    }
    stack.push_back(std::move(a));
    stack.push_back(std::move(b));
  }
  return out;
}

}  // namespace rearm::geometry
