// The two alphabets of docs/symbolic.md, as guard algebras with one interface, so the
// translator and the automaton algorithms are written once (templates over Alphabet).
//
//   GeneralAlphabet: symbols are subsets of AP (bit i = aps[i] true); guards are BDDs.
//   ActionAlphabet:  symbols are letters 0..N (0 = no action, i+1 = only aps[i] true);
//                    guards are LetterSets. Exclusivity is built in: a guard needing two
//                    predicates at once is the empty set (the paper's b_inf pruning).
//
// Common interface: Guard, Symbol, aps, top(), bottom(), ap(i, positive), conj, disj,
// implies, is_false, contains(guard, symbol), and label(guard): a Boolean expression over
// AP indices in HOA syntax ("t", "0&!1 | 2"). For ActionAlphabet the label is exact on
// symbols with at most one true proposition (the alphabet's whole domain).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ltl/bdd.h"
#include "ltl/letter_set.h"

namespace rearm::ltl {

class GeneralAlphabet {
 public:
  using Guard = BddManager::Ref;
  using Symbol = std::vector<bool>;  // symbol[i]: aps[i] holds

  GeneralAlphabet();  // fresh manager, no propositions
  explicit GeneralAlphabet(std::vector<std::string> aps, std::shared_ptr<BddManager> bdd = nullptr);

  const std::vector<std::string>& aps() const { return aps_; }
  // Index of a proposition, adding it (and a BDD variable) when absent.
  std::uint32_t ap_index(const std::string& name);
  // Index or -1.
  int find_ap(const std::string& name) const;
  BddManager& bdd() const { return *bdd_; }
  const std::shared_ptr<BddManager>& bdd_ptr() const { return bdd_; }

  Guard top() const { return BddManager::kTrue; }
  Guard bottom() const { return BddManager::kFalse; }
  Guard ap(std::uint32_t i, bool positive) const;
  Guard conj(Guard a, Guard b) const { return bdd_->conj(a, b); }
  Guard disj(Guard a, Guard b) const { return bdd_->disj(a, b); }
  bool implies(Guard a, Guard b) const { return bdd_->implies(a, b); }
  bool is_false(Guard a) const { return a == BddManager::kFalse; }
  bool contains(Guard g, const Symbol& s) const;
  std::string label(Guard g) const;
  static std::size_t guard_hash(Guard g) { return g; }

 private:
  std::vector<std::string> aps_;
  std::shared_ptr<BddManager> bdd_;
};

class ActionAlphabet {
 public:
  using Guard = LetterSet;
  using Symbol = std::size_t;  // letter: 0 = no action, i+1 = aps[i]

  ActionAlphabet() = default;
  explicit ActionAlphabet(std::vector<std::string> aps);

  const std::vector<std::string>& aps() const { return aps_; }
  int find_ap(const std::string& name) const;
  std::size_t num_letters() const { return aps_.size() + 1; }

  Guard top() const { return LetterSet(num_letters(), true); }
  Guard bottom() const { return LetterSet(num_letters(), false); }
  // "aps[i]" is the letter i+1 alone; "!aps[i]" is every other letter.
  Guard ap(std::uint32_t i, bool positive) const;
  Guard conj(const Guard& a, const Guard& b) const { return a & b; }
  Guard disj(const Guard& a, const Guard& b) const { return a | b; }
  bool implies(const Guard& a, const Guard& b) const { return a.subset_of(b); }
  bool is_false(const Guard& a) const { return a.empty(); }
  bool contains(const Guard& g, Symbol s) const { return g.test(s); }
  std::string label(const Guard& g) const;
  static std::size_t guard_hash(const Guard& g) { return g.hash(); }
  // Name of a letter: "none" for 0, else the proposition.
  std::string letter_name(std::size_t letter) const;

 private:
  std::vector<std::string> aps_;
};

}  // namespace rearm::ltl
