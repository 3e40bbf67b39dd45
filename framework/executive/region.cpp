#include "executive/region.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "geometry/convex.h"

namespace rearm::executive {

std::vector<RegionOfInterest> validated(const std::vector<RegionOfInterest>& regions,
                                        const geometry::Polygon& workspace) {
  std::vector<RegionOfInterest> out;
  std::set<std::string> seen;
  for (const RegionOfInterest& r : regions) {
    if (r.id.empty()) throw Error("region of interest: empty id");
    if (!seen.insert(r.id).second) throw Error("region of interest '" + r.id + "': id used twice");
    const std::string what = "region of interest '" + r.id + "'";
    RegionOfInterest v{r.id, geometry::validated(r.polygon, what.c_str())};
    for (const geometry::Point& p : v.polygon.vertices) {
      if (!geometry::contains(workspace, p)) {
        throw Error(what + ": vertex (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                    ") lies outside the workspace");
      }
    }
    out.push_back(std::move(v));
  }
  return out;
}

geometry::Point region_target(const RegionOfInterest& region) {
  const geometry::Point c = region.polygon.centroid();
  if (geometry::contains(region.polygon, c)) return c;
  const std::vector<geometry::Polygon> triangles = geometry::triangulate(region.polygon).or_throw();
  const geometry::Polygon* best = nullptr;
  for (const geometry::Polygon& t : triangles) {
    if (best == nullptr || t.area() > best->area()) best = &t;
  }
  if (best == nullptr) throw Error("region of interest '" + region.id + "': cannot triangulate");
  return best->centroid();
}

std::vector<geometry::Point> region_grid(const RegionOfInterest& region, double step,
                                         double max_points) {
  geometry::Point lo = region.polygon.vertices.front(), hi = lo;
  for (const geometry::Point& v : region.polygon.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const geometry::Point size = hi - lo;
  step = std::max(step, std::sqrt(size.x() * size.y() / max_points));
  step = std::max({step, size.x() / max_points, size.y() / max_points});
  std::vector<geometry::Point> out{region_target(region)};
  const int nx = static_cast<int>(std::floor(size.x() / step));
  const int ny = static_cast<int>(std::floor(size.y() / step));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) out.emplace_back(lo.x() + i * step, lo.y() + j * step);
  }
  return out;
}

}  // namespace rearm::executive
