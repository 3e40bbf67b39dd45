// Regions of interest ℓ_j of the task (paper §II): named polygons of the workspace that the
// actions MOVE(ℓ_j) and RELEASE(M_i, ℓ_j) refer to.
#pragma once

#include <string>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::executive {

struct RegionOfInterest {
  std::string id;
  geometry::Polygon polygon;
};

// Checks the regions against the workspace: non-empty unique ids, valid polygons
// (geometry::validated), every vertex inside the workspace (exact). Returns them with every
// polygon counter-clockwise. Throws rearm::Error naming the region and the defect.
std::vector<RegionOfInterest> validated(const std::vector<RegionOfInterest>& regions,
                                        const geometry::Polygon& workspace);

// The navigation target of a region (paper §IV: "the centroid of region ℓ_j"). When the area
// centroid of a non-convex region lies outside it, the centroid of its largest ear-clipping
// triangle is used instead, so the target is always inside the region.
geometry::Point region_target(const RegionOfInterest& region);

// Candidate points of a region: region_target first, then a grid of spacing `step` (m) over the
// region's bounding box from its lower-left corner (row by row), coarsened so that it has at
// most about `max_points` points. Points of the grid may lie outside the region.
std::vector<geometry::Point> region_grid(const RegionOfInterest& region, double step,
                                         double max_points);

}  // namespace rearm::executive
