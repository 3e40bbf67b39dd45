// LTL parser (ltl/parser.h, docs/symbolic.md "Formulas"): both spellings, Spot's precedence,
// action predicates, error positions, the depth limit, fuzzing (any byte string parses or
// throws ParseError, nothing else), and printer/parser round trips. Expected trees are built
// with Formula's constructors, independently of the parser.
#include "ltl/parser.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.h"
#include "ltl/formula.h"

namespace rearm::ltl {
namespace {

using F = Formula;

const F a = F::ap("a");
const F b = F::ap("b");
const F c = F::ap("c");
const F d = F::ap("d");

// Parses `text`, failing the test (not throwing) on a ParseError.
F parsed(const std::string& text) {
  try {
    return parse(text);
  } catch (const ParseError& e) {
    ADD_FAILURE() << "'" << text << "': " << e.what();
    return F::ff();
  }
}

void expect_parse(const std::string& text, const F& expected) {
  const F got = parsed(text);
  EXPECT_EQ(got, expected) << "'" << text << "' parsed as " << got.to_string() << ", expected "
                           << expected.to_string();
}

// True when W, M or xor occurs (the Spin printer expands them into other operators).
bool has_spin_expansion(const F& f) {
  if (f.op() == Op::WeakUntil || f.op() == Op::StrongRelease || f.op() == Op::Xor) return true;
  for (const F& child : f.children()) {
    if (has_spin_expansion(child)) return true;
  }
  return false;
}

// Printed in either syntax, `f` reparses; to an equal tree unless the Spin printer expanded
// W, M or xor.
void expect_reparses(const F& f, const std::string& origin) {
  for (const Syntax syntax : {Syntax::Spot, Syntax::Spin}) {
    const std::string printed = f.to_string(syntax);
    try {
      const F g = parse(printed);
      if (syntax == Syntax::Spot || !has_spin_expansion(f)) {
        EXPECT_EQ(g, f) << "input '" << origin << "' printed '" << printed << "'";
      }
    } catch (const ParseError& e) {
      ADD_FAILURE() << "input '" << origin << "' printed '" << printed << "': " << e.what();
    }
  }
}

// ---------------------------------------------------------------------------------------
// Spellings.

TEST(ParserTest, SpinSpelling) {
  expect_parse("<>a", F::eventually(a));
  expect_parse("[]a", F::always(a));
  expect_parse("!a", F::lnot(a));
  expect_parse("a && b", F::conj(a, b));
  expect_parse("a || b", F::disj(a, b));
  expect_parse("a -> b", F::implies(a, b));
  expect_parse("a <-> b", F::equiv(a, b));
  expect_parse("a U b", F::until(a, b));
  expect_parse("a V b", F::release(a, b));
  expect_parse("true", F::tt());
  expect_parse("false", F::ff());
  expect_parse("X a", F::next(a));
  expect_parse("[]<>a && <>[]!b",
               F::conj(F::always(F::eventually(a)), F::eventually(F::always(F::lnot(b)))));
}

TEST(ParserTest, SpotSpelling) {
  expect_parse("F a", F::eventually(a));
  expect_parse("G a", F::always(a));
  expect_parse("X a", F::next(a));
  expect_parse("a & b", F::conj(a, b));
  expect_parse("a | b", F::disj(a, b));
  expect_parse("a R b", F::release(a, b));
  expect_parse("a M b", F::strong_release(a, b));
  expect_parse("a W b", F::weak_until(a, b));
  expect_parse("a xor b", F::lxor(a, b));
  expect_parse("a ^ b", F::lxor(a, b));
  expect_parse("1", F::tt());
  expect_parse("0", F::ff());
  expect_parse("a => b", F::implies(a, b));
  expect_parse("a <=> b", F::equiv(a, b));
  expect_parse("a /\\ b", F::conj(a, b));
  expect_parse("a \\/ b", F::disj(a, b));
  expect_parse("~a", F::lnot(a));
  expect_parse("G(a -> F b)", F::always(F::implies(a, F::eventually(b))));
}

TEST(ParserTest, WhitespaceIsOptionalAndIncludesNewlines) {
  expect_parse("a&b", F::conj(a, b));
  expect_parse("(a)U(b)", F::until(a, b));
  expect_parse(" \t\r\n a \n&&\n\f\v b \n", F::conj(a, b));
  expect_parse("!(a)", F::lnot(a));
  expect_parse("((((a))))", a);
}

TEST(ParserTest, QuotedPropositions) {
  expect_parse("\"a b\"", F::ap("a b"));
  expect_parse("\"F1\" U \"true\"", F::until(F::ap("F1"), F::ap("true")));
  expect_parse("\"move( l1)\"", F::ap("move( l1)"));  // quoted: taken verbatim
  expect_parse("!\"1\"", F::lnot(F::ap("1")));
  expect_parse(std::string("\"a\0\xff\nb\"", 7), F::ap(std::string("a\0\xff\nb", 5)));
}

// ---------------------------------------------------------------------------------------
// Precedence and associativity (Spot's: -> <-> loosest and right-assoc, then |, xor, &,
// then U R V W M right-assoc, then the unary operators).

TEST(ParserTest, BooleanPrecedence) {
  expect_parse("a | b & c", F::disj(a, F::conj(b, c)));
  expect_parse("a & b | c", F::disj(F::conj(a, b), c));
  expect_parse("a xor b & c", F::lxor(a, F::conj(b, c)));
  expect_parse("a & b xor c", F::lxor(F::conj(a, b), c));
  expect_parse("a | b xor c", F::disj(a, F::lxor(b, c)));
  expect_parse("a xor b | c", F::disj(F::lxor(a, b), c));
  expect_parse("a -> b | c", F::implies(a, F::disj(b, c)));
  expect_parse("a | b -> c", F::implies(F::disj(a, b), c));
  expect_parse("a <-> b & c", F::equiv(a, F::conj(b, c)));
  expect_parse("(a | b) & c", F::conj(F::disj(a, b), c));
}

TEST(ParserTest, Associativity) {
  expect_parse("a -> b -> c", F::implies(a, F::implies(b, c)));
  expect_parse("a <-> b -> c", F::equiv(a, F::implies(b, c)));
  expect_parse("a -> b <-> c", F::implies(a, F::equiv(b, c)));
  expect_parse("(a -> b) -> c", F::implies(F::implies(a, b), c));
  expect_parse("a xor b xor c", F::lxor(F::lxor(a, b), c));
  expect_parse("a xor (b xor c)", F::lxor(a, F::lxor(b, c)));
  expect_parse("a U b U c", F::until(a, F::until(b, c)));
  expect_parse("a U b R c", F::until(a, F::release(b, c)));
  expect_parse("a W b M c V d", F::weak_until(a, F::strong_release(b, F::release(c, d))));
  expect_parse("(a U b) U c", F::until(F::until(a, b), c));
}

TEST(ParserTest, AndOrChainsAreNary) {
  expect_parse("a & b & c", F::conj({a, b, c}));
  expect_parse("a && b & c /\\ d", F::conj({a, b, c, d}));
  expect_parse("a | b || c \\/ d", F::disj({a, b, c, d}));
  expect_parse("(a & b) & c", F::conj(F::conj(a, b), c));
  expect_parse("a & (b & c)", F::conj(a, F::conj(b, c)));
  expect_parse("a & !b & c", F::conj({a, F::lnot(b), c}));
  expect_parse("a & b | c & d", F::disj(F::conj(a, b), F::conj(c, d)));
  expect_parse("a & b U c & d", F::conj({a, F::until(b, c), d}));
}

TEST(ParserTest, TemporalAgainstBoolean) {
  expect_parse("a U b & c", F::conj(F::until(a, b), c));
  expect_parse("a & b U c", F::conj(a, F::until(b, c)));
  expect_parse("a | b R c", F::disj(a, F::release(b, c)));
  expect_parse("a U b -> c", F::implies(F::until(a, b), c));
}

TEST(ParserTest, UnaryBindsTightest) {
  expect_parse("!a U b", F::until(F::lnot(a), b));
  expect_parse("F a U b", F::until(F::eventually(a), b));
  expect_parse("a U G b", F::until(a, F::always(b)));
  expect_parse("X a & b", F::conj(F::next(a), b));
  expect_parse("!a & b", F::conj(F::lnot(a), b));
  expect_parse("!!a", F::lnot(F::lnot(a)));
  expect_parse("! F ~ [] X a", F::lnot(F::eventually(F::lnot(F::always(F::next(a))))));
  expect_parse("!(a & b)", F::lnot(F::conj(a, b)));
  expect_parse("F G a", F::eventually(F::always(a)));
}

// ---------------------------------------------------------------------------------------
// Identifier splitting (the rule documented in parser.cpp).

TEST(ParserTest, OperatorLettersSplitBeforeLowerCase) {
  expect_parse("GFa", F::always(F::eventually(a)));
  expect_parse("Fa", F::eventually(a));
  expect_parse("Fp1", F::eventually(F::ap("p1")));
  expect_parse("XXGb_c", F::next(F::next(F::always(F::ap("b_c")))));
  expect_parse("XXtrue", F::next(F::next(F::tt())));
  expect_parse("Fmove(l1)", F::eventually(F::ap("move(l1)")));
  expect_parse("GFa & FGb", F::conj(F::always(F::eventually(a)), F::eventually(F::always(b))));
}

TEST(ParserTest, IdentifiersOfOperatorLettersOnlyAreOperators) {
  expect_parse("GF(a)", F::always(F::eventually(F::ap("a"))));
  expect_parse("FG (a)", F::eventually(F::always(F::ap("a"))));
  expect_parse("XF !a", F::next(F::eventually(F::lnot(F::ap("a")))));
  expect_parse("FF a", F::eventually(F::eventually(F::ap("a"))));
  expect_parse("\"FF\"", F::ap("FF"));
}

TEST(ParserTest, OperatorLettersOtherwiseFormOneProposition) {
  expect_parse("F1", F::ap("F1"));
  expect_parse("GF2", F::ap("GF2"));
  expect_parse("FGA", F::ap("FGA"));
  expect_parse("F_a", F::ap("F_a"));
  expect_parse("Ab", F::ap("Ab"));
  expect_parse("aUb", F::ap("aUb"));
  expect_parse("U1", F::ap("U1"));
  expect_parse("xor1", F::ap("xor1"));
  expect_parse("TRUE", F::ap("TRUE"));
  expect_parse("F F1", F::eventually(F::ap("F1")));
}

// ---------------------------------------------------------------------------------------
// Action predicates: canonical spelling without blanks.

TEST(ParserTest, ActionPredicatesAreCanonicalized) {
  expect_parse("move(l1)", F::ap("move(l1)"));
  expect_parse("move ( l1 )", F::ap("move(l1)"));
  expect_parse("grasp(M2)", F::ap("grasp(M2)"));
  expect_parse("grasp(\tM2\t)", F::ap("grasp(M2)"));
  expect_parse("release(M1,l2)", F::ap("release(M1,l2)"));
  expect_parse("release( M1 ,\n l2 )", F::ap("release(M1,l2)"));
  expect_parse("<>(grasp(M1) && <>release(M1, l2))",
               F::eventually(F::conj(F::ap("grasp(M1)"), F::eventually(F::ap("release(M1,l2)")))));
  expect_parse("release(F,G)", F::ap("release(F,G)"));  // arguments are not keywords
  expect_parse("move", F::ap("move"));                  // a verb alone is a proposition
  expect_parse("move & grasp", F::conj(F::ap("move"), F::ap("grasp")));
  const F p = parsed("release (M1 , l2)");
  EXPECT_TRUE(is_action_predicate(p.name()));
  EXPECT_EQ(p.to_string(), "release(M1,l2)");
}

// ---------------------------------------------------------------------------------------
// Errors: position and expectation.

constexpr const char* kPredicates = "move(region), grasp(object) or release(object,region)";

struct BadInput {
  std::string text;
  std::size_t line, column;
  std::string expected, found;
};

TEST(ParserTest, MalformedInputsReportPositionAndExpectation) {
  const std::string formula = "a formula";
  const std::string op_or_end = "a binary operator or end of input";
  const std::string op_or_paren = "a binary operator or ')'";
  const std::string end = "end of input";
  const std::vector<BadInput> cases = {
      {"", 1, 1, formula, end},
      {"   ", 1, 4, formula, end},
      {"a &", 1, 4, formula, end},
      {"& a", 1, 1, formula, "'&'"},
      {"a & & b", 1, 5, formula, "'&'"},
      {"a b", 1, 3, op_or_end, "'b'"},
      {"(a", 1, 3, op_or_paren, end},
      {"(a b)", 1, 4, op_or_paren, "'b'"},
      {"a)", 1, 2, op_or_end, "')'"},
      {"a & (b | c))", 1, 12, op_or_end, "')'"},
      {"()", 1, 2, formula, "')'"},
      {"a U", 1, 4, formula, end},
      {"U a", 1, 1, formula, "'U'"},
      {"!", 1, 2, formula, end},
      {"X", 1, 2, formula, end},
      {"a xor", 1, 6, formula, end},
      {"a - b", 1, 3, "'->'", "'-'"},
      {"a <- b", 1, 3, "'<->'", "'<-'"},
      {"a <= b", 1, 3, "'<=>'", "'<='"},
      {"a < b", 1, 3, "'<>', '<->' or '<=>'", "'<'"},
      {"[ a", 1, 1, "'[]'", "'['"},
      {"a / b", 1, 3, "'/\\'", "'/'"},
      {"a \\ b", 1, 3, "'\\/'", "'\\'"},
      {"a = b", 1, 3, "'=>'", "'='"},
      {"\"abc", 1, 5, "a closing '\"'", end},
      {"a & \"\"", 1, 5, "a non-empty proposition name", "'\"\"'"},
      {"a @ b", 1, 3, op_or_end, "'@'"},
      {"a , b", 1, 3, op_or_end, "','"},
      {"12", 1, 1, formula, "'12'"},
      {"1a", 1, 1, formula, "'1a'"},
      {"Fxor a", 1, 2, formula, "'xor'"},
      {"move()", 1, 6, "a region name", "')'"},
      {"grasp()", 1, 7, "an object name", "')'"},
      {"grasp(", 1, 7, "an object name", end},
      {"release(M1)", 1, 11, "',' and a region name", "')'"},
      {"release(M1 l2)", 1, 12, "',' and a region name", "'l2'"},
      {"release(M1,)", 1, 12, "a region name", "')'"},
      {"move(l1", 1, 8, "')'", end},
      {"move(l1,l2)", 1, 8, "')'", "','"},
      {"release(M1,l2,l3)", 1, 14, "')'", "','"},
      {"move(1)", 1, 6, "a region name", "'1'"},
      {"move(l1) grasp(M1)", 1, 10, op_or_end, "'grasp(M1)'"},
      // A word applied to arguments is named as an unknown predicate, with the closest action
      // verb when one is near (edit distance, core/suggest.h).
      {"<>mvoe(l1)", 1, 3, kPredicates, "the unknown predicate 'mvoe'; did you mean 'move'?"},
      {"F relase (M1, l1)", 1, 3, kPredicates,
       "the unknown predicate 'relase'; did you mean 'release'?"},
      {"a & gasp(M1)", 1, 5, kPredicates, "the unknown predicate 'gasp'; did you mean 'grasp'?"},
      {"pick(M1)", 1, 1, kPredicates, "the unknown predicate 'pick'"},
      {"a\n&& )", 2, 4, formula, "')'"},
      {"a &&\n\n  (b", 3, 5, op_or_paren, end},
      {"a U\r\n\tb c", 2, 4, op_or_end, "'c'"},
      {std::string("a\0b", 3), 1, 2, op_or_end, "'\\x00'"},
      {"\xff", 1, 1, formula, "'\\xff'"},
      {"a & \xc3\xa9", 1, 5, formula, "'\\xc3'"},
      {"p & " + std::string(100, 'q') + " r", 1, 106, op_or_end, "'r'"},
      {"p " + std::string(100, 'q'), 1, 3, op_or_end, "'" + std::string(32, 'q') + "...'"},
  };
  ASSERT_GE(cases.size(), 25u);
  for (const BadInput& bad : cases) {
    SCOPED_TRACE("input: '" + bad.text + "'");
    try {
      const F f = parse(bad.text);
      ADD_FAILURE() << "parsed as " << f.to_string();
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), bad.line);
      EXPECT_EQ(e.column(), bad.column);
      EXPECT_EQ(e.expected(), bad.expected);
      EXPECT_EQ(e.found(), bad.found);
    }
  }
}

