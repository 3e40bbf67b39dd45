#include "executive/context.h"

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "core/stopwatch.h"
#include "core/text.h"
#include "geometry/dilation.h"
#include "reactive/grasp.h"

namespace rearm::executive {

std::string point_text(const Point& p) {
  return "(" + rearm::fixed(p.x(), 3) + ", " + rearm::fixed(p.y(), 3) + ")";
}

Moving moving(const Context& c, const ActionState& a, const Pose& pose) {
  const std::optional<std::string> carried = c.map.carried();
  const double r = plan_radius(c, a);
  if (!carried) return {0, r, pose.x};
  const double rho = object_radius(c, *carried);
  return {rho, r + rho + c.p.grasp.pair_margin, reactive::pair_center(pose.x, pose.psi, rho)};
}

const RegionOfInterest& region(const Context& c, const std::string& id) {
  for (const RegionOfInterest& r : c.regions) {
    if (r.id == id) return r;
  }
  throw Error("executive: unknown region of interest '" + id + "'");
}

double object_radius(const Context& c, const std::string& id) {
  const auto d = c.map.object(id);
  if (!d) throw Error("executive: unknown object '" + id + "'");
  return d->radius;
}

double max_object_radius(const Context& c) {
  double m = 0;
  for (const auto& o : c.map.ground_truth().movable) m = std::max(m, o.disk.radius);
  return m;
}

double plan_radius(const Context& c) { return c.p.robot_radius + c.p.robust.contact_margin; }

double plan_radius(const Context& c, const ActionState& a) {
  return a.bare ? c.p.robot_radius : plan_radius(c);
}

double miter_limit(const ExecutiveParams& p) {
  return p.robust.bevel ? kBevelMiterLimit : geometry::kMiterLimit;
}

reactive::SemanticInput semantic_input(const Context& c) {
  return reactive::SemanticInput{c.map.workspace(), c.map.familiar(), c.map.unknown(),
                                 c.map.movable()};
}

topology::TopologyResult timed_check(const Context& c, double radius, const Point& x,
                                     const Point& target) {
  const ScopedStopwatch sw(c.times.topology_s);
  const topology::TopologyInput in =
      topology::make_input(c.map.workspace(), c.map.familiar(), c.map.movable(), radius, x, target,
                           std::nullopt, c.topology_cache);
  return topology::check_topology(in, c.topology_cache);
}

}  // namespace rearm::executive
