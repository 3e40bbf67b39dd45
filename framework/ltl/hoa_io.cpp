// HOA v1 (Hanoi Omega-Automata, as Spot and Owl read and write it) for ltl/automaton_io.h:
// the writer to_hoa and the reader read_hoa.
//
// The reader (its quirks are listed in docs/symbolic.md) keeps the HOA state numbers when
// acceptance is on states (or is t / f). With marks on transitions it builds states (q, b),
// b = "the transition that entered q was in the Inf set", accepting iff b, and keeps only
// those reachable from the initial states.
#include <algorithm>
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

using io_detail::describe;
using io_detail::fail;
using io_detail::HoaTok;
using io_detail::HoaToken;
using io_detail::is_punct;
using io_detail::kMaxNesting;
using io_detail::kOneAction;
using io_detail::kOneActionNote;
using io_detail::LabelParser;
using io_detail::lex_hoa;
using io_detail::quoted;
using io_detail::Ref;
using io_detail::state_name;

// Largest number of HOA states accepted (the reader allocates per state index before it has
// seen the states' bodies): above the translator's per-stage budget (TranslateOptions::
// max_states), so every automaton rearm writes reads back, and small enough that a file naming
// a huge state index (Start: 4849003 without States:, found by fuzzing) is rejected at once
// instead of building and writing millions of empty states (over 6 s in the fuzz build).
constexpr std::uint32_t kMaxHoaStates = 1u << 18;

const char* const kHoaReader = "read_hoa";

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
    const std::vector<Item> items = collect_items();
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
      if (item.name == "States") read_num_states(item);
      if (item.name == "Acceptance") read_acceptance(item);
    }
    if (seen["Acceptance"] == 0) fail(kHoaReader, body_line, "missing 'Acceptance:' header");
    for (const Item& item : items) {
      if (item.name == "Start") read_start(item);
    }
    // acc-name, tool, name, properties and unknown headers carry no semantics we need (the
    // Acceptance: line defines acceptance, HOA v1 "Acceptance Specifications").
    pos_ = body_pos;
  }

  // The header items up to the first token that ends the header (--BODY--, say), each with
  // its value tokens; pos_ is left at that token.
  std::vector<Item> collect_items() {
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
    return items;
  }

  void read_num_states(const Item& item) {
    pos_ = item.begin;
    num_states_ = read_int(item, "the number of states");
    if (num_states_ > kMaxHoaStates) {
      fail(kHoaReader, item.line,
           "too many states (at most " + std::to_string(kMaxHoaStates) + ")");
    }
    has_num_states_ = true;
    expect_item_end(item);
  }

  void read_start(const Item& item) {
    pos_ = item.begin;
    const std::uint32_t q = read_state_index(item.line, "Start:");
    if (pos_ < item.end && is_punct(peek(), '&')) {
      fail(kHoaReader, peek().line,
           "a conjunction of initial states (alternating automaton) is not supported");
    }
    expect_item_end(item);
    if (std::find(start_.begin(), start_.end(), q) == start_.end()) start_.push_back(q);
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
        current = read_state(t.line);
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

  // A state declaration after its 'State:' (at `line`): label? INT STRING? acc-sig?
  RawState* read_state(int line) {
    bool has_label = false;
    Ref label = BddManager::kTrue;
    if (is_punct(peek(), '[')) {
      ++pos_;
      label = parse_label();
      expect_close_bracket();
      has_label = true;
    }
    const std::uint32_t index = read_state_index(line, "State:");
    RawState* current = &raw(index);
    if (current->declared) {
      fail(kHoaReader, line, "state " + std::to_string(index) + " declared twice");
    }
    current->declared = true;
    current->has_label = has_label;
    current->label = label;
    if (peek().kind == HoaTok::kString) {
      current->name = next().text;
      has_names_ = true;
    }
    if (is_punct(peek(), '{')) current->mark = read_acc_sig();
    return current;
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

}  // namespace

std::string to_hoa(const GeneralNba& a, const std::string& name) { return write_hoa(a, name); }
std::string to_hoa(const ActionNba& a, const std::string& name) { return write_hoa(a, name); }

GeneralNba read_hoa(std::string_view text, GeneralAlphabet alphabet) {
  return HoaReader(text, std::move(alphabet)).read();
}

}  // namespace rearm::ltl