TEST(ParserTest, MessageFormat) {
  try {
    parse("G (a ->\n  b c)");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(),
                 "ltl parse error at line 2, column 5: expected a binary operator or ')', "
                 "found 'c'");
  }
  try {
    parse("release(M1)");
    FAIL() << "no error";
  } catch (const Error& e) {  // a rearm::Error, as every bad-input exception
    EXPECT_STREQ(e.what(),
                 "ltl parse error at line 1, column 11: expected ',' and a region name, "
                 "found ')'");
  }
}

// ---------------------------------------------------------------------------------------
// Depth limit: too deep is a ParseError, never a stack overflow.

constexpr std::size_t kHugeNesting = 100000;

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += s;
  return out;
}

void expect_too_deep(const std::string& text) {
  try {
    parse(text);
    ADD_FAILURE() << "parsed input of " << text.size() << " bytes";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.expected(), "nesting depth at most " + std::to_string(kMaxParseDepth));
  }
}

TEST(ParserTest, DeepNestingIsAnError) {
  expect_too_deep(repeat("(", kHugeNesting));
  expect_too_deep(repeat("(", kHugeNesting) + "a" + repeat(")", kHugeNesting));
  expect_too_deep(repeat("!", kHugeNesting) + "a");
  expect_too_deep(repeat("[]", kHugeNesting) + "a");
  expect_too_deep(repeat("F", kHugeNesting) + "a");  // one split identifier
  expect_too_deep(repeat("a U ", kHugeNesting) + "a");
  expect_too_deep(repeat("a -> ", kHugeNesting) + "a");
  expect_too_deep(repeat("a xor ", kHugeNesting) + "a");  // left-assoc: deep on the left
  expect_too_deep(repeat("(a & ", kHugeNesting) + "a" + repeat(")", kHugeNesting));
  expect_too_deep(repeat("a & (", kHugeNesting) + "a" + repeat(")", kHugeNesting));
}

