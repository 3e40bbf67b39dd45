// The lengths an instance is built from (random_instance.h, "Clearances"): the workspace of
// an InstanceSpec, the spacing, passage and grasp clearances of its solvability argument, the
// dense rules when the points do not fit sparsely, and the checks of a spec's ranges.
#pragma once

#include <string>

#include "geometry/polygon.h"
#include "scenario/random_instance.h"

namespace rearm::scenario {

// Shared with the generator (random_instance.cpp).
constexpr double kPlacementSlack = 1e-6;  // m: keeps region vertices inside despite rounding
constexpr double kDenseRegionGap = 0.05;  // m: dense Chebyshev spacing beyond s

// Lengths derived from the spec (random_instance.h, "Clearances").
struct Layout {
  double width = 0, height = 0;
  double passage = 0;         // w
  double pair = 0;            // R of solvability.h
  double grasp = 0;           // cg
  double point_obstacle = 0;  // co: points ↔ obstacles (random_instance.h, "Clearances")
  double point_pocket = 0;    // points ↔ the sealed pocket's box: max(cg, s/√2 + slack)
  double point_boundary = 0;  // cb
  double region_side = 0;     // s
  double spacing = 0;         // d
  bool dense = false;         // Chebyshev spacing
  double robot_object = 0;    // robot start to object start (centres)
};

// The disk area of the objects (and the sealed class's blocker).
double footprint_area(const InstanceSpec& spec);
// The workspace sides (random_instance.h: width x height, or the footprint square).
geometry::Point workspace_size(const InstanceSpec& spec);
Layout layout(const InstanceSpec& spec);
// Throws rearm::Error naming the field of a spec outside its range, or a workspace too small
// for the clearances.
void check_spec(const InstanceSpec& spec);
// "random_instance(class c, N=n, density d, seed s, W x H m)", for messages.
std::string describe(const InstanceSpec& spec);

}  // namespace rearm::scenario
