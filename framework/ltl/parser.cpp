// LTL parser (parser.h; docs/symbolic.md "Formulas"): a lexer plus an operator-precedence
// (shunting-yard) parser with explicit stacks, so no input can exhaust the call stack.
//
// Choices the header leaves open, fixed here:
//  - Identifier splitting (Spot's `GFa` convenience). An identifier that is not a keyword,
//    starts with a run of the letters F, G, X and continues with a lower-case ASCII letter
//    reads as if a space followed every letter of the run: `GFa` is `G F a`, `Fp1` is `F p1`,
//    `XXtrue` is `X X true`, `Fmove(l1)` is `F move(l1)`; an identifier made only of those
//    letters is all operators (`GF(a)` is `G F a`, `FG a` is `F G a`). When the run is
//    followed by a digit, an upper-case letter or '_', the identifier is one proposition:
//    `F1`, `GF2`, `FGA`, `F_a` are atomic propositions. formula.cpp's needs_quotes
//    quotes every proposition longer than one letter that starts with F, G or X, so the
//    printer never relies on either reading and to_string() reparses to an equal tree.
//  - `xor` / `^` is left-associative (as in Spot); `&` and `|` chains give one
//    n-ary node (`a & b & c` is And(a, b, c), `(a & b) & c` stays nested), which is what
//    Formula::to_string() prints.
//  - Nesting depth is the height of the syntax tree (`a` is 1, `!a` is 2) and, separately,
//    the nesting of parentheses; either above kMaxParseDepth is a ParseError at the operator
//    or parenthesis that goes too deep. Parentheses are not tree levels, so every accepted
//    tree prints (Formula::to_string nests parentheses less deeply than the tree) and
//    reparses.
//  - `1` and `0` are constants only as whole tokens; any other word starting with a digit is
//    an error. Action-predicate arguments are plain identifiers, keywords included
//    (`grasp(F)` is accepted, as formula.cpp's is_action_predicate accepts it).
//  - Character classes are ASCII and locale-independent; outside quotes, any other byte is
//    an error token, reported as \xNN.
//  - Spot's precedence table (ltlparse.yy: `%right OP_IMPLIES OP_EQUIV`, `%left OP_OR`,
//    `%left OP_XOR`, `%left OP_AND`, `%right OP_U OP_R OP_M OP_W`, unary above).
#include "ltl/parser.h"

#include <algorithm>
#include <cstdint>
#include <new>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/suggest.h"

namespace rearm::ltl {
namespace {

std::string error_message(std::size_t line, std::size_t column, const std::string& expected,
                          const std::string& found) {
  return "ltl parse error at line " + std::to_string(line) + ", column " + std::to_string(column) +
         ": expected " + expected + ", found " + found;
}

}  // namespace

ParseError::ParseError(std::size_t line, std::size_t column, std::string expected,
                       std::string found)
    : Error(error_message(line, column, expected, found)),
      line_(line),
      column_(column),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

namespace {

// Longest excerpt of the input quoted in an error message (a megabyte-long identifier must
// not make a megabyte-long message).
constexpr std::size_t kMaxFoundBytes = 32;
constexpr const char* kEndOfInput = "end of input";
constexpr const char* kExpectedFormula = "a formula";

// Binding strengths come from ltl::precedence (formula.h), shared with the printer:
// -> <-> right-assoc, | n-ary, xor left-assoc, & n-ary, U R V W M right-assoc, then unary.
const int kUnaryPrecedence = precedence(Op::Not);

enum class Assoc : std::uint8_t { Left, Right, NAry };

Assoc associativity(Op op) {
  switch (op) {
    case Op::And:
    case Op::Or:
      return Assoc::NAry;
    case Op::Xor:
      return Assoc::Left;
    default:
      return Assoc::Right;
  }
}

// ASCII classes, independent of the C locale (std::isalpha may accept bytes >= 0x80).
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_lower(char c) { return c >= 'a' && c <= 'z'; }
bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_start(char c) { return is_lower(c) || is_upper(c) || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }
bool is_split_letter(char c) { return c == 'F' || c == 'G' || c == 'X'; }

Op split_letter_op(char c) {
  switch (c) {
    case 'F':
      return Op::Eventually;
    case 'G':
      return Op::Always;
    default:
      return Op::Next;
  }
}

// `'text'` with non-printable bytes as \xNN, cut after kMaxFoundBytes bytes.
std::string quote(std::string_view bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  constexpr unsigned char kFirstPrintable = 0x20, kLastPrintable = 0x7e;
  std::string out = "'";
  const std::size_t n = std::min(bytes.size(), kMaxFoundBytes);
  for (std::size_t i = 0; i < n; ++i) {
    const auto b = static_cast<unsigned char>(bytes[i]);
    if (b >= kFirstPrintable && b <= kLastPrintable) {
      out += static_cast<char>(b);
    } else {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 0xf];
    }
  }
  if (bytes.size() > n) out += "...";
  out += '\'';
  return out;
}

enum class TokenKind : std::uint8_t { End, LParen, RParen, Unary, Binary, Constant, Atom, Invalid };

struct Token {
  TokenKind kind = TokenKind::End;
  Op op = Op::True;                // Unary, Binary, Constant
  std::size_t begin = 0, end = 0;  // byte offsets of the spelling in the input
  std::string name;  // Atom: the proposition (action predicates in canonical spelling)
};

struct Keyword {
  std::string_view word;
  TokenKind kind;
  Op op;
};

constexpr Keyword kKeywords[] = {
    {"true", TokenKind::Constant, Op::True}, {"false", TokenKind::Constant, Op::False},
    {"X", TokenKind::Unary, Op::Next},       {"F", TokenKind::Unary, Op::Eventually},
    {"G", TokenKind::Unary, Op::Always},     {"U", TokenKind::Binary, Op::Until},
    {"R", TokenKind::Binary, Op::Release},   {"V", TokenKind::Binary, Op::Release},
    {"W", TokenKind::Binary, Op::WeakUntil}, {"M", TokenKind::Binary, Op::StrongRelease},
    {"xor", TokenKind::Binary, Op::Xor},
};

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  Token next();

