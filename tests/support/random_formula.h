// Seeded random LTL formulas for property tests of the translator (docs/symbolic.md
// "Correctness is tested against independent truth": tree size 5–20, 2–5 propositions,
// with and without X and !).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/rng.h"
#include "ltl/formula.h"

namespace rearm::test_support {

struct RandomFormulaOptions {
  // Tree size (Formula::size(), number of nodes), drawn uniformly in [min_size, max_size].
  // The generated tree has exactly that size when the operator set allows it.
  std::size_t min_size = 5, max_size = 20;
  // Propositions: `aps` when non-empty, else p0..p{k-1} with k drawn uniformly in
  // [min_aps, max_aps]. Not every proposition need occur in a given formula.
  std::vector<std::string> aps;
  std::size_t min_aps = 2, max_aps = 5;
  // X allowed.
  bool allow_next = true;
  // Negation anywhere; when false, `!` occurs only directly above a proposition.
  bool negation_anywhere = true;
  // true / false leaves allowed (with a small probability).
  bool allow_constants = true;
  // Only what `spin -f` accepts once printed with Syntax::Spin (the printer expands W, M
  // and xor; spin rejects X): forces allow_next = false.
  bool spin_safe = false;
  // Operators to draw from (unary and binary ones of ltl::Op; True/False/Ap are governed
  // by the options above). Empty: all of them. Next and Not are still subject to
  // allow_next / negation_anywhere.
  std::vector<ltl::Op> ops;
};

// The proposition list the options describe (draws k from rng when options.aps is empty).
std::vector<std::string> random_aps(Rng& rng, const RandomFormulaOptions& options);

// A random formula over `aps` (non-empty).
ltl::Formula random_formula(Rng& rng, const std::vector<std::string>& aps,
                            const RandomFormulaOptions& options = {});

// A random formula over random_aps(rng, options).
ltl::Formula random_formula(Rng& rng, const RandomFormulaOptions& options = {});

}  // namespace rearm::test_support
