// What the interface layer's parts share (docs/executive.md, "Recoveries: causes, units and the
// policy table"): the parameters, the regions, the semantic map, the reactive controller of [7],
// the topology caches, and the run's counters and compute split. The Executive owns all of it;
// phases, navigation, planning, targets, motion checks and recovery units are free functions of
// a Context and the action's state.
#pragma once

#include <string>
#include <vector>

#include "executive/action.h"
#include "executive/params.h"
#include "executive/region.h"
#include "perception/semantic_map.h"
#include "reactive/kinematics.h"
#include "reactive/mapped_space.h"
#include "reactive/reactive_controller.h"
#include "topology/topology_check.h"

namespace rearm::executive {

using reactive::Pose;

struct Context {
  const ExecutiveParams& p;
  const std::vector<RegionOfInterest>& regions;
  const perception::SemanticMap& map;
  reactive::ReactiveController& controller;
  // Workspace erosions, obstacle dilations and bound − ∪fixed, kept across topology checks (they
  // change only when a familiar obstacle is localized or the radius changes).
  topology::TopologyCache& topology_cache;
  reactive::DilationCache& drop_dilations;  // the drop-point search's mapped spaces
  ComputeTimes& times;
  RecoveryCounts& recoveries;
  int& topology_checks;
  const Twist& last_u;  // the last tick's command (RELEASE opens the gripper only after a stop)
  // RobustParams::object_blockers: the disks (centre, radius of the pair or robot dilation) of
  // the grasp side or release pose the current LTL action sent objects to Fix mode for; Fix
  // mode's drop points keep their pair disks out of them. Emptied when an LTL action starts.
  std::vector<geometry::Disk>& keep_clear;
  // RobustParams::drop: the ways Fix mode was entered to open for the current LTL action (the
  // interrupted actions' blocked ways); Fix mode's drop points keep them open (targets.cpp).
  // Emptied when an LTL action starts.
  std::vector<Way>& fix_ways;
};

// "(x, y)" with millimetres, for reasons and notes.
std::string point_text(const Point& p);

// What the law moves for an action: the robot (radius plan_radius(a), centre x), or with an
// object in the gripper the robot–object pair (radius + ρ + pair_margin, centre x_c).
struct Moving {
  double rho;     // ρ of the carried object, 0 for the robot alone
  double radius;  // the law's dilation radius
  Point center;   // the controlled point
};
Moving moving(const Context& c, const ActionState& a, const Pose& pose);

// The region of interest `id`; throws rearm::Error naming an unknown one.
const RegionOfInterest& region(const Context& c, const std::string& id);
// ρ of object `id`; throws rearm::Error naming an unknown one.
double object_radius(const Context& c, const std::string& id);
double max_object_radius(const Context& c);
// The robot radius of every planning freespace: r + RobustParams::contact_margin; for an
// action whose x* only the margin separates from the robot, r (ActionState::bare).
double plan_radius(const Context& c);
double plan_radius(const Context& c, const ActionState& a);
// The familiar dilations' miter limit (RobustParams::bevel).
double miter_limit(const ExecutiveParams& p);
reactive::SemanticInput semantic_input(const Context& c);
// The topology check of Appendix III for a disk of `radius` at x and the target (no carried
// object excluded), its time added to the topology compute.
topology::TopologyResult timed_check(const Context& c, double radius, const Point& x,
                                     const Point& target);

}  // namespace rearm::executive
