#include "executive/restores.h"

#include "core/error.h"
#include "geometry/polygon.h"

namespace rearm::executive {
namespace {

// Whether the map locates the object's centre inside region `id` (exact).
bool in_region(const perception::SemanticMap& map, const std::vector<RegionOfInterest>& regions,
               const std::string& object, const std::string& id) {
  const auto d = map.object(object);
  if (!d) return false;
  for (const RegionOfInterest& r : regions) {
    if (r.id == id) return geometry::contains(r.polygon, d->center);
  }
  throw Error("executive: unknown region of interest '" + id + "'");
}

}  // namespace

void Restores::placed(const std::string& object, const std::string& region) {
  placed_[object] = region;
}

void Restores::grasped(const std::string& object) { placed_.erase(object); }

void Restores::displaced(const std::string& object, bool restore) {
  if (const auto p = placed_.find(object); p != placed_.end() && restore) {
    displaced_.emplace_back(p->first, p->second);
  }
}

std::size_t Restores::limit(const perception::SemanticMap& map) {
  return 2 * (map.ground_truth().movable.size() + 1);
}

// The mission is accepting, but Fix mode moved objects that LTL actions had placed (the
// formula's "eventually release" held when they were released, the task's end state has them
// elsewhere): each is released into its region again.
std::optional<std::pair<std::string, std::string>> Restores::next(
    const perception::SemanticMap& map, const std::vector<RegionOfInterest>& regions) {
  while (!displaced_.empty() && count_ < limit(map)) {
    const auto [object, region] = displaced_.front();
    displaced_.erase(displaced_.begin());
    const auto it = placed_.find(object);
    if (it == placed_.end() || it->second != region) continue;  // placed anew since
    if (in_region(map, regions, object, region)) continue;
    ++count_;
    return std::pair{object, region};
  }
  return std::nullopt;
}

std::string Restores::moved(const perception::SemanticMap& map,
                            const std::vector<RegionOfInterest>& regions) const {
  std::string moved;
  for (const auto& [object, id] : placed_) {
    if (!in_region(map, regions, object, id)) {
      moved += (moved.empty() ? "" : ", ") + object + " not in " + id;
    }
  }
  return moved;
}

}  // namespace rearm::executive
