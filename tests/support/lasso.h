// Lasso words u·v^ω and the direct evaluator of LTL on them: the independent truth the
// translator is tested against (docs/symbolic.md "Correctness is tested against independent
// truth", item 1; docs/architecture.md rule 9).
//
// The evaluator reads a formula only through Formula's accessors (op, name, children) and
// gives every operator of ltl::Op its own semantics; it never rewrites one operator into
// another and shares no code with the translator, so a bug in the rewriting or translation
// cannot hide itself here.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "ltl/formula.h"

namespace rearm::test_support {

// An infinite word u·v^ω. Letters are bit vectors over `aps`: letter[i] says whether aps[i]
// holds. Propositions not in `aps` are false at every position. Positions are numbered
// 0..size()-1 over u then v; the successor of the last position is loop_start() (= |u|).
struct Lasso {
  using Letter = std::vector<bool>;

  std::vector<std::string> aps;
  std::vector<Letter> prefix;  // u, may be empty
  std::vector<Letter> loop;    // v, never empty for a valid lasso

  // Builds a lasso from letters given as sets of true proposition names; aps is the sorted
  // union of all names that occur, plus `extra_aps` (which may then be false everywhere).
  static Lasso from_names(const std::vector<std::vector<std::string>>& prefix,
                          const std::vector<std::vector<std::string>>& loop,
                          const std::vector<std::string>& extra_aps = {});

  std::size_t size() const { return prefix.size() + loop.size(); }
  std::size_t loop_start() const { return prefix.size(); }
  // Position after `pos` (pos < size()).
  std::size_t successor(std::size_t pos) const { return pos + 1 < size() ? pos + 1 : loop_start(); }
  // The letter at position pos < size().
  const Letter& letter(std::size_t pos) const {
    return pos < prefix.size() ? prefix[pos] : loop[pos - prefix.size()];
  }
  // Index of a proposition in aps, or -1.
  int find_ap(const std::string& name) const;
  // Whether `name` holds at position pos (false for names not in aps).
  bool holds(std::size_t pos, const std::string& name) const;
  // Names of the propositions true at position pos, in aps order.
  std::vector<std::string> true_aps(std::size_t pos) const;

  // "u=({p0},{}) v=({p0,p1})": readable form for failure messages.
  std::string to_string() const;
};

// Parameters of random lassos. Lengths are drawn uniformly in the closed ranges.
struct LassoOptions {
  std::size_t min_prefix = 0, max_prefix = 4;
  std::size_t min_loop = 1, max_loop = 4;  // min_loop >= 1
  // Each proposition holds independently with this probability (ignored when one_hot).
  double p_true = 0.5;
  // At most one proposition per letter (the one-action-at-a-time alphabet): each letter is
  // "none" or one proposition, uniformly among the |aps|+1 choices.
  bool one_hot = false;
};

// A seeded random lasso over `aps`.
Lasso random_lasso(Rng& rng, const std::vector<std::string>& aps, const LassoOptions& options = {});

// Calls visit(lasso) for every lasso over `aps` with |u| <= max_prefix and
// 1 <= |v| <= max_loop; letters range over all 2^|aps| subsets, or over the |aps|+1 one-hot
// letters when one_hot. Different lassos may denote the same word. visit returns false to
// stop early; the function returns false iff stopped early.
bool for_each_lasso(const std::vector<std::string>& aps, std::size_t max_prefix,
                    std::size_t max_loop, bool one_hot,
                    const std::function<bool(const Lasso&)>& visit);

// Truth of f at every position 0..w.size()-1 of w (the word starting at that position).
// Until, Eventually and StrongRelease are least fixpoints, Release, Always and WeakUntil
// greatest fixpoints of their one-step expansions, iterated over the lasso positions.
// Throws std::invalid_argument for an empty loop.
std::vector<bool> evaluate_all(const ltl::Formula& f, const Lasso& w);

// w |= f (truth at position 0).
bool evaluate(const ltl::Formula& f, const Lasso& w);

}  // namespace rearm::test_support
