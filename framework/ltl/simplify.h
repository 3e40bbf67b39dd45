// Formula normalization and rewriting before translation (docs/symbolic.md "Translation").
//
// to_nnf: negation normal form over tt, ff, p, !p, &, |, X, F, G, U, R (W, M, ->, <->, xor
// are expanded; negation is pushed to the propositions with the LTL dualities).
// rewrite: to_nnf followed by bottom-up rewriting to a fixpoint with the rules of Somenzi &
// Bloem (CAV 2000) and Etessami & Holzmann (CONCUR 2000): Boolean absorption, idempotence,
// F F a = F a, G G a = G a, a U F b = F b, a R G b = G b, pure eventualities (e = F e) and
// universalities (u = G u), suspendable formulas (both; X s = s, F(a & s) = F a & s,
// G(a | s) = G a | s), X distribution, F a | F b = F(a | b), G(a & b) = G a & G b, and
// GF(a & F b) = GF a & GF b (which turns the sequenced patrol into a conjunction of GF).
// Every rule is an LTL equivalence; the translator's tests check the result's language.
#pragma once

#include "ltl/formula.h"

namespace rearm::ltl {

Formula to_nnf(const Formula& f);
Formula rewrite(const Formula& f);

// Syntactic classes of Etessami & Holzmann (on NNF formulas): a pure eventuality satisfies
// e == F e, a purely universal formula u == G u; suspendable formulas are both.
bool is_eventual(const Formula& f);
bool is_universal(const Formula& f);

}  // namespace rearm::ltl
