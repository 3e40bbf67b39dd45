// The semantic map (paper §II and Appendix II; docs/reactive.md §2): what the robot knows of the
// world. Familiar obstacles localized so far (memory, never forgotten), the fragments of unknown
// convex obstacles visible now (recomputed at every update; the reactive layer of [7] sees these
// alone), what has been seen of each unknown obstacle so far (for the robust variant's guide
// paths, which the paper does not have), and the movable
// objects (known at all times) except the carried one. A `version` counter increments exactly
// when this knowledge changes, so the reactive layer rebuilds its diffeomorphism only then
// (docs/reactive.md §2: "rebuild only when the semantic map changes").
//
// The accessors return the kinds of reactive::SemanticInput (workspace, familiar, unknown,
// movable), with parallel id lists for the executive and the figures.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/box.h"
#include "perception/sensor.h"
#include "perception/world.h"

namespace rearm::perception {

// A visible fragment changes (bumping the version) when some vertex moved by more than this
// (m): each vertex of the new fragment must lie within it of a vertex of the old one and vice
// versa. A moving robot changes its fragments continuously and that is intended; a robot
// standing still (or jittering by rounding) changes nothing.
inline constexpr double kFragmentTolerance = 1e-3;
// Whatever the tolerance, a fragment changes when it grew (geometry/convex_difference.h) within
// this fraction of the sensing range R of the robot: the tolerance is there for the growth where
// the footprint cuts an obstacle, about R away, and must not hide an obstacle's corner that the
// footprint cut off earlier and the robot now approaches (a 0.1 m tolerance let the law's local
// freespace reach 0.1 m into such a corner, and the robot touched it). With scan_spacing at most
// R/4, what the map misses stays at least R/4 from the robot.
inline constexpr double kFragmentNearFraction = 0.5;
// A movable object moved (bumping the version) when its centre is farther than this (m) from
// where the map last reported it; slower motion accumulates until it crosses the tolerance.
inline constexpr double kObjectMoveTolerance = 1e-3;

// The unknown fragments are read again once the robot has travelled this far (m) from where
// they were last read; 0 reads them at every update (the paper's sensor, §II). Between readings
// the fragments are those seen from a point within s of the robot, whose footprint contains
// the disk of radius R − s around it: everything within R − s of the robot is known as at
// every update. At most the sensing range R over kMaxScanSpacingFraction.
inline constexpr double kMaxScanSpacingFraction = 4;

// What has been seen of an unknown obstacle grows (its convex hull is recomputed) when a vertex
// of a new fragment lies more than this (m) outside it.
inline constexpr double kSeenGrowth = 1e-3;
// Hull vertices whose turn is below this (the cross product of the unit edge directions) are
// dropped: the cut points of successive footprints on one obstacle edge are collinear.
inline constexpr double kSeenCollinear = 1e-9;

struct ChangeTolerances {
  double fragment = kFragmentTolerance;
  double object_move = kObjectMoveTolerance;
  double scan_spacing = 0;
};

class SemanticMap {
 public:
  // Validates the world (world.h) and the tolerances (finite, non-negative); throws rearm::Error.
  // Starts at version 0 with nothing localized and nothing visible; call update() with the
  // robot's first position.
  SemanticMap(const World& world, const Sensor& sensor, const ChangeTolerances& tol = {});

  // Senses from robot position x (paper §II): localizes every familiar obstacle within distance
  // R, recomputes the visible fragments (when x is scan_spacing from the last reading). Returns
  // true (and increments the version once) when the map changed. O(obstacles); with nothing new it
  // allocates nothing. Throws rearm::Error when x is not finite.
  bool update(const Point& robot);

  // Movable objects (paper §II: positions known at all times). Each returns true (and increments
  // the version once) when the map changed. Throws rearm::Error on an unknown id, a duplicate id
  // or an invalid object. The carried object's motion never changes the map (it is not an
  // obstacle); its true position is still tracked.
  bool move_object(std::string_view id, const Point& center);
  bool add_object(const MovableObject& object);
  bool remove_object(std::string_view id);
  // The object held by the gripper (nullopt: none); excluded from movable().
  bool set_carried(std::optional<std::string_view> id);

  std::uint64_t version() const { return version_; }
  const Sensor& sensor() const { return sensor_; }
  const ChangeTolerances& tolerances() const { return tol_; }
  // The validated ground truth, movable objects at their true current positions.
  const World& ground_truth() const { return world_; }

  const Polygon& workspace() const { return world_.workspace; }
  // Localized familiar obstacles, whole, in order of localization (ties in world order).
  const std::vector<Polygon>& familiar() const { return familiar_; }
  const std::vector<std::string>& familiar_ids() const { return familiar_ids_; }
  bool is_localized(std::string_view id) const;
  // Visible unknown fragments (convex, counter-clockwise) in world order, and the id of the
  // obstacle each belongs to; as computed at the last version change.
  const std::vector<Polygon>& unknown() const { return unknown_; }
  const std::vector<std::string>& unknown_ids() const { return unknown_ids_; }
  // Per unknown obstacle, in world order: the convex hull of every fragment read so far (empty
  // when none was). A subset of the obstacle, which is convex; never forgotten, and its growth
  // does not change the version (the reactive layer of [7] sees the visible fragments only).
  const std::vector<Polygon>& seen() const { return seen_; }
  // Movable obstacles (every object but the carried one) in world order, positions as of the
  // last version change (each within object_move of the truth).
  const std::vector<Disk>& movable() const { return movable_; }
  const std::vector<std::string>& movable_ids() const { return movable_ids_; }
  const std::optional<std::string>& carried() const { return carried_; }
  // The true current disk of a movable object (carried or not); nullopt for an unknown id.
  std::optional<Disk> object(std::string_view id) const;

 private:
  void bump();                                         // version + 1 and a fresh movable snapshot
  std::size_t find_object(std::string_view id) const;  // throws on an unknown id
  bool id_in_use(std::string_view id) const;
  void remember(std::size_t j, const std::vector<Point>& fragment);  // grows seen_[j]

  World world_;
  Sensor sensor_;
  ChangeTolerances tol_;
  std::uint64_t version_ = 0;

  std::vector<geometry::Box> familiar_boxes_;
  std::vector<std::size_t> pending_;  // familiar obstacles not localized yet, world order
  std::vector<Polygon> familiar_;
  std::vector<std::string> familiar_ids_;

  std::vector<geometry::Box> unknown_boxes_;
  std::vector<std::vector<Point>> visible_;    // per unknown obstacle: fragment (maybe empty)
  std::vector<std::vector<Point>> candidate_;  // per unknown obstacle: this update's fragment
  std::vector<Point> scratch_;
  std::vector<Polygon> unknown_;
  std::vector<std::string> unknown_ids_;
  std::vector<Polygon> seen_;        // per unknown obstacle: hull of its fragments so far
  std::optional<Point> last_robot_;  // robot position of the last update
  std::optional<Point> scanned_;     // robot position of the last reading of the fragments

  std::vector<Point> reported_;  // per movable object: centre at the last version change
  std::optional<std::string> carried_;
  std::vector<Disk> movable_;
  std::vector<std::string> movable_ids_;
};

}  // namespace rearm::perception
