// Tarjan's SCCs against brute-force reachability (Floyd–Warshall transitive closure).
#include "core/scc.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/rng.h"

namespace rearm {
namespace {

TEST(SccTest, MatchesMutualReachabilityOnRandomGraphs) {
  Rng rng(17);
  for (int trial = 0; trial < 300; ++trial) {
    const auto n = static_cast<std::uint32_t>(1 + rng.index(24));
    const double density = rng.uniform(0.0, 0.3);
    std::vector<std::vector<std::uint32_t>> out(n);
    std::vector<std::vector<bool>> reach(n, std::vector<bool>(n, false));
    for (std::uint32_t u = 0; u < n; ++u) {
      reach[u][u] = true;
      for (std::uint32_t v = 0; v < n; ++v) {
        if (rng.bernoulli(density)) {
          out[u].push_back(v);
          reach[u][v] = true;
        }
      }
    }
    for (std::uint32_t k = 0; k < n; ++k) {
      for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
          if (reach[i][k] && reach[k][j]) reach[i][j] = true;
        }
      }
    }
    std::uint32_t count = 0;
    const auto comp = strongly_connected_components(
        out, [](std::uint32_t v) { return v; }, &count);
    for (std::uint32_t u = 0; u < n; ++u) {
      ASSERT_LT(comp[u], count);
      for (std::uint32_t v = 0; v < n; ++v) {
        EXPECT_EQ(comp[u] == comp[v], reach[u][v] && reach[v][u]) << trial << ": " << u << "," << v;
      }
      for (std::uint32_t v : out[u]) EXPECT_LE(comp[v], comp[u]) << "reverse topological order";
    }
  }
}

TEST(SccTest, DeepChainDoesNotRecurse) {
  constexpr std::uint32_t kN = 200000;  // a recursive Tarjan would overflow the stack
  std::vector<std::vector<std::uint32_t>> out(kN);
  for (std::uint32_t v = 0; v + 1 < kN; ++v) out[v].push_back(v + 1);
  out[kN - 1].push_back(0);
  std::uint32_t count = 0;
  const auto comp = strongly_connected_components(
      out, [](std::uint32_t v) { return v; }, &count);
  EXPECT_EQ(count, 1u);
  EXPECT_EQ(comp[kN / 2], comp[0]);
}

}  // namespace
}  // namespace rearm
