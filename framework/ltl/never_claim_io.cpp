// Spin never claims for ltl/automaton_io.h: the writer to_never_claim and the reader
// read_never_claim (the Promela subset printed by `spin -f` and ltl2ba).
//
// The reader (the quirks of `spin -f` are listed in docs/symbolic.md) keeps the textual state
// order. `goto` is a jump, not a step (spin removes jumps when it compiles a claim), so a
// state whose only statement is `goto s` is another name of s. `skip` is a step on any symbol
// to the textually next state; after the last state the claim ends, which spin reports as an
// accepting run, so a final `skip` state accepts every continuation (accepting, true
// self-loop). `atomic { (g) -> assert(!(g)) }` fails the assertion, which spin also reports as
// an accepting run: an edge g to that accept-everything state (a fresh one when the claim has
// none).
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ltl/automaton_io.h"
#include "ltl/automaton_io_internal.h"

namespace rearm::ltl {
namespace {

using io_detail::describe_char;
using io_detail::fail;
using io_detail::is_digit;
using io_detail::is_ident_char;
using io_detail::is_ident_start;
using io_detail::kMaxNesting;
using io_detail::kOneAction;
using io_detail::kOneActionNote;
using io_detail::label_expr;
using io_detail::Ref;
using io_detail::spell;
using io_detail::Spelling;
using io_detail::state_name;

const char* const kNeverReader = "read_never_claim";

// Text that may go inside a /* */ comment of HOA, Promela or DOT.
std::string comment_safe(std::string s) {
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if ((s[i] == '*' && s[i + 1] == '/') || (s[i] == '/' && s[i + 1] == '*')) s[i] = ' ';
  }
  return s;
}

constexpr Spelling kSpinSpelling{"1", "0", " && ", " || ", true};

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

// The edges of all initial states, one per destination (their guards or-ed): the edges of
// the fresh initial state that write_never_claim adds when there are several.
template <class Alphabet>
std::vector<typename Automaton<Alphabet>::Edge> initial_edges(const Automaton<Alphabet>& a) {
  using Edge = typename Automaton<Alphabet>::Edge;
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
  return edges;
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
    write_state("T0_init", "initial states", initial_edges(a));
  } else {
    write_state(label(init), state_name(a, init), a.out[init]);
  }
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    if (fresh_init || q != init) write_state(label(q), state_name(a, q), a.out[q]);
  }
  return out + "}\n";
}

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

  void index_labels() {
    for (std::size_t r = 0; r < states_.size(); ++r) {
      for (const std::string& l : states_[r].labels) {
        if (!by_label_.emplace(l, r).second) {
          fail(kNeverReader, states_[r].line, "label '" + l + "' defined twice");
        }
      }
    }
  }

  // The raw state of the first label that ends in "init"; the first state when none does.
  std::size_t initial_raw() const {
    for (std::size_t r = 0; r < states_.size(); ++r) {
      for (const std::string& l : states_[r].labels) {
        if (l.ends_with("init")) return r;
      }
    }
    return 0;
  }

  void build() {
    index_labels();
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
    a.initial.push_back(index[resolve_raw(initial_raw())]);
  }

  std::vector<NcToken> toks_;
  std::size_t pos_ = 0;
  std::vector<RawState> states_;
  std::map<std::string, std::size_t> by_label_;
  GeneralNba result_;
};

}  // namespace

std::string to_never_claim(const GeneralNba& a) { return write_never_claim(a); }
std::string to_never_claim(const ActionNba& a) { return write_never_claim(a); }

GeneralNba read_never_claim(std::string_view text, GeneralAlphabet alphabet) {
  return NeverReader(text, std::move(alphabet)).read();
}

}  // namespace rearm::ltl
