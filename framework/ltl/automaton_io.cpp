// Automaton readers and writers: HOA v1, spin never claims, Graphviz DOT.
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
// Readers (the quirks of `spin -f` are listed in docs/symbolic.md):
//  - read_hoa keeps the HOA state numbers when acceptance is on states (or is t / f). With
//    marks on transitions it builds states (q, b), b = "the transition that entered q was in
//    the Inf set", accepting iff b, and keeps only those reachable from the initial states.
//  - read_never_claim keeps the textual state order. `goto` is a jump, not a step (spin
//    removes jumps when it compiles a claim), so a state whose only statement is `goto s` is
//    another name of s. `skip` is a step on any symbol to the textually next state; after the
//    last state the claim ends, which spin reports as an accepting run, so a final `skip`
//    state accepts every continuation (accepting, true self-loop). `atomic { (g) ->
//    assert(!(g)) }` fails the assertion, which spin also reports as an accepting run: an
//    edge g to that accept-everything state (a fresh one when the claim has none).
#include "ltl/automaton_io.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"

namespace rearm::ltl {
namespace {

using Ref = BddManager::Ref;

// Nesting depth of label and guard expressions beyond which input is rejected with an error
// (the parsers are recursive; this bounds their stack use on hostile input).
constexpr int kMaxNesting = 500;
// Largest number of HOA states accepted (the reader allocates per state index before it has
// seen the states' bodies): above the translator's per-stage budget (TranslateOptions::
// max_states), so every automaton rearm writes reads back, and small enough that a file naming
// a huge state index (Start: 4849003 without States:, found by fuzzing) is rejected at once
// instead of building and writing millions of empty states (over 6 s in the fuzz build).
constexpr std::uint32_t kMaxHoaStates = 1u << 18;
// HOA INT: "a non-negative integer less than 2^31".
constexpr std::uint64_t kMaxHoaInt = (1ull << 31) - 1;

const char* const kHoaReader = "read_hoa";
const char* const kNeverReader = "read_never_claim";
const char* const kOneActionNote =
    "one-action alphabet: guards are exact only on symbols with at most one true proposition";

[[noreturn]] void fail(const char* reader, int line, const std::string& reason) {
  throw Error(std::string(reader) + ": line " + std::to_string(line) + ": " + reason);
}

std::string describe_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (std::isprint(u)) return std::string("'") + c + "'";
  static const char* const kHex = "0123456789abcdef";
  return std::string("byte 0x") + kHex[u >> 4] + kHex[u & 15];
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }

// Text that may go inside a /* */ comment of HOA, Promela or DOT.
std::string comment_safe(std::string s) {
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if ((s[i] == '*' && s[i + 1] == '/') || (s[i] == '/' && s[i + 1] == '*')) s[i] = ' ';
  }
  return s;
}

// A double-quoted string for HOA and DOT (both escape '"' and '\').
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

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

bool is_hoa_ident_char(char c) { return is_ident_char(c) || c == '-'; }

std::vector<HoaToken> lex_hoa(std::string_view s, const char* who) {
  std::vector<HoaToken> toks;
  std::size_t i = 0;
  int line = 1;
  const std::size_t n = s.size();
  for (;;) {
    // Whitespace and (nested) comments.
    for (;;) {
      if (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\n')) {
        if (s[i] == '\n') ++line;
        ++i;
      } else if (i + 1 < n && s[i] == '/' && s[i + 1] == '*') {
        const int start_line = line;
        int depth = 0;
        while (true) {
          if (i + 1 >= n) fail(who, start_line, "unterminated comment");
          if (s[i] == '/' && s[i + 1] == '*') {
            ++depth;
            i += 2;
          } else if (s[i] == '*' && s[i + 1] == '/') {
            i += 2;
            if (--depth == 0) break;
          } else {
            if (s[i] == '\n') ++line;
            ++i;
          }
        }
      } else {
        break;
      }
    }
    HoaToken t;
    t.line = line;
    if (i >= n) {
      toks.push_back(t);
      return toks;
    }
    const char c = s[i];
    if (c == '"') {
      t.kind = HoaTok::kString;
      ++i;
      for (;;) {
        if (i >= n) fail(who, t.line, "unterminated string");
        if (s[i] == '"') break;
        if (s[i] == '\\') {
          if (++i >= n) fail(who, t.line, "unterminated string");
        }
        if (s[i] == '\n') ++line;
        t.text += s[i++];
      }
      ++i;
    } else if (is_digit(c)) {
      t.kind = HoaTok::kInt;
      std::uint64_t v = 0;
      while (i < n && is_digit(s[i])) {
        v = v * 10 + static_cast<std::uint64_t>(s[i] - '0');
        if (v > kMaxHoaInt) fail(who, line, "integer too large (HOA integers are < 2^31)");
        t.text += s[i++];
      }
      t.value = static_cast<std::uint32_t>(v);
    } else if (is_ident_start(c)) {
      while (i < n && is_hoa_ident_char(s[i])) t.text += s[i++];
      if (i < n && s[i] == ':') {
        t.kind = HoaTok::kHeader;
        ++i;
      } else {
        t.kind = HoaTok::kIdent;
      }
    } else if (c == '@') {
      t.kind = HoaTok::kAlias;
      ++i;
      while (i < n && is_hoa_ident_char(s[i])) t.text += s[i++];
      if (t.text.empty()) fail(who, line, "'@' must be followed by an alias name");
    } else if (c == '-') {
      static const std::pair<const char*, HoaTok> kMarkers[] = {{"--BODY--", HoaTok::kBody},
                                                                {"--END--", HoaTok::kEndMarker},
                                                                {"--ABORT--", HoaTok::kAbort}};
      bool found = false;
      for (const auto& [text, kind] : kMarkers) {
        if (s.substr(i).starts_with(text)) {
          t.kind = kind;
          t.text = text;
          i += std::string_view(text).size();
          found = true;
          break;
        }
      }
      if (!found) fail(who, line, "unexpected '-' (expected --BODY--, --END-- or --ABORT--)");
    } else if (std::string_view("[]{}()!&|").find(c) != std::string_view::npos) {
      t.kind = HoaTok::kPunct;
      t.text = std::string(1, c);
      ++i;
    } else {
      fail(who, line, "unexpected character " + describe_char(c));
    }
    toks.push_back(std::move(t));
  }
}

std::string describe(const HoaToken& t) {
  switch (t.kind) {
    case HoaTok::kEnd:
      return "end of text";
    case HoaTok::kInt:
      return "integer " + t.text;
    case HoaTok::kString:
      return "string " + quoted(t.text);
    case HoaTok::kIdent:
      return "'" + t.text + "'";
    case HoaTok::kHeader:
      return "header '" + t.text + ":'";
    case HoaTok::kAlias:
      return "alias '@" + t.text + "'";
    case HoaTok::kPunct:
      return "'" + t.text + "'";
    default:
      return t.text;
  }
}

