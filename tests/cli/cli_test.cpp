// End-to-end tests of the `rearm` command line: help, output formats, exit codes and error
// messages for bad input. The HOA output is read back and checked against the formula's
// semantics with the independent lasso evaluator.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
  const Result unknown = run("frobnicate");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_TRUE(contains(unknown.out, "rearm: unknown command 'frobnicate'")) << unknown.out;
  EXPECT_TRUE(contains(run("topolgy").out, "did you mean 'topology'?"));
  const Result version = run("--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_EQ(version.out.rfind("rearm 0.", 0), 0u) << version.out;
  EXPECT_TRUE(contains(version.out, "(revision ")) << version.out;
}

// Every command (and the sweep's subcommands) answers --help with exit 0 and its usage line,
// and an unknown option, an option without its value and a negative count with exit 2 and
// the same message shape: "rearm <command>: <what>" then "(try 'rearm <command> --help')".
TEST(CliTest, EveryCommandHasTheSameHelpAndErrorStyle) {
  const std::string fig3 = " experiments/scenarios/fig3.yaml";
  const std::vector<std::pair<std::string, std::string>> commands{
      {"translate", " 'F p'"},
      {"plan", " --formula '<>move(l1)'"},
      {"diffeo", fig3 + " --out /tmp/rearm-cli-unused"},
      {"run", fig3},
      {"baseline", fig3 + " --method birrt"},
      {"sweep", " experiments/sweeps/smoke.yaml --out /tmp/rearm-cli-unused"},
      {"sweep merge", " a b --out /tmp/rearm-cli-unused"},
      {"sweep report", " /tmp/rearm-cli-unused"},
      {"topology", fig3}};
  for (const auto& [name, valid] : commands) {
    const Result help = run(name + " --help");
    EXPECT_EQ(help.code, 0) << name;
    EXPECT_TRUE(contains(help.out, "Usage: rearm " + name)) << help.out;
    const std::string try_line = "(try 'rearm " + name + " --help')";
    const Result unknown = run(name + valid + " --frobnicate");
    EXPECT_EQ(unknown.code, 2) << name;
    EXPECT_EQ(unknown.out.rfind("rearm " + name + ": ", 0), 0u) << unknown.out;
    EXPECT_TRUE(contains(unknown.out, "--frobnicate")) << unknown.out;
    EXPECT_TRUE(contains(unknown.out, try_line)) << unknown.out;
  }
  for (const std::string& bad : {std::string("run") + fig3 + " --seed -3",
                                 std::string("run") + fig3 + " --seed 99999999999999999999",
                                 std::string("diffeo") + fig3 + " --out /tmp/x --seed",
                                 std::string("baseline") + fig3 + " --method mrs --seed 1.5"}) {
    const Result r = run(bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_TRUE(contains(r.out, "--seed")) << r.out;
  }
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
  EXPECT_TRUE(contains(missing.out, "FORMULA is required")) << missing.out;
  const Result number = run("translate --max-states nan 'F p'");
  EXPECT_EQ(number.code, 2);
  const Result budget =
      run("translate --max-states 100 'F p1 & F p2 & F p3 & F p4 & F p5 & F p6 & F p7 & F p8'");
  EXPECT_EQ(budget.code, 1);
  EXPECT_TRUE(contains(budget.out, "budget")) << budget.out;
}

TEST(CliTest, PlanPrintsThePaperExamplesActionLassos) {
  const Result eq1 =
      run("plan --formula '<>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && "
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

// Fig. 7 (Appendix I-B): the paper's G of []<>move(l1) && []<>move(l2) has d_F 2, 1, 0 along
// q_aux, the node before V_F and V_F's one node.
TEST(CliTest, PlanShowsThePapersGraph) {
  const Result r = run("plan --graph paper --show-graph --formula '[]<>move(l1) && []<>move(l2)'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "G (paper construction, Appendix I-B): 3 nodes")) << r.out;
  EXPECT_TRUE(contains(r.out, "node q_aux: d_F 2\n")) << r.out;
  EXPECT_TRUE(contains(r.out, ": d_F 1\n")) << r.out;
  EXPECT_TRUE(contains(r.out, ": d_F 0, in V_F\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "cycle: move(l1) move(l2)\n") ||
              contains(r.out, "cycle: move(l2) move(l1)\n"))
      << r.out;
  const Result bad = run("plan --graph spot --formula '<>move(l1)'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(contains(bad.out, "--graph: spot not in {paper,selfloop}")) << bad.out;
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
  // The paper's fragment has no negation (Section II-B, footnote 4); --allow-negation plans
  // negated predicates symbolically.
  const Result forbid = run("plan --formula '<>move(l1) && [](!grasp(M2))'");
  EXPECT_EQ(forbid.code, 2);
  EXPECT_TRUE(contains(forbid.out, "negation is not allowed")) << forbid.out;
  const Result allowed = run("plan --formula '<>move(l1) && [](!grasp(M2))' --allow-negation");
  EXPECT_EQ(allowed.code, 0) << allowed.out;
  EXPECT_EQ(allowed.out, "prefix: move(l1)\ncycle: idle\n");
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

// ---- rearm diffeo ----

std::string temp_dir() {
  std::string t = ::testing::TempDir() + "rearm_diffeo_XXXXXX";
  EXPECT_NE(mkdtemp(t.data()), nullptr);
  return t;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

using Json = nlohmann::json;

// The file's JSON document (strict RFC 8259); a failed expectation and a discarded value when it
// does not parse.
Json read_json(const std::string& path) {
  const std::string text = slurp(path);
  EXPECT_TRUE(Json::accept(text)) << path << " is not JSON";
  return Json::parse(text, nullptr, false);
}

// The nulls of j outside "lid" (the one key of diffeo.json that may be null): each one a
// non-finite number written.
int nulls_but_lids(const Json& j) {
  if (j.is_null()) return 1;
  int n = 0;
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) n += k == "lid" ? 0 : nulls_but_lids(v);
  } else if (j.is_array()) {
    for (const Json& v : j) n += nulls_but_lids(v);
  }
  return n;
}

// Whether every floating-point number of j has at most `digits` significant digits.
bool at_most_digits(const Json& j, int digits) {
  if (j.is_number_float()) {
    std::array<char, 32> buf;
    std::snprintf(buf.data(), buf.size(), "%.*g", digits, j.get<double>());
    return std::strtod(buf.data(), nullptr) == j.get<double>();
  }
  for (const Json& v : j) {
    if (v.is_structured() || v.is_number_float()) {
      if (!at_most_digits(v, digits)) return false;
    }
  }
  return true;
}

// The values of `key` over the objects of the array j.
std::vector<Json> column(const Json& j, const std::string& key) {
  std::vector<Json> out;
  for (const Json& o : j) out.push_back(o.value(key, Json()));
  return out;
}

bool has(const std::vector<Json>& values, const Json& x) {
  return std::find(values.begin(), values.end(), x) != values.end();
}

// The command looks for a python3 with matplotlib the same way.
bool have_python_modules(const std::string& imports) {
  const char* env = std::getenv("REARM_PYTHON");
  for (const std::string& py :
       {std::string(env ? env : ""), std::string("python3"), std::string("/usr/bin/python3")}) {
    if (py.empty()) continue;
    if (std::system(("'" + py + "' -c '" + imports + "' > /dev/null 2>&1").c_str()) == 0) {
      return true;
    }
  }
  return false;
}

TEST(CliTest, DiffeoWritesTheJsonAndThePlots) {
  const std::string dir = temp_dir();
  const Result r =
      run("diffeo experiments/scenarios/diffeo_demo.yaml --out " + dir + " --starts 2 --seed 5");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "paths: 3/3 reached the goal")) << r.out;
  const Json json = read_json(dir + "/diffeo.json");
  ASSERT_TRUE(json.is_object());
  for (const char* key : {"semantic", "mapped", "purges", "model", "grid", "paths"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_TRUE(json["mapped"].contains("enclosing"));
  EXPECT_TRUE(json["mapped"]["freespace"]["outer"].is_array());
  const std::vector<Json> kinds = column(json["purges"], "kind");
  EXPECT_TRUE(has(kinds, "boundary_root"));
  EXPECT_TRUE(has(kinds, "child"));
  EXPECT_TRUE(json["purges"][0].contains("collar"));
  EXPECT_FALSE(json["model"]["disks"].empty());
  EXPECT_FALSE(json["grid"].empty());
  ASSERT_EQ(json["paths"].size(), 3u);
  for (const Json& status : column(json["paths"], "status")) EXPECT_EQ(status, "reached");
  std::size_t lids = 0;
  for (const Json& lid : column(json["mapped"]["familiar"], "lid")) lids += lid.size() == 2;
  EXPECT_GE(lids, 1u) << "no familiar component with a lid";
  EXPECT_EQ(nulls_but_lids(json), 0) << "a non-finite number was written";
  EXPECT_TRUE(at_most_digits(json, 9)) << "diffeo.json keeps 9 significant digits";
  const bool plots = have_python_modules("import matplotlib");
  for (const char* png : {"semantic.png", "mapped.png", "model.png", "path.png"}) {
    EXPECT_EQ(std::filesystem::exists(dir + "/" + png), plots) << png;
  }
  if (!plots) {
    EXPECT_TRUE(contains(r.out, "warning")) << r.out;
  }

  const std::string dir2 = temp_dir();
  const Result h =
      run("diffeo experiments/scenarios/diffeo_simple.yaml --robot holonomic --no-plot "
          "--out " +
          dir2);
  ASSERT_EQ(h.code, 0) << h.out;
  EXPECT_EQ(read_json(dir2 + "/diffeo.json")["robot"]["model"], "holonomic");
  EXPECT_FALSE(std::filesystem::exists(dir2 + "/model.png"));
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(dir2);
}

TEST(CliTest, DiffeoUsage) {
  const Result help = run("diffeo --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_TRUE(contains(help.out, "--robot")) << help.out;
  EXPECT_TRUE(contains(run("--help").out, "diffeo"));
  const std::string scene = " experiments/scenarios/diffeo_simple.yaml";
  const Result no_out = run("diffeo" + scene);
  EXPECT_EQ(no_out.code, 2);
  EXPECT_TRUE(contains(no_out.out, "--out is required")) << no_out.out;
  const Result robot = run("diffeo" + scene + " --out /tmp/x --robot tank");
  EXPECT_EQ(robot.code, 2);
  EXPECT_TRUE(contains(robot.out, "--robot")) << robot.out;
  EXPECT_EQ(run("diffeo" + scene + " --out /tmp/x --starts -3").code, 2);
  const Result missing = run("diffeo no/such/scene.yaml --out /tmp/x");
  EXPECT_EQ(missing.code, 2);
  EXPECT_TRUE(contains(missing.out, "no/such/scene.yaml")) << missing.out;
}

TEST(CliTest, DiffeoRejectsBadScenesNamingTheProblem) {
  const std::string dir = temp_dir();
  // A valid scenario (diffeo_simple's room, l1 in the far corner), edited line by line.
  const std::string ws = "name: b\nworkspace: [[0,0],[10,0],[10,10],[0,10]]\n";
  const std::string robot = "robot: {radius: 0.2, start: [1,1]}\n";
  const std::string rest =
      "regions:\n  - {name: l1, polygon: [[8.5,8.5],[9.5,8.5],[9.5,9.5],[8.5,9.5]]}\n"
      "task: \"<>move(l1)\"\n";
  struct Case {
    std::string text, extra, message;  // message: expected in the output
  };
  const Case cases[] = {
      {ws + rest, "", "bad.yaml: robot: required key is missing"},
      {ws + "robot: {radius: 0.2, start: [nan,1]}\n" + rest, "",
       "robot.start[0]: must be a finite number, got 'nan' (line 3)"},
      {ws + robot + rest +
           "familiar:\n  - {name: P1, polygon: [[0.5,0.5],[2,0.5],[2,2],[0.5,2]]}\n",
       "", "robot.start: the robot's start disk (radius 0.2) overlaps familiar obstacle 'P1'"},
      {ws + robot + rest +
           "unknown:\n  - {name: C1, polygon: [[3,3],[6,3],[6,4],[4,4],[4,6],[3,6]]}\n",
       "", "unknown[0].polygon: unknown obstacles must be convex"},
      {ws + robot + rest + "controller: {p: 3}\n", "", "controller.p: must be an even integer"},
      {ws + robot + rest + "colour: 3\n", "", "colour: unknown key"},
      // The goal: the only region covered by an obstacle, an unknown name, a point outside F.
      {ws + robot + rest + "familiar:\n  - {name: P1, polygon: [[7,7],[10,7],[10,10],[7,10]]}\n",
       "", "no region has a point in the robot's freespace component"},
      {ws + robot + rest, " --goal l7", "--goal: 'l7' is neither a region of the scenario"},
      {ws + robot + rest, " --goal 1e300,5", "the goal is not in the robot's freespace component"},
      {ws + robot + rest, " --goal 1,nan", "--goal expects a finite decimal number, got 'nan'"},
  };
  for (const Case& c : cases) {
    const std::string file = dir + "/bad.yaml";
    std::ofstream(file) << c.text;
    const Result r = run("diffeo " + file + c.extra + " --no-plot --out " + dir + "/out");
    EXPECT_EQ(r.code, 2) << c.text << r.out;
    EXPECT_TRUE(contains(r.out, c.message)) << c.text << "\n--- got:\n" << r.out;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

TEST(CliTest, RunWritesMetricsFigureAndAnimation) {
  const std::string dir = temp_dir();
  const Result r = run("run experiments/scenarios/fig3.yaml --seed 3 --stride 20 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "fig3: completed")) << r.out;
  const Json metrics = read_json(dir + "/metrics.json");
  EXPECT_EQ(metrics["status"], "completed");
  EXPECT_EQ(metrics["seed"], 3);
  EXPECT_EQ(metrics["plant"], "box2d");
  EXPECT_EQ(metrics["collisions"], 0);
  EXPECT_GT(metrics["topology_checks"].get<int>(), 0);
  EXPECT_GT(metrics["topology_time_s"].get<double>(), 0);
  const std::vector<Json> actions = column(metrics["actions"], "action");
  const auto disassemble = std::find(actions.begin(), actions.end(), "disassemble(M1)");
  ASSERT_NE(disassemble, actions.end());
  EXPECT_EQ(metrics["actions"][disassemble - actions.begin()]["fix_mode"], true);
  const Json trajectory = read_json(dir + "/trajectory.json");
  EXPECT_EQ(trajectory["status"], "completed");
  EXPECT_FALSE(trajectory["robot"].empty());
  const bool plots = have_python_modules("import matplotlib; import PIL");
  EXPECT_EQ(std::filesystem::exists(dir + "/run.png"), plots);
  EXPECT_EQ(std::filesystem::exists(dir + "/run.gif"), plots);
  // --snapshots and --format reach the figure (run.py; its content: tests/plot/test_run_figure.py).
  const Result svg =
      run("run experiments/scenarios/fig3.yaml --no-animation --snapshots 2 "
          "--format svg --out " +
          dir + "/svg");
  ASSERT_EQ(svg.code, 0) << svg.out;
  EXPECT_EQ(std::filesystem::exists(dir + "/svg/run.svg"), plots);
  if (plots) {
    EXPECT_EQ(read_json(dir + "/svg/run_figure.json")["snapshots"], 2);
  }
  EXPECT_EQ(run("run experiments/scenarios/fig3.yaml --snapshots 0").code, 2);
  std::filesystem::remove_all(dir);
}

// rearm topology: Fig. 3 of the paper, where M1 cuts the robot off from l1 (§VI-A); the same
// scene with x* on the robot's side of M1 is reachable, and x* inside a familiar obstacle's
// dilation is cut off by fixed obstacles. Fig. 5's M1 carried (the pair at M1) toward l2 is
// blocked by M2, which sits in l2 (the paper's Fig. 5, Fix mode's first object).
TEST(CliTest, TopologyNamesTheBlockingObjectsAndTimesTheCheck) {
  const std::string dir = temp_dir();
  const Result r =
      run("topology experiments/scenarios/fig3.yaml --repeat 5 --json " + dir + "/t.json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out,
                       "verdict: blocked by objects; blocking objects (the first moved "
                       "first): M1"))
      << r.out;
  const Json j = read_json(dir + "/t.json");
  EXPECT_EQ(j["verdict"], "blocked by objects");
  EXPECT_EQ(j["blocking"], Json::array({"M1"}));
  EXPECT_EQ(j["repeat"], 5);
  EXPECT_GT(j["check_cold_s"].get<double>(), 0);
  EXPECT_GT(j["check_warm_median_s"].get<double>(), 0);
  EXPECT_GE(j["check_warm_median_s"].get<double>(), j["check_warm_min_s"].get<double>());
  const Result near = run("topology experiments/scenarios/fig3.yaml --to 2.5,3");
  EXPECT_EQ(near.code, 0) << near.out;
  EXPECT_TRUE(contains(near.out, "verdict: reachable")) << near.out;
  const Result wall = run("topology experiments/scenarios/fig3.yaml --to 5,1");  // inside P1
  EXPECT_EQ(wall.code, 0) << wall.out;
  EXPECT_TRUE(contains(wall.out, "verdict: blocked by fixed obstacles")) << wall.out;
  const Result carried = run("topology experiments/scenarios/fig5.yaml --carrying M1");
  EXPECT_TRUE(contains(carried.out, "blocking objects (the first moved first): M2")) << carried.out;
  const Result bad = run("topology experiments/scenarios/fig3.yaml --carrying M7");
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(contains(bad.out, "unknown object 'M7'")) << bad.out;
  const Result to = run("topology experiments/scenarios/fig3.yaml --to nowhere");
  EXPECT_EQ(to.code, 2);
  EXPECT_TRUE(contains(to.out, "neither a region of the scenario nor a point")) << to.out;
  std::filesystem::remove_all(dir);
}

TEST(CliTest, RunRejectsBadScenariosAndUsage) {
  const std::string dir = temp_dir();
  const std::string bad = dir + "/bad.yaml";
  std::ofstream(bad) << "name: bad\nworkspace: [[0,0],[4,0],[4,4],[0,4]]\n"
                        "robot: {radius: -0.2, start: [1, 1]}\ntask: \"<>move(l1)\"\n";
  const Result neg = run("run " + bad + " --out " + dir);
  EXPECT_EQ(neg.code, 2);
  EXPECT_TRUE(contains(neg.out, "bad.yaml")) << neg.out;
  EXPECT_TRUE(contains(neg.out, "robot.radius")) << neg.out;
  const std::string unknown_name = dir + "/unknown.yaml";
  std::ofstream(unknown_name) << "name: u\nworkspace: [[0,0],[4,0],[4,4],[0,4]]\n"
                                 "robot: {radius: 0.2, start: [1, 1]}\n"
                                 "regions:\n  - {name: l1, polygon: [[2,2],[3,2],[3,3],[2,3]]}\n"
                                 "task: \"<>move(l7)\"\n";
  const Result un = run("run " + unknown_name + " --out " + dir);
  EXPECT_EQ(un.code, 2);
  EXPECT_TRUE(contains(un.out, "task")) << un.out;
  EXPECT_TRUE(contains(un.out, "l7")) << un.out;
  EXPECT_EQ(run("run").code, 2);
  EXPECT_EQ(run("run experiments/scenarios/fig3.yaml --plant tank").code, 2);
  EXPECT_EQ(run("run experiments/scenarios/fig3.yaml --stride 0").code, 2);
  EXPECT_EQ(run("run experiments/scenarios/fig3.yaml --frobnicate").code, 2);
  const Result missing = run("run no/such.yaml");
  EXPECT_EQ(missing.code, 2);
  EXPECT_TRUE(contains(missing.out, "no/such.yaml")) << missing.out;
  EXPECT_TRUE(contains(run("run --help").out, "metrics.json"));
  std::filesystem::remove_all(dir);
}

TEST(CliTest, BaselineWritesMetricsWithRunsKeysAndThePlannersCounters) {
  const std::string dir = temp_dir();
  const Result r =
      run("baseline experiments/scenarios/fig5.yaml --method birrt --time-limit 30 "
          "--seed 4 --no-animation --out " +
          dir);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "fig5 (birrt): completed")) << r.out;
  const Json metrics = read_json(dir + "/metrics.json");
  // The keys of `rearm run`'s metrics.json, then the planners' own.
  for (const char* key : {"scenario",
                          "source",
                          "plant",
                          "task",
                          "reason",
                          "min_clearance",
                          "min_clearance_by_kind",
                          "sim_time_s",
                          "steps",
                          "dt_s",
                          "wall_time_s",
                          "controller_time_s",
                          "real_time_factor",
                          "fix_mode_entries",
                          "recoveries",
                          "robot_path_length_m",
                          "object_path_length_m",
                          "rebuilds",
                          "topology_checks",
                          "objects",
                          "planning_time_s",
                          "subqueries",
                          "nodes"}) {
    EXPECT_TRUE(metrics.contains(key)) << key;
  }
  EXPECT_EQ(metrics["seed"], 4);
  EXPECT_EQ(metrics["status"], "completed");
  EXPECT_EQ(metrics["collisions"], 0);
  EXPECT_EQ(metrics["method"], "birrt");
  EXPECT_TRUE(has(column(metrics["actions"], "action"), "release(M1,l2)"));
  EXPECT_EQ(read_json(dir + "/trajectory.json")["status"], "completed");
  EXPECT_EQ(std::filesystem::exists(dir + "/run.png"),
            have_python_modules("import matplotlib; import PIL"));
  // B1 cannot solve the cyclic shift and says why (exit 1: the method failed cleanly).
  const Result b1 =
      run("baseline experiments/scenarios/fig5.yaml --method mrs --no-plot --out " + dir + "/mrs");
  EXPECT_EQ(b1.code, 1) << b1.out;
  EXPECT_TRUE(contains(b1.out, "infeasible (non-monotone")) << b1.out;
  EXPECT_EQ(read_json(dir + "/mrs/metrics.json")["status"], "infeasible");
  std::filesystem::remove_all(dir);
}

TEST(CliTest, BaselineRejectsBadUsage) {
  EXPECT_EQ(run("baseline").code, 2);
  const Result no_method = run("baseline experiments/scenarios/fig5.yaml");
  EXPECT_EQ(no_method.code, 2);
  EXPECT_TRUE(contains(no_method.out, "--method")) << no_method.out;
  const Result bad_method = run("baseline experiments/scenarios/fig5.yaml --method prm");
  EXPECT_EQ(bad_method.code, 2);
  EXPECT_TRUE(contains(bad_method.out, "prm")) << bad_method.out;
  for (const char* limit : {"0", "-1", "nan", "inf", "1e999", "abc"})
    EXPECT_EQ(run(std::string("baseline experiments/scenarios/fig5.yaml --method mrs "
                              "--time-limit ") +
                  limit)
                  .code,
              2)
        << limit;
  EXPECT_EQ(run("baseline experiments/scenarios/fig5.yaml --method mrs --seed -3").code, 2);
  // A patrol is no rearrangement: the task key is named.
  const Result patrol = run("baseline experiments/scenarios/patrol.yaml --method birrt");
  EXPECT_EQ(patrol.code, 2);
  EXPECT_TRUE(contains(patrol.out, "task")) << patrol.out;
  EXPECT_TRUE(contains(run("baseline --help").out, "planning_time_s"));
}

TEST(CliTest, SweepRejectsBadUsageAndBadFilesWithTheKey) {
  EXPECT_EQ(run("sweep --help").code, 0);
  EXPECT_TRUE(contains(run("sweep --help").out, "--shard I/N"));
  EXPECT_EQ(run("sweep").code, 2);
  EXPECT_EQ(run("sweep experiments/sweeps/smoke.yaml").code, 2);  // no --out
  const std::string dir = temp_dir();
  EXPECT_EQ(run("sweep experiments/sweeps/smoke.yaml --out " + dir + " --shard 3/3").code, 2);
  EXPECT_EQ(run("sweep experiments/sweeps/smoke.yaml --out " + dir + " --threads 0").code, 2);
  EXPECT_EQ(run("sweep experiments/sweeps/smoke.yaml --out " + dir + " --frobnicate").code, 2);
  {
    std::ofstream bad(dir + "/bad.yaml");
    bad << "name: bad\nmethods: [rearm, rrtstar]\nclasses: [random]\nobjects: [1]\n"
           "densities: [0.1]\nworkspace: {side: 8}\n";
  }
  const Result unknown = run("sweep " + dir + "/bad.yaml --out " + dir + "/out");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_TRUE(contains(unknown.out, "methods[1]: unknown method 'rrtstar'")) << unknown.out;
  const Result missing = run("sweep /nonexistent.yaml --out " + dir + "/out");
  EXPECT_EQ(missing.code, 2);
  EXPECT_TRUE(contains(missing.out, "/nonexistent.yaml: file: cannot read")) << missing.out;
  EXPECT_EQ(run("sweep merge --out " + dir + "/m").code, 2);
  EXPECT_EQ(run("sweep merge /nonexistent --out " + dir + "/m").code, 2);
  EXPECT_EQ(run("sweep report /nonexistent").code, 2);
  std::filesystem::remove_all(dir);
}

// A cell the generator cannot give its target obstacle density is refused before any trial
// runs (exit 2, the cell and the reason named, no row written); with `refused_cells: skip` the
// other cells run and DIR/cells.csv lists the verdicts.
TEST(CliTest, SweepRefusesCellsThatMissTheirObstacleDensity) {
  const std::string dir = temp_dir();
  const std::string cells =
      "methods: [mrs]\nclasses: [random]\nobjects: [1]\ndensities: [0.05, 0.45]\n"
      "workspace: {side: 5}\nseeds: 2\ntime_limit: 5\nquery_limit: 2000\n"
      "instance: {max_attempts: 100}\n";
  {
    std::ofstream f(dir + "/refuse.yaml");
    f << "name: refuse\n" << cells;
    std::ofstream g(dir + "/skip.yaml");
    g << "name: skip\nrefused_cells: skip\n" << cells;
  }
  const Result refused = run("sweep " + dir + "/refuse.yaml --quiet --out " + dir + "/r");
  EXPECT_EQ(refused.code, 2) << refused.out;
  EXPECT_TRUE(contains(refused.out, "random_n1_d0.45_side5_u0.5_round: instance r")) << refused.out;
  EXPECT_TRUE(contains(refused.out, "target 0.450")) << refused.out;
  EXPECT_FALSE(contains(refused.out, "random_n1_d0.05_side5")) << refused.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r/trials.csv"));
  // --check-cells: the verdicts only, whatever refused_cells says.
  const Result checked =
      run("sweep " + dir + "/refuse.yaml --quiet --check-cells --out " + dir + "/c");
  EXPECT_EQ(checked.code, 0) << checked.out;
  EXPECT_TRUE(contains(checked.out, "1 of 2 cells refused")) << checked.out;
  EXPECT_TRUE(contains(slurp(dir + "/c/cells.csv"), "1,random_n1_d0.45_side5_u0.5_round,refused,"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/c/trials.csv"));
  const Result skipped = run("sweep " + dir + "/skip.yaml --quiet --out " + dir + "/s");
  EXPECT_EQ(skipped.code, 0) << skipped.out;
  EXPECT_TRUE(contains(skipped.out, "skipping refused cells")) << skipped.out;
  const std::string csv = slurp(dir + "/s/trials.csv");
  EXPECT_TRUE(contains(csv, "random_n1_d0.05_side5_u0.5_round_r1")) << csv;
  EXPECT_FALSE(contains(csv, "_d0.45_")) << csv;
  const std::string verdicts = slurp(dir + "/s/cells.csv");
  EXPECT_TRUE(contains(verdicts, "0,random_n1_d0.05_side5_u0.5_round,accepted,")) << verdicts;
  EXPECT_TRUE(contains(verdicts, "1,random_n1_d0.45_side5_u0.5_round,refused,")) << verdicts;
  // A malformed verdict file stops the merge with the file, the line and the field named.
  {
    std::ofstream f(dir + "/s/cells.csv", std::ios::app);
    f << "x1,not_a_cell,accepted,\n";
  }
  const Result merged = run("sweep merge " + dir + "/s --out " + dir + "/m");
  EXPECT_NE(merged.code, 0) << merged.out;
  EXPECT_TRUE(contains(merged.out, "cells.csv line 4: 'x1' is not a cell index")) << merged.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