  // Throws the ParseError for byte offset `offset` (line and column computed here).
  [[noreturn]] void fail(std::size_t offset, std::string expected, std::string found) const {
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    throw ParseError(line, offset - line_start + 1, std::move(expected), std::move(found));
  }
  [[noreturn]] void fail(const Token& t, std::string expected) const {
    fail(t.begin, std::move(expected), describe(t));
  }

  std::string describe(const Token& t) const {
    if (t.kind == TokenKind::End) return kEndOfInput;
    return quote(text_.substr(t.begin, t.end - t.begin));
  }

 private:
  std::size_t skip_space(std::size_t p) const {
    while (p < text_.size() && is_space(text_[p])) ++p;
    return p;
  }
  std::size_t word_end(std::size_t p) const {
    while (p < text_.size() && is_ident_char(text_[p])) ++p;
    return p;
  }
  bool at(std::size_t p, char c) const { return p < text_.size() && text_[p] == c; }
  // What stands at `p`, for messages: end of input, a whole word, or one byte.
  std::string describe_at(std::size_t p) const {
    if (p >= text_.size()) return kEndOfInput;
    const std::size_t e = is_ident_char(text_[p]) ? word_end(p) : p + 1;
    return quote(text_.substr(p, e - p));
  }
  Token make(TokenKind kind, Op op, std::size_t length) {
    Token t;
    t.kind = kind;
    t.op = op;
    t.begin = pos_;
    t.end = pos_ + length;
    pos_ = t.end;
    return t;
  }
  // Multi-byte operator spelled `spelling` starting at pos_: all of it or an error.
  Token spelled(std::string_view spelling, TokenKind kind, Op op) {
    std::size_t i = 0;
    while (i < spelling.size() && at(pos_ + i, spelling[i])) ++i;
    if (i < spelling.size()) {
      fail(pos_, quote(spelling), quote(text_.substr(pos_, std::max<std::size_t>(i, 1))));
    }
    return make(kind, op, spelling.size());
  }
  Token quoted();
  Token word();
  Token action_predicate(std::string_view verb, std::size_t open_paren);
  std::string argument(std::size_t& p, const char* what) const;

  std::string_view text_;
  std::size_t pos_ = 0;
  // End of a run of F/G/X letters being split into operators (see the file comment).
  std::size_t split_run_end_ = 0;
};

Token Lexer::next() {
  if (pos_ < split_run_end_) return make(TokenKind::Unary, split_letter_op(text_[pos_]), 1);
  pos_ = skip_space(pos_);
  if (pos_ >= text_.size()) return make(TokenKind::End, Op::True, 0);
  const char c = text_[pos_];
  const auto followed_by = [&](char d) { return at(pos_ + 1, d); };
  switch (c) {
    case '(':
      return make(TokenKind::LParen, Op::True, 1);
    case ')':
      return make(TokenKind::RParen, Op::True, 1);
    case '!':
    case '~':
      return make(TokenKind::Unary, Op::Not, 1);
    case '&':
      return make(TokenKind::Binary, Op::And, followed_by('&') ? 2 : 1);
    case '|':
      return make(TokenKind::Binary, Op::Or, followed_by('|') ? 2 : 1);
    case '^':
      return make(TokenKind::Binary, Op::Xor, 1);
    case '-':
      return spelled("->", TokenKind::Binary, Op::Implies);
    case '=':
      return spelled("=>", TokenKind::Binary, Op::Implies);
    case '/':
      return spelled("/\\", TokenKind::Binary, Op::And);
    case '\\':
      return spelled("\\/", TokenKind::Binary, Op::Or);
    case '[':
      return spelled("[]", TokenKind::Unary, Op::Always);
    case '<':
      if (followed_by('>')) return make(TokenKind::Unary, Op::Eventually, 2);
      if (followed_by('-')) return spelled("<->", TokenKind::Binary, Op::Equiv);
      if (followed_by('=')) return spelled("<=>", TokenKind::Binary, Op::Equiv);
      fail(pos_, "'<>', '<->' or '<=>'", quote(text_.substr(pos_, 1)));
    case '"':
      return quoted();
    default:
      break;
  }
  if (is_ident_char(c)) return word();
  return make(TokenKind::Invalid, Op::True, 1);
}

