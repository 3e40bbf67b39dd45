// core/suggest.h: the edit distance against an independent recursive definition of the optimal
// string alignment distance on every pair of short strings, hand-checked values, and the
// nearest-name rule (close, unique, not the name itself).
#include "core/suggest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace rearm {
namespace {

// The recursive definition, straight from the textbook recurrence (no table): the distance of
// a's first i and b's first j bytes.
std::size_t osa(const std::string& a, const std::string& b, std::size_t i, std::size_t j) {
  if (i == 0) return j;
  if (j == 0) return i;
  std::size_t best = std::min({osa(a, b, i - 1, j) + 1, osa(a, b, i, j - 1) + 1,
                               osa(a, b, i - 1, j - 1) + (a[i - 1] == b[j - 1] ? 0 : 1)});
  if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
    best = std::min(best, osa(a, b, i - 2, j - 2) + 1);
  }
  return best;
}

// Every string over {a, b, c} of length at most 4.
std::vector<std::string> short_strings() {
  std::vector<std::string> out = {""};
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out[k].size() == 4) continue;
    for (char c : {'a', 'b', 'c'}) out.push_back(out[k] + c);
  }
  return out;
}

TEST(EditDistance, EqualsTheRecursiveDefinitionOnEveryPairOfShortStrings) {
  const std::vector<std::string> all = short_strings();
  ASSERT_EQ(all.size(), 121u);  // 1 + 3 + 9 + 27 + 81
  for (const std::string& a : all) {
    for (const std::string& b : all) {
      ASSERT_EQ(edit_distance(a, b), osa(a, b, a.size(), b.size())) << a << " / " << b;
    }
  }
}

TEST(EditDistance, HandCheckedValues) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("mvoe", "move"), 1u);       // one transposition
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);          // OSA edits no substring twice
  EXPECT_EQ(edit_distance("", "release"), 7u);
  EXPECT_EQ(edit_distance("fig5.yml", "fig5.yaml"), 1u);
}

TEST(ClosestName, OnlyAUniqueNearName) {
  const std::vector<std::string> verbs = {"move", "grasp", "release"};
  EXPECT_EQ(closest_name("mvoe", verbs), "move");
  EXPECT_EQ(closest_name("relase", verbs), "release");
  EXPECT_EQ(closest_name("pick", verbs), std::nullopt);  // nothing near
  EXPECT_EQ(closest_name("move", verbs), std::nullopt);  // known: nothing to suggest
  const std::vector<std::string> regions = {"l1", "l2", "l3"};
  EXPECT_EQ(closest_name("l7", regions), std::nullopt);  // a tie at distance 1
  EXPECT_EQ(closest_name("L1", regions), "l1");
  // The limit grows with the typed name: max(1, |typed| / 3).
  EXPECT_EQ(closest_name("tsak", {"task"}), "task");
  EXPECT_EQ(closest_name("tk", {"task"}), std::nullopt);
  EXPECT_EQ(did_you_mean("taks", {"task", "name"}), "; did you mean 'task'?");
  EXPECT_EQ(did_you_mean("zzz", {"task", "name"}), "");
}

}  // namespace
}  // namespace rearm