bool is_punct(const HoaToken& t, char c) {
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

class ExprBuilder {
 public:
  using Value = LabelExpr;
  explicit ExprBuilder(std::size_t num_aps) : num_aps_(num_aps) {}
  Value constant(bool value) const {
    return LabelExpr{value ? LabelExpr::Kind::kTrue : LabelExpr::Kind::kFalse, 0, {}};
  }
  Value ap(std::uint32_t i, int line) const {
    if (i >= num_aps_) fail("label", line, "proposition index out of range");
    return LabelExpr{LabelExpr::Kind::kAp, i, {}};
  }
  Value alias(const std::string& name, int line) const {
    fail("label", line, "unexpected alias @" + name);
  }
  Value neg(Value a) const { return LabelExpr{LabelExpr::Kind::kNot, 0, {std::move(a)}}; }
  Value conj(Value a, Value b) const {
    return join(LabelExpr::Kind::kAnd, std::move(a), std::move(b));
  }
  Value disj(Value a, Value b) const {
    return join(LabelExpr::Kind::kOr, std::move(a), std::move(b));
  }

 private:
  static Value join(LabelExpr::Kind kind, Value a, Value b) {
    LabelExpr out{kind, 0, {}};
    for (Value* v : {&a, &b}) {
      if (v->kind == kind) {
        for (LabelExpr& k : v->kids) out.kids.push_back(std::move(k));
      } else {
        out.kids.push_back(std::move(*v));
      }
    }
    return out;
  }
  std::size_t num_aps_;
};

template <class Alphabet>
LabelExpr label_expr(const Alphabet& alphabet, const typename Alphabet::Guard& g) {
  const std::string text = alphabet.label(g);
  try {
    const std::vector<HoaToken> toks = lex_hoa(text, "label");
    std::size_t pos = 0;
    ExprBuilder builder(alphabet.aps().size());
    LabelExpr e = LabelParser<ExprBuilder>(toks, pos, builder, "label").parse();
    REARM_DEMAND(toks[pos].kind == HoaTok::kEnd, "trailing text in alphabet label: " + text);
    return e;
  } catch (const Error& e) {
    REARM_DEMAND(
        false, "alphabet label is not a HOA label expression: \"" + text + "\" (" + e.what() + ")");
  }
  return {};
}

struct Spelling {
  const char* true_text;
  const char* false_text;
  const char* and_text;
  const char* or_text;
  // Parenthesize each disjunct of a top-level disjunction, as spin does: "(a && !b) || (c)".
  bool paren_top_disjuncts;
};

constexpr Spelling kSpinSpelling{"1", "0", " && ", " || ", true};
constexpr Spelling kDotSpelling{"true", "false", " & ", " | ", false};

std::string spell(const LabelExpr& e, const std::vector<std::string>& names, const Spelling& sp,
                  bool top) {
  using Kind = LabelExpr::Kind;
  switch (e.kind) {
    case Kind::kTrue:
      return sp.true_text;
    case Kind::kFalse:
      return sp.false_text;
    case Kind::kAp:
      return names[e.ap];
    case Kind::kNot: {
      const LabelExpr& k = e.kids[0];
      const bool atom = k.kind == Kind::kAp || k.kind == Kind::kTrue || k.kind == Kind::kFalse;
      const std::string inner = spell(k, names, sp, false);
      return atom ? "!" + inner : "!(" + inner + ")";
    }
    case Kind::kAnd: {
      std::string out;
      for (std::size_t i = 0; i < e.kids.size(); ++i) {
        if (i > 0) out += sp.and_text;
        const std::string inner = spell(e.kids[i], names, sp, false);
        out += e.kids[i].kind == Kind::kOr ? "(" + inner + ")" : inner;
      }
      return out;
    }
    case Kind::kOr: {
      std::string out;
      for (std::size_t i = 0; i < e.kids.size(); ++i) {
        if (i > 0) out += sp.or_text;
        const std::string inner = spell(e.kids[i], names, sp, false);
        out += top && sp.paren_top_disjuncts ? "(" + inner + ")" : inner;
      }
      return out;
    }
  }
  return {};
}

template <class Alphabet>
constexpr bool kOneAction = std::is_same_v<Alphabet, ActionAlphabet>;

template <class Alphabet>
std::string state_name(const Automaton<Alphabet>& a, std::uint32_t q) {
  return q < a.state_names.size() ? a.state_names[q] : std::string();
}

template <class Alphabet>
std::string write_hoa(const Automaton<Alphabet>& a, const std::string& name) {
  std::string out = "HOA: v1\n";
  if (!name.empty()) out += "name: " + quoted(name) + "\n";
  out += "States: " + std::to_string(a.num_states()) + "\n";
  for (const std::uint32_t q : a.initial) out += "Start: " + std::to_string(q) + "\n";
  const auto& aps = a.alphabet.aps();
  out += "AP: " + std::to_string(aps.size());
  for (const std::string& p : aps) out += " " + quoted(p);
  out += "\nacc-name: Buchi\nAcceptance: 1 Inf(0)\n";
  out += "properties: trans-labels explicit-labels state-acc\n";
  if constexpr (kOneAction<Alphabet>) {
    out += std::string("rearm-alphabet: \"one-action\" /* ") + kOneActionNote + " */\n";
  }
  out += "--BODY--\n";
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    out += "State: " + std::to_string(q);
    const std::string sname = state_name(a, q);
    if (!sname.empty()) out += " " + quoted(sname);
    if (a.accepting[q]) out += " {0}";
    out += "\n";
    for (const auto& e : a.out[q]) {
      // Appended piecewise: "[" + std::string temporaries trip GCC 12's -Wrestrict.
      out += '[';
      out += a.alphabet.label(e.guard);
      out += "] ";
      out += std::to_string(e.dst);
      out += '\n';
    }
  }
  out += "--END--\n";
  return out;
}

// Promela keywords and predefined names: never valid as proposition identifiers.
bool is_promela_reserved(const std::string& s) {
  static const std::set<std::string> kReserved = {
      "active",   "assert",   "atomic",  "bit",     "bool",     "break",      "byte",     "c_code",
      "c_decl",   "c_expr",   "c_state", "c_track", "chan",     "d_proctype", "d_step",   "do",
      "else",     "empty",    "enabled", "eval",    "false",    "fi",         "for",      "full",
      "goto",     "hidden",   "if",      "in",      "init",     "inline",     "int",      "len",
      "local",    "mtype",    "nempty",  "never",   "nfull",    "np_",        "od",       "of",
      "pc_value", "pid",      "printf",  "printm",  "priority", "proctype",   "provided", "run",
      "select",   "short",    "show",    "skip",    "timeout",  "trace",      "true",     "typedef",
      "unless",   "unsigned", "xr",      "xs",      "notrace",  "_",          "_last",    "_nr_pr",
      "_pid",     "_priority"};
  return kReserved.count(s) > 0;
}

