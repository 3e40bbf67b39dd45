// RELEASE(M, ℓ)'s pose (robust variant, RobustParams::release_pose; docs/executive.md, "Crowded
// rooms"): where the pair's centre x* goes and from which direction, so that M's centre lands
// inside ℓ. The predicate holds wherever in ℓ the object lies (§II-B); the paper drives the
// pair's centre to ℓ's centroid (§IV), and release_point to a point of ℓ from which every
// heading leaves the object inside ℓ. In a crowded room ℓ is about a pair's width: beside a
// wall neither point lies in the pair's freespace, although the object can be set down in ℓ
// with the pair on ℓ's open side. The pose fixes the heading h of the last straight stretch:
// the object's centre lies `lead` (r + dock gap) ahead of the pair's centre along the heading
// (reactive::pair_center), so x* = o − lead·h for an object point o of ℓ.
#pragma once

#include <optional>
#include <string_view>

#include "executive/interface_layer.h"
#include "executive/region.h"
#include "geometry/polygon.h"
#include "perception/semantic_map.h"

namespace rearm::executive {

using geometry::Point;

struct ReleasePose {
  Point object;   // where M's centre lands, at least `inside` within ℓ
  Point pair;     // x*: the pair centre, object − lead·h
  Point lead_in;  // the start of the straight last stretch, pair − approach·h
};

struct ReleasePoseParams {
  double lead = 0;       // m from the pair's centre to the object's along the heading
  double clearance = 0;  // m x* keeps from everything known (the law's goal, with a slack)
  double stretch = 0;    // m every point of the last stretch keeps (the pair's radius)
  double inside = 0;     // m within ℓ for the object's centre
  double approach = 0;   // m: length of the straight last stretch
  double enough = 0;     // m: clearance counted up to when poses are compared
  double step = 0;       // m: grid spacing of the object points
  int headings = 0;      // directions tried at each object point
  Objects objects = Objects::kCounted;  // kIgnored: clearances from the fixed obstacles alone
};

// Object points on a grid of spacing p.step over ℓ (the centroid first), at least p.inside
// within ℓ; for each, p.headings headings h. A pose is kept when its pair centre and every
// sample (kPoseSamples per stretch) of the straight stretch from the lead-in lie in the pair's
// freespace `freespace` (its components; exact point location), x* with known_clearance ≥
// p.clearance from everything known but the carried object, the stretch with p.stretch. Chosen: the
// largest clearance at the pair centre, counted up to p.enough; then the object point nearest ℓ's
// centroid; then the lead-in nearest `from`. nullopt when none is kept. A region needing more than
// kMaxPoseObjectPoints grid points gets a coarser step. Throws rearm::Error on non-finite or
// non-positive parameters.
inline constexpr int kPoseSamples = 8;
inline constexpr double kMaxPoseObjectPoints = 2000;
std::optional<ReleasePose> release_pose(const geometry::RegionSet& freespace,
                                        const RegionOfInterest& region,
                                        const perception::SemanticMap& map,
                                        std::string_view carried, const Point& from,
                                        const ReleasePoseParams& p);

// The object's centre lies at least `inside` within ℓ (exact signed distance).
bool object_inside(const RegionOfInterest& region, const Point& object, double inside);

}  // namespace rearm::executive
