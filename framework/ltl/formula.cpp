#include "ltl/formula.h"

#include <algorithm>
#include <unordered_set>

#include "core/error.h"

namespace rearm::ltl {

struct Formula::Node {
  Op op;
  std::string name;
  std::vector<Formula> children;
  std::size_t hash = 0;
  std::size_t size = 1;
  bool boolean = true;
  bool has_next = false;
};

namespace {

// ASCII classes (the <cctype> ones depend on the C locale; the parser is ASCII-only).
bool ascii_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool ascii_alnum(char c) { return ascii_alpha(c) || (c >= '0' && c <= '9'); }

std::size_t mix(std::size_t h, std::size_t v) {
  return h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

bool is_temporal(Op op) {
  switch (op) {
    case Op::Next:
    case Op::Eventually:
    case Op::Always:
    case Op::Until:
    case Op::Release:
    case Op::WeakUntil:
    case Op::StrongRelease:
      return true;
    default:
      return false;
  }
}

int expected_arity(Op op) {
  switch (op) {
    case Op::True:
    case Op::False:
    case Op::Ap:
      return 0;
    case Op::Not:
    case Op::Next:
    case Op::Eventually:
    case Op::Always:
      return 1;
    case Op::And:
    case Op::Or:
      return -1;  // n-ary, >= 2
    default:
      return 2;
  }
}

const Formula& shared_tt() {
  static const Formula f = Formula::make(Op::True, {});
  return f;
}

}  // namespace

Formula Formula::make(Op op, std::vector<Formula> children) {
  const int arity = expected_arity(op);
  if (arity >= 0 && static_cast<int>(children.size()) != arity) {
    throw Error("ltl: operator expects " + std::to_string(arity) + " operand(s), got " +
                std::to_string(children.size()));
  }
  if (arity < 0 && children.size() < 2) {
    throw Error("ltl: n-ary operator expects at least 2 operands");
  }
  auto n = std::make_shared<Node>();
  n->op = op;
  std::size_t h = std::hash<int>()(static_cast<int>(op) + 1);
  for (const Formula& c : children) {
    h = mix(h, c.hash());
    n->size += c.size();
    n->boolean = n->boolean && c.is_boolean();
    n->has_next = n->has_next || c.has_next();
  }
  if (is_temporal(op)) n->boolean = false;
  if (op == Op::Next) n->has_next = true;
  n->children = std::move(children);
  n->hash = h;
  return Formula(std::move(n));
}

Formula Formula::tt() { return shared_tt(); }
Formula Formula::ff() {
  static const Formula f = make(Op::False, {});
  return f;
}
Formula Formula::ap(std::string name) {
  if (name.empty()) throw Error("ltl: empty atomic proposition name");
  if (name.find('"') != std::string::npos) {
    throw Error("ltl: atomic proposition names cannot contain '\"'");
  }
  auto n = std::make_shared<Node>();
  n->op = Op::Ap;
  n->hash = mix(std::hash<std::string>()(name), 0x51ed27);
  n->name = std::move(name);
  return Formula(std::move(n));
}
Formula Formula::lnot(Formula a) { return make(Op::Not, {std::move(a)}); }
Formula Formula::conj(std::vector<Formula> c) {
  if (c.empty()) return tt();
  if (c.size() == 1) return c[0];
  return make(Op::And, std::move(c));
}
Formula Formula::disj(std::vector<Formula> c) {
  if (c.empty()) return ff();
  if (c.size() == 1) return c[0];
  return make(Op::Or, std::move(c));
}
Formula Formula::implies(Formula a, Formula b) { return make(Op::Implies, {a, b}); }
Formula Formula::equiv(Formula a, Formula b) { return make(Op::Equiv, {a, b}); }
Formula Formula::lxor(Formula a, Formula b) { return make(Op::Xor, {a, b}); }
Formula Formula::next(Formula a) { return make(Op::Next, {a}); }
Formula Formula::eventually(Formula a) { return make(Op::Eventually, {a}); }
Formula Formula::always(Formula a) { return make(Op::Always, {a}); }
Formula Formula::until(Formula a, Formula b) { return make(Op::Until, {a, b}); }
Formula Formula::release(Formula a, Formula b) { return make(Op::Release, {a, b}); }
Formula Formula::weak_until(Formula a, Formula b) { return make(Op::WeakUntil, {a, b}); }
Formula Formula::strong_release(Formula a, Formula b) { return make(Op::StrongRelease, {a, b}); }

Formula::Formula() : node_(shared_tt().node_) {}

Op Formula::op() const { return node_->op; }
const std::string& Formula::name() const { return node_->name; }
std::size_t Formula::arity() const { return node_->children.size(); }
const Formula& Formula::child(std::size_t i) const { return node_->children.at(i); }
const std::vector<Formula>& Formula::children() const { return node_->children; }
std::size_t Formula::hash() const { return node_->hash; }
std::size_t Formula::size() const { return node_->size; }
bool Formula::is_boolean() const { return node_->boolean; }
bool Formula::has_next() const { return node_->has_next; }

bool Formula::operator==(const Formula& o) const {
  if (node_ == o.node_) return true;
  if (node_->hash != o.node_->hash || node_->op != o.node_->op || node_->size != o.node_->size ||
      node_->name != o.node_->name || node_->children.size() != o.node_->children.size()) {
    return false;
  }
  for (std::size_t i = 0; i < node_->children.size(); ++i) {
    if (node_->children[i] != o.node_->children[i]) return false;
  }
  return true;
}

bool Formula::operator<(const Formula& o) const {
  if (node_ == o.node_) return false;
  if (node_->hash != o.node_->hash) return node_->hash < o.node_->hash;
  if (node_->op != o.node_->op) return node_->op < o.node_->op;
  if (node_->name != o.node_->name) return node_->name < o.node_->name;
  if (node_->children.size() != o.node_->children.size()) {
    return node_->children.size() < o.node_->children.size();
  }
  for (std::size_t i = 0; i < node_->children.size(); ++i) {
    if (node_->children[i] != o.node_->children[i])
      return node_->children[i] < o.node_->children[i];
  }
  return false;
}

std::vector<std::string> Formula::atomic_propositions() const {
  std::vector<std::string> out;
  std::unordered_set<std::string> seen;
  std::vector<const Formula*> stack{this};
  while (!stack.empty()) {
    const Formula* f = stack.back();
    stack.pop_back();
    if (f->op() == Op::Ap) {
      if (seen.insert(f->name()).second) out.push_back(f->name());
      continue;
    }
    for (auto it = f->children().rbegin(); it != f->children().rend(); ++it) stack.push_back(&*it);
  }
  return out;
}

namespace {

bool needs_quotes(const std::string& name) {
  if (is_action_predicate(name)) return false;
  if (!(ascii_alpha(name[0]) || name[0] == '_')) return true;
  for (char c : name) {
    if (!(ascii_alnum(c) || c == '_')) return true;
  }
  static const std::unordered_set<std::string> reserved = {"true", "false", "X", "F", "G",  "U",
                                                           "R",    "W",     "M", "V", "xor"};
  if (reserved.count(name)) return true;
  // Identifiers starting with F, G or X then a lower-case letter or digit would split
  // into operators (see parser.h).
  if (name.size() > 1 && (name[0] == 'F' || name[0] == 'G' || name[0] == 'X')) return true;
  return false;
}

void print(const Formula& f, Syntax s, std::string& out);

void print_operand(const Formula& c, int parent_prec, Syntax s, std::string& out) {
  // Always parenthesize a binary child of a binary operator: unambiguous in both syntaxes
  // (spin's own precedence differs from Spot's).
  // In spin syntax every compound operand is parenthesized except a negated proposition.
  const int cp = precedence(c.op());
  const bool spin_compound =
      s == Syntax::Spin && c.arity() > 0 && !(c.op() == Op::Not && c.child(0).arity() == 0);
  if ((cp <= 5 && parent_prec <= 6) || spin_compound) {
    out += '(';
    print(c, s, out);
    out += ')';
  } else {
    print(c, s, out);
  }
}

void print(const Formula& f, Syntax s, std::string& out) {
  const bool spin = s == Syntax::Spin;
  const int p = precedence(f.op());
  auto binary = [&](const char* spin_op, const char* spot_op) {
    print_operand(f.child(0), p, s, out);
    out += spin ? spin_op : spot_op;
    print_operand(f.child(1), p, s, out);
  };
  auto unary = [&](const char* spin_op, const char* spot_op) {
    out += spin ? spin_op : spot_op;
    print_operand(f.child(0), p, s, out);
  };
  switch (f.op()) {
    case Op::True:
      out += "true";
      return;
    case Op::False:
      out += "false";
      return;
    case Op::Ap:
      if (needs_quotes(f.name())) {
        out += '"';
        out += f.name();
        out += '"';
      } else {
        out += f.name();
      }
      return;
    case Op::Not:
      unary("!", "!");
      return;
    case Op::Next:
      unary("X ", "X ");
      return;
    case Op::Eventually:
      unary("<> ", "F ");
      return;
    case Op::Always:
      unary("[] ", "G ");
      return;
    case Op::And:
    case Op::Or:
      for (std::size_t i = 0; i < f.arity(); ++i) {
        if (i) out += f.op() == Op::And ? (spin ? " && " : " & ") : (spin ? " || " : " | ");
        print_operand(f.child(i), p, s, out);
      }
      return;
    case Op::Implies:
      binary(" -> ", " -> ");
      return;
    case Op::Equiv:
      binary(" <-> ", " <-> ");
      return;
    case Op::Xor:
      if (spin) {  // spin has no xor: a xor b == !(a <-> b)
        out += "!(";
        binary(" <-> ", " <-> ");
        out += ')';
      } else {
        binary(" xor ", " xor ");
      }
      return;
    case Op::Until:
      binary(" U ", " U ");
      return;
    case Op::Release:
      binary(" V ", " R ");
      return;
    case Op::WeakUntil:
      // spin has no W. a W b == (a U b) || [] a == b V (a || b): the spelling repeats the
      // smaller operand, so that nested W stay polynomial in size (a chain of n right-nested W
      // printed as b V (a || b) throughout doubles n times).
      if (spin) {
        const Formula& a = f.child(0);
        const Formula& b = f.child(1);
        print(a.size() <= b.size() ? Formula::disj(Formula::until(a, b), Formula::always(a))
                                   : Formula::release(b, Formula::disj(a, b)),
              s, out);
      } else {
        binary(" W ", " W ");
      }
      return;
    case Op::StrongRelease:
      // spin has no M. a M b == (a R b) && <> a == b U (a && b): the smaller operand repeats.
      if (spin) {
        const Formula& a = f.child(0);
        const Formula& b = f.child(1);
        print(a.size() <= b.size() ? Formula::conj(Formula::release(a, b), Formula::eventually(a))
                                   : Formula::until(b, Formula::conj(a, b)),
              s, out);
      } else {
        binary(" M ", " M ");
      }
      return;
  }
}

}  // namespace

std::string Formula::to_string(Syntax syntax) const {
  std::string out;
  print(*this, syntax, out);
  return out;
}

int precedence(Op op) {
  switch (op) {
    case Op::Implies:
    case Op::Equiv:
      return 1;
    case Op::Or:
      return 2;
    case Op::Xor:
      return 3;
    case Op::And:
      return 4;
    case Op::Until:
    case Op::Release:
    case Op::WeakUntil:
    case Op::StrongRelease:
      return 5;
    case Op::Not:
    case Op::Next:
    case Op::Eventually:
    case Op::Always:
      return 6;
    default:
      return 7;
  }
}

bool is_action_predicate(const std::string& n) {
  auto ident = [](const std::string& s) {
    if (s.empty() || !(ascii_alpha(s[0]) || s[0] == '_')) return false;
    for (char c : s)
      if (!(ascii_alnum(c) || c == '_')) return false;
    return true;
  };
  const auto open = n.find('(');
  if (open == std::string::npos || n.back() != ')') return false;
  const std::string verb = n.substr(0, open);
  const std::string args = n.substr(open + 1, n.size() - open - 2);
  const auto comma = args.find(',');
  if (verb == "move" || verb == "grasp") return comma == std::string::npos && ident(args);
  if (verb == "release") {
    return comma != std::string::npos && ident(args.substr(0, comma)) &&
           ident(args.substr(comma + 1));
  }
  return false;
}

}  // namespace rearm::ltl