bool is_spin_identifier(const std::string& s) {
  if (s.empty() || !is_ident_start(s[0])) return false;
  for (const char c : s) {
    if (!is_ident_char(c)) return false;
  }
  return !is_promela_reserved(s);
}

// Spin identifiers for the propositions: valid names are kept; others (e.g. the action
// predicate move(l1)) become a readable identifier (move_l1), unique among all names.
std::vector<std::string> spin_names(const std::vector<std::string>& aps) {
  std::vector<std::string> out(aps.size());
  std::set<std::string> used;
  for (std::size_t i = 0; i < aps.size(); ++i) {
    if (is_spin_identifier(aps[i])) {
      out[i] = aps[i];
      used.insert(aps[i]);
    }
  }
  for (std::size_t i = 0; i < aps.size(); ++i) {
    if (!out[i].empty()) continue;
    std::string base;
    for (const char c : aps[i]) {
      if (is_ident_char(c)) {
        base += c;
      } else if (!base.empty() && base.back() != '_') {
        base += '_';
      }
    }
    while (!base.empty() && base.back() == '_') base.pop_back();
    if (base.empty() || is_digit(base[0])) base = "p_" + base;
    if (is_promela_reserved(base)) base += "_";
    std::string name = base;
    for (int k = 2; used.count(name) > 0; ++k) name = base + "_" + std::to_string(k);
    used.insert(name);
    out[i] = name;
  }
  return out;
}

template <class Alphabet>
std::string write_never_claim(const Automaton<Alphabet>& a) {
  using Edge = typename Automaton<Alphabet>::Edge;
  const std::vector<std::string>& aps = a.alphabet.aps();
  const std::vector<std::string> names = spin_names(aps);
  std::string out;
  for (std::size_t i = 0; i < aps.size(); ++i) {
    if (names[i] != aps[i]) {
      out += "/* proposition " + names[i] + " stands for " + comment_safe(aps[i]) + " */\n";
    }
  }
  if constexpr (kOneAction<Alphabet>) out += std::string("/* ") + kOneActionNote + " */\n";
  out += "never {\n";
  if (a.initial.empty()) return out + "T0_init:\n\tfalse;\n}\n";

  // Spin starts a claim at its first statement, so the initial state is written first. With
  // several initial states a fresh one, visited once, takes the union of their edges.
  // States are numbered by their place in the text (the fresh state, or the initial one, is
  // place 0), the order read_never_claim keeps: the claim read back writes the same labels.
  const bool fresh_init = a.initial.size() > 1;
  const std::uint32_t init = a.initial.front();
  auto place = [&](std::uint32_t q) -> std::uint32_t {
    if (fresh_init) return q + 1;
    if (q == init) return 0;
    return q < init ? q + 1 : q;
  };
  auto label = [&](std::uint32_t q) {
    const char* prefix = a.accepting[q] ? "accept_" : "T0_";
    if (!fresh_init && q == init) return std::string(prefix) + "init";
    return std::string(prefix) + "S" + std::to_string(place(q));
  };
  auto write_state = [&](const std::string& lbl, const std::string& comment,
                         const std::vector<Edge>& edges) {
    out += lbl + ":";
    if (!comment.empty()) out += "\t/* " + comment_safe(comment) + " */";
    out += "\n";
    if (edges.empty()) {
      out += "\tfalse;\n";
      return;
    }
    out += "\tif\n";
    for (const Edge& e : edges) {
      out += "\t:: (" + spell(label_expr(a.alphabet, e.guard), names, kSpinSpelling, true) +
             ") -> goto " + label(e.dst) + "\n";
    }
    out += "\tfi;\n";
  };
  if (fresh_init) {
    std::vector<Edge> edges;
    for (const std::uint32_t q : a.initial) {
      for (const Edge& e : a.out[q]) {
        auto it =
            std::find_if(edges.begin(), edges.end(), [&](const Edge& f) { return f.dst == e.dst; });
        if (it == edges.end()) {
          edges.push_back(e);
        } else {
          it->guard = a.alphabet.disj(it->guard, e.guard);
        }
      }
    }
    write_state("T0_init", "initial states", edges);
  } else {
    write_state(label(init), state_name(a, init), a.out[init]);
  }
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    if (fresh_init || q != init) write_state(label(q), state_name(a, q), a.out[q]);
  }
  return out + "}\n";
}

template <class Alphabet>
std::string write_dot(const Automaton<Alphabet>& a) {
  std::string out = "digraph nba {\n";
  if constexpr (kOneAction<Alphabet>) out += std::string("  /* ") + kOneActionNote + " */\n";
  out += "  rankdir=LR;\n  node [shape=circle];\n";
  out += "  start [label=\"\", shape=point, style=invis, width=0];\n";
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    const std::string sname = state_name(a, q);
    out +=
        "  " + std::to_string(q) + " [label=" + quoted(sname.empty() ? std::to_string(q) : sname);
    if (a.accepting[q]) out += ", shape=doublecircle";
    out += "];\n";
  }
  for (const std::uint32_t q : a.initial) out += "  start -> " + std::to_string(q) + ";\n";
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    for (const auto& e : a.out[q]) {
      out += "  " + std::to_string(q) + " -> " + std::to_string(e.dst) + " [label=" +
             quoted(spell(label_expr(a.alphabet, e.guard), a.alphabet.aps(), kDotSpelling, true)) +
             "];\n";
    }
  }
  return out + "}\n";
}

// ----------------------------------------------------------------------------------------
// HOA reader.

class GuardBuilder {
 public:
  using Value = Ref;
  GuardBuilder(GeneralAlphabet& alphabet, const std::vector<std::uint32_t>& ap_map,
               const std::map<std::string, Ref>& aliases)
      : alphabet_(alphabet), ap_map_(ap_map), aliases_(aliases) {}
  Value constant(bool value) const { return value ? alphabet_.top() : alphabet_.bottom(); }
  Value ap(std::uint32_t i, int line) const {
    if (i >= ap_map_.size()) {
      fail(kHoaReader, line,
           "proposition " + std::to_string(i) + " out of range (AP: declares " +
               std::to_string(ap_map_.size()) + ")");
    }
    return alphabet_.ap(ap_map_[i], true);
  }
  Value alias(const std::string& name, int line) const {
    const auto it = aliases_.find(name);
    if (it == aliases_.end()) fail(kHoaReader, line, "undefined alias @" + name);
    return it->second;
  }
  Value neg(Value a) const { return alphabet_.bdd().neg(a); }
  Value conj(Value a, Value b) const { return alphabet_.conj(a, b); }
  Value disj(Value a, Value b) const { return alphabet_.disj(a, b); }

 private:
  GeneralAlphabet& alphabet_;
  const std::vector<std::uint32_t>& ap_map_;
  const std::map<std::string, Ref>& aliases_;
};

