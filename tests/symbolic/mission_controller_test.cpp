// The mission controller on the paper's examples (docs/symbolic.md "What must be tested"),
// its failure handling, and its input checks. Random formulas are in mission_property_test.
#include "symbolic/mission_controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "ltl/parser.h"

namespace rearm::symbolic {
namespace {

struct Outcome {
  std::vector<std::string> actions;  // performed, in order
  MissionStatus status;
  std::string reason;
};

// Perfect executor: every action succeeds except `infeasible`; stops after `steps` actions,
// when the controller idles, or when it gives up.
Outcome execute(const std::string& formula, std::size_t steps,
                const std::vector<std::string>& infeasible = {}, MissionOptions options = {}) {
  MissionController mc(ltl::parse(formula), options);
  Outcome r;
  for (std::size_t k = 0; k < steps + infeasible.size();) {
    const auto a = mc.next_action();
    if (!a) break;
    bool bad = false;
    for (const auto& x : infeasible) bad = bad || a->to_string() == x;
    if (bad) {
      mc.report_infeasible(*a);
    } else {
      mc.report_success();
      r.actions.push_back(a->to_string());
      ++k;
    }
  }
  r.status = mc.status();
  r.reason = mc.reason();
  return r;
}

using Strings = std::vector<std::string>;

TEST(MissionController, PaperFormulaOneRearrangesThreeObjects) {
  const Outcome r = execute(
      "<>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && <>(release(M2,l3) && "
      "<>(grasp(M3) && <>release(M3,l1))))))",
      100);
  EXPECT_EQ(r.actions, (Strings{"grasp(M1)", "release(M1,l2)", "grasp(M2)", "release(M2,l3)",
                                "grasp(M3)", "release(M3,l1)"}));
  EXPECT_EQ(r.status, MissionStatus::Accepting);
}

TEST(MissionController, PaperFigureFourTask) {
  const Outcome r =
      execute("<>(move(l1) && <>(move(l2) && <>(grasp(M1) && <>release(M1,l3))))", 100);
  EXPECT_EQ(r.actions, (Strings{"move(l1)", "move(l2)", "grasp(M1)", "release(M1,l3)"}));
  EXPECT_EQ(r.status, MissionStatus::Accepting);
}

TEST(MissionController, EventuallyMoveIsOneActionThenIdle) {
  MissionController mc(ltl::parse("<>move(l1)"));
  const auto a = mc.next_action();
  ASSERT_TRUE(a);
  EXPECT_EQ(a->to_string(), "move(l1)");
  EXPECT_EQ(mc.next_action(), a) << "asking twice returns the pending action";
  mc.report_success();
  EXPECT_FALSE(mc.next_action());  // idles in the accepting self-loop
  EXPECT_EQ(mc.status(), MissionStatus::Accepting);
  EXPECT_FALSE(mc.next_action());
}

TEST(MissionController, PatrolVisitsBothRegionsForever) {
  const Outcome r = execute("[]<>move(l1) && []<>move(l2)", 40);
  ASSERT_EQ(r.actions.size(), 40u);
  for (std::size_t i = 1; i < r.actions.size(); ++i) {
    EXPECT_NE(r.actions[i], r.actions[i - 1]) << "the patrol alternates regions";
  }
  EXPECT_EQ(r.status, MissionStatus::Accepting);
}

TEST(MissionController, FourRegionPatrolCyclesThroughAll) {
  const Outcome r = execute("[]<>move(l1) && []<>move(l2) && []<>move(l3) && []<>move(l4)", 40);
  ASSERT_EQ(r.actions.size(), 40u);
  for (std::size_t i = 0; i + 4 <= r.actions.size(); i += 4) {
    Strings window(r.actions.begin() + i, r.actions.begin() + i + 4);
    std::sort(window.begin(), window.end());
    EXPECT_EQ(window, (Strings{"move(l1)", "move(l2)", "move(l3)", "move(l4)"}));
  }
}

TEST(MissionController, InitialSymbolIsTheFirstLetterOfTheWord) {
  // G(l1 | l2) fails at instant 0 when nothing holds, and holds forever from move(l2).
  EXPECT_EQ(execute("[](move(l1) || move(l2))", 10).status, MissionStatus::Infeasible);
  MissionOptions o;
  o.initial = Action::parse("move(l2)");
  const Outcome r = execute("[](move(l1) || move(l2))", 10, {}, o);
  EXPECT_TRUE(r.actions.empty());
  EXPECT_EQ(r.status, MissionStatus::Accepting);
  // A task already done by π0 needs nothing.
  o.initial = Action::parse("move(l1)");
  EXPECT_TRUE(execute("<>move(l1)", 10, {}, o).actions.empty());
}

TEST(MissionController, AnotherSymbolOfTheSameEdgeReplacesAnInfeasibleOne) {
  const Outcome r = execute("<>(move(l1) || move(l2))", 10, {"move(l1)"});
  EXPECT_EQ(r.actions, Strings{"move(l2)"});
  EXPECT_EQ(r.status, MissionStatus::Accepting);
}

TEST(MissionController, AnotherRouteReplacesAnInfeasibleAction) {
  // Grasping M1 from l1 is impossible: the task's other branch goes through l2.
  const Outcome r =
      execute("<>(move(l1) && <>grasp(M1)) || <>(move(l2) && <>grasp(M2))", 10, {"move(l1)"});
  EXPECT_EQ(r.actions, (Strings{"move(l2)", "grasp(M2)"}));
  EXPECT_EQ(r.status, MissionStatus::Accepting);
  // The failure arrives only after a first step: G and d_F are rebuilt from there.
  const Outcome s = execute(
      "<>(move(l3) && <>(move(l1) && <>grasp(M1))) || <>(move(l3) && <>(move(l2) && "
      "<>grasp(M2)))",
      10, {"move(l1)"});
  EXPECT_EQ(s.actions, (Strings{"move(l3)", "move(l2)", "grasp(M2)"}));
}

TEST(MissionController, InfeasibleMissionSaysWhy) {
  const Outcome r = execute("<>move(l1)", 10, {"move(l1)"});
  EXPECT_TRUE(r.actions.empty());
  EXPECT_EQ(r.status, MissionStatus::Infeasible);
  EXPECT_NE(r.reason.find("move(l1)"), std::string::npos) << r.reason;
  const Outcome p = execute("[]<>move(l1) && []<>move(l2)", 10, {"move(l2)"});
  EXPECT_EQ(p.status, MissionStatus::Infeasible);
  EXPECT_NE(p.reason.find("move(l2)"), std::string::npos) << p.reason;
}

TEST(MissionController, ReportsMustMatchThePendingAction) {
  MissionController mc(ltl::parse("<>move(l1)"));
  EXPECT_THROW(mc.report_success(), Error);
  ASSERT_TRUE(mc.next_action());
  EXPECT_THROW(mc.report_infeasible(Action::parse("move(l2)")), Error);
}

// π0 is the symbol of the first instant (Appendix I-B's q_aux edge): [](move(l1) || move(l2))
// holds on the word that holds move(l1) from the start and never does anything else, and on
// no word that starts with the empty symbol.
TEST(MissionController, InitialPredicateIsTheFirstSymbol) {
  const char* f = "[](move(l1) || move(l2))";
  MissionController without(ltl::parse(f));
  EXPECT_FALSE(without.next_action());
  EXPECT_EQ(without.status(), MissionStatus::Infeasible);
  MissionOptions o;
  o.initial = Action::parse("move(l1)");
  MissionController with(ltl::parse(f), o);
  EXPECT_FALSE(with.next_action());
  EXPECT_EQ(with.status(), MissionStatus::Accepting);
  const Outcome then_l2 = execute(std::string(f) + " && <>move(l2)", 5, {}, o);
  EXPECT_EQ(then_l2.actions, std::vector<std::string>{"move(l2)"});
  EXPECT_EQ(then_l2.status, MissionStatus::Accepting);
}

TEST(MissionController, RejectsFormulasOutsideTheFragment) {
  auto message = [](const std::string& f, const Vocabulary& v = {}, bool allow_negation = false) {
    try {
      MissionOptions o{std::nullopt, v, {}};
      o.allow_negation = allow_negation;
      MissionController mc(ltl::parse(f), o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("X move(l1)").find("X (next)"), std::string::npos);
  EXPECT_NE(message("<>(move(l1) && X grasp(M1))").find("X (next)"), std::string::npos);
  EXPECT_NE(message("<>p1").find("'p1' is not an action predicate"), std::string::npos);
  const Vocabulary v{{"M1"}, {"l1", "l2"}};
  EXPECT_NE(message("<>move(l7)", v).find("unknown region 'l7'"), std::string::npos);
  EXPECT_NE(message("<>release(M9,l1)", v).find("unknown object 'M9'"), std::string::npos);
  // The closest known name when one is near and unique (core/suggest.h): M11 -> M1; l7 is one
  // edit from both l1 and l2, so nothing is suggested.
  EXPECT_NE(message("<>release(M11,l1)", v).find("did you mean 'M1'?"), std::string::npos);
  EXPECT_EQ(message("<>move(l7)", v).find("did you mean"), std::string::npos);
  // The paper's fragment has no negation (Section II-B, footnote 4): every form is refused,
  // the implicit ones of ->, <-> and xor too, naming the paper's reason.
  for (const char* f :
       {"<>move(l1) && [](!grasp(M2))", "!move(l2) U move(l1)", "[](grasp(M1) -> <>move(l1))",
        "<>(move(l1) <-> move(l2))", "<>(move(l1) xor move(l2))", "!<>move(l1)"}) {
    const std::string m = message(f);
    EXPECT_NE(m.find("negation is not allowed"), std::string::npos) << f << ": " << m;
    EXPECT_NE(m.find("footnote 4"), std::string::npos) << f << ": " << m;
  }
  EXPECT_EQ(message("[]<>move(l1) && []<>(move(l2) || grasp(M1))"), "accepted");
  // allow_negation (symbolic planning only): negation over predicates is planned; over a
  // temporal subformula it is still refused.
  EXPECT_EQ(message("<>(move(l1) && !grasp(M1))", {}, true), "accepted");
  EXPECT_EQ(message("!move(l2) U move(l1)", v, true), "accepted");
  EXPECT_NE(message("!<>move(l1)", {}, true).find("negation over the temporal"), std::string::npos);
  EXPECT_NE(message("<>move(l1) -> <>move(l2)", {}, true).find("negation"), std::string::npos);
  EXPECT_NE(message("(<>move(l1)) <-> move(l2)", {}, true).find("negation"), std::string::npos);
}

TEST(MissionGraph, SelfLoopizationKeepsASymbolCyclingWithoutSelfLoops) {
  // q0 -a-> q1 -a-> q0, q1 accepting, no self-loops: a^ω is accepted, but the paper's G
  // needs a state with a self-loop under a and finds no edge. Self-loopized, holding a
  // cycles q1 -> q0 -> q1 through G.
  ltl::ActionNba nba;
  nba.alphabet = ltl::ActionAlphabet({"move(l1)"});
  nba.add_state(false);
  nba.add_state(true);
  nba.initial = {0};
  const ltl::LetterSet a = nba.alphabet.ap(0, true);
  nba.add_edge(0, 1, a);
  nba.add_edge(1, 0, a);
  const MissionGraph g(nba, MissionGraph::Start{{}, 1}, ltl::LetterSet(nba.alphabet.num_letters()));
  EXPECT_NE(g.d_f(g.start()), MissionGraph::kInfinity);
  // From the empty start the first action a is needed; then holding it is enough.
  const MissionGraph h(nba, MissionGraph::Start{{}, 0}, ltl::LetterSet(nba.alphabet.num_letters()));
  EXPECT_EQ(h.d_f(h.start()), MissionGraph::kInfinity) << "q0 cannot read the empty symbol";
}

TEST(Action, ParseAndPrint) {
  EXPECT_EQ(Action::parse("release( M1 , l2 )").to_string(), "release(M1,l2)");
  EXPECT_EQ(Action::parse("grasp(M3)").kind, ActionKind::Grasp);
  EXPECT_EQ(Action::parse("move(l1)").region, "l1");
  EXPECT_THROW(Action::parse("release(M1)"), Error);
  EXPECT_THROW(Action::parse("push(M1)"), Error);
  EXPECT_THROW(Action::parse(""), Error);
}

}  // namespace
}  // namespace rearm::symbolic
