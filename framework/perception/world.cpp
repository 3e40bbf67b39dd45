// Validation of the ground-truth world (see world.h).
#include "perception/world.h"

#include <cmath>
#include <string>
#include <unordered_set>

#include "core/error.h"

namespace rearm::perception {
namespace {

std::string label(const char* kind, const std::string& id) {
  return std::string(kind) + " '" + id + "'";
}

void check_id(const char* kind, const std::string& id, std::unordered_set<std::string>& seen) {
  if (id.empty()) throw Error(std::string("world: a ") + kind + " has an empty id");
  if (!seen.insert(id).second) {
    throw Error("world: duplicate id '" + id + "' (" + kind + "); ids must be unique");
  }
}

}  // namespace

void validate_movable(const MovableObject& m) {
  if (m.id.empty()) throw Error("world: a movable object has an empty id");
  const std::string what = label("movable object", m.id);
  if (!m.disk.center.allFinite()) throw Error(what + ": centre is not finite");
  if (!std::isfinite(m.disk.radius)) throw Error(what + ": radius is not finite");
  if (!(m.disk.radius > 0)) {
    throw Error(what + ": radius must be positive, got " + std::to_string(m.disk.radius));
  }
}

World validated(const World& w) {
  World out;
  out.workspace = geometry::validated(w.workspace, "world: workspace");
  std::unordered_set<std::string> seen;
  out.familiar.reserve(w.familiar.size());
  for (const FamiliarObstacle& f : w.familiar) {
    check_id("familiar obstacle", f.id, seen);
    const std::string what = "world: " + label("familiar obstacle", f.id);
    out.familiar.push_back({f.id, geometry::validated(f.polygon, what.c_str())});
  }
  out.unknown.reserve(w.unknown.size());
  for (const UnknownObstacle& u : w.unknown) {
    check_id("unknown obstacle", u.id, seen);
    const std::string what = "world: " + label("unknown obstacle", u.id);
    Polygon p = geometry::validated(u.polygon, what.c_str());
    if (!p.is_convex()) throw Error(what + ": must be convex (paper §II), it has a reflex vertex");
    out.unknown.push_back({u.id, std::move(p)});
  }
  out.movable.reserve(w.movable.size());
  for (const MovableObject& m : w.movable) {
    check_id("movable object", m.id, seen);
    validate_movable(m);
    out.movable.push_back(m);
  }
  return out;
}

}  // namespace rearm::perception