// Acceptance conditions (HOA v1 "Acceptance:"), reduced to what a Büchi automaton can carry.
struct AccNode {
  enum class Kind { kTrue, kFalse, kInf, kFin, kAnd, kOr };
  Kind kind = Kind::kTrue;
  std::uint32_t set = 0;
  bool complemented = false;
  std::vector<AccNode> kids;
};

class HoaReader {
 public:
  HoaReader(std::string_view text, GeneralAlphabet alphabet) : toks_(lex_hoa(text, kHoaReader)) {
    result_.alphabet = std::move(alphabet);
  }

  GeneralNba read() {
    read_header();
    read_body();
    build();
    return std::move(result_);
  }

 private:
  enum class AccMode { kAll, kNone, kInf };
  struct Item {
    std::string name;
    std::size_t begin = 0, end = 0;  // value tokens [begin, end)
    int line = 0;
  };
  struct RawEdge {
    Ref guard;
    std::uint32_t dst;
    bool mark;  // in the Inf set
  };
  struct RawState {
    bool declared = false;
    std::string name;
    bool mark = false;
    bool has_label = false;
    Ref label = BddManager::kTrue;
    std::vector<RawEdge> edges;
  };

  const HoaToken& peek() const { return toks_[pos_]; }
  const HoaToken& next() { return toks_[pos_++]; }

  void read_header() {
    const HoaToken& first = next();
    if (first.kind != HoaTok::kHeader || first.text != "HOA") {
      fail(kHoaReader, first.line, "expected 'HOA:' at the start, found " + describe(first));
    }
    const HoaToken& version = next();
    if (version.kind != HoaTok::kIdent || version.text != "v1") {
      fail(kHoaReader, version.line,
           "unsupported HOA version " + describe(version) + " (only v1 is read)");
    }
    std::vector<Item> items;
    while (peek().kind == HoaTok::kHeader) {
      Item item{next().text, pos_, pos_, toks_[pos_ - 1].line};
      while (peek().kind != HoaTok::kHeader && peek().kind != HoaTok::kBody &&
             peek().kind != HoaTok::kEnd && peek().kind != HoaTok::kEndMarker &&
             peek().kind != HoaTok::kAbort) {
        ++pos_;
      }
      item.end = pos_;
      items.push_back(std::move(item));
    }
    check_not_aborted();
    if (peek().kind != HoaTok::kBody) {
      fail(kHoaReader, peek().line,
           "expected a header item or --BODY--, found " + describe(peek()));
    }
    const int body_line = peek().line;
    const std::size_t body_pos = ++pos_;

    std::map<std::string, int> seen;
    for (const Item& item : items) {
      if ((item.name == "States" || item.name == "AP" || item.name == "Acceptance") &&
          seen[item.name]++ > 0) {
        fail(kHoaReader, item.line, "duplicate '" + item.name + ":' header");
      }
    }
    // AP first, then aliases in order (they refer to propositions and earlier aliases),
    // whatever the order of the items in the text.
    for (const Item& item : items) {
      if (item.name == "AP") read_ap(item);
    }
    for (const Item& item : items) {
      if (item.name == "Alias") read_alias(item);
      if (item.name == "States") {
        pos_ = item.begin;
        num_states_ = read_int(item, "the number of states");
        if (num_states_ > kMaxHoaStates) {
          fail(kHoaReader, item.line,
               "too many states (at most " + std::to_string(kMaxHoaStates) + ")");
        }
        has_num_states_ = true;
        expect_item_end(item);
      }
      if (item.name == "Acceptance") read_acceptance(item);
    }
    if (seen["Acceptance"] == 0) fail(kHoaReader, body_line, "missing 'Acceptance:' header");
    for (const Item& item : items) {
      if (item.name != "Start") continue;
      pos_ = item.begin;
      const std::uint32_t q = read_state_index(item.line, "Start:");
      if (pos_ < item.end && is_punct(peek(), '&')) {
        fail(kHoaReader, peek().line,
             "a conjunction of initial states (alternating automaton) is not supported");
      }
      expect_item_end(item);
      if (std::find(start_.begin(), start_.end(), q) == start_.end()) start_.push_back(q);
    }
    // acc-name, tool, name, properties and unknown headers carry no semantics we need (the
    // Acceptance: line defines acceptance, HOA v1 "Acceptance Specifications").
    pos_ = body_pos;
  }

  void check_not_aborted() const {
    if (peek().kind == HoaTok::kAbort) {
      fail(kHoaReader, peek().line, "automaton aborted by --ABORT--");
    }
  }

  std::uint32_t read_int(const Item& item, const char* what) {
    if (pos_ >= item.end || peek().kind != HoaTok::kInt) {
      fail(kHoaReader, pos_ < item.end ? peek().line : item.line,
           std::string("expected ") + what + " after '" + item.name + ":'");
    }
    return next().value;
  }

  void expect_item_end(const Item& item) {
    if (pos_ < item.end) {
      fail(kHoaReader, peek().line,
           "unexpected " + describe(peek()) + " in '" + item.name + ":' header");
    }
  }

  std::uint32_t read_state_index(int line, const char* where) {
    if (peek().kind != HoaTok::kInt) {
      fail(kHoaReader, peek().kind == HoaTok::kEnd ? line : peek().line,
           std::string("expected a state number in ") + where + ", found " + describe(peek()));
    }
    const HoaToken& t = next();
    check_state_index(t.value, t.line);
    return t.value;
  }

  void check_state_index(std::uint32_t q, int line) const {
    if (has_num_states_ && q >= num_states_) {
      fail(kHoaReader, line,
           "state " + std::to_string(q) + " out of range (States: " + std::to_string(num_states_) +
               ")");
    }
    if (q >= kMaxHoaStates) fail(kHoaReader, line, "state number too large");
  }

