// Internal to the ltl module: the pieces that more than one automaton format of
// ltl/automaton_io.h uses (hoa_io.cpp, never_claim_io.cpp, dot_io.cpp). Errors with a line
// number, character classes, HOA tokens (the HOA reader reads them, and the writers lex
// Alphabet::label's text with them), the HOA label-expression parser, the label expression
// tree the writers re-spell, and the one-action note.
//
// Guards are printed through Alphabet::label (a HOA label expression over proposition
// indices), parsed back into a small expression tree and re-spelled for spin and DOT, so all
// three writers print the same Boolean expression.
//
// The one-action alphabet: ActionAlphabet::label is exact only on symbols with at most one
// true proposition (the empty symbol and the N singletons, the alphabet's whole domain). A
// tool that reads the output over the general alphabet (Spot, spin) sees some guard also
// accept symbols with two or more true propositions, where the ActionNba says nothing. The
// HOA output says so in a `rearm-alphabet: "one-action"` header (a header whose name starts
// with a lower-case letter may be ignored by tools, HOA v1 "Header") and a comment; the
// never claim and the DOT text in a comment.
//
// Include only from the ltl module's .cpp files.
#pragma once

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "ltl/automaton.h"

namespace rearm::ltl::io_detail {

using Ref = BddManager::Ref;

// Nesting depth of label and guard expressions beyond which input is rejected with an error
// (the parsers are recursive; this bounds their stack use on hostile input).
constexpr int kMaxNesting = 500;

inline const char* const kOneActionNote =
    "one-action alphabet: guards are exact only on symbols with at most one true proposition";

[[noreturn]] void fail(const char* reader, int line, const std::string& reason);

std::string describe_char(char c);

inline bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }

// A double-quoted string for HOA and DOT (both escape '"' and '\').
std::string quoted(const std::string& s);

// ----------------------------------------------------------------------------------------
// HOA tokens (HOA v1, "Common Tokens"). Comments nest.

enum class HoaTok {
  kEnd,
  kInt,
  kString,
  kIdent,
  kHeader,
  kAlias,
  kBody,
  kEndMarker,
  kAbort,
  kPunct
};

struct HoaToken {
  HoaTok kind = HoaTok::kEnd;
  // Identifier, header name without ':', unescaped string, alias name without '@', or the
  // punctuation character.
  std::string text;
  std::uint32_t value = 0;  // kInt
  int line = 1;
};

std::vector<HoaToken> lex_hoa(std::string_view s, const char* who);

std::string describe(const HoaToken& t);

inline bool is_punct(const HoaToken& t, char c) {
  return t.kind == HoaTok::kPunct && t.text.size() == 1 && t.text[0] == c;
}

// ----------------------------------------------------------------------------------------
// HOA label expressions: label-expr ::= BOOLEAN | INT | ANAME | "!" label-expr | "(" ... ")"
// | label-expr "&" label-expr | label-expr "|" label-expr; "!" binds tighter than "&", "&"
// tighter than "|". Parsed over a token vector into whatever a Builder makes (guards for the
// reader, expression trees for the writers).

template <class Builder>
class LabelParser {
 public:
  using Value = typename Builder::Value;
  LabelParser(const std::vector<HoaToken>& toks, std::size_t& pos, Builder& builder,
              const char* who)
      : toks_(toks), pos_(pos), b_(builder), who_(who) {}

  Value parse() { return parse_or(0); }

 private:
  const HoaToken& peek() const { return toks_[pos_]; }

  Value parse_or(int depth) {
    Value v = parse_and(depth);
    while (is_punct(peek(), '|')) {
      ++pos_;
      v = b_.disj(std::move(v), parse_and(depth));
    }
    return v;
  }
  Value parse_and(int depth) {
    Value v = parse_not(depth);
    while (is_punct(peek(), '&')) {
      ++pos_;
      v = b_.conj(std::move(v), parse_not(depth));
    }
    return v;
  }
  Value parse_not(int depth) {
    const HoaToken& t = peek();
    if (depth > kMaxNesting) fail(who_, t.line, "label expression nested too deeply");
    if (is_punct(t, '!')) {
      ++pos_;
      return b_.neg(parse_not(depth + 1));
    }
    if (is_punct(t, '(')) {
      ++pos_;
      Value v = parse_or(depth + 1);
      if (!is_punct(peek(), ')')) {
        fail(who_, peek().line, "expected ')' in label expression, found " + describe(peek()));
      }
      ++pos_;
      return v;
    }
    if (t.kind == HoaTok::kIdent && (t.text == "t" || t.text == "f")) {
      ++pos_;
      return b_.constant(t.text == "t");
    }
    if (t.kind == HoaTok::kInt) {
      ++pos_;
      return b_.ap(t.value, t.line);
    }
    if (t.kind == HoaTok::kAlias) {
      ++pos_;
      return b_.alias(t.text, t.line);
    }
    fail(who_, t.line,
         "expected a label expression (t, f, an integer, an @alias, '!' or '('),"
         " found " +
             describe(t));
  }

  const std::vector<HoaToken>& toks_;
  std::size_t& pos_;
  Builder& b_;
  const char* who_;
};

// ----------------------------------------------------------------------------------------
// Writers: expression trees from Alphabet::label, re-spelled per output format.

struct LabelExpr {
  enum class Kind { kTrue, kFalse, kAp, kNot, kAnd, kOr };
  Kind kind = Kind::kTrue;
  std::uint32_t ap = 0;
  std::vector<LabelExpr> kids;
};

// The expression tree of alphabet.label(g); instantiated for GeneralAlphabet and
// ActionAlphabet (automaton_io_internal.cpp).
template <class Alphabet>
LabelExpr label_expr(const Alphabet& alphabet, const typename Alphabet::Guard& g);

struct Spelling {
  const char* true_text;
  const char* false_text;
  const char* and_text;
  const char* or_text;
  // Parenthesize each disjunct of a top-level disjunction, as spin does: "(a && !b) || (c)".
  bool paren_top_disjuncts;
};

std::string spell(const LabelExpr& e, const std::vector<std::string>& names, const Spelling& sp,
                  bool top);

template <class Alphabet>
constexpr bool kOneAction = std::is_same_v<Alphabet, ActionAlphabet>;

template <class Alphabet>
std::string state_name(const Automaton<Alphabet>& a, std::uint32_t q) {
  return q < a.state_names.size() ? a.state_names[q] : std::string();
}

}  // namespace rearm::ltl::io_detail
