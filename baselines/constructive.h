// Instances known to be solvable: the constructive class (scenario::GoalClass::kConstructive),
// each built backwards from its solution.
//
// The room, the goal regions and the fixed obstacles are the random class's for the same spec
// (scenario::generate_room: same rules, certificate and density checks), or, when no scatter
// succeeds there, the random class's for a seed derived from the spec's (kRoomRedraws): the
// class holds the rooms where a rearrangement of the baselines' kind exists, a selection the
// rows state (ConstructiveInstance::room_redraws, the description). The objects start in
// their goals (the region centres); K pick-and-place moves (InstanceSpec::scatter_move_count)
// scatter them. Each move tries the objects not moved yet first, then the others but the one
// just moved, each group in a random order, and takes the first that finds a target (an object
// whose way back into a crowded goal is blocked waits until its neighbours have left); with
// K >= N every object must have moved. A move of object o from a to a target b is drawn
// uniformly in the room, kept only when b lies outside o's own goal region, o fits there
// (MovePlanner::placement_free: clear of the obstacles, the walls and the other objects by the
// placement margin, with a free pre-grasp pose) and the move back from b to a can be planned in
// the arrangement after the move (MovePlanner::plan without its transit: a free grasp, a
// transfer of the pair disk found by RRTConnect and checked by the exact segment tests of
// disk_world.h, a free straight approach, a release whose predicted landing lies in o's goal
// region when a is o's goal). The instance's start is where the objects end.
//
// The witness is the K moves reversed, planned again for real from the robot's start: the robot
// starts where the scatter left it, backed off from the last object it set down (up to
// kStartBackoff behind the pre-grasp pose of that object, facing it), and each move's transit
// is planned from where the previous one left the robot, with the pose carried from move to
// move (the scatter's own transits are not planned: the direction that proves the instance
// solvable is the witness's). A landing lies a few cm from its target (the off-axis law's
// heading, plan.h), so the witness walks the arrangements it actually makes. A scatter whose
// witness cannot be planned, or that the independent validator (validator.h) rejects, is drawn
// again from the next stream; the instance returned always carries a witness that
// validate_plan accepts and that ends with every object in its goal region.
//
// Determinism: every draw comes from Rng streams of the spec's seed, every motion query is
// seeded from it and capped by iterations, never by time, so the same spec gives the same
// instance and witness on any machine load and thread count.
#pragma once

#include "baselines/plan.h"
#include "baselines/problem.h"
#include "scenario/random_instance.h"

namespace rearm::baselines {

// m: how far behind the first move's pre-grasp pose the robot may start (less where the robot
// disk would not fit).
inline constexpr double kStartBackoff = 0.3;
// Targets drawn per object and scatter move before the move tries the next object.
inline constexpr int kScatterTargetTries = 50;
// Scatters drawn (streams) per room before the room is drawn again.
inline constexpr int kScatterRedraws = 6;
// Rooms drawn again (generate_room with a seed derived from the spec's) before the spec is
// refused: a room where the pair's release approach fits no goal with the others in theirs
// admits no rearrangement of the baselines' kind.
inline constexpr int kRoomRedraws = 9;
// RRTConnect iterations per motion query while scattering and planning the witness.
inline constexpr int kScatterIterations = 5000;

struct ConstructiveInstance {
  scenario::GeneratedInstance instance;  // instance.witness: the plan as JSON (plan_json.h)
  Plan witness;
  int scatter_redraws = 0;  // scatters drawn again in its room before this one
  int room_redraws = 0;     // rooms drawn again before its own (0: the random class's room)
};

// The constructive instance of a spec of class kConstructive (any other class: rearm::Error).
// Throws rearm::Error naming the spec when generate_room does, or when kScatterRedraws + 1
// scatters fail in each of kRoomRedraws + 1 rooms (no target for a move in kScatterTargetTries
// draws per object, or no witness).
ConstructiveInstance constructive_instance(const scenario::InstanceSpec& spec);

// constructive_instance(spec).instance: the experiment layer's generator of the class.
scenario::GeneratedInstance generate_constructive(const scenario::InstanceSpec& spec);

}  // namespace rearm::baselines
