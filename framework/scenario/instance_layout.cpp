#include "scenario/instance_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace rearm::scenario {
namespace {

using geometry::Point;

// Input ranges (random_instance.h, InstanceSpec).
constexpr int kMinObjects = 1;
constexpr double kMinLength = 0.01;           // m: below this no length is meaningful
constexpr double kMaxWorkspaceSide = 100;     // m: bounds the obstacle count (and run time)
constexpr int kMaxAttemptsLimit = 1'000'000;  // bounds the run time of a hopeless spec

// Clearances of the header's solvability argument.
constexpr double kRegionGap = 0.1;       // m: start/goal spacing beyond the region diagonal
constexpr double kRobotObjectGap = 0.5;  // m: robot start disk to object start disk

// Clearances (random_instance.h, "Clearances").
constexpr double kGraspMargin = 0.05;      // m: cg beyond 2r + ρ
constexpr double kDenseWallGap = 0.1;      // m: dense cb beyond ρ
constexpr double kMinRegionMargin = 0.05;  // m: the smallest region side is 2ρ + this
// Share of the points' area that n points of spacing d may claim (d² each) before the dense
// rules apply: random sequential placement of squares jams near 0.56, so 0.45 keeps rejection
// sampling quick.
constexpr double kPackingFraction = 0.45;

[[noreturn]] void bad_field(const char* field, const std::string& reason) {
  throw Error(std::string("random_instance: ") + field + ": " + reason);
}

void check_length(double x, const char* field,
                  double max = std::numeric_limits<double>::infinity()) {
  if (!(std::isfinite(x) && x >= kMinLength && x <= max)) {
    const std::string range = std::isfinite(max) ? "in [" + shortest_decimal(kMinLength) + ", " +
                                                       shortest_decimal(max) + "] m"
                                                 : ">= " + shortest_decimal(kMinLength) + " m";
    bad_field(field, "must be finite and " + range + ", got " + shortest_decimal(x));
  }
}

void check_fraction(double x, const char* field, double max) {
  if (!(std::isfinite(x) && x >= 0 && x <= max)) {
    bad_field(field, "must be finite and in [0, " + shortest_decimal(max) + "], got " +
                         shortest_decimal(x));
  }
}

double sparse_spacing(const InstanceSpec& spec, double w) {
  return std::max(spec.region_side * std::numbers::sqrt2 + kRegionGap, w);
}

// The workspace (footprint square or width x height) fits the clearances.
void check_workspace(const InstanceSpec& spec) {
  const Layout l = layout(spec);
  const char* wfield = spec.footprint_density > 0 ? "footprint_density" : "width";
  const char* hfield = spec.footprint_density > 0 ? "footprint_density" : "height";
  if (spec.footprint_density > 0 && !(l.width >= kMinLength && l.width <= kMaxWorkspaceSide)) {
    bad_field("footprint_density", "gives a workspace side of " + shortest_decimal(l.width) +
                                       " m, outside [" + shortest_decimal(kMinLength) + ", " +
                                       shortest_decimal(kMaxWorkspaceSide) + "] m");
  }
  auto wide_enough = [&](double side, const char* field) {
    if (!(side > 2 * l.point_boundary)) {
      bad_field(field, "workspace too small: a side must exceed " +
                           shortest_decimal(2 * l.point_boundary) + " m (twice the " +
                           shortest_decimal(l.point_boundary) +
                           " m that object starts and goals keep from the boundary), got " +
                           shortest_decimal(side));
    }
  };
  wide_enough(l.width, wfield);
  wide_enough(l.height, hfield);
}

}  // namespace

double footprint_area(const InstanceSpec& spec) {
  const int objects = spec.objects + (spec.goal_class == GoalClass::kSealed ? 1 : 0);
  return objects * std::numbers::pi * spec.object_radius * spec.object_radius;
}

Point workspace_size(const InstanceSpec& spec) {
  if (spec.footprint_density == 0) return Point(spec.width, spec.height);
  const double side = std::sqrt(footprint_area(spec) / spec.footprint_density);
  return Point(side, side);
}

