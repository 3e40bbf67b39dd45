// LTL formulas as immutable, shareable syntax trees (value type: copying is cheap, nodes are
// shared and never modified, so formulas may be read from several threads).
//
// Constructors build exactly the tree asked for (no simplification), so the parser's output
// is the formula as written; ltl/simplify.h does normalization and rewriting. Atomic
// propositions are plain identifiers (`p1`) or the paper's action predicates, stored in the
// canonical spelling without spaces: `move(l1)`, `grasp(M1)`, `release(M1,l2)`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rearm::ltl {

enum class Op : std::uint8_t {
  True,
  False,
  Ap,  // atomic proposition
  Not,
  And,            // n-ary (>= 2 children)
  Or,             // n-ary (>= 2 children)
  Implies,        // a -> b
  Equiv,          // a <-> b
  Xor,            // a xor b
  Next,           // X a
  Eventually,     // F a  (<> a)
  Always,         // G a  ([] a)
  Until,          // a U b
  Release,        // a R b  (a V b)
  WeakUntil,      // a W b
  StrongRelease,  // a M b
};

// Output spelling: Spin is spin/ltl2ba's (`<>`, `[]`, `V`, `&&`, `||`, `->`, `<->`; W and M
// are expanded, X is written `X`); Spot is Spot's (`F`, `G`, `R`, `&`, `|`, `W`, `M`, `X`).
enum class Syntax : std::uint8_t { Spin, Spot };

class Formula {
 public:
  // Leaves.
  static Formula tt();
  static Formula ff();
  static Formula ap(std::string name);
  // Operators. `conj`/`disj` with one child return that child, with none tt()/ff().
  static Formula lnot(Formula a);
  static Formula conj(std::vector<Formula> children);
  static Formula disj(std::vector<Formula> children);
  static Formula conj(Formula a, Formula b) { return conj(std::vector<Formula>{a, b}); }
  static Formula disj(Formula a, Formula b) { return disj(std::vector<Formula>{a, b}); }
  static Formula implies(Formula a, Formula b);
  static Formula equiv(Formula a, Formula b);
  static Formula lxor(Formula a, Formula b);
  static Formula next(Formula a);
  static Formula eventually(Formula a);
  static Formula always(Formula a);
  static Formula until(Formula a, Formula b);
  static Formula release(Formula a, Formula b);
  static Formula weak_until(Formula a, Formula b);
  static Formula strong_release(Formula a, Formula b);
  // Generic constructor for an operator and its children (arity checked, throws rearm::Error).
  static Formula make(Op op, std::vector<Formula> children);

  Formula();  // tt()

  Op op() const;
  // Name of an atomic proposition (empty for other operators).
  const std::string& name() const;
  std::size_t arity() const;
  const Formula& child(std::size_t i) const;
  const std::vector<Formula>& children() const;

  // Structural hash and equality (equal trees compare equal whatever their sharing).
  std::size_t hash() const;
  bool operator==(const Formula& other) const;
  bool operator!=(const Formula& other) const { return !(*this == other); }
  // A strict total order on trees (by hash, then structure), for canonical sorting.
  bool operator<(const Formula& other) const;

  // Number of nodes of the tree.
  std::size_t size() const;
  // True when no temporal operator occurs (X F G U R W M).
  bool is_boolean() const;
  // True when X occurs.
  bool has_next() const;
  // Atomic proposition names in order of first occurrence (left to right).
  std::vector<std::string> atomic_propositions() const;

  // Fully parenthesized where precedence needs it. The Spot spelling reparses to an equal tree
  // with parse(); so does the spin spelling, except that spin has no xor and a xor b is written
  // !(a <-> b), an equivalent tree that prints to the same spin text.
  std::string to_string(Syntax syntax = Syntax::Spot) const;

  // Identity of the shared node (for memo tables); equal formulas may have different ids.
  const void* node_id() const { return node_.get(); }

  struct Node;

 private:
  explicit Formula(std::shared_ptr<const Node> n) : node_(std::move(n)) {}
  std::shared_ptr<const Node> node_;
};

struct FormulaHash {
  std::size_t operator()(const Formula& f) const { return f.hash(); }
};

// Binding strength in Spot's precedence, shared by the parser and the printer (higher binds
// tighter): 1 -> <->, 2 |, 3 xor, 4 &, 5 U R W M, 6 ! X F G, 7 leaves.
int precedence(Op op);

// True for action-predicate names: move(x), grasp(x), release(x,y).
bool is_action_predicate(const std::string& ap_name);

}  // namespace rearm::ltl