// '"' any bytes but '"' '"': the proposition named by the bytes between the quotes.
Token Lexer::quoted() {
  const std::size_t close = text_.find('"', pos_ + 1);
  if (close == std::string_view::npos) fail(text_.size(), "a closing '\"'", kEndOfInput);
  if (close == pos_ + 1) fail(pos_, "a non-empty proposition name", quote(text_.substr(pos_, 2)));
  Token t = make(TokenKind::Atom, Op::True, close + 1 - pos_);
  t.name = std::string(text_.substr(t.begin + 1, close - t.begin - 1));
  return t;
}

Token Lexer::word() {
  const std::size_t end = word_end(pos_);
  const std::string_view w = text_.substr(pos_, end - pos_);
  if (is_digit(w[0])) {
    if (w == "1") return make(TokenKind::Constant, Op::True, 1);
    if (w == "0") return make(TokenKind::Constant, Op::False, 1);
    return make(TokenKind::Invalid, Op::True, w.size());
  }
  for (const Keyword& k : kKeywords) {
    if (w == k.word) return make(k.kind, k.op, w.size());
  }
  if (is_split_letter(w[0])) {
    const std::size_t run = std::find_if_not(w.begin(), w.end(), is_split_letter) - w.begin();
    if (run == w.size() || is_lower(w[run])) {
      split_run_end_ = pos_ + run;
      return make(TokenKind::Unary, split_letter_op(w[0]), 1);
    }
  }
  const std::size_t open = skip_space(end);
  if (w == "move" || w == "grasp" || w == "release") {
    if (at(open, '(')) return action_predicate(w, open);
  } else if (at(open, '(')) {
    // A word applied to arguments is meant as a predicate: name it (a proposition followed by
    // '(' is an error anyway).
    fail(pos_, "move(region), grasp(object) or release(object,region)",
         "the unknown predicate " + quote(w) + did_you_mean(w, {"move", "grasp", "release"}));
  }
  Token t = make(TokenKind::Atom, Op::True, w.size());
  t.name = std::string(w);
  return t;
}

// An identifier argument of an action predicate at `p` (after blanks); advances `p`.
std::string Lexer::argument(std::size_t& p, const char* what) const {
  p = skip_space(p);
  if (p >= text_.size() || !is_ident_start(text_[p])) fail(p, what, describe_at(p));
  const std::size_t e = word_end(p);
  std::string name(text_.substr(p, e - p));
  p = skip_space(e);
  return name;
}

// move(x), grasp(x), release(x,y) with optional blanks, named canonically without them
// (formula.h): `release ( M1 , l2 )` is the proposition "release(M1,l2)".
Token Lexer::action_predicate(std::string_view verb, std::size_t open_paren) {
  constexpr const char* kRegion = "a region name";
  constexpr const char* kObject = "an object name";
  std::size_t p = open_paren + 1;
  std::string name(verb);
  name += '(';
  name += argument(p, verb == "move" ? kRegion : kObject);
  if (verb == "release") {
    if (!at(p, ',')) fail(p, "',' and a region name", describe_at(p));
    ++p;
    name += ',';
    name += argument(p, kRegion);
  }
  if (!at(p, ')')) fail(p, "')'", describe_at(p));
  name += ')';
  Token t = make(TokenKind::Atom, Op::True, p + 1 - pos_);
  t.name = std::move(name);
  return t;
}

// Shunting-yard over the lexer's tokens. Every pending operator (unary, or binary still
// waiting for its right operand) encloses the operators pushed after it, so the finished
// tree is at least (pending operators + 1) high: bounding pending operators and open
// parentheses by kMaxParseDepth bounds the stacks before the exact height check at each
// reduction.
class Parser {
 public:
  explicit Parser(std::string_view text) : lexer_(text) {}

