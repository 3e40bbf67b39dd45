// The planners' collision model (docs/experiments.md, "Baseline": "validity = disk vs polygons
// and disks"): the full map offline (workspace and every obstacle polygon) and the objects of an
// arrangement as disks. A disk swept along a segment (a capsule) is free when its distance to
// every obstacle, to the workspace boundary and to every other disk is at least its radius plus
// a margin — tested exactly in double precision (segment–segment and point–segment distances),
// so the planners need no discretized motion checks. The plan validator (validator.h) checks
// plans by a different method (sampled geometry::disk_clearance), independently of this one.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::baselines {

class DiskWorld {
 public:
  // Throws rearm::Error for an empty workspace or non-finite coordinates.
  DiskWorld(const geometry::Polygon& workspace, std::vector<geometry::Polygon> obstacles);

  // The disk of `radius` swept from a to b keeps distance >= margin from the boundary (inside
  // the workspace), from every obstacle, and from every disk in `disks` but `skip`.
  bool segment_free(const geometry::Point& a, const geometry::Point& b, double radius,
                    double margin, const std::vector<geometry::Disk>& disks,
                    std::optional<std::size_t> skip = std::nullopt) const;
  bool disk_free(const geometry::Point& c, double radius, double margin,
                 const std::vector<geometry::Disk>& disks,
                 std::optional<std::size_t> skip = std::nullopt) const {
    return segment_free(c, c, radius, margin, disks, skip);
  }

  const geometry::Polygon& workspace() const { return workspace_; }
  const std::vector<geometry::Polygon>& obstacles() const { return obstacles_; }
  // The workspace's axis-aligned bounding box.
  geometry::Point lower() const { return lo_; }
  geometry::Point upper() const { return hi_; }

 private:
  struct Box {
    geometry::Point lo, hi;
  };
  geometry::Polygon workspace_;
  std::vector<geometry::Polygon> obstacles_;
  std::vector<Box> boxes_;
  geometry::Point lo_, hi_;
};

// Distance between segments [a, b] and [c, d] (0 when they intersect).
double segment_distance(const geometry::Point& a, const geometry::Point& b,
                        const geometry::Point& c, const geometry::Point& d);

}  // namespace rearm::baselines