TEST(ParserTest, DepthLimitIsExact) {
  // The tree may be kMaxParseDepth levels high (a leaf is 1, each operator one more), and
  // parentheses may nest kMaxParseDepth deep.
  const std::size_t fits = kMaxParseDepth - 1;
  EXPECT_EQ(parsed(repeat("!", fits) + "a").size(), kMaxParseDepth);
  expect_too_deep(repeat("!", fits + 1) + "a");
  EXPECT_EQ(parsed(repeat("(", kMaxParseDepth) + "a" + repeat(")", kMaxParseDepth)), a);
  expect_too_deep(repeat("(", kMaxParseDepth + 1) + "a" + repeat(")", kMaxParseDepth + 1));
  EXPECT_EQ(parsed(repeat("a U ", fits) + "a").size(), 2 * fits + 1);
  expect_too_deep(repeat("a U ", fits + 1) + "a");
  EXPECT_EQ(parsed(repeat("a xor ", fits) + "a").size(), 2 * fits + 1);
  expect_too_deep(repeat("a xor ", fits + 1) + "a");
  // Every tree the parser accepts prints and reparses: the printer's parentheses nest less
  // deeply than the tree.
  const F deepest = parsed(repeat("!(a U ", fits / 2) + "a" + repeat(")", fits / 2));
  expect_reparses(deepest, "deepest");
  const F deepest_binary = parsed(repeat("a R ", fits) + "a");
  expect_reparses(deepest_binary, "deepest_binary");
}

