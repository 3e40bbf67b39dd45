#include "experiment/scenario_task.h"

#include <string>

#include "geometry/polygon.h"
#include "ltl/parser.h"
#include "scenario/scenario_io.h"
#include "symbolic/mission_controller.h"

namespace rearm::experiment {

namespace {

const scenario::NamedPolygon* find_region(const scenario::Scenario& s, const std::string& name) {
  for (const auto& r : s.regions) {
    if (r.name == name) return &r;
  }
  return nullptr;
}

// π0 must be true of the scene at the start: the robot inside the region it claims to be in,
// the object inside the region it claims to have been released in; the gripper starts open.
symbolic::Action initial_action(const scenario::Scenario& s, const symbolic::Vocabulary& v) {
  const symbolic::Action a = symbolic::Action::parse(s.initial_predicate);
  v.check(a);
  const scenario::NamedPolygon* region = a.region.empty() ? nullptr : find_region(s, a.region);
  switch (a.kind) {
    case symbolic::ActionKind::Grasp:
      throw Error("'" + s.initial_predicate +
                  "' cannot hold at the start: the robot starts with its gripper open");
    case symbolic::ActionKind::Move:
      if (!geometry::contains(region->polygon, s.robot.start)) {
        throw Error("'" + s.initial_predicate + "' does not hold at the start: the robot's start " +
                    "is not inside region " + a.region);
      }
      return a;
    case symbolic::ActionKind::Release:
      for (const auto& o : s.objects) {
        if (o.name == a.object && !geometry::contains(region->polygon, o.disk.center)) {
          throw Error("'" + s.initial_predicate + "' does not hold at the start: " + a.object +
                      " does not start inside region " + a.region);
        }
      }
      return a;
  }
  return a;
}

}  // namespace

ScenarioTask parse_task(const scenario::Scenario& s) {
  symbolic::Vocabulary v;
  for (const auto& o : s.objects) v.objects.push_back(o.name);
  for (const auto& r : s.regions) v.regions.push_back(r.name);
  const std::string where = s.source.empty() ? s.name : s.source;
  ScenarioTask t;
  try {
    t.formula = ltl::parse(s.task);
    symbolic::check_mission_formula(t.formula, v);
  } catch (const scenario::ScenarioError&) {
    throw;
  } catch (const Error& e) {
    throw scenario::ScenarioError(where, "task", e.what());
  }
  if (s.initial_predicate.empty()) return t;
  try {
    t.initial = initial_action(s, v);
  } catch (const Error& e) {
    throw scenario::ScenarioError(where, "initial_predicate", e.what());
  }
  return t;
}

void check_task(const scenario::Scenario& s) { (void)parse_task(s); }

}  // namespace rearm::experiment
