// Objects that close the way to x* where the plain topology check of Appendix III sees none
// (docs/executive.md, "Recoveries"): objects that narrow a passage below what the law gets
// through (grown by kNarrowSlacks), or that close it together with visible unknown fragments;
// the narrow, fragment-blocker and memory-blocker units send them to Fix mode (paper §IV).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "executive/action.h"
#include "executive/context.h"

namespace rearm::executive {

struct Narrowing {
  std::vector<std::size_t> blocking;  // indices into the map's movable objects
  std::string reason;
  double slack = 0;  // m the objects were grown by
};
// The topology check with `fixed` as the fixed obstacles (the topology cache only for the
// familiar ones) and every movable object grown by kNarrowSlacks in turn: the first slack whose
// verdict names objects, or whose grown objects cover the centre (then those whose grown
// dilation contains it); nullopt when fixed obstacles separate x* or no slack names any.
std::optional<Narrowing> grown_blockers(const Context& c,
                                        const std::vector<geometry::Polygon>& fixed,
                                        bool familiar_only, double radius, const Point& center,
                                        const Point& target);
// Fix mode (paper §IV) for the objects `blocking` (indices into the map's movable objects) but
// the action's own object, with the action's guide and back-up budgets renewed; nullopt when
// none is left.
std::optional<Advance> fix_mode_for(const Context& c, ActionState& a,
                                    const std::vector<std::size_t>& blocking, std::string reason);
// B_M (indices into the map's movable objects, as the topology check names them) cut down to a
// minimal subset whose removal leaves x* reachable from the centre, trying the objects farthest
// from the segment centre–x* first; B_M itself when removing all of it does not.
std::vector<std::size_t> minimal_blockers(const Context& c,
                                          const std::vector<std::size_t>& blocking, double radius,
                                          const Point& center, const Point& target);
// The fixed obstacles with the visible unknown fragments (and with RobustParams::memory what was
// seen of them): the obstacles the topology check of Appendix III does not model, added.
std::vector<geometry::Polygon> fixed_with_fragments(const Context& c);
// The topology check's input (Appendix III) with the fixed_with_fragments obstacles: the familiar
// dilations and the bound from the topology cache, the fragments dilated here as the mapped
// space dilates them (miter_limit). check_topology(in) without the cache: bound − ∪fixed
// changes as the fragments grow.
// `objects`: the movable objects (the map's, or a hypothetical placement of them).
topology::TopologyInput input_with_fragments(const Context& c,
                                             const std::vector<geometry::Disk>& objects,
                                             double radius, const Point& x, const Point& target,
                                             std::optional<std::size_t> carried = std::nullopt);
// The topology check again with the visible unknown fragments (and with RobustParams::memory
// what was seen of them) as fixed obstacles: objects that close the way with them, or narrow
// it (grown_blockers), go to Fix mode; counted in RecoveryCounts::fragment_fixes.
std::optional<Advance> closing_with_fragments(const Context& c, ActionState& a, double radius,
                                              const Point& center);

// The components of bound − ∪(familiar obstacles) for a disk of `radius`, the movable objects
// left out (the topology cache's set), and the one that contains `center` (nullopt: none);
// with_fragments: the visible unknown fragments counted as fixed obstacles (fixed_with_fragments).
geometry::RegionSet fixed_components(const Context& c, double radius, bool with_fragments = false);
std::optional<geometry::Region> fixed_component(const Context& c, double radius,
                                                const Point& center, bool with_fragments = false);
// Appends to `out` (once each) the indices of the movable objects but `except` whose disk comes
// within `clearance` of x.
void add_intruders(const Context& c, const Point& x, double clearance, const std::string& except,
                   std::vector<std::size_t>& out);

}  // namespace rearm::executive