TEST(ParserTest, HugeInputsAreLinear) {
  constexpr std::size_t kMegabyte = std::size_t{1} << 20;
  EXPECT_EQ(parsed(std::string(kMegabyte, 'q')), F::ap(std::string(kMegabyte, 'q')));
  expect_too_deep(std::string(kMegabyte, 'F') + "a");  // split letters are lexed once each
  expect_too_deep(std::string(kMegabyte, '('));
  try {
    parse("\"" + std::string(kMegabyte, 'q'));
    ADD_FAILURE() << "unterminated quote parsed";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.column(), kMegabyte + 2);
    EXPECT_EQ(e.expected(), "a closing '\"'");
  }
}

TEST(ParserTest, WideInputsAreFine) {
  constexpr std::size_t kWide = 100000;
  const F f = parsed(repeat("a & ", kWide - 1) + "a");
  EXPECT_EQ(f.op(), Op::And);
  EXPECT_EQ(f.arity(), kWide);
  const F g = parsed(repeat("(a) | ", kWide - 1) + "(a)");
  EXPECT_EQ(g.arity(), kWide);
}

// ---------------------------------------------------------------------------------------
// Fuzzing: every byte string parses or throws ParseError; what parses prints and reparses
// to an equal tree.

// Outcome of one fuzz input; anything but Parsed/Rejected is a test failure.
enum class Outcome { Parsed, Rejected, Other };