  Formula run() {
    bool want_operand = true;
    for (;;) {
      Token t = lexer_.next();
      if (want_operand) {
        switch (t.kind) {
          case TokenKind::Unary:
            push(Entry{EntryKind::Unary, t.op, kUnaryPrecedence, 1, t});
            continue;
          case TokenKind::LParen:
            push(Entry{EntryKind::Paren, Op::True, 0, 0, t});
            continue;
          case TokenKind::Constant:
            operands_.push_back({t.op == Op::True ? Formula::tt() : Formula::ff(), 1});
            want_operand = false;
            continue;
          case TokenKind::Atom:
            operands_.push_back({intern(std::move(t.name)), 1});
            want_operand = false;
            continue;
          default:
            lexer_.fail(t, kExpectedFormula);
        }
      }
      switch (t.kind) {
        case TokenKind::Binary:
          binary(t);
          want_operand = true;
          continue;
        case TokenKind::RParen:
          if (open_parens_ == 0) lexer_.fail(t, expected_after_operand());
          close_paren();
          continue;
        case TokenKind::End:
          if (open_parens_ > 0) lexer_.fail(t, expected_after_operand());
          while (!pending_.empty()) reduce();
          return operands_.back().formula;
        default:
          lexer_.fail(t, expected_after_operand());
      }
    }
  }

 private:
  enum class EntryKind : std::uint8_t { Paren, Unary, Binary };
  struct Entry {
    EntryKind kind;
    Op op;
    int precedence;
    std::size_t arity;  // operands taken by the reduction (n-ary chains grow it)
    Token token;        // for messages
  };
  struct Operand {
    Formula formula;
    std::size_t depth;  // tree height
  };

  std::string expected_after_operand() const {
    return open_parens_ > 0 ? "a binary operator or ')'" : "a binary operator or end of input";
  }
  [[noreturn]] void too_deep(const Token& t) const {
    lexer_.fail(t, "nesting depth at most " + std::to_string(kMaxParseDepth));
  }

  void push(Entry e) {
    if (e.kind == EntryKind::Paren) {
      if (open_parens_ + 1 > kMaxParseDepth) too_deep(e.token);
      ++open_parens_;
    } else {
      if (pending_operators_ + 2 > kMaxParseDepth) too_deep(e.token);
      ++pending_operators_;
    }
    pending_.push_back(std::move(e));
  }

  // A binary operator: reduce what binds tighter (or equally, for left-associative xor),
  // extend an n-ary chain of the same operator, else wait for the right operand.
  void binary(const Token& t) {
    const int p = precedence(t.op);
    const Assoc assoc = associativity(t.op);
    while (!pending_.empty() && pending_.back().kind != EntryKind::Paren) {
      Entry& top = pending_.back();
      if (top.precedence < p) break;
      if (top.precedence == p && assoc == Assoc::NAry) {
        ++top.arity;  // same level, so the same operator
        return;
      }
      if (top.precedence == p && assoc == Assoc::Right) break;
      reduce();
    }
    push(Entry{EntryKind::Binary, t.op, p, 2, t});
  }

  void close_paren() {
    while (pending_.back().kind != EntryKind::Paren) reduce();
    pending_.pop_back();
    --open_parens_;
  }

  void reduce() {
    const Entry e = std::move(pending_.back());
    pending_.pop_back();
    --pending_operators_;
    const auto first = operands_.end() - static_cast<std::ptrdiff_t>(e.arity);
    std::vector<Formula> children;
    children.reserve(e.arity);
    std::size_t depth = 0;
    for (auto it = first; it != operands_.end(); ++it) {
      depth = std::max(depth, it->depth);
      children.push_back(std::move(it->formula));
    }
    operands_.erase(first, operands_.end());
    if (++depth > kMaxParseDepth) too_deep(e.token);
    operands_.push_back({Formula::make(e.op, std::move(children)), depth});
  }

  // One shared leaf per proposition name (equal trees whatever the sharing, less memory).
  Formula intern(std::string name) {
    auto it = atoms_.find(name);
    if (it == atoms_.end()) it = atoms_.emplace(name, Formula::ap(name)).first;
    return it->second;
  }

  Lexer lexer_;
  std::vector<Entry> pending_;
  std::vector<Operand> operands_;
  std::size_t open_parens_ = 0;
  std::size_t pending_operators_ = 0;  // entries of pending_ that are not parentheses
  std::unordered_map<std::string, Formula> atoms_;
};

}  // namespace

Formula parse(std::string_view text) {
  try {
    return Parser(text).run();
  } catch (const std::bad_alloc&) {
    // parser.h: no exception but ParseError for any byte string, however large.
    throw ParseError(1, 1, "an input that fits in memory",
                     "an input of " + std::to_string(text.size()) + " bytes");
  }
}

}  // namespace rearm::ltl
