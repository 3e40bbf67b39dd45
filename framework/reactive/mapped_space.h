// Semantic → mapped space (docs/reactive.md §2; paper Appendix II and III): obstacles dilated
// by the robot radius (by r + ρ_i while carrying object i), overlapping ones consolidated, the
// robot's freespace component F_k found, and the enclosing freespace F_e = Conv(F_k) formed.
// Everything in F_e outside F_k is an obstacle for the diffeomorphism: the holes of F_k (one
// per obstacle cluster) and the pockets between F_k and ∂F_e, which are merged into the
// boundary (each pocket touches ∂F_e along one lid edge).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/dilation.h"
#include "geometry/polygon.h"

namespace rearm::reactive {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

// What perception knows, undilated (paper §II): the workspace, the familiar obstacles localized
// so far (whole polygons, possibly non-convex), the visible fragments of unknown convex
// obstacles and the movable objects that are obstacles now (not the carried one).
struct SemanticInput {
  Polygon workspace;
  std::vector<Polygon> familiar;
  std::vector<Polygon> unknown;
  std::vector<Disk> movable;
};

// One polygonal obstacle of the mapped space that the diffeomorphism purges: a cluster hole
// of F_k (deformed to a disk) or a pocket (merged into ∂F_e through its lid edge).
struct FamiliarComponent {
  Polygon polygon;                             // simple, counter-clockwise, no collinear vertex
  std::optional<std::pair<Point, Point>> lid;  // pockets only: the edge on ∂F_e
  // The cluster includes a movable object or an unknown obstacle: its boundary has arcs of
  // many short edges (the circumscribed disk polygons and round dilations of §2).
  bool curved = false;
};

struct MappedSpace {
  double radius = 0;                        // the dilation radius used (r or r + ρ_i)
  Polygon enclosing;                        // F_e: convex, counter-clockwise
  geometry::Region freespace;               // F_k: the robot's freespace component
  std::vector<FamiliarComponent> familiar;  // purged by the diffeomorphism
  std::vector<Polygon> unknown;             // dilated convex fragments, kept as they are
  // Dilated movable objects, kept as they are: disks of radius (ρ + r + kContactSlack) /
  // cos(π / kDiskPolygonSides), circumscribing the polygon the freespace leaves out for them.
  std::vector<Disk> movable;
};

// Thrown by build_mapped_space when the robot (or pair) centre is not in the freespace: an
// expected outcome for the executive (ReactiveController::try_rebuild reports it as a value),
// unlike malformed input.
class NotInFreespace : public Error {
 public:
  explicit NotInFreespace(const std::string& what) : Error(what) {}
};

// Builds the mapped space seen from `robot` (the robot's, or the robot–object pair's, centre).
// Familiar polygons are dilated with miter joins, unknown fragments and the workspace with round
// joins (the workspace is eroded). Documented fallback: a hole of F_k made of one unknown
// fragment stays an unknown convex obstacle, one movable object stays a disk; any other
// cluster (a familiar obstacle, or several overlapping obstacles of any kind) is purged as one
// familiar component. Throws rearm::Error on invalid input (non-finite numbers, invalid
// polygons, a non-convex unknown fragment, radius <= 0), and NotInFreespace when `robot` is
// not in the freespace (start inside an obstacle or outside the workspace).
MappedSpace build_mapped_space(const SemanticInput& input, double radius, const Point& robot);

// Dilations remembered between rebuilds, keyed by the exact vertices and radius: the mitered
// dilations of familiar obstacles (a familiar obstacle never changes once localized, and the
// radius only at a grasp or a release), the round dilations of unknown fragments (a fragment
// changes only when the sensor sees more of it; the others stay as they were) and the eroded
// workspace. Each kind that grows past kDilationCacheEntries is emptied. Not thread-safe (one
// per controller).
inline constexpr std::size_t kDilationCacheEntries = 256;

class DilationCache {
 public:
  // `miter_limit`: geometry::dilate_miter's limit for every dilation of this cache.
  explicit DilationCache(double miter_limit = geometry::kMiterLimit);
  // The mitered dilation of p by d (geometry::dilate_miter), computed once per (p, d).
  const geometry::RegionSet& miter(const Polygon& p, double d);
  // The round dilation of p by d (geometry::dilate_round), computed once per (p, d).
  const geometry::RegionSet& round(const Polygon& p, double d);
  // The workspace eroded by d (geometry::erode), computed once per (workspace, d).
  const geometry::RegionSet& eroded(const Polygon& workspace, double d);
  std::size_t size() const { return miters_.size() + rounds_.size() + erosions_.size(); }
  // A new limit empties the mitered dilations.
  void set_miter_limit(double limit);
  double miter_limit() const { return miter_limit_; }

 private:
  double miter_limit_;
  struct Entry {
    Polygon polygon;
    double distance;
    geometry::RegionSet result;
  };
  template <class Make>
  static const geometry::RegionSet& lookup(std::vector<Entry>& entries, const Polygon& p, double d,
                                           Make make);
  std::vector<Entry> miters_;
  std::vector<Entry> rounds_;
  std::vector<Entry> erosions_;
};

// The same, with the dilations and the erosion taken from (and added to) `cache`; the result is
// identical.
MappedSpace build_mapped_space(const SemanticInput& input, double radius, const Point& robot,
                               DilationCache& cache);

// Where each unknown fragment of the input went in a mapped space: the index of its hole in
// freespace.holes and of its convex obstacle in `unknown` when it is a lone hole of F_k, -1
// otherwise (merged into a cluster or a pocket, or outside F_k).
struct LoneFragments {
  std::vector<int> hole;
  std::vector<int> slot;
};

// Builds the mapped spaces of a sequence of semantic inputs (one controller's rebuilds). A
// moving robot sees its unknown fragments change at almost every step, and in the random
// scenes nearly every rebuild is that alone. When every changed fragment was a lone hole of F_k
// and its new dilation still is (it touches no other dilated obstacle and no boundary of the
// eroded workspace, exact tests; the robot stays in F_k), the previous mapped space is updated
// in place: the fragment's hole and its convex obstacle replaced, everything else as it was.
// Otherwise (and for anything else that changed) the whole construction runs. Both give the
// same mapped space up to the order of freespace.holes and the first vertex of each hole.
class MappedSpaceBuilder {
 public:
  explicit MappedSpaceBuilder(double miter_limit = geometry::kMiterLimit);
  // build_mapped_space(input, radius, robot, dilations()), incrementally where it can.
  MappedSpace build(const SemanticInput& input, double radius, const Point& robot);
  DilationCache& dilations() { return cache_; }
  // Builds that updated the previous mapped space in place.
  int incremental() const { return incremental_; }

 private:
  struct Last {
    SemanticInput input;
    double radius = 0;
    double miter_limit = 0;
    MappedSpace result;
    LoneFragments lone;
  };
  std::optional<MappedSpace> update(const SemanticInput& input, double radius, const Point& robot);
  DilationCache cache_;
  std::optional<Last> last_;
  int incremental_ = 0;
};

// Is x in the closed freespace F_k of the mapped space (exact)?
bool in_freespace(const MappedSpace& m, const Point& x);

}  // namespace rearm::reactive
