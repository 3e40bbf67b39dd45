#include "scenario/coverage_grid.h"

#include <algorithm>
#include <cmath>

#include "geometry/proximity.h"

namespace rearm::scenario {

using geometry::Point;

CoverageGrid::CoverageGrid(double width, double height, double cell)
    : h_(cell),
      nx_(std::max(1, static_cast<int>(std::ceil(width / cell)))),
      ny_(std::max(1, static_cast<int>(std::ceil(height / cell)))),
      covered_(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0) {}

std::size_t CoverageGrid::fresh(const geometry::Polygon& p, bool commit) {
  Point lo = p.vertices.front(), hi = lo;
  for (const Point& v : p.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const int x0 = std::max(0, static_cast<int>(lo.x() / h_));
  const int x1 = std::min(nx_ - 1, static_cast<int>(hi.x() / h_));
  const int y0 = std::max(0, static_cast<int>(lo.y() / h_));
  const int y1 = std::min(ny_ - 1, static_cast<int>(hi.y() / h_));
  std::size_t n = 0;
  for (int iy = y0; iy <= y1; ++iy) {
    for (int ix = x0; ix <= x1; ++ix) {
      std::uint8_t& c = covered_[static_cast<std::size_t>(iy * nx_ + ix)];
      if (c != 0 || !geometry::inside_by_crossings(p, Point((ix + 0.5) * h_, (iy + 0.5) * h_))) {
        continue;
      }
      ++n;
      if (commit) c = 1;
    }
  }
  return n;
}

}  // namespace rearm::scenario
