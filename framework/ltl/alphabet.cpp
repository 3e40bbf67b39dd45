#include "ltl/alphabet.h"

#include <algorithm>
#include <utility>

#include "core/error.h"

namespace rearm::ltl {
namespace {

using Ref = BddManager::Ref;

void check_distinct(const std::vector<std::string>& aps) {
  for (std::size_t i = 0; i < aps.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (aps[i] == aps[j]) throw Error("duplicate atomic proposition \"" + aps[i] + "\"");
    }
  }
}

int find_in(const std::vector<std::string>& aps, const std::string& name) {
  const auto it = std::find(aps.begin(), aps.end(), name);
  return it == aps.end() ? -1 : static_cast<int>(it - aps.begin());
}

// Cofactor of f with respect to variable v (v at or above f's top variable).
Ref cofactor(const BddManager& m, Ref f, std::uint32_t v, bool value) {
  if (m.top_var(f) != v) return f;
  return value ? m.high(f) : m.low(f);
}

// Minato–Morreale irredundant sum of products: a cover C of some function between the
// interval [lower, upper] (lower implies upper) in which no cube and no literal can be
// dropped. Returns the cubes (literals in increasing variable order); *cover receives the
// BDD of their disjunction.
std::vector<Cube> isop(BddManager& m, Ref lower, Ref upper, Ref* cover) {
  if (lower == BddManager::kFalse) {
    *cover = BddManager::kFalse;
    return {};
  }
  if (upper == BddManager::kTrue) {
    *cover = BddManager::kTrue;
    return {Cube{}};
  }
  const std::uint32_t v = std::min(m.top_var(lower), m.top_var(upper));
  const Ref l0 = cofactor(m, lower, v, false), l1 = cofactor(m, lower, v, true);
  const Ref u0 = cofactor(m, upper, v, false), u1 = cofactor(m, upper, v, true);

  // Minterms that need !v (resp. v): those of the lower bound outside the other cofactor.
  Ref r0 = 0, r1 = 0, rd = 0;
  std::vector<Cube> c0 = isop(m, m.conj(l0, m.neg(u1)), u0, &r0);
  std::vector<Cube> c1 = isop(m, m.conj(l1, m.neg(u0)), u1, &r1);
  // What is left is covered by cubes without v, inside both upper cofactors.
  const Ref rest = m.disj(m.conj(l0, m.neg(r0)), m.conj(l1, m.neg(r1)));
  std::vector<Cube> cd = isop(m, rest, m.conj(u0, u1), &rd);

  std::vector<Cube> out;
  out.reserve(c0.size() + c1.size() + cd.size());
  for (Cube& c : c0) {
    c.insert(c.begin(), Literal{v, false});
    out.push_back(std::move(c));
  }
  for (Cube& c : c1) {
    c.insert(c.begin(), Literal{v, true});
    out.push_back(std::move(c));
  }
  for (Cube& c : cd) out.push_back(std::move(c));
  const Ref x = m.var(v);
  *cover = m.disj(m.disj(m.conj(m.neg(x), r0), m.conj(x, r1)), rd);
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// GeneralAlphabet. Proposition i is BDD variable i. A manager shared between alphabets
// must be shared by alphabets that agree on the proposition order (e.g. copies of one).

GeneralAlphabet::GeneralAlphabet() : bdd_(std::make_shared<BddManager>()) {}

GeneralAlphabet::GeneralAlphabet(std::vector<std::string> aps, std::shared_ptr<BddManager> bdd)
    : aps_(std::move(aps)), bdd_(std::move(bdd)) {
  check_distinct(aps_);
  if (!bdd_) bdd_ = std::make_shared<BddManager>(static_cast<std::uint32_t>(aps_.size()));
  while (bdd_->num_vars() < aps_.size()) bdd_->add_var();
}

std::uint32_t GeneralAlphabet::ap_index(const std::string& name) {
  const int found = find_ap(name);
  if (found >= 0) return static_cast<std::uint32_t>(found);
  aps_.push_back(name);
  while (bdd_->num_vars() < aps_.size()) bdd_->add_var();
  return static_cast<std::uint32_t>(aps_.size() - 1);
}

int GeneralAlphabet::find_ap(const std::string& name) const { return find_in(aps_, name); }

GeneralAlphabet::Guard GeneralAlphabet::ap(std::uint32_t i, bool positive) const {
  REARM_DEMAND(i < aps_.size(), "proposition index out of range");
  return positive ? bdd_->var(i) : bdd_->nvar(i);
}

bool GeneralAlphabet::contains(Guard g, const Symbol& s) const {
  // Walks the BDD directly: only the variables on the path need a value.
  const BddManager& m = *bdd_;
  while (!m.is_terminal(g)) {
    const std::uint32_t v = m.top_var(g);
    REARM_DEMAND(v < s.size(), "symbol shorter than the propositions of the guard");
    g = s[v] ? m.high(g) : m.low(g);
  }
  return g == BddManager::kTrue;
}

std::string GeneralAlphabet::label(Guard g) const {
  if (g == BddManager::kTrue) return "t";
  if (g == BddManager::kFalse) return "f";
  Ref cover = 0;
  const std::vector<Cube> cubes = isop(*bdd_, g, g, &cover);
  REARM_DEMAND(cover == g, "irredundant cover differs from the guard");
  std::string out;
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    if (i > 0) out += " | ";
    // A cube is never empty here: the empty cube would make g true.
    for (std::size_t j = 0; j < cubes[i].size(); ++j) {
      if (j > 0) out += '&';
      if (!cubes[i][j].positive) out += '!';
      out += std::to_string(cubes[i][j].var);
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// ActionAlphabet.

ActionAlphabet::ActionAlphabet(std::vector<std::string> aps) : aps_(std::move(aps)) {
  check_distinct(aps_);
}

int ActionAlphabet::find_ap(const std::string& name) const { return find_in(aps_, name); }

ActionAlphabet::Guard ActionAlphabet::ap(std::uint32_t i, bool positive) const {
  REARM_DEMAND(i < aps_.size(), "proposition index out of range");
  if (positive) return LetterSet::single(num_letters(), i + 1);
  LetterSet s(num_letters(), true);
  s.reset(i + 1);
  return s;
}

std::string ActionAlphabet::label(const Guard& g) const {
  REARM_DEMAND(g.universe() == num_letters(), "guard over a different alphabet");
  if (g.full()) return "t";
  if (g.empty()) return "f";
  std::string out;
  if (!g.test(0)) {
    // No-action excluded: some included proposition must hold ("0 | 3").
    for (std::size_t l = g.next(1); l < num_letters(); l = g.next(l + 1)) {
      if (!out.empty()) out += " | ";
      out += std::to_string(l - 1);
    }
  } else {
    // No-action included: none of the excluded propositions may hold ("!1&!2"). The set is
    // not full, so at least one letter is excluded.
    for (std::size_t l = 1; l < num_letters(); ++l) {
      if (g.test(l)) continue;
      if (!out.empty()) out += '&';
      out += '!';
      out += std::to_string(l - 1);
    }
  }
  return out;
}

std::string ActionAlphabet::letter_name(std::size_t letter) const {
  REARM_DEMAND(letter < num_letters(), "letter out of range");
  return letter == 0 ? "none" : aps_[letter - 1];
}

}  // namespace rearm::ltl