Outcome fuzz_one(const std::string& text) {
  F f;
  try {
    f = parse(text);
  } catch (const ParseError& e) {
    EXPECT_GE(e.line(), 1u);
    EXPECT_GE(e.column(), 1u);
    EXPECT_LE(e.column(), text.size() + 1);
    return Outcome::Rejected;
  } catch (...) {
    ADD_FAILURE() << "unexpected exception type for input '" << text << "'";
    return Outcome::Other;
  }
  expect_reparses(f, text);
  return Outcome::Parsed;
}

// Bytes that reach deep parser states more often than uniform bytes do.
const std::string kLtlBytes = "aFGXUVRWMxor()!~&|^-<>=[]/\\\"1 0\nmovegrasprelease,l1M2pq_";

char random_byte(Rng& rng) {
  constexpr double kUniformByteProbability = 0.3;
  constexpr std::uint64_t kByteValues = 256;
  if (rng.bernoulli(kUniformByteProbability)) {
    return static_cast<char>(rng.index(kByteValues));
  }
  return kLtlBytes[rng.index(kLtlBytes.size())];
}

TEST(ParserFuzzTest, RandomByteStrings) {
  constexpr std::uint64_t kSeed = 20240611;
  constexpr int kInputs = 20000;
  constexpr std::int64_t kMaxLength = 48;
  Rng rng(kSeed);
  int parsed_count = 0;
  for (int i = 0; i < kInputs; ++i) {
    std::string text(static_cast<std::size_t>(rng.uniform_int(0, kMaxLength)), '\0');
    for (char& ch : text) ch = random_byte(rng);
    const Outcome o = fuzz_one(text);
    ASSERT_NE(o, Outcome::Other);
    parsed_count += o == Outcome::Parsed;
  }
  EXPECT_GT(parsed_count, 0);  // the byte mix does reach successful parses
}

