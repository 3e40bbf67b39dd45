#include "executive/map_news.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/convex_difference.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double disk_distance(const Disk& d, const Point& x) {
  return std::max(0.0, (d.center - x).norm() - d.radius);
}

template <typename T>
const T* find_named(const std::vector<std::string>& ids, const std::vector<T>& items,
                    const std::string& id) {
  const auto it = std::find(ids.begin(), ids.end(), id);
  return it == ids.end() ? nullptr : &items[static_cast<std::size_t>(it - ids.begin())];
}

}  // namespace

MapSnapshot MapSnapshot::of(const perception::SemanticMap& map) {
  return MapSnapshot{map.familiar_ids(), map.unknown_ids(), map.unknown(), map.movable_ids(),
                     map.movable()};
}

double news_distance(const MapSnapshot& then, const perception::SemanticMap& now, const Point& x) {
  double d = kInfinity;
  for (std::size_t i = 0; i < now.familiar().size(); ++i) {
    const std::string& id = now.familiar_ids()[i];
    if (std::find(then.familiar_ids.begin(), then.familiar_ids.end(), id) ==
        then.familiar_ids.end()) {
      d = std::min(d, geometry::distance(now.familiar()[i], x));
    }
  }
  for (std::size_t j = 0; j < now.unknown().size(); ++j) {
    const Polygon& fragment = now.unknown()[j];
    const Polygon* old = find_named(then.unknown_ids, then.unknown, now.unknown_ids()[j]);
    if (old != nullptr && old->vertices == fragment.vertices) continue;
    const double du =
        geometry::convex_difference_distance(old != nullptr ? *old : Polygon{}, fragment, x);
    d = std::min(d, du);
  }
  for (std::size_t k = 0; k < now.movable().size(); ++k) {
    const Disk& disk = now.movable()[k];
    const Disk* old = find_named(then.movable_ids, then.movable, now.movable_ids()[k]);
    if (old != nullptr && old->center == disk.center && old->radius == disk.radius) continue;
    d = std::min(d, disk_distance(disk, x));
  }
  return d;
}

}  // namespace rearm::executive
