// The `buffer` baseline: TRLB's running-buffer rearrangement (Gao, Lau, Huang, Bekris, Yu,
// "Fast high-quality tabletop rearrangement in bounded workspace", ICRA 2022), adapted to the
// paper's mobile robot. The dependency graph of goals on starts (buffer_order.h) fixes an order
// that keeps the fewest objects in buffers at once; walking it, the objects that block the next
// goal are parked at buffer spots chosen lazily (only when the order needs them), then the
// object goes to its goal. Unlike the tabletop original, every step is a move of move_planner.h:
// a transit of the robot alone and a transfer of the robot–object pair, each an OMPL motion
// query in the current arrangement, so objects also close ways, release approaches and grasps:
// a move that fails for one of those parks the objects in question (off the way) and tries once
// more. A move that still fails tries the next buffer spot, then the next object in the order's
// ranking (a depth-first search over orders, the sets of arrived
// objects that led nowhere remembered as in mRS).
#pragma once

#include "baselines/mrs.h"

namespace rearm::baselines {

struct BufferOptions {
  // Buffer spot candidates drawn uniformly in the workspace's box per parking, and how many
  // of the acceptable ones (nearest the object first) are tried with a move.
  int spot_samples = 400;
  int spot_tries = 8;
  // TRLB's allocation (true, method `buffer`): a spot keeps clear of the poses occupied while
  // the object is parked (every object where it stands) and of the goals filled in that time
  // (the goal objects the order sends before the parked one, as the order's first choices from
  // the current set), not of every goal region; and a parked object that closes a way a move
  // needs is parked again elsewhere (a new constraint), where before the move gave up. false
  // (method `buffer-strict`, this baseline before TRLB's allocation): every goal region kept
  // clear, a parked object never moved again.
  bool lifetime_spots = true;
};

PlanResult plan_buffer(const RearrangementProblem& problem, const BaselineParams& params,
                       const PlannerOptions& options, const BufferOptions& buffer = {});

}  // namespace rearm::baselines