  void read_ap(const Item& item) {
    pos_ = item.begin;
    const std::uint32_t n = read_int(item, "the number of propositions");
    std::vector<std::string> names;
    while (pos_ < item.end && peek().kind == HoaTok::kString) names.push_back(next().text);
    expect_item_end(item);
    if (names.size() != n) {
      fail(kHoaReader, item.line,
           "AP: declares " + std::to_string(n) + " propositions but names " +
               std::to_string(names.size()));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (names[i] == names[j]) {
          fail(kHoaReader, item.line, "proposition " + quoted(names[i]) + " listed twice in AP:");
        }
      }
      ap_map_.push_back(result_.alphabet.ap_index(names[i]));
    }
  }

  void read_alias(const Item& item) {
    pos_ = item.begin;
    if (pos_ >= item.end || peek().kind != HoaTok::kAlias) {
      fail(kHoaReader, item.line, "expected an @alias name after 'Alias:'");
    }
    const std::string name = next().text;
    if (aliases_.count(name) > 0) fail(kHoaReader, item.line, "alias @" + name + " redefined");
    const Ref g = parse_label();
    expect_item_end(item);
    aliases_[name] = g;
  }

  Ref parse_label() {
    GuardBuilder builder(result_.alphabet, ap_map_, aliases_);
    return LabelParser<GuardBuilder>(toks_, pos_, builder, kHoaReader).parse();
  }

  void read_acceptance(const Item& item) {
    pos_ = item.begin;
    num_sets_ = read_int(item, "the number of acceptance sets");
    const AccNode cond = simplify(parse_acc_or(item, 0));
    expect_item_end(item);
    using Kind = AccNode::Kind;
    std::set<std::uint32_t> inf_sets;
    bool only_inf = true;
    collect_inf(cond, &inf_sets, &only_inf);
    if (cond.kind == Kind::kTrue) {
      acc_ = AccMode::kAll;
    } else if (cond.kind == Kind::kFalse) {
      acc_ = AccMode::kNone;
    } else if (only_inf && inf_sets.size() == 1 && cond.kind != Kind::kFin) {
      acc_ = AccMode::kInf;
      inf_set_ = *inf_sets.begin();
    } else {
      fail(kHoaReader, item.line,
           "unsupported acceptance condition: only Büchi (Inf of one set), t and f are read;"
           " generalized Büchi, co-Büchi, Rabin, Streett and parity conditions are not");
    }
  }

  // Inf(k) atoms, and whether every atom is a non-complemented Inf of the same kind.
  static void collect_inf(const AccNode& n, std::set<std::uint32_t>* sets, bool* only_inf) {
    switch (n.kind) {
      case AccNode::Kind::kInf:
        if (n.complemented) *only_inf = false;
        sets->insert(n.set);
        break;
      case AccNode::Kind::kAnd:
      case AccNode::Kind::kOr:
        for (const AccNode& k : n.kids) collect_inf(k, sets, only_inf);
        break;
      default:
        *only_inf = false;
        break;
    }
  }

  // Constant folding: t & x = x, f | x = x, t | x = t, f & x = f.
  static AccNode simplify(AccNode n) {
    using Kind = AccNode::Kind;
    if (n.kind != Kind::kAnd && n.kind != Kind::kOr) return n;
    const Kind unit = n.kind == Kind::kAnd ? Kind::kTrue : Kind::kFalse;
    const Kind absorbing = n.kind == Kind::kAnd ? Kind::kFalse : Kind::kTrue;
    AccNode out{n.kind, 0, false, {}};
    for (AccNode& k : n.kids) {
      AccNode s = simplify(std::move(k));
      if (s.kind == absorbing) return AccNode{absorbing, 0, false, {}};
      if (s.kind != unit) out.kids.push_back(std::move(s));
    }
    if (out.kids.empty()) return AccNode{unit, 0, false, {}};
    if (out.kids.size() == 1) return std::move(out.kids[0]);
    return out;
  }

  AccNode parse_acc_or(const Item& item, int depth) {
    AccNode n = parse_acc_and(item, depth);
    while (pos_ < item.end && is_punct(peek(), '|')) {
      ++pos_;
      n = AccNode{AccNode::Kind::kOr, 0, false, {std::move(n), parse_acc_and(item, depth)}};
    }
    return n;
  }
  AccNode parse_acc_and(const Item& item, int depth) {
    AccNode n = parse_acc_atom(item, depth);
    while (pos_ < item.end && is_punct(peek(), '&')) {
      ++pos_;
      n = AccNode{AccNode::Kind::kAnd, 0, false, {std::move(n), parse_acc_atom(item, depth)}};
    }
    return n;
  }
  AccNode parse_acc_atom(const Item& item, int depth) {
    const int line = pos_ < item.end ? peek().line : item.line;
    if (depth > kMaxNesting) fail(kHoaReader, line, "acceptance condition nested too deeply");
    if (pos_ >= item.end) fail(kHoaReader, line, "incomplete acceptance condition");
    const HoaToken& t = next();
    if (is_punct(t, '(')) {
      AccNode n = parse_acc_or(item, depth + 1);
      if (pos_ >= item.end || !is_punct(peek(), ')')) {
        fail(kHoaReader, line, "expected ')' in acceptance condition");
      }
      ++pos_;
      return n;
    }
    if (t.kind == HoaTok::kIdent && (t.text == "t" || t.text == "f")) {
      return AccNode{t.text == "t" ? AccNode::Kind::kTrue : AccNode::Kind::kFalse, 0, false, {}};
    }
    if (t.kind == HoaTok::kIdent && (t.text == "Inf" || t.text == "Fin")) {
      AccNode n{t.text == "Inf" ? AccNode::Kind::kInf : AccNode::Kind::kFin, 0, false, {}};
      if (pos_ >= item.end || !is_punct(next(), '(')) {
        fail(kHoaReader, line, "expected '(' after " + t.text);
      }
      if (pos_ < item.end && is_punct(peek(), '!')) {
        n.complemented = true;
        ++pos_;
      }
      if (pos_ >= item.end || peek().kind != HoaTok::kInt) {
        fail(kHoaReader, line, "expected an acceptance set number in " + t.text + "(...)");
      }
      n.set = next().value;
      if (n.set >= num_sets_) {
        fail(kHoaReader, line,
             "acceptance set " + std::to_string(n.set) + " out of range (Acceptance: declares " +
                 std::to_string(num_sets_) + " sets)");
      }
      if (pos_ >= item.end || !is_punct(next(), ')')) {
        fail(kHoaReader, line, "expected ')' after the set number of " + t.text);
      }
      return n;
    }
    fail(kHoaReader, t.line,
         "expected Inf(..), Fin(..), t, f or '(' in acceptance condition,"
         " found " +
             describe(t));
  }

  // acc-sig ::= "{" INT* "}": whether it names the Inf set.
  bool read_acc_sig() {
    const int line = next().line;  // '{'
    bool mark = false;
    while (peek().kind == HoaTok::kInt) {
      const HoaToken& t = next();
      if (t.value >= num_sets_) {
        fail(kHoaReader, t.line,
             "acceptance set " + std::to_string(t.value) + " out of range (Acceptance: declares " +
                 std::to_string(num_sets_) + " sets)");
      }
      if (acc_ == AccMode::kInf && t.value == inf_set_) mark = true;
    }
    if (!is_punct(peek(), '}')) {
      fail(kHoaReader, peek().kind == HoaTok::kEnd ? line : peek().line,
           "expected '}' closing the acceptance sets, found " + describe(peek()));
    }
    ++pos_;
    return mark;
  }

  RawState& raw(std::uint32_t q) {
    if (q >= states_.size()) states_.resize(q + 1);
    return states_[q];
  }

  void read_body() {
    RawState* current = nullptr;
    std::uint32_t current_index = 0;
    for (;;) {
      const HoaToken& t = peek();
      check_not_aborted();
      if (t.kind == HoaTok::kEndMarker) {
        ++pos_;
        break;
      }
      if (t.kind == HoaTok::kEnd) fail(kHoaReader, t.line, "missing --END--");
      if (t.kind == HoaTok::kHeader && t.text == "State") {
        ++pos_;
        const int line = t.line;
        bool has_label = false;
        Ref label = BddManager::kTrue;
        if (is_punct(peek(), '[')) {
          ++pos_;
          label = parse_label();
          expect_close_bracket();
          has_label = true;
        }
        current_index = read_state_index(line, "State:");
        current = &raw(current_index);
        if (current->declared) {
          fail(kHoaReader, line, "state " + std::to_string(current_index) + " declared twice");
        }
        current->declared = true;
        current->has_label = has_label;
        current->label = label;
        if (peek().kind == HoaTok::kString) {
          current->name = next().text;
          has_names_ = true;
        }
        if (is_punct(peek(), '{')) current->mark = read_acc_sig();
        continue;
      }
      if (current == nullptr) {
        fail(kHoaReader, t.line, "expected 'State:' after --BODY--, found " + describe(t));
      }
      // An edge: label? state-conj acc-sig?
      Ref guard = current->label;
      if (is_punct(t, '[')) {
        if (current->has_label) {
          fail(kHoaReader, t.line, "edge label on a state that has a state label");
        }
        ++pos_;
        guard = parse_label();
        expect_close_bracket();
      } else if (t.kind == HoaTok::kInt && !current->has_label) {
        fail(kHoaReader, t.line, "implicit labels (an edge without [label]) are not supported");
      } else if (t.kind != HoaTok::kInt) {
        fail(kHoaReader, t.line, "expected an edge, 'State:' or --END--, found " + describe(t));
      }
      const std::uint32_t dst = read_state_index(t.line, "an edge");
      if (is_punct(peek(), '&')) {
        fail(kHoaReader, peek().line,
             "universal branching (a conjunction of destinations) is not supported");
      }
      bool mark = false;
      if (is_punct(peek(), '{')) mark = read_acc_sig();
      if (mark) any_edge_mark_ = true;
      max_dst_ = std::max(max_dst_, dst + 1);
      current->edges.push_back(RawEdge{guard, dst, mark});
    }
    if (peek().kind != HoaTok::kEnd) {
      fail(kHoaReader, peek().line,
           "unexpected " + describe(peek()) + " after --END-- (one automaton per text)");
    }
  }

  void expect_close_bracket() {
    if (!is_punct(peek(), ']')) {
      fail(kHoaReader, peek().line, "expected ']' closing the label, found " + describe(peek()));
    }
    ++pos_;
  }

  void build() {
    // Without States:, the states are those declared or referenced.
    std::uint32_t n = has_num_states_
                          ? num_states_
                          : std::max(static_cast<std::uint32_t>(states_.size()), max_dst_);
    for (const std::uint32_t q : start_) n = std::max(n, q + 1);
    states_.resize(n);
    GeneralNba& r = result_;
    if (acc_ != AccMode::kInf || !any_edge_mark_) {
      for (std::uint32_t q = 0; q < n; ++q) {
        const bool acc = acc_ == AccMode::kAll || (acc_ == AccMode::kInf && states_[q].mark);
        r.add_state(acc);
      }
      for (std::uint32_t q = 0; q < n; ++q) {
        for (const RawEdge& e : states_[q].edges) r.add_edge(q, e.dst, e.guard);
      }
      r.initial = start_;
      if (has_names_) {
        for (const RawState& s : states_) r.state_names.push_back(s.name);
      }
      return;
    }
    // Transition-based marks (a state mark is shorthand for marks on all its outgoing
    // edges, HOA v1 "Body"): state (q, b) with b = the entering edge was marked.
    std::vector<std::int64_t> id(2 * static_cast<std::size_t>(n), -1);
    std::vector<std::pair<std::uint32_t, bool>> queue;
    auto get = [&](std::uint32_t q, bool b) {
      std::int64_t& slot = id[2 * static_cast<std::size_t>(q) + (b ? 1 : 0)];
      if (slot < 0) {
        slot = r.add_state(b);
        if (has_names_) {
          r.state_names.push_back(states_[q].name.empty() || !b ? states_[q].name
                                                                : states_[q].name + " {0}");
        }
        queue.emplace_back(q, b);
      }
      return static_cast<std::uint32_t>(slot);
    };
    for (const std::uint32_t q : start_) r.initial.push_back(get(q, false));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto [q, b] = queue[head];
      const std::uint32_t src = get(q, b);
      for (const RawEdge& e : states_[q].edges) {
        r.add_edge(src, get(e.dst, e.mark || states_[q].mark), e.guard);
      }
    }
  }

  std::vector<HoaToken> toks_;
  std::size_t pos_ = 0;
  GeneralNba result_;
  std::vector<std::uint32_t> ap_map_;  // HOA proposition number -> alphabet index
  std::map<std::string, Ref> aliases_;
  bool has_num_states_ = false;
  std::uint32_t num_states_ = 0;
  std::vector<std::uint32_t> start_;
  std::uint32_t num_sets_ = 0;
  AccMode acc_ = AccMode::kAll;
  std::uint32_t inf_set_ = 0;
  std::vector<RawState> states_;
  bool has_names_ = false;
  bool any_edge_mark_ = false;
  std::uint32_t max_dst_ = 0;
};

