// "Did you mean …?": the known name closest to a mistyped one, for error messages that name the
// mistake (an unknown predicate, region, object, key or file).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rearm {

// The optimal string alignment distance of a and b: the fewest insertions, deletions,
// substitutions and transpositions of two adjacent characters that turn a into b, no substring
// edited twice (so "mvoe" -> "move" is 1, "ca" -> "abc" is 3). Bytes compared exactly.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The known name nearest to `typed` when it is close (distance at most max(1, |typed| / 3)) and
// no other known name is as near; nullopt otherwise (nothing near, a tie, or `typed` itself
// known).
std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& known);

// "; did you mean 'x'?" for closest_name's answer, or "" when there is none.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known);

}  // namespace rearm
