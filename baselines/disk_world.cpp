#include "baselines/disk_world.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/distance.h"

namespace rearm::baselines {

using geometry::Point;

namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

double point_segment_distance(const Point& x, const Point& a, const Point& b) {
  return (x - geometry::nearest_on_segment(a, b, x)).norm();
}

// Proper or touching intersection of two segments by orientation signs.
bool segments_intersect(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on = [](const Point& p, const Point& q, const Point& r, double o) {
    return o == 0 && std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4);
}

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

}  // namespace

double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (segments_intersect(a, b, c, d)) return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

DiskWorld::DiskWorld(const geometry::Polygon& workspace, std::vector<geometry::Polygon> obstacles)
    : workspace_(workspace), obstacles_(std::move(obstacles)) {
  if (workspace_.size() < 3) throw Error("DiskWorld: the workspace needs at least 3 vertices");
  lo_ = hi_ = workspace_.vertices[0];
  for (const auto& v : workspace_.vertices) {
    if (!finite(v)) throw Error("DiskWorld: non-finite workspace vertex");
    lo_ = lo_.cwiseMin(v);
    hi_ = hi_.cwiseMax(v);
  }
  for (const auto& o : obstacles_) {
    if (o.size() < 3) throw Error("DiskWorld: an obstacle needs at least 3 vertices");
    Box b{o.vertices[0], o.vertices[0]};
    for (const auto& v : o.vertices) {
      if (!finite(v)) throw Error("DiskWorld: non-finite obstacle vertex");
      b.lo = b.lo.cwiseMin(v);
      b.hi = b.hi.cwiseMax(v);
    }
    boxes_.push_back(b);
  }
}

bool DiskWorld::segment_free(const Point& a, const Point& b, double radius, double margin,
                             const std::vector<geometry::Disk>& disks,
                             std::optional<std::size_t> skip) const {
  if (!finite(a) || !finite(b) || !std::isfinite(radius) || !std::isfinite(margin)) return false;
  const double need = radius + margin;
  // Inside the workspace: both ends inside and the segment at >= need from every edge (then it
  // never crosses the boundary).
  if (!geometry::contains(workspace_, a) || !geometry::contains(workspace_, b)) return false;
  const std::size_t nw = workspace_.size();
  for (std::size_t k = 0; k < nw; ++k)
    if (segment_distance(a, b, workspace_.vertices[k], workspace_.vertices[(k + 1) % nw]) < need)
      return false;
  const Point slo = a.cwiseMin(b) - Point(need, need), shi = a.cwiseMax(b) + Point(need, need);
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const Box& box = boxes_[i];
    if (box.hi.x() < slo.x() || box.lo.x() > shi.x() || box.hi.y() < slo.y() ||
        box.lo.y() > shi.y())
      continue;
    const auto& o = obstacles_[i];
    // An end inside the polygon means distance 0; otherwise the distance is attained on edges.
    if (geometry::contains(o, a) || geometry::contains(o, b)) return false;
    for (std::size_t k = 0; k < o.size(); ++k)
      if (segment_distance(a, b, o.vertices[k], o.vertices[(k + 1) % o.size()]) < need)
        return false;
  }
  for (std::size_t j = 0; j < disks.size(); ++j) {
    if (skip && *skip == j) continue;
    if (point_segment_distance(disks[j].center, a, b) < need + disks[j].radius) return false;
  }
  return true;
}

}  // namespace rearm::baselines
