// The running-buffer order of TRLB (Gao, Lau, Huang, Bekris, Yu, "Fast high-quality tabletop
// rearrangement in bounded workspace", ICRA 2022) on its dependency graph of goals on starts:
// the order in which objects reach their goals that keeps the fewest objects parked in buffers
// at once (running buffers). Pure combinatorics: the planner (buffer.h) builds the graph from
// exact disk overlaps and turns the order into moves, choosing buffer spots lazily.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rearm::baselines {

// Objects 0 .. goal_count - 1 have goals; goal_count .. object_count - 1 have none (they are
// parked in a buffer when they block a goal, and stay there). blockers[i] (i < goal_count): the
// objects whose start overlaps object i's goal: they must leave their start before i arrives.
struct DependencyGraph {
  std::size_t object_count = 0;
  std::size_t goal_count = 0;
  std::vector<std::vector<std::size_t>> blockers;
};

// Bit i: object i. Graphs hold at most kMaxOrderObjects objects.
using ObjectSet = std::uint64_t;
inline constexpr std::size_t kMaxOrderObjects = 64;
// Goal objects up to which the order is exact: dynamic programming over the 2^n sets of
// objects at their goals (TRLB's running-buffer minimisation). Beyond, a greedy order.
inline constexpr std::size_t kExactOrderLimit = 16;

// Every goal object: the set of a finished order.
ObjectSet all_goals(const DependencyGraph& g);
// The objects in buffers once the objects of `at_goal` have arrived: every blocker of an
// arrived object that is not itself at its goal.
ObjectSet buffered(const DependencyGraph& g, ObjectSet at_goal);
// The running buffers while goal object i goes to its goal from `at_goal`: the objects already
// buffered and i's blockers still at their starts (i itself while it waits in a buffer).
int peak(const DependencyGraph& g, ObjectSet at_goal, std::size_t i);

class BufferOrder {
 public:
  // Throws rearm::Error for more than kMaxOrderObjects objects or a blocker out of range.
  explicit BufferOrder(DependencyGraph g);

  bool exact() const { return !cost_.empty(); }
  // The least maximum of running buffers over every order (exact), or the greedy order's.
  int running_buffers() const { return running_buffers_; }
  // The goal objects to send next from `at_goal`, best first: exact, by the fewest running
  // buffers over the rest of the order; greedy, by this step's running buffers, then the
  // fewest new buffers; ties by index.
  std::vector<std::size_t> candidates(ObjectSet at_goal) const;
  const DependencyGraph& graph() const { return g_; }

 private:
  int best_to_finish(ObjectSet at_goal, std::size_t i) const;
  DependencyGraph g_;
  std::vector<ObjectSet> blocker_sets_;
  std::vector<std::uint8_t> cost_;  // exact: the least max peak from each set to the end
  int running_buffers_ = 0;
};

}  // namespace rearm::baselines