// Token sequences reach successful parses (and near misses) far more often than bytes do.
TEST(ParserFuzzTest, RandomTokenSequences) {
  const std::vector<std::string> tokens = {
      "a",      "p1",   "F1",    "GFa", "\"q r\"", "move(l1)", "release( M1 , l2 )",
      "grasp(", "(",    "(",     ")",   ")",       "!",        "~",
      "X",      "F",    "G",     "<>",  "[]",      "&",        "&&",
      "/\\",    "|",    "||",    "\\/", "^",       "xor",      "->",
      "=>",     "<->",  "<=>",   "U",   "V",       "R",        "W",
      "M",      "true", "false", "1",   "0"};
  const std::vector<std::string> blanks = {"", " ", "\n", "\t "};
  constexpr std::uint64_t kSeed = 4242;
  constexpr int kInputs = 10000;
  constexpr std::int64_t kMaxTokens = 16;
  Rng rng(kSeed);
  int parsed_count = 0;
  for (int i = 0; i < kInputs; ++i) {
    std::string text;
    const std::int64_t n = rng.uniform_int(1, kMaxTokens);
    for (std::int64_t k = 0; k < n; ++k) {
      text += tokens[rng.index(tokens.size())];
      text += blanks[rng.index(blanks.size())];
    }
    const Outcome o = fuzz_one(text);
    ASSERT_NE(o, Outcome::Other);
    parsed_count += o == Outcome::Parsed;
  }
  EXPECT_GT(parsed_count, kInputs / 100);
}

