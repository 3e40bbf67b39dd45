// A small reduced ordered BDD package: the canonical guard form of the general alphabet
// (docs/symbolic.md "Translation": guards are cubes or a BDD-like canonical form; the
// 2^|AP| alphabet is never enumerated). Variables are ordered by index (0 at the root).
//
// Nodes are hash-consed, so two guards are equal iff their Refs are equal. Nodes are never
// freed (a manager lives as long as the automata that use it). Not thread-safe: one manager
// per translation / per thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rearm::ltl {

struct Literal {
  std::uint32_t var;
  bool positive;
  bool operator==(const Literal&) const = default;
};
// A conjunction of literals, sorted by variable.
using Cube = std::vector<Literal>;

class BddManager {
 public:
  using Ref = std::uint32_t;
  static constexpr Ref kFalse = 0;
  static constexpr Ref kTrue = 1;

  // max_nodes: the node budget; exceeding it throws rearm::BudgetExceeded.
  explicit BddManager(std::uint32_t num_vars = 0, std::size_t max_nodes = 1u << 26);

  std::uint32_t num_vars() const;
  // Adds a variable at the bottom of the order and returns its index.
  std::uint32_t add_var();

  Ref var(std::uint32_t v);   // the function "v"
  Ref nvar(std::uint32_t v);  // the function "!v"
  Ref literal(Literal l) { return l.positive ? var(l.var) : nvar(l.var); }
  Ref cube(const Cube& c);

  Ref conj(Ref a, Ref b);
  Ref disj(Ref a, Ref b);
  Ref neg(Ref a);
  // a implies b (a & !b is false).
  bool implies(Ref a, Ref b);
  // a and b share a satisfying assignment.
  bool intersects(Ref a, Ref b);

  // Value of f under an assignment (assignment[v] for each variable v < num_vars()).
  bool eval(Ref f, const std::vector<bool>& assignment) const;

  // A disjoint cover of f by cubes (one per path to true); empty for false, {{}} for true.
  std::vector<Cube> cubes(Ref f) const;

  // Node structure (for printers and readers). Terminals have var() == num_vars sentinel.
  bool is_terminal(Ref f) const { return f <= kTrue; }
  std::uint32_t top_var(Ref f) const;
  Ref low(Ref f) const;
  Ref high(Ref f) const;

  std::size_t node_count() const;

 private:
  struct Node {
    std::uint32_t var;
    Ref low, high;
  };
  Ref make(std::uint32_t var, Ref low, Ref high);
  Ref apply_and(Ref a, Ref b);
  Ref apply_not(Ref a);

  std::uint32_t num_vars_;
  std::size_t max_nodes_;
  std::vector<Node> nodes_;
  // Open-addressing unique table and operation caches (implementation detail).
  std::vector<Ref> unique_;
  struct CacheEntry {
    Ref a = 0, b = 0, r = 0;
    std::uint32_t op = 0;  // 0 = empty
  };
  std::vector<CacheEntry> cache_;
  void grow_unique();
};

}  // namespace rearm::ltl