Layout layout(const InstanceSpec& spec) {
  const double r = spec.robot_radius, rho = spec.object_radius;
  Layout l;
  const Point size = workspace_size(spec);
  l.width = size.x();
  l.height = size.y();
  l.passage = 2 * (r + rho) + spec.passage_margin;
  l.pair = r + rho + kPairMargin;
  l.grasp = 2 * r + rho + kGraspMargin;
  l.region_side = spec.region_side;
  l.spacing = sparse_spacing(spec, l.passage);
  l.point_boundary = std::max(l.grasp, l.region_side / 2 + kPlacementSlack);
  const double inner = std::max(0.0, l.width - 2 * l.point_boundary) *
                       std::max(0.0, l.height - 2 * l.point_boundary);
  const int points = spec.objects + 1;  // the goals (or starts) and the parking spot
  const double fit = std::sqrt(kPackingFraction * inner / points);
  l.robot_object = r + rho + kRobotObjectGap;
  if (fit < l.spacing) {
    l.dense = true;
    const double smallest = std::min(spec.region_side, 2 * rho + kMinRegionMargin);
    l.region_side = std::clamp(fit - kDenseRegionGap, smallest, spec.region_side);
    l.spacing = l.region_side + kDenseRegionGap;
    l.point_boundary = std::max(rho + kDenseWallGap, l.region_side / 2 + kPlacementSlack);
    l.robot_object = r + rho + kDenseRegionGap;
  }
  const double region_clear = l.region_side / std::numbers::sqrt2 + kPlacementSlack;
  l.point_pocket = std::max(l.grasp, region_clear);
  // Dense: an object next to an obstacle is graspable from its free side only, as next to a
  // wall (cb); the certificate's grasp test is one-sided (solvability.h (b)).
  l.point_obstacle = l.dense ? std::max(rho + kDenseWallGap, region_clear) : l.point_pocket;
  return l;
}

void check_spec(const InstanceSpec& spec) {
  if (spec.objects < kMinObjects || spec.objects > kMaxInstanceObjects) {
    bad_field("objects", "must be an integer in [" + std::to_string(kMinObjects) + ", " +
                             std::to_string(kMaxInstanceObjects) + "], got " +
                             std::to_string(spec.objects));
  }
  check_fraction(spec.obstacle_density, "obstacle_density", kMaxObstacleDensity);
  check_fraction(spec.unknown_fraction, "unknown_fraction", 1);
  check_fraction(spec.footprint_density, "footprint_density", kMaxFootprintDensity);
  check_length(spec.width, "width", kMaxWorkspaceSide);
  check_length(spec.height, "height", kMaxWorkspaceSide);
  check_length(spec.robot_radius, "robot_radius");
  check_length(spec.object_radius, "object_radius");
  check_length(spec.region_side, "region_side");
  check_length(spec.sensor_range, "sensor_range");
  check_length(spec.max_obstacle_side, "max_obstacle_side", kMaxMaxObstacleSide);
  if (spec.max_obstacle_side < kMinMaxObstacleSide) {
    bad_field("max_obstacle_side", "must be >= " + shortest_decimal(kMinMaxObstacleSide) +
                                       " m, got " + shortest_decimal(spec.max_obstacle_side));
  }
  if (!(std::isfinite(spec.passage_margin) && spec.passage_margin >= kMinPassageMargin &&
        spec.passage_margin <= kMaxPassageMargin)) {
    bad_field("passage_margin", "must be finite and in [" + shortest_decimal(kMinPassageMargin) +
                                    ", " + shortest_decimal(kMaxPassageMargin) + "] m, got " +
                                    shortest_decimal(spec.passage_margin));
  }
  if (spec.max_attempts < 1 || spec.max_attempts > kMaxAttemptsLimit) {
    bad_field("max_attempts", "must be an integer in [1, " + std::to_string(kMaxAttemptsLimit) +
                                  "], got " + std::to_string(spec.max_attempts));
  }
  if (spec.scatter_moves < 0 || spec.scatter_moves > kMaxScatterMovesPerObject * spec.objects) {
    bad_field("scatter_moves",
              "must be an integer in [0, " + std::to_string(kMaxScatterMovesPerObject) +
                  " N = " + std::to_string(kMaxScatterMovesPerObject * spec.objects) +
                  "] (0: 2N), got " + std::to_string(spec.scatter_moves));
  }
  if (spec.region_side < 2 * spec.object_radius) {
    bad_field("region_side",
              "must be >= 2 object_radius = " + shortest_decimal(2 * spec.object_radius) +
                  " m (an object must fit in its region), got " +
                  shortest_decimal(spec.region_side));
  }
  check_workspace(spec);
}

std::string describe(const InstanceSpec& spec) {
  const Point size = workspace_size(spec);
  return std::string("random_instance(class ") + to_string(spec.goal_class) +
         ", N=" + std::to_string(spec.objects) + ", density " +
         shortest_decimal(spec.obstacle_density) + ", seed " + std::to_string(spec.seed) + ", " +
         shortest_decimal(size.x()) + " x " + shortest_decimal(size.y()) + " m)";
}

}  // namespace rearm::scenario
