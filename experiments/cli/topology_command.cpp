// rearm topology SCENARIO.yaml [--to NAME|X,Y] [--carrying M] [--with-unknown] [--repeat K]
//                [--json FILE]
// The topology check of Appendix III on a scenario's scene, as the executive runs it when an
// action plans (paper §IV): does a path lead from x to x* among the fixed obstacles, and if the
// movable objects cut it, which (the stack B_M)? Prints the verdict, the blocking objects and
// the times of a cold call (nothing cached) and of warm ones (a TopologyCache that has seen the
// familiar obstacles, as in the executive's loop), and writes them as JSON with --json.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/suggest.h"
#include "core/text.h"
#include "ltl/formula.h"
#include "ltl/parser.h"
#include "options.h"
#include "scenario/scenario_io.h"
#include "symbolic/action.h"
#include "topology/topology_check.h"

namespace rearm::cli {
namespace {

using Json = nlohmann::ordered_json;
using geometry::Point;

constexpr const char* kFooter =
    "Runs the topology check of Appendix III (topology/topology_check.h) on the scene of\n"
    "SCENARIO.yaml: from the robot's start x to x*, with the familiar obstacles fixed (and the\n"
    "unknown ones with --with-unknown, as if mapped) and every movable object in the way; the\n"
    "paper's dilations (radius r, mitered familiar obstacles). --to: a region (x* its\n"
    "centroid) or a point X,Y; default the region of the task's first move or release.\n"
    "--carrying M: the robot-object pair (radius r + rho_M) at M's centre, M left out, as when\n"
    "M is gripped. Prints the verdict (reachable, blocked by objects, blocked by fixed\n"
    "obstacles), the blocking objects in B_M's order (the top, moved first, first) and the\n"
    "times: make_input and check_topology cold (nothing cached), then --repeat K warm calls\n"
    "(default 20; a TopologyCache that has seen the familiar obstacles): median and least.\n"
    "--json FILE writes the same. Exit: 0 a verdict, 1 the start not free (inside an\n"
    "obstacle's dilation), 2 bad usage or a bad scenario.";

constexpr int kMaxRepeat = 1000000;
constexpr int kMilliDigits = 4;  // significant digits of the printed times

struct TopologyArgs {
  std::string scenario, to, carrying, json;
  bool with_unknown = false;
  int repeat = 20;
};

// What the check runs on, resolved from the scenario and the flags.
struct Setup {
  std::vector<geometry::Polygon> fixed;
  std::vector<geometry::Disk> objects;
  std::vector<std::string> names;
  std::optional<std::size_t> carried;
  double radius = 0;
  Point x, target;
  std::string target_text;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string ms(double s) { return significant(s * 1e3, kMilliDigits) + " ms"; }

std::vector<std::string> region_names(const scenario::Scenario& s) {
  std::vector<std::string> out;
  for (const auto& r : s.regions) out.push_back(r.name);
  return out;
}

// The region of the task's first move(l) or release(M,l) (its propositions left to right), or
// "" when it has none.
std::string first_task_region(const std::string& task) {
  for (const std::string& p : ltl::parse(task).atomic_propositions()) {
    if (!ltl::is_action_predicate(p)) continue;
    const symbolic::Action action = symbolic::Action::parse(p);
    if (!action.region.empty()) return action.region;
  }
  return "";
}

// x* of --to (a region's centroid or X,Y), or of the task's first region.
void resolve_target(const scenario::Scenario& s, const std::string& to, Setup& u) {
  const std::string name = to.empty() ? first_task_region(s.task) : to;
  for (const auto& r : s.regions) {
    if (r.name != name) continue;
    u.target = r.polygon.centroid();
    u.target_text = "the centroid of " + name;
    return;
  }
  if (const std::optional<Point> p = parse_point("--to", to)) {
    u.target = *p;
    u.target_text = "the point";
    return;
  }
  if (to.empty()) throw Error("the task names no region: give x* with --to NAME|X,Y");
  throw Error("--to: '" + to + "' is neither a region of the scenario nor a point X,Y" +
              did_you_mean(to, region_names(s)));
}

Setup resolve(const scenario::Scenario& s, const TopologyArgs& a) {
  Setup u;
  for (const auto& f : s.familiar) u.fixed.push_back(f.polygon);
  if (a.with_unknown) {
    for (const auto& f : s.unknown) u.fixed.push_back(f.polygon);
  }
  for (const auto& o : s.objects) {
    u.objects.push_back(o.disk);
    u.names.push_back(o.name);
  }
  u.radius = s.robot.radius;
  u.x = s.robot.start;
  if (!a.carrying.empty()) {
    const auto it = std::find(u.names.begin(), u.names.end(), a.carrying);
    if (it == u.names.end()) {
      throw Error("--carrying: unknown object '" + a.carrying + "'" +
                  did_you_mean(a.carrying, u.names));
    }
    u.carried = static_cast<std::size_t>(it - u.names.begin());
    u.radius += u.objects[*u.carried].radius;
    u.x = u.objects[*u.carried].center;
  }
  resolve_target(s, a.to, u);
  return u;
}

// Cold and warm timings and the (cold) verdict.
struct Measured {
  topology::TopologyResult result;
  double input_cold = 0, check_cold = 0, input_warm = 0;
  std::vector<double> warm;  // check_topology with the cache, one per repeat
};

Measured measure(const scenario::Scenario& s, const Setup& u, int repeat) {
  Measured m;
  auto t0 = std::chrono::steady_clock::now();
  const topology::TopologyInput cold =
      topology::make_input(s.workspace, u.fixed, u.objects, u.radius, u.x, u.target, u.carried);
  m.input_cold = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  m.result = topology::check_topology(cold);
  m.check_cold = seconds_since(t0);
  topology::TopologyCache cache;
  const topology::TopologyInput first = topology::make_input(
      s.workspace, u.fixed, u.objects, u.radius, u.x, u.target, u.carried, cache);
  topology::check_topology(first, cache);  // primes bound − ∪fixed
  t0 = std::chrono::steady_clock::now();
  const topology::TopologyInput warm = topology::make_input(
      s.workspace, u.fixed, u.objects, u.radius, u.x, u.target, u.carried, cache);
  m.input_warm = seconds_since(t0);
  for (int k = 0; k < repeat; ++k) {
    t0 = std::chrono::steady_clock::now();
    topology::check_topology(warm, cache);
    m.warm.push_back(seconds_since(t0));
  }
  return m;
}

const char* verdict_text(topology::Verdict v) {
  switch (v) {
    case topology::Verdict::kReachable:
      return "reachable";
    case topology::Verdict::kBlockedByObjects:
      return "blocked by objects";
    case topology::Verdict::kBlockedByFixed:
      return "blocked by fixed obstacles";
  }
  return "?";
}

// B_M's names, the top (moved first) first.
std::vector<std::string> blocking_names(const Setup& u, const topology::TopologyResult& r) {
  std::vector<std::string> out;
  for (auto it = r.blocking.rbegin(); it != r.blocking.rend(); ++it) out.push_back(u.names[*it]);
  return out;
}

double least(const std::vector<double>& v) {
  return v.empty() ? 0 : *std::min_element(v.begin(), v.end());
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

Json report_json(const scenario::Scenario& s, const TopologyArgs& a, const Setup& u,
                 const Measured& m) {
  return Json{{"scenario", s.name},
              {"x", {u.x.x(), u.x.y()}},
              {"target", {u.target.x(), u.target.y()}},
              {"target_from", u.target_text},
              {"radius_m", u.radius},
              {"carrying", a.carrying},
              {"with_unknown", a.with_unknown},
              {"verdict", verdict_text(m.result.verdict)},
              {"blocking", blocking_names(u, m.result)},
              {"reason", m.result.reason},
              {"make_input_cold_s", m.input_cold},
              {"check_cold_s", m.check_cold},
              {"make_input_warm_s", m.input_warm},
              {"check_warm_median_s", median(m.warm)},
              {"check_warm_min_s", least(m.warm)},
              {"repeat", a.repeat}};
}

void print_report(const scenario::Scenario& s, const TopologyArgs& a, const Setup& u,
                  const Measured& m) {
  std::string head = s.name + ": x = (" + fixed(u.x.x(), 3) + ", " + fixed(u.x.y(), 3) +
                     "), x* = " + u.target_text + " (" + fixed(u.target.x(), 3) + ", " +
                     fixed(u.target.y(), 3) + "), radius " + fixed(u.radius, 3) + " m";
  if (!a.carrying.empty()) head += ", carrying " + a.carrying;
  std::string blocking;
  for (const std::string& b : blocking_names(u, m.result)) {
    blocking += (blocking.empty() ? "; blocking objects (the first moved first): " : ", ") + b;
  }
  std::printf("%s\nverdict: %s%s\nreason: %s\n", head.c_str(), verdict_text(m.result.verdict),
              blocking.c_str(), m.result.reason.c_str());
  std::printf(
      "make_input: %s cold, %s warm; check_topology: %s cold, %s warm (median of %d, "
      "least %s)\n",
      ms(m.input_cold).c_str(), ms(m.input_warm).c_str(), ms(m.check_cold).c_str(),
      ms(median(m.warm)).c_str(), a.repeat, ms(least(m.warm)).c_str());
}

int topology_run(const TopologyArgs& a) {
  const scenario::Scenario s = scenario::load_scenario(a.scenario);
  const Setup u = resolve(s, a);
  Measured m;
  try {
    m = measure(s, u, a.repeat);
  } catch (const topology::CenterNotFree& e) {
    std::fprintf(stderr, "rearm topology: %s\n", e.what());
    return kExitFailure;
  }
  print_report(s, a, u, m);
  if (!a.json.empty()) {
    write_file_atomically(a.json, report_json(s, a, u, m).dump(2) + "\n");
    std::printf("wrote %s\n", a.json.c_str());
  }
  return kExitOk;
}

}  // namespace

Command add_topology(CLI::App& program) {
  CLI::App* c = program.add_subcommand(
      "topology", "run the topology check of Appendix III on a scenario's scene and time it");
  c->footer(kFooter);
  auto a = std::make_shared<TopologyArgs>();
  add_scenario_file(*c, a->scenario);
  c->add_option("--to", a->to, "x*: a region's name or a point X,Y")->type_name("NAME|X,Y");
  c->add_option("--carrying", a->carrying, "the robot carries this object")->type_name("M");
  c->add_flag("--with-unknown", a->with_unknown, "the unknown obstacles count as mapped");
  c->add_option("--repeat", a->repeat, "warm calls timed (default 20)")
      ->check(CLI::Range(1, kMaxRepeat))
      ->type_name("K");
  c->add_option("--json", a->json, "also write the report as JSON")->type_name("FILE");
  return {c, [a] { return topology_run(*a); }};
}

}  // namespace rearm::cli
