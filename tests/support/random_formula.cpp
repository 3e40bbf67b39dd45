#include "support/random_formula.h"

#include <algorithm>
#include <stdexcept>

namespace rearm::test_support {
namespace {

using ltl::Formula;
using ltl::Op;

// Probability that a leaf is a constant (when allowed): rare, constants mostly test the
// translator's simplifications.
constexpr double kConstantLeafProbability = 0.05;

bool is_unary(Op op) {
  return op == Op::Not || op == Op::Next || op == Op::Eventually || op == Op::Always;
}

bool is_binary(Op op) {
  switch (op) {
    case Op::And:
    case Op::Or:
    case Op::Implies:
    case Op::Equiv:
    case Op::Xor:
    case Op::Until:
    case Op::Release:
    case Op::WeakUntil:
    case Op::StrongRelease:
      return true;
    default:
      return false;
  }
}

class Generator {
 public:
  Generator(Rng& rng, const std::vector<std::string>& aps, const RandomFormulaOptions& o)
      : rng_(rng), aps_(aps), o_(o) {
    std::vector<Op> ops = o.ops;
    if (ops.empty()) {
      ops = {Op::Not,     Op::Next,      Op::Eventually,   Op::Always, Op::And,
             Op::Or,      Op::Implies,   Op::Equiv,        Op::Xor,    Op::Until,
             Op::Release, Op::WeakUntil, Op::StrongRelease};
    }
    const bool next_ok = o.allow_next && !o.spin_safe;
    for (Op op : ops) {
      if (op == Op::Next && !next_ok) continue;
      if (op == Op::Not) {
        negated_literals_ = true;
        if (!o.negation_anywhere) continue;
      }
      if (is_unary(op)) unary_.push_back(op);
      if (is_binary(op)) binary_.push_back(op);
    }
  }

  Formula gen(std::size_t n) {
    if (n <= 1) return leaf();
    // Candidate shapes of exactly n nodes: unary op over n-1, binary op over a split of
    // n-1, or (restricted negation, n == 2) a negated proposition.
    const bool literal = n == 2 && negated_literals_ && !o_.negation_anywhere;
    const std::size_t nb = n >= 3 ? binary_.size() : 0;
    const std::size_t choices = unary_.size() + nb + (literal ? 1 : 0);
    if (choices == 0) return leaf();
    std::size_t c = rng_.index(choices);
    if (c < unary_.size()) return Formula::make(unary_[c], {gen(n - 1)});
    c -= unary_.size();
    if (c < nb) {
      const std::size_t left =
          static_cast<std::size_t>(rng_.uniform_int(1, static_cast<std::int64_t>(n) - 2));
      Formula a = gen(left);
      Formula b = gen(n - 1 - left);
      return Formula::make(binary_[c], {a, b});
    }
    return Formula::lnot(Formula::ap(aps_[rng_.index(aps_.size())]));
  }

 private:
  Formula leaf() {
    if (o_.allow_constants && rng_.bernoulli(kConstantLeafProbability)) {
      return rng_.bernoulli(0.5) ? Formula::tt() : Formula::ff();
    }
    return Formula::ap(aps_[rng_.index(aps_.size())]);
  }

  Rng& rng_;
  const std::vector<std::string>& aps_;
  const RandomFormulaOptions& o_;
  std::vector<Op> unary_, binary_;
  bool negated_literals_ = false;
};

}  // namespace

std::vector<std::string> random_aps(Rng& rng, const RandomFormulaOptions& o) {
  if (!o.aps.empty()) return o.aps;
  if (o.min_aps < 1 || o.min_aps > o.max_aps) {
    throw std::invalid_argument("random_aps: bad proposition count range");
  }
  const auto k = static_cast<std::size_t>(
      rng.uniform_int(static_cast<std::int64_t>(o.min_aps), static_cast<std::int64_t>(o.max_aps)));
  std::vector<std::string> aps;
  for (std::size_t i = 0; i < k; ++i) aps.push_back(std::string("p").append(std::to_string(i)));
  return aps;
}

ltl::Formula random_formula(Rng& rng, const std::vector<std::string>& aps,
                            const RandomFormulaOptions& o) {
  if (aps.empty()) throw std::invalid_argument("random_formula: no propositions");
  if (o.min_size < 1 || o.min_size > o.max_size) {
    throw std::invalid_argument("random_formula: bad size range");
  }
  const auto n = static_cast<std::size_t>(rng.uniform_int(static_cast<std::int64_t>(o.min_size),
                                                          static_cast<std::int64_t>(o.max_size)));
  return Generator(rng, aps, o).gen(n);
}

ltl::Formula random_formula(Rng& rng, const RandomFormulaOptions& o) {
  const std::vector<std::string> aps = random_aps(rng, o);
  return random_formula(rng, aps, o);
}

}  // namespace rearm::test_support
