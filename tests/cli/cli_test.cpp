// End-to-end tests of the `rearm` command line: help, output formats, exit codes and error
// messages for bad input. The HOA output is read back and checked against the formula's
// semantics with the independent lasso evaluator.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "ltl/automaton_io.h"
#include "ltl/parser.h"
#include "support/lasso.h"
#include "support/nba_oracle.h"

namespace {

struct Result {
  int code;
  std::string out;
};

// Runs the CLI with a shell-quoted argument string; captures stdout and stderr.
Result run(const std::string& args) {
  const std::string cmd = std::string(REARM_CLI_PATH) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr);
  Result r{-1, ""};
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

bool contains(const std::string& s, const std::string& x) { return s.find(x) != std::string::npos; }

TEST(CliTest, HelpForTheProgramAndEachCommand) {
  const Result top = run("--help");
  EXPECT_EQ(top.code, 0);
  EXPECT_TRUE(contains(top.out, "translate"));
  const Result tr = run("translate --help");
  EXPECT_EQ(tr.code, 0);
  EXPECT_TRUE(contains(tr.out, "--alphabet")) << tr.out;
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("frobnicate").code, 2);
}

TEST(CliTest, StatsAreKeyValueLines) {
  const Result r = run("translate --format stats 'F(p1 & F(p2 & F p3))'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "states: 4\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "edges: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "milliseconds: ")) << r.out;
}

TEST(CliTest, HoaOutputAcceptsExactlyTheFormulasWords) {
  const std::string formula = "G(p -> F q) & F r";
  const Result r = run("translate --format hoa '" + formula + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto a = rearm::ltl::read_hoa(r.out);
  const auto f = rearm::ltl::parse(formula);
  rearm::Rng rng(11);
  for (int i = 0; i < 500; ++i) {
    const auto w = rearm::test_support::random_lasso(rng, f.atomic_propositions());
    ASSERT_EQ(rearm::test_support::accepts(a, w), rearm::test_support::evaluate(f, w))
        << w.to_string();
  }
}

TEST(CliTest, OtherFormatsAndTheActionAlphabet) {
  const Result never = run("translate --format never '[]<>move(l1) && []<>move(l2)'");
  ASSERT_EQ(never.code, 0) << never.out;
  EXPECT_TRUE(contains(never.out, "never")) << never.out;
  const Result dot = run("translate --alphabet actions --format dot 'F grasp(M1)'");
  ASSERT_EQ(dot.code, 0) << dot.out;
  EXPECT_TRUE(contains(dot.out, "digraph")) << dot.out;
  const Result st = run("translate --alphabet actions --format stats 'GF p1 & GF p2 & GF p3'");
  EXPECT_TRUE(contains(st.out, "states: 4\n")) << st.out;
}

TEST(CliTest, BadInputGivesAClearErrorAndExitCode) {
  const Result parse_error = run("translate 'F (p &'");
  EXPECT_EQ(parse_error.code, 2);
  EXPECT_TRUE(contains(parse_error.out, "column")) << parse_error.out;
  const Result option = run("translate --format xml 'F p'");
  EXPECT_EQ(option.code, 2);
  EXPECT_TRUE(contains(option.out, "--format")) << option.out;
  const Result missing = run("translate");
  EXPECT_EQ(missing.code, 2);
  EXPECT_TRUE(contains(missing.out, "missing FORMULA")) << missing.out;
  const Result number = run("translate --max-states nan 'F p'");
  EXPECT_EQ(number.code, 2);
  const Result budget =
      run("translate --max-states 100 'F p1 & F p2 & F p3 & F p4 & F p5 & F p6 & F p7 & F p8'");
  EXPECT_EQ(budget.code, 1);
  EXPECT_TRUE(contains(budget.out, "budget")) << budget.out;
}

TEST(CliTest, PlanPrintsThePaperExamplesActionLassos) {
  const Result eq1 = run(
      "plan --formula '<>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && "
      "<>(release(M2,l3) && <>(grasp(M3) && <>release(M3,l1))))))'");
  ASSERT_EQ(eq1.code, 0) << eq1.out;
  EXPECT_EQ(eq1.out,
            "prefix: grasp(M1) release(M1,l2) grasp(M2) release(M2,l3) grasp(M3) "
            "release(M3,l1)\ncycle: idle\n");
  const Result fig4 =
      run("plan --formula '<>(move(l1) && <>(move(l2) && <>(grasp(M1) && <>release(M1,l3))))'");
  EXPECT_EQ(fig4.out, "prefix: move(l1) move(l2) grasp(M1) release(M1,l3)\ncycle: idle\n");
  EXPECT_EQ(run("plan --formula '<>move(l1)'").out, "prefix: move(l1)\ncycle: idle\n");
  const Result patrol = run("plan --formula '[]<>move(l1) && []<>move(l2)'");
  EXPECT_TRUE(contains(patrol.out, "cycle: move(l1) move(l2)\n") ||
              contains(patrol.out, "cycle: move(l2) move(l1)\n"))
      << patrol.out;
  EXPECT_EQ(run("plan --help").code, 0);
}

TEST(CliTest, PlanWithInfeasibleActions) {
  EXPECT_EQ(run("plan --formula '<>(move(l1) || move(l2))' --infeasible 'move(l1)'").out,
            "prefix: move(l2)\ncycle: idle\n");
  const Result r = run("plan --formula '<>move(l1)' --infeasible 'move(l1)'");
  EXPECT_EQ(r.code, 0);
  EXPECT_TRUE(contains(r.out, "infeasible: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "move(l1)")) << r.out;
}

TEST(CliTest, PlanRejectsBadInputWithAReason) {
  const Result x = run("plan --formula 'X move(l1)'");
  EXPECT_EQ(x.code, 2);
  EXPECT_TRUE(contains(x.out, "X (next)")) << x.out;
  const Result neg = run("plan --formula '!<>move(l1)'");
  EXPECT_EQ(neg.code, 2);
  EXPECT_TRUE(contains(neg.out, "negation")) << neg.out;
  const Result name = run("plan --formula '<>move(l9)' --regions l1,l2");
  EXPECT_EQ(name.code, 2);
  EXPECT_TRUE(contains(name.out, "unknown region 'l9'")) << name.out;
  const Result inf = run("plan --formula '<>grasp(M1)' --objects M1 --infeasible 'grasp(M7)'");
  EXPECT_EQ(inf.code, 2);
  EXPECT_TRUE(contains(inf.out, "unknown object 'M7'")) << inf.out;
  const Result ap = run("plan --formula '<>p1'");
  EXPECT_EQ(ap.code, 2);
  EXPECT_TRUE(contains(ap.out, "not an action predicate")) << ap.out;
  EXPECT_EQ(run("plan").code, 2);
}

}  // namespace
