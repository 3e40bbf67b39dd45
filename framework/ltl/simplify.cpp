#include "ltl/simplify.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "core/error.h"

namespace rearm::ltl {
namespace {

using F = Formula;

F nnf(const F& f, bool neg) {
  const auto& c = f.children();
  switch (f.op()) {
    case Op::True:
      return neg ? F::ff() : F::tt();
    case Op::False:
      return neg ? F::tt() : F::ff();
    case Op::Ap:
      return neg ? F::lnot(f) : f;
    case Op::Not:
      return nnf(c[0], !neg);
    case Op::And:
    case Op::Or: {
      std::vector<F> out;
      out.reserve(c.size());
      for (const F& x : c) out.push_back(nnf(x, neg));
      return (f.op() == Op::And) != neg ? F::conj(std::move(out)) : F::disj(std::move(out));
    }
    case Op::Implies:  // a -> b == !a | b
      return nnf(F::disj(F::lnot(c[0]), c[1]), neg);
    case Op::Equiv:  // a <-> b == (a & b) | (!a & !b); !(a <-> b) == (a & !b) | (!a & b)
      return F::disj(F::conj(nnf(c[0], false), nnf(c[1], neg)),
                     F::conj(nnf(c[0], true), nnf(c[1], !neg)));
    case Op::Xor:
      return nnf(F::equiv(c[0], c[1]), !neg);
    case Op::Next:
      return F::next(nnf(c[0], neg));
    case Op::Eventually:
      return neg ? F::always(nnf(c[0], true)) : F::eventually(nnf(c[0], false));
    case Op::Always:
      return neg ? F::eventually(nnf(c[0], true)) : F::always(nnf(c[0], false));
    case Op::Until:  // !(a U b) == !a R !b
      return neg ? F::release(nnf(c[0], true), nnf(c[1], true))
                 : F::until(nnf(c[0], false), nnf(c[1], false));
    case Op::Release:
      return neg ? F::until(nnf(c[0], true), nnf(c[1], true))
                 : F::release(nnf(c[0], false), nnf(c[1], false));
    case Op::WeakUntil:  // a W b == b R (a | b)
      return nnf(F::release(c[1], F::disj(c[0], c[1])), neg);
    case Op::StrongRelease:  // a M b == b U (a & b)
      return nnf(F::until(c[1], F::conj(c[0], c[1])), neg);
  }
  REARM_DEMAND(false, "unknown operator");
}

bool is_literal(const F& f) {
  return f.op() == Op::Ap || (f.op() == Op::Not && f.child(0).op() == Op::Ap);
}

F negate_literal(const F& f) { return f.op() == Op::Not ? f.child(0) : F::lnot(f); }

bool is_gf(const F& f) { return f.op() == Op::Always && f.child(0).op() == Op::Eventually; }
bool is_suspendable(const F& f) { return is_eventual(f) && is_universal(f); }

// Smart constructors: each applies the local rules of the header and returns a formula
// whose direct children are already rewritten.
F mk_and(std::vector<F> in);
F mk_or(std::vector<F> in);
F mk_next(const F& a);
F mk_eventually(const F& a);
F mk_always(const F& a);
F mk_until(const F& a, const F& b);
F mk_release(const F& a, const F& b);

// Flattens, drops neutral elements, sorts, dedupes; returns false when absorbed.
bool collect(Op op, const std::vector<F>& in, std::vector<F>& out) {
  const Op absorbing = op == Op::And ? Op::False : Op::True;
  const Op neutral = op == Op::And ? Op::True : Op::False;
  for (const F& x : in) {
    if (x.op() == absorbing) return false;
    if (x.op() == neutral) continue;
    if (x.op() == op) {
      for (const F& y : x.children()) out.push_back(y);
    } else {
      out.push_back(x);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  for (const F& x : out) {  // p and !p together
    if (is_literal(x) && x.op() == Op::Not &&
        std::binary_search(out.begin(), out.end(), negate_literal(x))) {
      return false;
    }
  }
  return true;
}

F mk_and(std::vector<F> in) {
  std::vector<F> xs;
  if (!collect(Op::And, in, xs)) return F::ff();
  // X a & X b == X(a & b); F G a & F G b == F G(a & b).
  std::vector<F> nexts, fgs, rest;
  for (const F& x : xs) {
    if (x.op() == Op::Next) {
      nexts.push_back(x.child(0));
    } else if (x.op() == Op::Eventually && x.child(0).op() == Op::Always) {
      fgs.push_back(x.child(0).child(0));
    } else {
      rest.push_back(x);
    }
  }
  if (nexts.size() > 1) {
    rest.push_back(mk_next(mk_and(nexts)));
  } else if (nexts.size() == 1) {
    rest.push_back(F::next(nexts[0]));
  }
  if (fgs.size() > 1) {
    rest.push_back(mk_eventually(mk_always(mk_and(fgs))));
  } else if (fgs.size() == 1) {
    rest.push_back(F::eventually(F::always(fgs[0])));
  }
  if (nexts.size() > 1 || fgs.size() > 1) {
    std::vector<F> again;
    if (!collect(Op::And, rest, again)) return F::ff();
    rest = std::move(again);
  } else {
    std::sort(rest.begin(), rest.end());
  }
  return F::conj(std::move(rest));
}

F mk_or(std::vector<F> in) {
  std::vector<F> xs;
  if (!collect(Op::Or, in, xs)) return F::tt();
  // F a | F b == F(a | b); X a | X b == X(a | b); G F a | G F b == G F(a | b).
  std::vector<F> evs, nexts, gfs, rest;
  for (const F& x : xs) {
    if (is_gf(x)) {
      gfs.push_back(x.child(0).child(0));
    } else if (x.op() == Op::Eventually) {
      evs.push_back(x.child(0));
    } else if (x.op() == Op::Next) {
      nexts.push_back(x.child(0));
    } else {
      rest.push_back(x);
    }
  }
  bool changed = false;
  auto fold = [&](std::vector<F>& group, auto make, auto single) {
    if (group.size() > 1) {
      rest.push_back(make(mk_or(group)));
      changed = true;
    } else if (group.size() == 1) {
      rest.push_back(single(group[0]));
    }
  };
  fold(
      evs, [](const F& a) { return mk_eventually(a); },
      [](const F& a) { return F::eventually(a); });
  fold(
      nexts, [](const F& a) { return mk_next(a); }, [](const F& a) { return F::next(a); });
  fold(
      gfs, [](const F& a) { return mk_always(mk_eventually(a)); },
      [](const F& a) { return F::always(F::eventually(a)); });
  if (changed) {
    std::vector<F> again;
    if (!collect(Op::Or, rest, again)) return F::tt();
    rest = std::move(again);
  } else {
    std::sort(rest.begin(), rest.end());
  }
  return F::disj(std::move(rest));
}

F mk_next(const F& a) {
  if (a.op() == Op::True || a.op() == Op::False) return a;
  if (is_suspendable(a)) return a;  // X s == s
  return F::next(a);
}

// Splits the operands of `f` (an And when op == And, an Or when op == Or, else {f}) into
// suspendable ones and the rest.
void split_suspendable(const F& f, Op op, std::vector<F>& susp, std::vector<F>& rest) {
  if (f.op() == op) {
    for (const F& x : f.children()) (is_suspendable(x) ? susp : rest).push_back(x);
  } else {
    (is_suspendable(f) ? susp : rest).push_back(f);
  }
}

F mk_eventually(const F& a) {
  if (a.op() == Op::True || a.op() == Op::False) return a;
  if (is_eventual(a)) return a;                               // F e == e (includes F F a == F a)
  if (a.op() == Op::Until) return mk_eventually(a.child(1));  // F(a U b) == F b
  if (a.op() == Op::Next) return mk_next(mk_eventually(a.child(0)));  // F X a == X F a
  if (a.op() == Op::Or) {
    // F(e | (a U b) | c) == e | F(b | c) for eventual e. The disjuncts left inside are not
    // eventual, so mk_or's regrouping of F's cannot come back here with the same operand.
    std::vector<F> evs, rest;
    for (const F& x : a.children()) {
      const F y = x.op() == Op::Until ? x.child(1) : x;
      (is_eventual(y) ? evs : rest).push_back(y);
    }
    if (evs.empty()) return F::eventually(mk_or(std::move(rest)));
    if (!rest.empty()) evs.push_back(F::eventually(mk_or(std::move(rest))));
    return mk_or(std::move(evs));
  }
  std::vector<F> susp, rest;
  split_suspendable(a, Op::And, susp, rest);  // F(a & s) == F a & s
  if (!susp.empty()) {
    susp.push_back(mk_eventually(mk_and(rest)));
    return mk_and(std::move(susp));
  }
  return F::eventually(a);
}

// G F a with the rules GF(a & F b) == GF a & GF b, GF(X a) == GF a, GF(F a) == GF a, and
// GF(a & s) == GF a & s for suspendable s.
F mk_always_eventually(const F& a) {
  if (a.op() == Op::True || a.op() == Op::False) return a;
  if (a.op() == Op::Next) return mk_always_eventually(a.child(0));
  if (a.op() == Op::Eventually) return mk_always_eventually(a.child(0));
  if (is_suspendable(a)) return a;
  if (a.op() == Op::And) {
    std::vector<F> parts, rest;
    for (const F& x : a.children()) {
      if (is_suspendable(x)) {
        parts.push_back(x);
      } else if (x.op() == Op::Eventually) {
        parts.push_back(mk_always_eventually(x.child(0)));
      } else {
        rest.push_back(x);
      }
    }
    if (!parts.empty()) {
      if (!rest.empty()) parts.push_back(mk_always_eventually(mk_and(rest)));
      return mk_and(std::move(parts));
    }
  }
  if (a.op() == Op::Or) {  // GF(a | b): F distributes first
    std::vector<F> xs;
    for (const F& x : a.children()) {
      xs.push_back(x.op() == Op::Eventually ? x.child(0) : x);
    }
    return F::always(F::eventually(mk_or(std::move(xs))));
  }
  return F::always(F::eventually(a));
}

F mk_always(const F& a) {
  if (a.op() == Op::True || a.op() == Op::False) return a;
  if (is_universal(a)) return a;                            // G u == u (includes G G a == G a)
  if (a.op() == Op::Release) return mk_always(a.child(1));  // G(a R b) == G b
  if (a.op() == Op::Next) return mk_next(mk_always(a.child(0)));  // G X a == X G a
  if (a.op() == Op::Eventually) return mk_always_eventually(a.child(0));
  if (a.op() == Op::And) {  // G(a & b) == G a & G b
    std::vector<F> xs;
    for (const F& x : a.children()) xs.push_back(mk_always(x));
    return mk_and(std::move(xs));
  }
  std::vector<F> susp, rest;
  split_suspendable(a, Op::Or, susp, rest);  // G(a | s) == G a | s
  if (!susp.empty()) {
    susp.push_back(mk_always(mk_or(rest)));
    return mk_or(std::move(susp));
  }
  return F::always(a);
}

F mk_until(const F& a, const F& b) {
  if (b.op() == Op::True || b.op() == Op::False) return b;
  if (a.op() == Op::False) return b;
  if (a.op() == Op::True) return mk_eventually(b);
  if (a == b) return a;
  if (is_eventual(b)) return b;  // a U e == e (includes a U F b == F b)
  if (a.op() == Op::Next && b.op() == Op::Next) return mk_next(mk_until(a.child(0), b.child(0)));
  if (b.op() == Op::Until && b.child(0) == a) return b;  // a U (a U b) == a U b
  return F::until(a, b);
}

F mk_release(const F& a, const F& b) {
  if (b.op() == Op::True || b.op() == Op::False) return b;
  if (a.op() == Op::True) return b;
  if (a.op() == Op::False) return mk_always(b);
  if (a == b) return a;
  if (is_universal(b)) return b;  // a R u == u (includes a R G b == G b)
  if (a.op() == Op::Next && b.op() == Op::Next) {
    return mk_next(mk_release(a.child(0), b.child(0)));
  }
  if (b.op() == Op::Release && b.child(0) == a) return b;  // a R (a R b) == a R b
  return F::release(a, b);
}

F rewrite_once(const F& f) {
  std::vector<F> c;
  c.reserve(f.arity());
  for (const F& x : f.children()) c.push_back(rewrite_once(x));
  switch (f.op()) {
    case Op::And:
      return mk_and(std::move(c));
    case Op::Or:
      return mk_or(std::move(c));
    case Op::Next:
      return mk_next(c[0]);
    case Op::Eventually:
      return mk_eventually(c[0]);
    case Op::Always:
      return mk_always(c[0]);
    case Op::Until:
      return mk_until(c[0], c[1]);
    case Op::Release:
      return mk_release(c[0], c[1]);
    default:
      return f;  // tt, ff, literals
  }
}

}  // namespace

bool is_eventual(const F& f) {
  switch (f.op()) {
    case Op::True:
    case Op::False:
      return true;
    case Op::Eventually:
      return true;
    case Op::Always:
    case Op::Next:
      return is_eventual(f.child(0));
    case Op::Until:
      return is_eventual(f.child(1));
    case Op::Release:
      return is_eventual(f.child(0)) && is_eventual(f.child(1));
    case Op::And:
    case Op::Or:
      return std::all_of(f.children().begin(), f.children().end(),
                         [](const F& x) { return is_eventual(x); });
    default:
      return false;
  }
}

bool is_universal(const F& f) {
  switch (f.op()) {
    case Op::True:
    case Op::False:
      return true;
    case Op::Always:
      return true;
    case Op::Eventually:
    case Op::Next:
      return is_universal(f.child(0));
    case Op::Release:
      return is_universal(f.child(1));
    case Op::Until:
      return is_universal(f.child(0)) && is_universal(f.child(1));
    case Op::And:
    case Op::Or:
      return std::all_of(f.children().begin(), f.children().end(),
                         [](const F& x) { return is_universal(x); });
    default:
      return false;
  }
}

Formula to_nnf(const Formula& f) { return nnf(f, false); }

Formula rewrite(const Formula& f) {
  F cur = to_nnf(f);
  // Each pass only shrinks or regroups; a handful of passes reach the fixpoint.
  constexpr int kMaxPasses = 16;
  for (int i = 0; i < kMaxPasses; ++i) {
    F next = rewrite_once(cur);
    if (next == cur) break;
    cur = next;
  }
  return cur;
}

}  // namespace rearm::ltl
