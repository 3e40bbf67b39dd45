// Sensor model of paper §II (see sensor.h).
#include "perception/sensor.h"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.h"
#include "geometry/convex.h"

namespace rearm::perception {
namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Squared distance from x to the segment [a, b].
double segment_distance2(const Point& a, const Point& b, const Point& x) {
  const Point d = b - a;
  const double len2 = d.squaredNorm();
  double t = len2 > 0 ? (x - a).dot(d) / len2 : 0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return (a + t * d - x).squaredNorm();
}

// Even-odd point location for an x farther than R > 0 from every edge. Rounding in the
// crossing abscissa matters only within a few ulps of an edge, so this double-precision test
// decides exactly here, without the exact predicate's allocation on the per-tick path.
bool inside_far_from_boundary(const Polygon& p, const Point& x) {
  bool inside = false;
  for (std::size_t i = 0, n = p.size(), j = n - 1; i < n; j = i++) {
    const Point& a = p.vertices[i];
    const Point& b = p.vertices[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < a.x() + (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

void check_point(const Point& x, const char* what) {
  if (!x.allFinite()) {
    throw Error(std::string(what) + ": robot position is not finite (" + std::to_string(x.x()) +
                ", " + std::to_string(x.y()) + ")");
  }
}

// Relative turning below which a fragment vertex counts as collinear (or reflex by rounding):
// the sine of the turning angle. The exact intersection is convex, so any non-left turn is an
// artefact of rounding in the clip.
constexpr double kCollinearSine = 1e-9;

// Removes coincident and collinear vertices of a convex polygon in place.
void clean_convex(std::vector<Point>& v) {
  constexpr double merge2 = kFragmentMergeDistance * kFragmentMergeDistance;
  std::size_t k = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (k == 0 || (v[i] - v[k - 1]).squaredNorm() > merge2) v[k++] = v[i];
  }
  while (k > 1 && (v[k - 1] - v[0]).squaredNorm() <= merge2) --k;
  v.resize(k);
  bool changed = true;
  while (changed && v.size() >= 3) {
    changed = false;
    std::size_t m = 0;
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = m == 0 ? v[n - 1] : v[m - 1];
      const Point& b = v[i];
      const Point& c = v[(i + 1) % n];
      const Point e1 = b - a;
      const Point e2 = c - b;
      if (cross(e1, e2) <= kCollinearSine * e1.norm() * e2.norm()) {
        changed = true;  // drop b
      } else {
        v[m++] = b;
      }
    }
    v.resize(m);
  }
  if (v.size() < 3) v.clear();
}

double area(const std::vector<Point>& v) {
  double twice = 0;
  for (std::size_t i = 0, n = v.size(); i < n; ++i) twice += cross(v[i], v[(i + 1) % n]);
  return twice / 2;
}

}  // namespace

Sensor::Sensor(const SensorParams& params) : params_(params) {
  if (!std::isfinite(params.range) || !(params.range > 0)) {
    throw Error("sensor: range R must be finite and positive, got " + std::to_string(params.range));
  }
  const double tol = params.footprint_tolerance;
  if (!std::isfinite(tol) || !(tol > 0)) {
    throw Error("sensor: footprint tolerance must be finite and positive, got " +
                std::to_string(tol));
  }
  if (!std::isfinite(params.sliver_area) || params.sliver_area < 0) {
    throw Error("sensor: sliver area must be finite and non-negative, got " +
                std::to_string(params.sliver_area));
  }
  const double pi = std::numbers::pi;
  int n = kMinFootprintSides;
  while (1 / std::cos(pi / n) - 1 > tol) {
    if (++n > kMaxFootprintSides) {
      throw Error("sensor: footprint tolerance " + std::to_string(tol) + " needs more than " +
                  std::to_string(kMaxFootprintSides) + " sides");
    }
  }
  normals_.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * pi * (k + 0.5) / n;
    normals_.emplace_back(std::cos(a), std::sin(a));
  }
}

Polygon Sensor::footprint(const Point& x) const {
  check_point(x, "sensor footprint");
  return geometry::regular_polygon(geometry::Disk{x, params_.range}, sides(), true);
}

bool Sensor::sees(const Polygon& p, const Point& x) const {
  check_point(x, "sensor");
  if (p.size() < 3) throw Error("sensor: polygon has fewer than 3 vertices");
  const double r2 = params_.range * params_.range;
  Point lo = p.vertices.front();
  Point hi = lo;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Point& a = p.vertices[i];
    if (segment_distance2(a, p.vertices[(i + 1) % n], x) <= r2) return true;
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(a);
  }
  // The boundary is out of range: the polygon meets the disk only if it contains x.
  if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) return false;
  return inside_far_from_boundary(p, x);
}

void Sensor::fragment(const Polygon& convex, const Point& x, std::vector<Point>& out,
                      std::vector<Point>& scratch) const {
  check_point(x, "sensor");
  out.assign(convex.vertices.begin(), convex.vertices.end());
  const double range = params_.range;
  // Sutherland–Hodgman against each footprint edge { q : u·(q − x) <= R }, ping-ponging between
  // the two buffers; an edge that keeps every vertex costs one pass and no copy.
  for (const Point& u : normals_) {
    bool any_out = false;
    bool any_in = false;
    for (const Point& q : out) {
      if (u.dot(q - x) > range) {
        any_out = true;
      } else {
        any_in = true;
      }
    }
    if (!any_out) continue;
    if (!any_in) {
      out.clear();
      return;
    }
    scratch.clear();
    for (std::size_t i = 0, n = out.size(); i < n; ++i) {
      const Point& p = out[i];
      const Point& q = out[(i + 1) % n];
      const double fp = u.dot(p - x) - range;
      const double fq = u.dot(q - x) - range;
      if (fp <= 0) scratch.push_back(p);
      if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) scratch.push_back(p + fp / (fp - fq) * (q - p));
    }
    std::swap(out, scratch);
  }
  clean_convex(out);
  if (!out.empty() && area(out) < params_.sliver_area) out.clear();
}

Polygon Sensor::fragment(const Polygon& convex, const Point& x) const {
  Polygon out;
  std::vector<Point> scratch;
  fragment(convex, x, out.vertices, scratch);
  return out;
}

}  // namespace rearm::perception
