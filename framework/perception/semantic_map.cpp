// The semantic map: memory of familiar obstacles, visible fragments, movable objects and change
// detection (see semantic_map.h).
#include "perception/semantic_map.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"
#include "geometry/box.h"
#include "geometry/convex.h"
#include "geometry/convex_difference.h"

namespace rearm::perception {
namespace {

// Does every vertex of a lie within tol of some vertex of b? Then the convex hull of a lies
// within tol of that of b.
bool covered(const std::vector<Point>& a, const std::vector<Point>& b, double tol2) {
  for (const Point& p : a) {
    bool near = false;
    for (const Point& q : b) {
      if ((p - q).squaredNorm() <= tol2) {
        near = true;
        break;
      }
    }
    if (!near) return false;
  }
  return true;
}

// Did a fragment change by more than tol (kFragmentTolerance)? Fast path: the same vertex count
// matched cyclically from the vertex nearest a[0]; otherwise the symmetric vertex cover.
bool fragment_changed(const std::vector<Point>& a, const std::vector<Point>& b, double tol) {
  if (a.empty() || b.empty()) return a.empty() != b.empty();
  const double tol2 = tol * tol;
  const std::size_t n = a.size();
  if (n == b.size()) {
    std::size_t k = 0;
    double best = (a[0] - b[0]).squaredNorm();
    for (std::size_t j = 1; j < n; ++j) {
      const double d = (a[0] - b[j]).squaredNorm();
      if (d < best) {
        best = d;
        k = j;
      }
    }
    bool same = best <= tol2;
    for (std::size_t i = 1; same && i < n; ++i) {
      same = (a[i] - b[(k + i) % n]).squaredNorm() <= tol2;
    }
    if (same) return false;
  }
  return !(covered(a, b, tol2) && covered(b, a, tol2));
}

// True when the convex fragment `now` adds to `then` a part within `near` of x (both non-empty;
// an empty one is fragment_changed's case).
bool grew_near(const std::vector<Point>& then, const std::vector<Point>& now, const Point& x,
               double near) {
  if (then.size() < 3 || now.size() < 3 || then == now) return false;
  return geometry::convex_difference_distance(Polygon{then}, Polygon{now}, x) <= near;
}

void check_tolerance(double v, const char* what) {
  if (!std::isfinite(v) || v < 0) {
    throw Error(std::string("semantic map: ") + what +
                " tolerance must be finite and non-negative, got " + std::to_string(v));
  }
}

}  // namespace

SemanticMap::SemanticMap(const World& world, const Sensor& sensor, const ChangeTolerances& tol)
    : world_(validated(world)), sensor_(sensor), tol_(tol) {
  check_tolerance(tol.fragment, "fragment");
  check_tolerance(tol.object_move, "object move");
  check_tolerance(tol.scan_spacing, "scan spacing");
  if (tol.scan_spacing > sensor_.range() / kMaxScanSpacingFraction) {
    throw Error("semantic map: the scan spacing (" + std::to_string(tol.scan_spacing) +
                " m) must be at most a quarter of the sensing range (" +
                std::to_string(sensor_.range()) + " m)");
  }
  const std::size_t nf = world_.familiar.size();
  familiar_boxes_.reserve(nf);
  pending_.reserve(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    familiar_boxes_.push_back(geometry::box_of(world_.familiar[i].polygon));
    pending_.push_back(i);
  }
  const std::size_t nu = world_.unknown.size();
  unknown_boxes_.reserve(nu);
  for (const UnknownObstacle& u : world_.unknown) {
    unknown_boxes_.push_back(geometry::box_of(u.polygon));
  }
  // Room for any fragment (a convex m-gon ∩ the footprint has at most m + n vertices) in every
  // buffer, since the clip swaps buffers between obstacles: updates then never allocate.
  std::size_t largest = 0;
  for (const UnknownObstacle& u : world_.unknown) largest = std::max(largest, u.polygon.size());
  const std::size_t cap = largest + static_cast<std::size_t>(sensor_.sides());
  visible_.resize(nu);
  candidate_.resize(nu);
  seen_.resize(nu);
  for (std::size_t j = 0; j < nu; ++j) {
    visible_[j].reserve(cap);
    candidate_[j].reserve(cap);
  }
  scratch_.reserve(cap);
  reported_.reserve(world_.movable.size());
  for (const MovableObject& m : world_.movable) reported_.push_back(m.disk.center);
  movable_.reserve(world_.movable.size());
  movable_ids_.reserve(world_.movable.size());
  for (const MovableObject& m : world_.movable) {
    movable_.push_back(m.disk);
    movable_ids_.push_back(m.id);
  }
}

bool SemanticMap::update(const Point& robot) {
  if (!robot.allFinite()) {
    throw Error("semantic map: robot position is not finite (" + std::to_string(robot.x()) + ", " +
                std::to_string(robot.y()) + ")");
  }
  // What the sensor reports is a function of the robot position alone (the fixed obstacles never
  // move), so an unchanged position changes nothing.
  if (last_robot_ && *last_robot_ == robot) return false;
  last_robot_ = robot;
  const double range = sensor_.range();
  bool changed = false;

  // Familiar obstacles: localized whole once within distance R, then remembered (paper §II).
  std::size_t kept = 0;
  for (const std::size_t i : pending_) {
    const FamiliarObstacle& f = world_.familiar[i];
    if (geometry::within(familiar_boxes_[i], robot, range) && sensor_.sees(f.polygon, robot)) {
      familiar_.push_back(f.polygon);
      familiar_ids_.push_back(f.id);
      changed = true;
    } else {
      pending_[kept++] = i;
    }
  }
  pending_.resize(kept);

  // Unknown obstacles: the fragment inside the footprint, read again once the robot is
  // scan_spacing from the last reading (at every update with 0).
  if (scanned_ && (robot - *scanned_).norm() < tol_.scan_spacing) {
    if (changed) bump();
    return changed;
  }
  scanned_ = robot;
  bool fragments_changed = false;
  for (std::size_t j = 0; j < world_.unknown.size(); ++j) {
    std::vector<Point>& c = candidate_[j];
    if (geometry::within(unknown_boxes_[j], robot,
                         range * (1 + sensor_.params().footprint_tolerance))) {
      sensor_.fragment(world_.unknown[j].polygon, robot, c, scratch_);
      remember(j, c);
    } else {
      c.clear();
    }
    if (!fragments_changed) {
      fragments_changed = fragment_changed(c, visible_[j], tol_.fragment) ||
                          grew_near(visible_[j], c, robot, range * kFragmentNearFraction);
    }
  }
  if (fragments_changed) {
    std::swap(visible_, candidate_);
    unknown_.clear();
    unknown_ids_.clear();
    for (std::size_t j = 0; j < visible_.size(); ++j) {
      if (visible_[j].empty()) continue;
      unknown_.push_back(Polygon{visible_[j]});
      unknown_ids_.push_back(world_.unknown[j].id);
    }
    changed = true;
  }

  if (changed) bump();
  return changed;
}

void SemanticMap::remember(std::size_t j, const std::vector<Point>& fragment) {
  Polygon& hull = seen_[j];
  const bool grows = std::any_of(fragment.begin(), fragment.end(), [&](const Point& v) {
    return hull.size() < 3 || !geometry::convex_contains(hull, v, kSeenGrowth);
  });
  if (!grows) return;
  std::vector<Point> points = hull.vertices;
  points.insert(points.end(), fragment.begin(), fragment.end());
  hull = geometry::remove_collinear(geometry::convex_hull(std::move(points)), kSeenCollinear);
}

void SemanticMap::bump() {
  ++version_;
  movable_.clear();
  movable_ids_.clear();
  for (std::size_t i = 0; i < world_.movable.size(); ++i) {
    const MovableObject& m = world_.movable[i];
    reported_[i] = m.disk.center;
    if (carried_ && *carried_ == m.id) continue;
    movable_.push_back(m.disk);
    movable_ids_.push_back(m.id);
  }
}

std::size_t SemanticMap::find_object(std::string_view id) const {
  for (std::size_t i = 0; i < world_.movable.size(); ++i) {
    if (world_.movable[i].id == id) return i;
  }
  throw Error("semantic map: no movable object with id '" + std::string(id) + "'");
}

bool SemanticMap::id_in_use(std::string_view id) const {
  const auto same = [id](const auto& item) { return item.id == id; };
  return std::any_of(world_.familiar.begin(), world_.familiar.end(), same) ||
         std::any_of(world_.unknown.begin(), world_.unknown.end(), same) ||
         std::any_of(world_.movable.begin(), world_.movable.end(), same);
}

bool SemanticMap::move_object(std::string_view id, const Point& center) {
  const std::size_t i = find_object(id);
  MovableObject& m = world_.movable[i];
  if (!center.allFinite()) {
    throw Error("semantic map: movable object '" + m.id + "': new centre is not finite");
  }
  m.disk.center = center;
  if (carried_ && *carried_ == m.id) return false;
  if ((center - reported_[i]).norm() <= tol_.object_move) return false;
  bump();
  return true;
}

bool SemanticMap::add_object(const MovableObject& object) {
  validate_movable(object);
  if (id_in_use(object.id)) {
    throw Error("semantic map: duplicate id '" + object.id + "' (movable object)");
  }
  world_.movable.push_back(object);
  reported_.push_back(object.disk.center);
  bump();
  return true;
}

bool SemanticMap::remove_object(std::string_view id) {
  const std::size_t i = find_object(id);
  if (carried_ && *carried_ == id) carried_.reset();
  world_.movable.erase(world_.movable.begin() + static_cast<std::ptrdiff_t>(i));
  reported_.erase(reported_.begin() + static_cast<std::ptrdiff_t>(i));
  bump();
  return true;
}

bool SemanticMap::set_carried(std::optional<std::string_view> id) {
  if (id) find_object(*id);  // throws on an unknown id
  if (carried_.has_value() == id.has_value() && (!id || *carried_ == *id)) return false;
  if (id) {
    carried_ = std::string(*id);
  } else {
    carried_.reset();
  }
  bump();
  return true;
}

bool SemanticMap::is_localized(std::string_view id) const {
  return std::find(familiar_ids_.begin(), familiar_ids_.end(), id) != familiar_ids_.end();
}

std::optional<Disk> SemanticMap::object(std::string_view id) const {
  for (const MovableObject& m : world_.movable) {
    if (m.id == id) return m.disk;
  }
  return std::nullopt;
}

}  // namespace rearm::perception
