// The automaton I/O pieces shared by the formats (automaton_io_internal.h): errors, quoting,
// the HOA lexer, and the label expression trees that the never-claim and DOT writers re-spell.
#include "ltl/automaton_io_internal.h"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"

namespace rearm::ltl::io_detail {
namespace {

// HOA INT: "a non-negative integer less than 2^31".
constexpr std::uint64_t kMaxHoaInt = (1ull << 31) - 1;

bool is_hoa_ident_char(char c) { return is_ident_char(c) || c == '-'; }

}  // namespace

[[noreturn]] void fail(const char* reader, int line, const std::string& reason) {
  throw Error(std::string(reader) + ": line " + std::to_string(line) + ": " + reason);
}

std::string describe_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (std::isprint(u)) return std::string("'") + c + "'";
  static const char* const kHex = "0123456789abcdef";
  return std::string("byte 0x") + kHex[u >> 4] + kHex[u & 15];
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

namespace {

// The HOA tokens of one text; errors name `who` and the line.
class HoaLexer {
 public:
  HoaLexer(std::string_view s, const char* who) : s_(s), who_(who) {}

  std::vector<HoaToken> lex() {
    std::vector<HoaToken> toks;
    for (;;) {
      skip_blank();
      HoaToken t;
      t.line = line_;
      if (i_ >= s_.size()) {
        toks.push_back(t);
        return toks;
      }
      lex_token(t);
      toks.push_back(std::move(t));
    }
  }

 private:
  // Whitespace and (nested) comments.
  void skip_blank() {
    const std::size_t n = s_.size();
    for (;;) {
      if (i_ < n && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r' || s_[i_] == '\n')) {
        if (s_[i_] == '\n') ++line_;
        ++i_;
      } else if (i_ + 1 < n && s_[i_] == '/' && s_[i_ + 1] == '*') {
        skip_comment();
      } else {
        break;
      }
    }
  }

  void skip_comment() {
    const std::size_t n = s_.size();
    const int start_line = line_;
    int depth = 0;
    while (true) {
      if (i_ + 1 >= n) fail(who_, start_line, "unterminated comment");
      if (s_[i_] == '/' && s_[i_ + 1] == '*') {
        ++depth;
        i_ += 2;
      } else if (s_[i_] == '*' && s_[i_ + 1] == '/') {
        i_ += 2;
        if (--depth == 0) break;
      } else {
        if (s_[i_] == '\n') ++line_;
        ++i_;
      }
    }
  }

  // The token that starts at s_[i_] (not blank, not the end).
  void lex_token(HoaToken& t) {
    const std::size_t n = s_.size();
    const char c = s_[i_];
    if (c == '"') {
      lex_string(t);
    } else if (is_digit(c)) {
      lex_int(t);
    } else if (is_ident_start(c)) {
      while (i_ < n && is_hoa_ident_char(s_[i_])) t.text += s_[i_++];
      if (i_ < n && s_[i_] == ':') {
        t.kind = HoaTok::kHeader;
        ++i_;
      } else {
        t.kind = HoaTok::kIdent;
      }
    } else if (c == '@') {
      t.kind = HoaTok::kAlias;
      ++i_;
      while (i_ < n && is_hoa_ident_char(s_[i_])) t.text += s_[i_++];
      if (t.text.empty()) fail(who_, line_, "'@' must be followed by an alias name");
    } else if (c == '-') {
      lex_marker(t);
    } else if (std::string_view("[]{}()!&|").find(c) != std::string_view::npos) {
      t.kind = HoaTok::kPunct;
      t.text = std::string(1, c);
      ++i_;
    } else {
      fail(who_, line_, "unexpected character " + describe_char(c));
    }
  }

  void lex_string(HoaToken& t) {
    const std::size_t n = s_.size();
    t.kind = HoaTok::kString;
    ++i_;
    for (;;) {
      if (i_ >= n) fail(who_, t.line, "unterminated string");
      if (s_[i_] == '"') break;
      if (s_[i_] == '\\') {
        if (++i_ >= n) fail(who_, t.line, "unterminated string");
      }
      if (s_[i_] == '\n') ++line_;
      t.text += s_[i_++];
    }
    ++i_;
  }

  void lex_int(HoaToken& t) {
    t.kind = HoaTok::kInt;
    std::uint64_t v = 0;
    while (i_ < s_.size() && is_digit(s_[i_])) {
      v = v * 10 + static_cast<std::uint64_t>(s_[i_] - '0');
      if (v > kMaxHoaInt) fail(who_, line_, "integer too large (HOA integers are < 2^31)");
      t.text += s_[i_++];
    }
    t.value = static_cast<std::uint32_t>(v);
  }

  void lex_marker(HoaToken& t) {
    static const std::pair<const char*, HoaTok> kMarkers[] = {{"--BODY--", HoaTok::kBody},
                                                              {"--END--", HoaTok::kEndMarker},
                                                              {"--ABORT--", HoaTok::kAbort}};
    for (const auto& [text, kind] : kMarkers) {
      if (s_.substr(i_).starts_with(text)) {
        t.kind = kind;
        t.text = text;
        i_ += std::string_view(text).size();
        return;
      }
    }
    fail(who_, line_, "unexpected '-' (expected --BODY--, --END-- or --ABORT--)");
  }

  std::string_view s_;
  const char* who_;
  std::size_t i_ = 0;
  int line_ = 1;
};

}  // namespace

std::vector<HoaToken> lex_hoa(std::string_view s, const char* who) {
  return HoaLexer(s, who).lex();
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

namespace {

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

}  // namespace

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

template LabelExpr label_expr(const GeneralAlphabet& alphabet, const GeneralAlphabet::Guard& g);
template LabelExpr label_expr(const ActionAlphabet& alphabet, const ActionAlphabet::Guard& g);

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

}  // namespace rearm::ltl::io_detail
