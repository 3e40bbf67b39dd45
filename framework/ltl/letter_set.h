// Guards of the one-action-at-a-time alphabet (docs/symbolic.md, paper Appendix I-B):
// with N action predicates the robot's feasible symbols are the empty symbol and the N
// singletons, so a guard is a set of those N+1 letters, stored as a bitset.
// Letter 0 is the empty symbol; letter i+1 is the symbol {aps[i]}.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rearm::ltl {

class LetterSet {
 public:
  LetterSet() = default;
  // The empty set (or, with full = true, all letters) over a universe of `num_letters`.
  explicit LetterSet(std::size_t num_letters, bool full = false);
  static LetterSet single(std::size_t num_letters, std::size_t letter);

  std::size_t universe() const { return n_; }
  bool test(std::size_t letter) const;
  void set(std::size_t letter);
  void reset(std::size_t letter);
  bool empty() const;
  bool full() const;
  std::size_t count() const;
  bool subset_of(const LetterSet& o) const;
  bool intersects(const LetterSet& o) const;
  // Smallest letter >= from in the set, or universe() when none.
  std::size_t next(std::size_t from) const;

  LetterSet operator&(const LetterSet& o) const;
  LetterSet operator|(const LetterSet& o) const;
  LetterSet operator~() const;  // complement within the universe
  LetterSet& operator&=(const LetterSet& o);
  LetterSet& operator|=(const LetterSet& o);
  bool operator==(const LetterSet& o) const = default;

  std::size_t hash() const;

 private:
  std::size_t n_ = 0;
  std::vector<std::uint64_t> words_;
};

}  // namespace rearm::ltl
