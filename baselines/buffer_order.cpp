#include "baselines/buffer_order.h"

#include <algorithm>
#include <bit>
#include <string>
#include <tuple>

#include "core/error.h"

namespace rearm::baselines {
namespace {

ObjectSet bit(std::size_t i) { return ObjectSet{1} << i; }

ObjectSet set_of(const std::vector<std::size_t>& objects) {
  ObjectSet s = 0;
  for (const std::size_t j : objects) s |= bit(j);
  return s;
}

}  // namespace

ObjectSet all_goals(const DependencyGraph& g) {
  return g.goal_count == 64 ? ~ObjectSet{0} : bit(g.goal_count) - 1;
}

ObjectSet buffered(const DependencyGraph& g, ObjectSet at_goal) {
  ObjectSet out = 0;
  for (std::size_t k = 0; k < g.goal_count; ++k) {
    if (at_goal & bit(k)) out |= set_of(g.blockers[k]);
  }
  return out & ~at_goal;
}

int peak(const DependencyGraph& g, ObjectSet at_goal, std::size_t i) {
  const ObjectSet waiting = buffered(g, at_goal) | (set_of(g.blockers[i]) & ~at_goal);
  return std::popcount(waiting);
}

BufferOrder::BufferOrder(DependencyGraph g) : g_(std::move(g)) {
  if (g_.object_count > kMaxOrderObjects || g_.goal_count > g_.object_count ||
      g_.blockers.size() != g_.goal_count) {
    throw Error("buffer order: at most " + std::to_string(kMaxOrderObjects) +
                " objects, one blocker list per goal object");
  }
  for (std::size_t i = 0; i < g_.goal_count; ++i) {
    for (const std::size_t j : g_.blockers[i]) {
      if (j >= g_.object_count || j == i) throw Error("buffer order: a blocker out of range");
    }
    blocker_sets_.push_back(set_of(g_.blockers[i]));
  }
  const ObjectSet full = all_goals(g_);
  if (g_.goal_count <= kExactOrderLimit) {
    // cost_[S] = min over i not in S of max(peak(S, i), cost_[S + i]); cost_[full] = 0. Sets
    // with more bits come first when counting down, so every S + i is known.
    cost_.assign(static_cast<std::size_t>(full) + 1, 0);
    for (ObjectSet s = full; s-- > 0;) {
      int best = 255;
      for (std::size_t i = 0; i < g_.goal_count; ++i) {
        if (!(s & bit(i))) best = std::min(best, best_to_finish(s, i));
      }
      cost_[static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(best);
    }
    running_buffers_ = cost_[0];
    return;
  }
  // Greedy: follow the first candidate, recording the largest step.
  for (ObjectSet s = 0; s != full;) {
    const std::size_t i = candidates(s).front();
    running_buffers_ = std::max(running_buffers_, peak(g_, s, i));
    s |= bit(i);
  }
}

int BufferOrder::best_to_finish(ObjectSet at_goal, std::size_t i) const {
  return std::max(peak(g_, at_goal, i), static_cast<int>(cost_[at_goal | bit(i)]));
}

std::vector<std::size_t> BufferOrder::candidates(ObjectSet at_goal) const {
  std::vector<std::tuple<int, int, std::size_t>> ranked;
  const ObjectSet parked = buffered(g_, at_goal);
  for (std::size_t i = 0; i < g_.goal_count; ++i) {
    if (at_goal & bit(i)) continue;
    const int fresh = std::popcount(blocker_sets_[i] & ~at_goal & ~parked);
    const int key = exact() ? best_to_finish(at_goal, i) : peak(g_, at_goal, i);
    ranked.emplace_back(key, exact() ? peak(g_, at_goal, i) : fresh, i);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::size_t> out;
  for (const auto& r : ranked) out.push_back(std::get<2>(r));
  return out;
}

}  // namespace rearm::baselines
