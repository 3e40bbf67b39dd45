// Strongly connected components (Tarjan), iterative so that deep graphs cannot exhaust the
// call stack. Shared by the translator (SCC pruning, degeneralization) and the mission
// graph (accepting edges inside a cycle).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace rearm {

// `out[v]` is the range of v's edges and `dst(edge)` the successor vertex. Returns the
// component of every vertex; components are numbered in reverse topological order (the
// successors of a component have smaller numbers). `count`, when given, receives the number
// of components.
template <class Out, class Dst>
std::vector<std::uint32_t> strongly_connected_components(const Out& out, Dst dst,
                                                         std::uint32_t* count = nullptr) {
  const auto n = static_cast<std::uint32_t>(out.size());
  constexpr std::uint32_t kUnvisited = ~0u;
  std::vector<std::uint32_t> index(n, kUnvisited), low(n, 0), comp(n, kUnvisited), stack;
  std::vector<bool> on_stack(n, false);
  std::vector<std::pair<std::uint32_t, std::size_t>> call;  // vertex, next edge
  std::uint32_t next_index = 0, components = 0;
  for (std::uint32_t root = 0; root < n; ++root) {
    if (index[root] != kUnvisited) continue;
    call.push_back({root, 0});
    while (!call.empty()) {
      auto& [v, i] = call.back();
      if (i == 0) {
        index[v] = low[v] = next_index++;
        stack.push_back(v);
        on_stack[v] = true;
      }
      if (i < out[v].size()) {
        const std::uint32_t w = dst(out[v][i]);
        ++i;
        if (index[w] == kUnvisited) {
          call.push_back({w, 0});
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      if (low[v] == index[v]) {
        std::uint32_t w;
        do {
          w = stack.back();
          stack.pop_back();
          on_stack[w] = false;
          comp[w] = components;
        } while (w != v);
        ++components;
      }
      const std::uint32_t done = v;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
    }
  }
  if (count) *count = components;
  return comp;
}

}  // namespace rearm