const std::vector<std::string> kValidCorpus = {
    "[]<>a && <>[]!b",
    "G(a -> F b) & (c U d)",
    "GFa | FGb xor X c",
    "a W b M c R d V e",
    "(a -> b) <-> !(c <=> d) => e",
    "a /\\ b \\/ ~c ^ d",
    "<>(grasp(M1) && <>(release(M1, l2) && <>(grasp(M2) && <>release(M2,l3))))",
    "[](move(l1) -> X !move(l2)) U true",
    "\"quoted name\" & \"F1\" | 1 & 0",
    "!(a U (b R (c W (d M e))))",
    "Fp1 & GFmove(l1) & XXtrue",
    "((((a))))",
};

TEST(ParserFuzzTest, MutationsOfValidFormulas) {
  constexpr std::uint64_t kSeed = 777;
  constexpr int kMutants = 20000;
  constexpr std::int64_t kMaxEdits = 4;
  Rng rng(kSeed);
  for (const std::string& text : kValidCorpus) ASSERT_EQ(fuzz_one(text), Outcome::Parsed) << text;
  int rejected = 0;
  for (int i = 0; i < kMutants; ++i) {
    std::string text = kValidCorpus[rng.index(kValidCorpus.size())];
    const std::int64_t edits = rng.uniform_int(1, kMaxEdits);
    for (std::int64_t e = 0; e < edits; ++e) {
      const std::size_t at = rng.index(text.size() + 1);
      switch (rng.index(3)) {
        case 0:  // insert
          text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), random_byte(rng));
          break;
        case 1:  // delete
          if (at < text.size()) text.erase(at, 1);
          break;
        default:  // replace
          if (at < text.size()) text[at] = random_byte(rng);
          break;
      }
    }
    const Outcome o = fuzz_one(text);
    ASSERT_NE(o, Outcome::Other);
    rejected += o == Outcome::Rejected;
  }
  EXPECT_GT(rejected, 0);
  EXPECT_LT(rejected, kMutants);
}

// ---------------------------------------------------------------------------------------
// Round trips: random trees printed in both syntaxes reparse to equal trees.

// Propositions the printer must quote or keep bare correctly.
const std::vector<std::string> kAps = {
    "a",   "b",   "p1",       "move(l1)", "grasp(M2)",    "release(M1,l2)", "F1",
    "GFa", "Xy",  "U",        "xor",      "true",         "TRUE",           "V1",
    "_x",  "a b", "1",        "move",     "release(F,G)", "a\nb",           "aUb",
    "F",   "Fa",  "move( l1)"};

