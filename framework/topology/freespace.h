// INTERNAL to framework/topology: the exact Booleans of the topology check (Appendix III,
// steps 1, 3 and 4), localized to where shapes interact, and the exact set bound − ∪fixed kept
// between calls. CGAL stays in freespace.cpp (docs/architecture.md); this header speaks doubles.
//
// Every set returned is the exact result of the regularized Boolean (CGAL Polygon_set_2 over
// the exact-constructions kernel), rounded to doubles as geometry::subtract rounds its results
// (each boundary cycle cut into simple loops; counter-clockwise loops bound material). One
// global overlay of everything costs about 1 µs per input edge (2 ms at 10 objects and 20
// obstacles); the localization only chooses *which* boundary pieces go into *which* exact
// overlay, so the sets are those of the global overlay (tests/topology/freespace_test compares
// them over random scenes); only the order of the components and the first vertex of a loop
// may differ.
//
// Difference base − ∪obstacles (base: interior-disjoint exact pieces, an outer cycle and holes
// each, cycles meeting at most at points, as CGAL returns them):
//  - Isolated obstacles. An obstacle whose bounding box meets the box of no other obstacle and
//    of no edge of the base has a boundary that meets no other boundary and no base loop inside
//    it, so it lies wholly in the interior of one base piece or wholly outside the base: one
//    exact point location of a vertex says which. Inside, it becomes a hole of the piece (its
//    own holes become pieces: freespace islands), with no overlay; outside, it changes
//    nothing. (Most objects of a room, none of those at a wall, a door or another object.)
//  - Windows. The other obstacles are grouped by overlapping boxes; each group gets a window,
//    an axis-parallel rectangle around the group's box grown by 1/16 of its larger side
//    (windows that meet are merged). Each piece reaching a window is cut where its loops
//    cross the window's boundary (exact intersection points): the parts inside the window
//    (Weiler–Atherton against the rectangle) minus the group's obstacles go through one small
//    exact overlay (one part and obstacles without holes whose boundaries meet only in proper
//    crossings: traced along the crossings by geometry::internal::crossing_difference, under a
//    quarter of the time of CGAL's arrangement per window at 10 objects × 20 obstacles while
//    carrying; otherwise CGAL's); the overlay's boundary chains between crossing points
//    replace the loops' chains inside the window, spliced at the crossing points (which then
//    drop out: each lies inside an edge of the piece that the result follows straight
//    through); loops the windows do not reach stay as they are. The resulting cycles are
//    sorted into pieces by exact point location. A window is in general position when no loop
//    vertex lies on its boundary and no loop edge passes through a corner (exact tests); otherwise
//    a larger window is tried (four in all). Loops through one point twice, and anything else the
//    splice does not expect, send the piece to the plain overlay (its outer cycle and the holes the
//    obstacles' boxes reach, minus the obstacles; the other holes then located in the result).
//  Boxes of exact (non-double) points are CGAL's interval enclosures and every box test is
//  conservative: taking a shape as interacting when it is not only costs an overlay.
//
// Determinism: the exact numbers of a kept set are evaluated to the end when it is built
// (settled), so their interval approximations, and hence every rounding to doubles and every
// construction that later starts from them, no longer depend on what other calls computed.
// Same inputs, same doubles out, whether the kept set is fresh or has served other calls
// (tests/topology/topology_cache_test).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::topology::detail {

// bound − ∪fixed, exact, settled; immutable once built (share it freely between calls).
class ExactFreespace {
 public:
  // bound and fixed: validated regions (geometry::validated loops); bound regions may overlap
  // (they are united), fixed regions may overlap each other and the bound's boundary.
  ExactFreespace(const geometry::RegionSet& bound, const geometry::RegionSet& fixed);
  ~ExactFreespace();
  ExactFreespace(const ExactFreespace&) = delete;
  ExactFreespace& operator=(const ExactFreespace&) = delete;

  // The components of bound − ∪fixed, rounded.
  const geometry::RegionSet& components() const;
  // The components of (bound − ∪fixed) − ∪movable, rounded; movable: validated simple polygons
  // (counter-clockwise).
  geometry::RegionSet subtract(const std::vector<geometry::Polygon>& movable) const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

// The components of (∪ polygons) ∩ region, exact and rounded (polygons: simple,
// counter-clockwise; region: validated loops, holes inside the outer boundary), localized as
// above: an isolated polygon is its own component when a vertex lies in the region (exact) and
// absent otherwise; each group of the others is intersected with the region clipped to the
// group's window (no splice needed: the result lies inside the window).
struct Clusters {
  geometry::RegionSet regions;
  // Per region: the polygons that may touch it (a superset: box filter).
  std::vector<std::vector<std::size_t>> candidates;
  // Per region: it is candidates[0]'s polygon alone, which no other polygon touches.
  std::vector<bool> sole;
};
Clusters clip_union(const std::vector<geometry::Polygon>& polygons, const geometry::Region& region);

}  // namespace rearm::topology::detail