// ----------------------------------------------------------------------------------------
// Never claim reader (the Promela subset printed by `spin -f` and ltl2ba).

enum class NcTok { kEnd, kIdent, kNumber, kPunct, kError };

struct NcToken {
  NcTok kind = NcTok::kEnd;
  std::string text;  // for kError, what is wrong
  int line = 1;
};

// Lexes up to the first lexical error, which becomes a final kError token: the parser then
// reports it where it reaches it, so text that is not a claim at all (spin's own error
// message, say) is reported as "expected 'never'".
std::vector<NcToken> lex_never(std::string_view s) {
  std::vector<NcToken> toks;
  std::size_t i = 0;
  int line = 1;
  const std::size_t n = s.size();
  for (;;) {
    NcToken t;
    for (;;) {
      if (i < n && std::isspace(static_cast<unsigned char>(s[i])) != 0) {
        if (s[i] == '\n') ++line;
        ++i;
      } else if (i + 1 < n && s[i] == '/' && s[i + 1] == '*') {
        const int start_line = line;
        i += 2;
        while (i + 1 < n && !(s[i] == '*' && s[i + 1] == '/')) {
          if (s[i] == '\n') ++line;
          ++i;
        }
        if (i + 1 >= n) {
          toks.push_back(NcToken{NcTok::kError, "unterminated comment", start_line});
          return toks;
        }
        i += 2;
      } else if (i + 1 < n && s[i] == '/' && s[i + 1] == '/') {
        while (i < n && s[i] != '\n') ++i;
      } else {
        break;
      }
    }
    t.line = line;
    if (i >= n) {
      toks.push_back(t);
      return toks;
    }
    const char c = s[i];
    if (is_ident_start(c)) {
      t.kind = NcTok::kIdent;
      while (i < n && is_ident_char(s[i])) t.text += s[i++];
    } else if (is_digit(c)) {
      t.kind = NcTok::kNumber;
      while (i < n && is_digit(s[i])) t.text += s[i++];
    } else {
      t.kind = NcTok::kPunct;
      static const char* const kTwo[] = {"::", "->", "&&", "||"};
      for (const char* two : kTwo) {
        if (s.substr(i).starts_with(two)) t.text = two;
      }
      if (t.text.empty() && std::string_view("{}():;!").find(c) != std::string_view::npos) {
        t.text = std::string(1, c);
      }
      if (t.text.empty()) {
        toks.push_back(NcToken{NcTok::kError, "character " + describe_char(c), line});
        return toks;
      }
      i += t.text.size();
    }
    toks.push_back(std::move(t));
  }
}

