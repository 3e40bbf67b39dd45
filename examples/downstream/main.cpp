// A downstream program against the installed rearm package: translates a scenario's task with
// rearm's LTL-to-Büchi translator, then runs the task in the Box2D world (the same closed loop
// as `rearm run`) and prints the outcome. Exit 0 when the task completed without a collision.
#include <cstdio>
#include <exception>

#include "experiment/run_scenario.h"
#include "ltl/parser.h"
#include "ltl/translate.h"
#include "scenario/scenario_io.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: downstream SCENARIO.yaml\n");
    return 2;
  }
  try {
    const rearm::scenario::Scenario s = rearm::scenario::load_scenario(argv[1]);
    const rearm::ltl::ActionNba nba = rearm::ltl::translate_actions(rearm::ltl::parse(s.task));
    std::printf("%s: task %s, %u automaton states\n", s.name.c_str(), s.task.c_str(),
                nba.num_states());
    const rearm::experiment::RunRecord r = rearm::experiment::run_scenario(s);
    const rearm::executive::TaskResult& t = r.result;
    std::printf("%s: %s (%s), %.2f s simulated, %d collisions\n", s.name.c_str(),
                rearm::executive::to_string(t.status), t.reason.c_str(), t.sim_time, t.collisions);
    return t.status == rearm::executive::TaskStatus::kCompleted && t.collisions == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "downstream: %s\n", e.what());
    return 2;
  }
}
