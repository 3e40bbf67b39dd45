#include "experiment/goals.h"

#include <string>

#include "core/error.h"
#include "executive/region.h"
#include "ltl/parser.h"
#include "scenario/scenario_io.h"
#include "symbolic/action.h"

namespace rearm::experiment {
namespace {

void collect_atoms(const ltl::Formula& f, std::vector<std::string>& atoms) {
  if (f.op() == ltl::Op::Ap) atoms.push_back(f.name());
  for (const auto& c : f.children()) collect_atoms(c, atoms);
}

// The action atoms of a reachability formula (atoms, && and <>); throws rearm::Error naming the
// first other operator.
void reachability_atoms(const ltl::Formula& f, std::vector<std::string>& atoms) {
  switch (f.op()) {
    case ltl::Op::Ap:
      atoms.push_back(f.name());
      return;
    case ltl::Op::True:
      return;
    case ltl::Op::And:
    case ltl::Op::Eventually:
      for (const auto& c : f.children()) reachability_atoms(c, atoms);
      return;
    default:
      throw Error(
          "the baselines plan reachability tasks only (action atoms joined by && and <>); "
          "found '" +
          f.to_string(ltl::Syntax::Spin) + "'");
  }
}

// The index of `name` among `items` (by .name); throws ScenarioError naming `what`.
template <typename T>
std::size_t index_of(const std::vector<T>& items, const std::string& name, const char* what,
                     const std::string& source) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return i;
  }
  throw scenario::ScenarioError(source, "task", std::string("unknown ") + what + " '" + name + "'");
}

// Records region j as the goal `slot` of `who`, refusing a second, different one.
void set_goal(std::optional<std::size_t>& slot, std::size_t j, const scenario::Scenario& s,
              const std::string& who, const std::string& source) {
  if (slot && *slot != j) {
    throw scenario::ScenarioError(source, "task",
                                  who + " goes to two regions ('" + s.regions[*slot].name +
                                      "' and '" + s.regions[j].name +
                                      "'); a rearrangement has one goal region each");
  }
  slot = j;
}

}  // namespace

ReachabilityGoals reachability_goals(const scenario::Scenario& s) {
  const std::string source = s.source.empty() ? s.name : s.source;
  std::vector<std::string> atoms;
  try {
    reachability_atoms(ltl::parse(s.task), atoms);
  } catch (const scenario::ScenarioError&) {
    throw;
  } catch (const Error& e) {
    throw scenario::ScenarioError(source, "task", e.what());
  }
  ReachabilityGoals g;
  g.object_region.assign(s.objects.size(), std::nullopt);
  g.object_target.assign(s.objects.size(), std::nullopt);
  for (const std::string& text : atoms) {
    symbolic::Action a;
    try {
      a = symbolic::Action::parse(text);
    } catch (const Error& e) {
      throw scenario::ScenarioError(source, "task", e.what());
    }
    if (a.kind == symbolic::ActionKind::Move) {
      set_goal(g.robot_region, index_of(s.regions, a.region, "region", source), s, "the robot",
               source);
      continue;
    }
    const std::size_t i = index_of(s.objects, a.object, "object", source);
    if (a.kind != symbolic::ActionKind::Release) continue;  // grasp(M): implied by release(M, l)
    set_goal(g.object_region[i], index_of(s.regions, a.region, "region", source), s,
             "object '" + a.object + "'", source);
  }
  auto target = [&](std::size_t j) {
    return executive::region_target({s.regions[j].name, s.regions[j].polygon});
  };
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    if (g.object_region[i]) g.object_target[i] = target(*g.object_region[i]);
  }
  if (g.robot_region) g.robot_target = target(*g.robot_region);
  return g;
}

std::vector<std::optional<std::size_t>> goal_regions(const scenario::Scenario& s) {
  const std::string source = s.source.empty() ? s.name : s.source;
  std::vector<std::string> atoms;
  try {
    collect_atoms(ltl::parse(s.task), atoms);
  } catch (const Error& e) {
    throw scenario::ScenarioError(source, "task", e.what());
  }
  const std::size_t none = s.regions.size();
  std::vector<std::size_t> goal(s.objects.size(), none);
  std::vector<bool> ambiguous(s.objects.size(), false);
  for (const std::string& text : atoms) {
    symbolic::Action a;
    try {
      a = symbolic::Action::parse(text);
    } catch (const Error&) {
      continue;  // not an action atom: check_task reports it where it matters
    }
    if (a.kind != symbolic::ActionKind::Release) continue;
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      if (s.objects[i].name != a.object) continue;
      for (std::size_t j = 0; j < s.regions.size(); ++j) {
        if (s.regions[j].name != a.region) continue;
        if (goal[i] != none && goal[i] != j) ambiguous[i] = true;
        goal[i] = j;
      }
    }
  }
  std::vector<std::optional<std::size_t>> out(s.objects.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (goal[i] != none && !ambiguous[i]) out[i] = goal[i];
  }
  return out;
}

bool goals_reached(const scenario::Scenario& s, const std::vector<geometry::Point>& end) {
  if (end.size() != s.objects.size()) return false;
  const auto goals = goal_regions(s);
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (goals[i] && !geometry::contains(s.regions[*goals[i]].polygon, end[i])) return false;
  }
  return true;
}

}  // namespace rearm::experiment
