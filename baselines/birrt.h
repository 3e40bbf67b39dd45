// B2: the non-monotone baseline (Krontiris & Bekris, ICRA 2016): a bidirectional RRT in the
// space of object arrangements. One tree grows from the start arrangement (with the robot's
// position), one from the goal arrangement. Each iteration samples a random arrangement (every
// object at a random placement), picks the nearest node of the current tree (sum of object
// displacements) and extends it by mRS moves of 1..max_extend of its objects to their sampled
// places — random temporary placements, which is what lets it solve non-monotone instances
// such as the cyclic shift of Fig. 5; then it tries to connect the new node to the nearest
// node of the other tree by a full monotone search (mrs.h). It begins with the direct mRS
// attempt from start to goal, so monotone instances are solved at once. Probabilistically
// complete (random placements are dense; each extension is a complete monotone search over few
// objects).
//
// Goal-tree edges were searched from the parent outwards; a connection is turned into a plan by
// planning the goal-side moves forward again (each object back to the parent's place), which
// also plans the transits the goal tree cannot know (it has no robot position). A connection
// whose forward replay fails is discarded and the search goes on.
//
// BiRRT(fmRS), the method `birrt-fmrs` (Krontiris & Bekris, ICRA 2016): the same trees with
// fmRS (fmrs.h) in place of the monotone search as the extension and connection primitive: one
// order from the dependency graph of minimum-constraint-removal paths instead of a depth-first
// search over orders, so a connection costs at most one move per object, and a cycle among the
// objects makes it fail at once (the random placements of later extensions break it).
#pragma once

#include "baselines/fmrs.h"
#include "baselines/mrs.h"

namespace rearm::baselines {

struct BirrtOptions {
  int max_extend = 2;        // objects moved per extension, at most
  int placement_tries = 50;  // rejection samples per random placement
  // Objects within this distance (m) of their place in the other tree's node count as placed
  // when connecting (landings differ from targets by the tracking law's few mm – cm).
  double connect_tolerance = 0.05;
  // The local planner of extensions and connections: mRS (B2, a complete monotone search) or
  // fmRS (BiRRT(fmRS) of Krontiris & Bekris, ICRA 2016: one order from the MCR dependency
  // graph, no backtracking; fmrs.h).
  enum class Extension { kMrs, kFmrs };
  Extension extension = Extension::kMrs;
  FmrsOptions fmrs;
};

PlanResult plan_birrt(const RearrangementProblem& problem, const BaselineParams& params,
                      const PlannerOptions& options, const BirrtOptions& birrt = {});

}  // namespace rearm::baselines
