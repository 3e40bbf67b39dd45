// The manipulation actions of the paper (Section II-B): MOVE(l), GRASP(M), RELEASE(M, l),
// spelled as the LTL action predicates move(l), grasp(M), release(M,l).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rearm::symbolic {

enum class ActionKind { Move, Grasp, Release };

struct Action {
  ActionKind kind = ActionKind::Move;
  std::string object;  // Grasp, Release
  std::string region;  // Move, Release

  // The predicate spelling: "move(l1)", "grasp(M1)", "release(M1,l2)".
  std::string to_string() const;
  bool operator==(const Action&) const = default;

  // Parses a predicate (spaces allowed); throws rearm::Error naming the text otherwise.
  static Action parse(const std::string& predicate);
};

// The scenario's names. An empty vocabulary accepts every name (no scenario given).
struct Vocabulary {
  std::vector<std::string> objects;
  std::vector<std::string> regions;

  bool empty() const { return objects.empty() && regions.empty(); }
  // Throws rearm::Error naming the unknown object or region (and the known ones).
  void check(const Action& a) const;
};

}  // namespace rearm::symbolic