std::string describe(const NcToken& t) {
  switch (t.kind) {
    case NcTok::kEnd:
      return "end of text";
    case NcTok::kError:
      return t.text;
    default:
      return "'" + t.text + "'";
  }
}

class NeverReader {
 public:
  NeverReader(std::string_view text, GeneralAlphabet alphabet) : toks_(lex_never(text)) {
    result_.alphabet = std::move(alphabet);
  }

  GeneralNba read() {
    parse();
    build();
    return std::move(result_);
  }

 private:
  struct Option {
    bool accept_jump = false;  // atomic { (g) -> assert(!(g)) }
    bool stay = false;         // a bare guard in a do-loop: stays in the state on g
    Ref guard = BddManager::kTrue;
    std::string target;
    int line = 0;
  };
  struct RawState {
    enum class Kind { kChoice, kFalse, kSkip, kGoto };
    std::vector<std::string> labels;
    int line = 0;
    Kind kind = Kind::kFalse;
    std::vector<Option> options;
    std::string target;  // kGoto
    int target_line = 0;
  };

  const NcToken& peek(std::size_t ahead = 0) const {
    return toks_[std::min(pos_ + ahead, toks_.size() - 1)];
  }
  const NcToken& next() {
    const NcToken& t = toks_[pos_];
    if (pos_ + 1 < toks_.size()) ++pos_;
    return t;
  }
  bool at_punct(const char* p) const { return peek().kind == NcTok::kPunct && peek().text == p; }
  bool at_ident(const char* w) const { return peek().kind == NcTok::kIdent && peek().text == w; }
  void expect_punct(const char* p, const char* context) {
    if (!at_punct(p)) {
      fail(kNeverReader, peek().line,
           std::string("expected '") + p + "' " + context + ", found " + describe(peek()));
    }
    next();
  }
  void skip_semicolon() {
    if (at_punct(";")) next();
  }
  std::string expect_ident(const char* context) {
    if (peek().kind != NcTok::kIdent) {
      fail(kNeverReader, peek().line,
           std::string("expected a name ") + context + ", found " + describe(peek()));
    }
    return next().text;
  }

  void parse() {
    if (!at_ident("never")) {
      fail(kNeverReader, peek().line, "expected 'never', found " + describe(peek()));
    }
    next();
    if (peek().kind == NcTok::kIdent) next();  // optional claim name
    expect_punct("{", "after 'never'");
    while (!at_punct("}")) {
      if (peek().kind == NcTok::kEnd) fail(kNeverReader, peek().line, "missing '}'");
      if (peek().kind == NcTok::kError) {
        fail(kNeverReader, peek().line, "unexpected " + describe(peek()));
      }
      RawState s;
      s.line = peek().line;
      while (peek().kind == NcTok::kIdent && peek(1).kind == NcTok::kPunct && peek(1).text == ":") {
        s.labels.push_back(next().text);
        next();
      }
      if (s.labels.empty() && !states_.empty()) {
        fail(kNeverReader, peek().line,
             "expected a state label (name:), found " + describe(peek()) +
                 " (one statement per state is supported)");
      }
      parse_statement(&s);
      states_.push_back(std::move(s));
    }
    if (states_.empty()) fail(kNeverReader, peek().line, "the never claim has no states");
    next();
    if (peek().kind != NcTok::kEnd) {
      fail(kNeverReader, peek().line,
           "unexpected " + describe(peek()) + " after the end of the never claim");
    }
  }

  void parse_statement(RawState* s) {
    const NcToken& t = peek();
    if (at_ident("if") || at_ident("do")) {
      const std::string close = t.text == "if" ? "fi" : "od";
      const int line = t.line;
      next();
      s->kind = RawState::Kind::kChoice;
      while (!at_ident(close.c_str())) {
        if (!at_punct("::")) {
          fail(kNeverReader, peek().line,
               "expected '::' or '" + close + "', found " + describe(peek()));
        }
        next();
        s->options.push_back(parse_option(close == "od"));
      }
      if (s->options.empty()) fail(kNeverReader, line, "'" + t.text + "' without options");
      next();
      skip_semicolon();
    } else if (at_ident("false")) {
      next();
      skip_semicolon();
      s->kind = RawState::Kind::kFalse;
    } else if (at_ident("skip")) {
      next();
      skip_semicolon();
      s->kind = RawState::Kind::kSkip;
    } else if (at_ident("goto")) {
      next();
      s->kind = RawState::Kind::kGoto;
      s->target_line = peek().line;
      s->target = expect_ident("after 'goto'");
      skip_semicolon();
    } else {
      fail(kNeverReader, t.line,
           "unsupported statement starting with " + describe(t) +
               " (expected if, do, false, skip or goto)");
    }
  }

  // in_do: the option belongs to a do-loop. A bare guard (no "-> goto", as spin prints
  // `do :: false od` for an empty language) repeats the loop, i.e. stays in the state; in
  // an if-block it would fall through to the next statement, which spin never prints and
  // which is only accepted when the guard is false (the option can never run).
  Option parse_option(bool in_do) {
    Option o;
    o.line = peek().line;
    if (at_ident("atomic")) {
      next();
      expect_punct("{", "after 'atomic'");
      o.guard = parse_guard();
      expect_punct("->", "after the guard of an atomic block");
      if (!at_ident("assert")) {
        fail(kNeverReader, peek().line,
             "unsupported atomic block: expected spin's '(g) -> assert(!(g))', found " +
                 describe(peek()));
      }
      next();
      expect_punct("(", "after 'assert'");
      const Ref asserted = parse_guard();
      expect_punct(")", "closing 'assert('");
      skip_semicolon();
      expect_punct("}", "closing the atomic block");
      if (asserted != result_.alphabet.bdd().neg(o.guard)) {
        fail(kNeverReader, o.line,
             "unsupported atomic block: the assertion is not the negation of the guard");
      }
      o.accept_jump = true;
      return o;
    }
    if (!at_ident("goto")) {
      o.guard = parse_guard();
      if (at_punct("::") || at_ident("od") || at_ident("fi")) {
        if (!in_do && o.guard != BddManager::kFalse) {
          fail(kNeverReader, o.line,
               "unsupported option: a guard without 'goto' inside 'if' (falls through)");
        }
        o.stay = true;
        return o;
      }
      if (!at_punct("->") && !at_punct(";")) {
        fail(kNeverReader, peek().line, "expected '->' after the guard, found " + describe(peek()));
      }
      next();
    }
    if (!at_ident("goto")) {
      fail(kNeverReader, peek().line, "expected 'goto' in an option, found " + describe(peek()));
    }
    next();
    o.line = peek().line;
    o.target = expect_ident("after 'goto'");
    skip_semicolon();
    return o;
  }

