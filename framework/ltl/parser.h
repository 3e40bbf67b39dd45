// LTL parser for the spin/ltl2ba and the Spot spellings (docs/symbolic.md "Formulas").
//
// Grammar (Spot's precedence, loosest first; binary temporal operators right-associative):
//   f ::= f '->' f | f '<->' f            (right-assoc; also '=>' '<=>')
//       | f '|' f  | f '||' f             (also '\/')
//       | f 'xor' f | f '^' f
//       | f '&' f  | f '&&' f             (also '/\')
//       | f 'U' f | f 'R' f | f 'V' f | f 'W' f | f 'M' f
//       | '!' f | '~' f | 'X' f | 'F' f | '<>' f | 'G' f | '[]' f
//       | '(' f ')' | 'true' | 'false' | '1' | '0' | ap
//   ap ::= identifier | '"' any chars but '"' '"'
//        | 'move' '(' id ')' | 'grasp' '(' id ')' | 'release' '(' id ',' id ')'
// Identifiers are [A-Za-z_][A-Za-z0-9_]*. As in Spot, an identifier made of a run of the
// unary operator letters F, G, X, alone or followed by a lower-case letter, is split into
// operators (`GFa` and `GF(a)` are G F a; `F1`, `FGA` are propositions); the single letters
// U R V W M X F G and `true`/`false` are keywords. Action predicates are stored in canonical
// spelling without spaces.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"
#include "ltl/formula.h"

namespace rearm::ltl {

// Raised for malformed input. what() reads
//   "ltl parse error at line L, column C: expected E, found F"
// with 1-based line and column (column counts bytes).
class ParseError : public Error {
 public:
  ParseError(std::size_t line, std::size_t column, std::string expected, std::string found);
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  std::size_t line_, column_;
  std::string expected_, found_;
};

// Parses any byte string: returns the formula or throws ParseError (never crashes; nesting
// deeper than kMaxParseDepth is an error, not a stack overflow).
Formula parse(std::string_view text);

inline constexpr std::size_t kMaxParseDepth = 1000;

}  // namespace rearm::ltl
