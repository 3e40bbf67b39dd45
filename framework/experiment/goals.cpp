#include "experiment/goals.h"

#include <string>

#include "core/error.h"
#include "ltl/parser.h"
#include "scenario/scenario_io.h"
#include "symbolic/action.h"

namespace rearm::experiment {
namespace {

void collect_atoms(const ltl::Formula& f, std::vector<std::string>& atoms) {
  if (f.op() == ltl::Op::Ap) atoms.push_back(f.name());
  for (const auto& c : f.children()) collect_atoms(c, atoms);
}

}  // namespace

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