  Ref parse_guard() { return parse_or(0); }
  Ref parse_or(int depth) {
    Ref g = parse_and(depth);
    while (at_punct("||")) {
      next();
      g = result_.alphabet.disj(g, parse_and(depth));
    }
    return g;
  }
  Ref parse_and(int depth) {
    Ref g = parse_unary(depth);
    while (at_punct("&&")) {
      next();
      g = result_.alphabet.conj(g, parse_unary(depth));
    }
    return g;
  }
  Ref parse_unary(int depth) {
    const NcToken& t = peek();
    if (depth > kMaxNesting) fail(kNeverReader, t.line, "guard nested too deeply");
    if (at_punct("!")) {
      next();
      return result_.alphabet.bdd().neg(parse_unary(depth + 1));
    }
    if (at_punct("(")) {
      next();
      const Ref g = parse_or(depth + 1);
      expect_punct(")", "in guard");
      return g;
    }
    if (t.kind == NcTok::kNumber) {
      next();
      const bool nonzero = t.text.find_first_not_of('0') != std::string::npos;
      return nonzero ? result_.alphabet.top() : result_.alphabet.bottom();
    }
    if (t.kind == NcTok::kIdent) {
      if (t.text == "true" || t.text == "false") {
        next();
        return t.text == "true" ? result_.alphabet.top() : result_.alphabet.bottom();
      }
      if (is_promela_reserved(t.text)) {
        fail(kNeverReader, t.line, "keyword '" + t.text + "' where a guard was expected");
      }
      next();
      return result_.alphabet.ap(result_.alphabet.ap_index(t.text), true);
    }
    fail(kNeverReader, t.line,
         "expected a guard (a proposition, true, false, 0, 1, '!' or"
         " '('), found " +
             describe(t));
  }

  // Raw state that a label names, following `goto` states (jumps, not steps).
  std::size_t resolve(const std::string& label, int line) const {
    const auto it = by_label_.find(label);
    if (it == by_label_.end()) fail(kNeverReader, line, "goto to undefined label '" + label + "'");
    return resolve_raw(it->second);
  }
  std::size_t resolve_raw(std::size_t r) const {
    const std::size_t start = r;
    for (std::size_t hops = 0; states_[r].kind == RawState::Kind::kGoto; ++hops) {
      if (hops > states_.size()) {
        fail(kNeverReader, states_[start].line, "cycle of gotos without a step");
      }
      const auto it = by_label_.find(states_[r].target);
      if (it == by_label_.end()) {
        fail(kNeverReader, states_[r].target_line,
             "goto to undefined label '" + states_[r].target + "'");
      }
      r = it->second;
    }
    return r;
  }

  void build() {
    for (std::size_t r = 0; r < states_.size(); ++r) {
      for (const std::string& l : states_[r].labels) {
        if (!by_label_.emplace(l, r).second) {
          fail(kNeverReader, states_[r].line, "label '" + l + "' defined twice");
        }
      }
    }
    GeneralNba& a = result_;
    // Automaton states: the non-goto raw states in textual order.
    std::vector<std::uint32_t> index(states_.size(), 0);
    std::vector<std::size_t> raw_of;
    for (std::size_t r = 0; r < states_.size(); ++r) {
      const RawState& s = states_[r];
      if (s.kind == RawState::Kind::kGoto) {
        resolve_raw(r);  // report undefined targets and cycles
        continue;
      }
      bool acc = false;
      for (const std::string& l : s.labels) acc = acc || l.starts_with("accept");
      // A final skip ends the claim: every continuation is accepted.
      const bool ends_claim = s.kind == RawState::Kind::kSkip && r + 1 == states_.size();
      index[r] = a.add_state(acc || ends_claim);
      a.state_names.push_back(s.labels.empty() ? std::string() : s.labels.front());
      raw_of.push_back(r);
    }
    std::int64_t sink = -1;
    auto accept_sink = [&]() {
      if (sink < 0) {
        const std::size_t last = states_.size() - 1;
        if (states_[last].kind == RawState::Kind::kSkip) {
          sink = index[last];
        } else {
          sink = a.add_state(true);
          a.state_names.push_back("accept_all");
          a.add_edge(static_cast<std::uint32_t>(sink), static_cast<std::uint32_t>(sink),
                     a.alphabet.top());
        }
      }
      return static_cast<std::uint32_t>(sink);
    };
    for (const std::size_t r : raw_of) {
      const RawState& s = states_[r];
      const std::uint32_t q = index[r];
      switch (s.kind) {
        case RawState::Kind::kChoice:
          for (const Option& o : s.options) {
            const std::uint32_t dst = o.stay          ? q
                                      : o.accept_jump ? accept_sink()
                                                      : index[resolve(o.target, o.line)];
            a.add_edge(q, dst, o.guard);
          }
          break;
        case RawState::Kind::kSkip:
          a.add_edge(q, r + 1 == states_.size() ? q : index[resolve_raw(r + 1)], a.alphabet.top());
          break;
        case RawState::Kind::kFalse:
        case RawState::Kind::kGoto:
          break;
      }
    }
    std::size_t init = 0;
    bool found = false;
    for (std::size_t r = 0; r < states_.size() && !found; ++r) {
      for (const std::string& l : states_[r].labels) {
        if (l.ends_with("init")) {
          init = r;
          found = true;
          break;
        }
      }
    }
    a.initial.push_back(index[resolve_raw(init)]);
  }

  std::vector<NcToken> toks_;
  std::size_t pos_ = 0;
  std::vector<RawState> states_;
  std::map<std::string, std::size_t> by_label_;
  GeneralNba result_;
};

}  // namespace

std::string to_hoa(const GeneralNba& a, const std::string& name) { return write_hoa(a, name); }
std::string to_hoa(const ActionNba& a, const std::string& name) { return write_hoa(a, name); }

std::string to_never_claim(const GeneralNba& a) { return write_never_claim(a); }
std::string to_never_claim(const ActionNba& a) { return write_never_claim(a); }

std::string to_dot(const GeneralNba& a) { return write_dot(a); }
std::string to_dot(const ActionNba& a) { return write_dot(a); }

GeneralNba read_hoa(std::string_view text, GeneralAlphabet alphabet) {
  return HoaReader(text, std::move(alphabet)).read();
}

GeneralNba read_never_claim(std::string_view text, GeneralAlphabet alphabet) {
  return NeverReader(text, std::move(alphabet)).read();
}

}  // namespace rearm::ltl
