#include "scenario/instance_difficulty.h"

#include <bitset>
#include <string>

#include "core/error.h"
#include "scenario/solvability.h"

namespace rearm::scenario {

namespace {

constexpr std::size_t kMaxObjects = 64;
using Set = std::bitset<kMaxObjects>;

// reach[i]: the objects reachable from i by one edge or more (transitive closure, Warshall).
std::vector<Set> closure(std::vector<Set> reach) {
  for (std::size_t k = 0; k < reach.size(); ++k) {
    for (std::size_t i = 0; i < reach.size(); ++i) {
      if (reach[i].test(k)) reach[i] |= reach[k];
    }
  }
  return reach;
}

}  // namespace

InstanceDifficulty instance_difficulty(const Scenario& s,
                                       const std::vector<geometry::Point>& goals) {
  const std::size_t n = s.objects.size();
  if (goals.size() > n || n > kMaxObjects) {
    throw Error("instance_difficulty: " + std::to_string(goals.size()) + " goals for " +
                std::to_string(n) + " objects (at most " + std::to_string(kMaxObjects) + ")");
  }
  InstanceDifficulty d;
  std::vector<Set> edges(n);
  for (std::size_t i = 0; i < goals.size(); ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const geometry::Disk& o = s.objects[j].disk;
      if (j != i && (goals[i] - o.center).norm() < s.objects[i].disk.radius + o.radius) {
        edges[i].set(j);
      }
    }
    d.goals_occupied += edges[i].any() ? 1 : 0;
  }
  const std::vector<Set> reach = closure(edges);
  for (std::size_t i = 0; i < n; ++i) d.goal_cycle_objects += reach[i].test(i) ? 1 : 0;
  for (const bool w : walled_in_objects(s)) d.walled_in += w ? 1 : 0;
  return d;
}

}  // namespace rearm::scenario
