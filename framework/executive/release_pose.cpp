#include "executive/release_pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "executive/interface_layer.h"
#include "geometry/distance.h"

namespace rearm::executive {
namespace {

void check(const ReleasePoseParams& p, const Point& from) {
  const bool finite = std::isfinite(p.lead) && std::isfinite(p.clearance) &&
                      std::isfinite(p.stretch) && std::isfinite(p.inside) &&
                      std::isfinite(p.approach) && std::isfinite(p.enough) && std::isfinite(p.step);
  if (!finite || !(p.lead > 0) || !(p.clearance > 0) || !(p.stretch > 0) || !(p.inside >= 0) ||
      !(p.approach > 0) || !(p.step > 0) || p.headings < 1 || !from.allFinite()) {
    throw Error(
        "release pose: lead, clearance, stretch, approach and step must be finite and > 0, inside "
        ">= 0, "
        "headings >= 1, the start finite");
  }
}

// The object points: ℓ's centroid, then a grid over ℓ (region_grid), each at least `inside`
// within ℓ.
std::vector<Point> object_points(const RegionOfInterest& region, double inside, double step) {
  std::vector<Point> out = region_grid(region, step, kMaxPoseObjectPoints);
  std::erase_if(out, [&](const Point& o) { return !object_inside(region, o, inside); });
  return out;
}

}  // namespace

bool object_inside(const RegionOfInterest& region, const Point& object, double inside) {
  return -geometry::signed_distance(region.polygon, object) >= inside;
}

std::optional<ReleasePose> release_pose(const geometry::RegionSet& freespace,
                                        const RegionOfInterest& region,
                                        const perception::SemanticMap& map,
                                        std::string_view carried, const Point& from,
                                        const ReleasePoseParams& p) {
  check(p, from);
  const Point centroid = region_target(region);
  auto clearance = [&](const Point& x) {
    return p.objects == Objects::kCounted ? known_clearance(map, x, carried)
                                          : fixed_clearance(map, x);
  };
  auto free = [&](const Point& x) {
    return geometry::contains(freespace, x) && clearance(x) >= p.stretch;
  };
  std::optional<ReleasePose> best;
  double best_score = 0, best_centre = 0, best_from = 0;
  for (const Point& o : object_points(region, p.inside, p.step)) {
    for (int k = 0; k < p.headings; ++k) {
      const double angle = 2 * std::numbers::pi * k / p.headings;
      const Point h(std::cos(angle), std::sin(angle));
      const ReleasePose pose{o, o - p.lead * h, o - (p.lead + p.approach) * h};
      if (!geometry::contains(freespace, pose.pair)) continue;
      const double score = std::min(clearance(pose.pair), p.enough);
      if (score < p.clearance) continue;
      const double centre = (o - centroid).norm();
      const double distance = (pose.lead_in - from).norm();
      // Cheaper tests first: the stretch is sampled only for a pose that would win.
      const bool wins = !best || score > best_score ||
                        (score == best_score &&
                         (centre < best_centre || (centre == best_centre && distance < best_from)));
      if (!wins) continue;
      bool stretch = true;
      for (int s = 0; s < kPoseSamples && stretch; ++s) {
        stretch = free(pose.lead_in + (pose.pair - pose.lead_in) * (double(s) / kPoseSamples));
      }
      if (!stretch) continue;
      best = pose;
      best_score = score;
      best_centre = centre;
      best_from = distance;
    }
  }
  return best;
}

}  // namespace rearm::executive