struct FormulaGenerator {
  Rng rng;
  bool spin_safe;  // no W, M, xor (the Spin printer expands them)

  F leaf() {
    constexpr std::uint64_t kConstantOneIn = 8;
    const std::uint64_t r = rng.index(kConstantOneIn * 2);
    if (r == 0) return F::tt();
    if (r == 1) return F::ff();
    return F::ap(kAps[rng.index(kAps.size())]);
  }

  // A tree of about `budget` nodes.
  F operator()(std::size_t budget) {
    if (budget <= 1) return leaf();
    const std::vector<Op> unary = {Op::Not, Op::Next, Op::Eventually, Op::Always};
    std::vector<Op> binary = {Op::And,   Op::Or,      Op::Implies, Op::Equiv,
                              Op::Until, Op::Release, Op::And,     Op::Or};
    if (!spin_safe) {
      binary.insert(binary.end(), {Op::Xor, Op::WeakUntil, Op::StrongRelease});
    }
    constexpr double kUnaryProbability = 0.35;
    if (rng.bernoulli(kUnaryProbability)) {
      return F::make(unary[rng.index(unary.size())], {(*this)(budget - 1)});
    }
    const Op op = binary[rng.index(binary.size())];
    constexpr std::int64_t kMaxNaryArity = 4;
    const std::size_t arity = (op == Op::And || op == Op::Or)
                                  ? static_cast<std::size_t>(rng.uniform_int(2, kMaxNaryArity))
                                  : 2;
    std::vector<F> children;
    std::size_t left = budget - 1;
    for (std::size_t i = 0; i < arity; ++i) {
      const std::size_t share = std::max<std::size_t>(1, left / (arity - i));
      children.push_back((*this)(share));
      left = left > share ? left - share : 0;
    }
    return F::make(op, std::move(children));
  }
};

void round_trip(Syntax syntax, std::uint64_t seed, bool spin_safe) {
  constexpr int kFormulas = 3000;
  constexpr std::int64_t kMaxBudget = 25;
  FormulaGenerator gen{Rng(seed), spin_safe};
  for (int i = 0; i < kFormulas; ++i) {
    const F f = gen(static_cast<std::size_t>(gen.rng.uniform_int(1, kMaxBudget)));
    const std::string text = f.to_string(syntax);
    try {
      const F g = parse(text);
      ASSERT_EQ(g, f) << "printed '" << text << "' reparsed as '" << g.to_string(syntax) << "'";
    } catch (const ParseError& e) {
      FAIL() << "printed '" << text << "': " << e.what();
    }
  }
}

TEST(ParserRoundTripTest, SpotSyntax) { round_trip(Syntax::Spot, 11, /*spin_safe=*/false); }

TEST(ParserRoundTripTest, SpinSyntaxWithoutWMXor) {
  round_trip(Syntax::Spin, 12, /*spin_safe=*/true);
}

TEST(ParserRoundTripTest, SpinExpansionsReparse) {
  // The Spin printer rewrites W, M and xor (formula.cpp); the result is their expansion.
  // With operands of equal size the smaller-operand rule repeats a.
  expect_parse(F::weak_until(a, b).to_string(Syntax::Spin), F::disj(F::until(a, b), F::always(a)));
  expect_parse(F::strong_release(a, b).to_string(Syntax::Spin),
               F::conj(F::release(a, b), F::eventually(a)));
  const F ab = F::conj(a, b);
  expect_parse(F::weak_until(ab, c).to_string(Syntax::Spin), F::release(c, F::disj(ab, c)));
  expect_parse(F::strong_release(ab, c).to_string(Syntax::Spin), F::until(c, F::conj(ab, c)));
  expect_parse(F::lxor(a, b).to_string(Syntax::Spin), F::lnot(F::equiv(a, b)));
}

}  // namespace
}  // namespace rearm::ltl
