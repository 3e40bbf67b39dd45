#include "baselines/run_baseline.h"

#include <chrono>
#include <cmath>

#include "baselines/validator.h"
#include "core/error.h"
#include "core/rng.h"
#include "experiment/json_writer.h"
#include "experiment/known_obstacles.h"
#include "experiment/run_scenario.h"
#include "experiment/task_from_scenario.h"
#include "experiment/trial_columns.h"
#include "sim/sim_config.h"
#include "sim/sim_world.h"

namespace rearm::baselines {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

PlanResult plan_with(Method m, const RearrangementProblem& p, const BaselineOptions& o,
                     double time_limit, std::uint64_t seed, long queries_used = 0) {
  PlannerOptions po;
  po.time_limit = time_limit;
  po.max_queries = o.query_limit == 0 ? 0 : std::max(1L, o.query_limit - queries_used);
  po.seed = seed;
  po.iterations_per_query = o.iterations_per_query;
  return m == Method::kMrs ? plan_mrs(p, o.params, po) : plan_birrt(p, o.params, po, o.birrt);
}

ExecutionOptions execution_options(const scenario::Scenario& s, const BaselineOptions& o) {
  ExecutionOptions e;
  e.record = o.record;
  e.time_budget = s.simulation.time_budget;
  e.dt = s.simulation.dt;
  return e;
}

void take_plan_stats(BaselineRecord& r, const PlanResult& p) {
  r.planning_time_s += p.planning_time_s;
  r.subqueries += p.subqueries;
  r.nodes += p.nodes;
  r.arrangement_nodes += p.arrangement_nodes;
  r.queries += p.queries;
  r.plan_status = p.status;
}

void set_status_from_plan(BaselineRecord& r, const PlanResult& p) {
  switch (p.status) {
    case PlanStatus::kSolved:
      break;
    case PlanStatus::kInfeasible:
      r.status = "infeasible";
      break;
    case PlanStatus::kUnsolved:
      r.status = "unsolved";
      break;
    case PlanStatus::kTimeout:
      r.status = "timeout";
      break;
  }
  r.reason = p.reason;
}

void set_status_from_execution(BaselineRecord& r, const RearrangementProblem& p) {
  const ExecutionLog& e = r.execution;
  if (e.status != ExecStatus::kCompleted) {
    r.status = e.status == ExecStatus::kTimeout ? "timeout" : "failed";
    r.reason = "execution: " + e.reason;
  } else if (!e.goals_reached || !e.robot_goal_reached) {
    r.status = "failed";
    r.reason = "execution ended with a goal missed (objects inside their regions: " +
               std::string(p.goals_reached(e.objects_end) ? "yes" : "no") + ")";
  } else {
    r.status = "completed";
    r.reason = "every object inside its goal region" +
               std::string(p.robot_goal ? ", the robot in its region" : "");
  }
}

// B1 / B2: plan offline on the full map, validate, execute.
void run_offline(const scenario::Scenario& s, const RearrangementProblem& p,
                 const BaselineOptions& o, BaselineRecord& r) {
  const PlanResult pr = plan_with(o.method, p, o, o.time_limit, o.seed);
  take_plan_stats(r, pr);
  set_status_from_plan(r, pr);
  if (pr.status != PlanStatus::kSolved) return;
  r.plan = pr.plan;
  r.violations = validate_plan(p, pr.plan, o.params);
  if (!r.violations.empty()) {
    r.status = "invalid_plan";
    r.reason = "the validator found " + std::to_string(r.violations.size()) +
               " violation(s); first: " + r.violations.front();
    return;
  }
  if (!o.execute) {
    r.status = "planned";
    r.reason = "not executed (--no-execute)";
    return;
  }
  r.execution = execute_plan(s, p, pr.plan, o.params, execution_options(s, o));
  r.executed = true;
  set_status_from_execution(r, p);
}

// Does a newly known obstacle meet what remains of the plan?
bool plan_invalidated(const std::vector<PlanExecutor::Sweep>& rest, const DiskWorld& known) {
  for (const auto& sw : rest) {
    if (sw.path.size() == 1 && !known.disk_free(sw.path[0], sw.radius, 0, {})) return true;
    for (std::size_t k = 0; k + 1 < sw.path.size(); ++k)
      if (!known.segment_free(sw.path[k], sw.path[k + 1], sw.radius, 0, {})) return true;
  }
  return false;
}

// The replanning variant (see the header).
// Continues the held object's interrupted transfer with one transfer query from the pair's
// centre, appending the move to `plan` and advancing `sub`; false, with the record's status
// set, when it cannot be continued.
bool continue_transfer(const RearrangementProblem& full, std::size_t i, const ObjectMove& move,
                       const sim::Pose& pose, double budget, std::uint64_t seed,
                       const BaselineOptions& o, RearrangementProblem& sub, Plan& plan,
                       BaselineRecord& r) {
  QueryContext ctx(budget, seed, o.query_limit == 0 ? 0 : std::max(1L, o.query_limit - r.queries));
  ctx.iterations_per_query = o.iterations_per_query;
  const MovePlanner mp(sub, o.params);
  const double ell = pair_offset(sub.object_radii[i], o.params);
  const Point p0 = pose.x + ell * heading_vector(pose.psi);
  const auto& region = full.goal_regions[i];
  const bool to_goal = region && geometry::contains(*region, move.to);
  MoveOutcome c =
      mp.transfer(sub.start, i, p0, pose.psi, move.to, to_goal ? region : std::nullopt, ctx);
  r.planning_time_s += ctx.elapsed();
  r.subqueries += ctx.subqueries;
  r.queries += ctx.queries;
  r.nodes += ctx.nodes;
  if (!c.move) {
    // A spent query budget is the deterministic limit (unsolved), not the wall clock.
    const bool clock = c.failure == MoveFailure::kTimeout && !ctx.out_of_queries();
    r.status = clock ? "timeout" : "unsolved";
    r.reason =
        std::string("replan: the held object's transfer cannot be continued: ") +
        (ctx.out_of_queries() ? "query limit of " + std::to_string(o.query_limit) + " reached"
                              : std::string(to_string(c.failure)));
    return false;
  }
  c.move->held_at_start = true;
  plan.moves.push_back(*c.move);
  sub.start[i] = c.move->to;
  sub.robot_start = c.robot_after;
  return true;
}

// Executes `plan`, checking its rest against what the sensor has revealed at every map change;
// true when a new obstacle invalidated it in a transit or a transfer (a dock or back-off runs to
// its end, at most a few cm), which is then interrupted (`current_move`: the move it was in).
bool execute_until_invalidated(PlanExecutor& exec, sim::SimWorld& world,
                               experiment::KnownObstacles& map, const geometry::Polygon& workspace,
                               const Plan& plan, std::optional<ObjectMove>& current_move) {
  exec.load(plan);
  bool pending = false;
  while (exec.tick()) {
    const bool changed = map.update(world.pose().x);
    if (!changed && !pending) continue;
    const auto rest = exec.remaining();
    if (rest.empty() || !plan_invalidated(rest, DiskWorld(workspace, map.polygons()))) {
      pending = false;
      continue;
    }
    const auto kind = rest.front().kind;
    if (kind == PlanExecutor::SweepKind::kTransit || kind == PlanExecutor::SweepKind::kTransfer ||
        kind == PlanExecutor::SweepKind::kFinalTransit) {
      const std::size_t mi = exec.move_index();
      current_move =
          mi < plan.moves.size() ? std::optional<ObjectMove>(plan.moves[mi]) : std::nullopt;
      exec.interrupt();
      return true;
    }
    pending = true;
  }
  return false;
}

void run_replanning(const scenario::Scenario& s, const RearrangementProblem& full,
                    const BaselineOptions& o, BaselineRecord& r) {
  sim::SimWorld world(s, sim::config_for(s));
  PlanExecutor exec(world, full, o.params, execution_options(s, o));
  experiment::KnownObstacles map(s);
  map.update(world.pose().x);
  r.executed = true;
  // A held object's interrupted move: its target and region, for the continuation.
  std::optional<ObjectMove> current_move;
  for (std::uint64_t round = 0;; ++round) {
    const double budget = o.time_limit - r.planning_time_s;
    if (budget <= 0) {
      r.status = "timeout";
      r.reason = "planning time limit of " + seconds_text(o.time_limit) + " reached after " +
                 std::to_string(r.replans) + " replans";
      break;
    }
    RearrangementProblem sub = full;
    sub.obstacles = map.polygons();
    sub.obstacle_names.clear();
    for (std::size_t i = 0; i < full.object_count(); ++i) sub.start[i] = world.object_center(i);
    const sim::Pose pose = world.pose();
    sub.robot_start = pose.x;
    sub.robot_heading = pose.psi;
    const std::uint64_t seed = Rng::derive(o.seed, round).next();
    const RearrangementProblem here = sub;  // the problem as it stands (for the validator)
    Plan plan;
    if (exec.held() && current_move &&
        !continue_transfer(full, *exec.held(), *current_move, pose, budget, seed, o, sub, plan,
                           r)) {
      break;
    }
    const double rest_budget = o.time_limit - r.planning_time_s;
    if (rest_budget <= 0) {
      r.status = "timeout";
      r.reason = "planning time limit reached";
      break;
    }
    if (o.query_limit > 0 && r.queries >= o.query_limit) {
      r.status = "unsolved";
      r.reason = "query limit of " + std::to_string(o.query_limit) + " reached after " +
                 std::to_string(r.replans) + " replans";
      break;
    }
    const PlanResult pr = plan_with(Method::kBirrt, sub, o, rest_budget, seed, r.queries);
    take_plan_stats(r, pr);
    if (pr.status != PlanStatus::kSolved) {
      set_status_from_plan(r, pr);
      break;
    }
    plan.moves.insert(plan.moves.end(), pr.plan.moves.begin(), pr.plan.moves.end());
    plan.final_transit = pr.plan.final_transit;
    plan.final_arrangement = pr.plan.final_arrangement;
    r.plan = plan;
    // Checked against the map known when it was made, from where the robot stands.
    const auto v = validate_plan(here, plan, o.params);
    r.violations.insert(r.violations.end(), v.begin(), v.end());
    if (!r.violations.empty()) {
      r.status = "invalid_plan";
      r.reason = "the validator found " + std::to_string(r.violations.size()) +
                 " violation(s); first: " + r.violations.front();
      break;
    }
    if (!execute_until_invalidated(exec, world, map, full.workspace, plan, current_move)) break;
    ++r.replans;
  }
  r.execution = exec.finish();
  if (r.status.empty()) set_status_from_execution(r, full);
}

void polygon(experiment::JsonWriter& j, const geometry::Polygon& p) {
  j.begin_array();
  for (const auto& v : p.vertices) j.begin_array().value(v.x()).value(v.y()).end_array();
  j.end_array();
}

}  // namespace

const char* to_string(Method m) {
  switch (m) {
    case Method::kMrs:
      return "mrs";
    case Method::kBirrt:
      return "birrt";
    case Method::kReplan:
      return "replan";
  }
  return "?";
}

Method method_from_string(const std::string& s) {
  if (s == "mrs") return Method::kMrs;
  if (s == "birrt") return Method::kBirrt;
  if (s == "replan") return Method::kReplan;
  throw Error("unknown baseline method '" + s + "' (expected mrs, birrt or replan)");
}

BaselineRecord run_baseline(const scenario::Scenario& s, const BaselineOptions& o) {
  if (!std::isfinite(o.time_limit) || o.time_limit <= 0)
    throw Error("baseline: the time limit must be a positive finite number of seconds");
  if (o.iterations_per_query < 1) throw Error("baseline: iterations per query must be >= 1");
  if (o.query_limit < 0) throw Error("baseline: the query limit must be >= 0");
  const Clock::time_point t0 = Clock::now();
  const RearrangementProblem p = problem_from_scenario(s);
  BaselineRecord r;
  r.scenario = s.name;
  r.method = o.method;
  r.seed = o.seed;
  r.time_limit = o.time_limit;
  if (o.method == Method::kReplan)
    run_replanning(s, p, o, r);
  else
    run_offline(s, p, o, r);
  r.wall_time_s = seconds_since(t0);
  return r;
}

std::string baseline_metrics_json(const scenario::Scenario& s, const BaselineRecord& r) {
  const ExecutionLog& e = r.execution;
  experiment::JsonWriter j(true);
  j.begin_object();
  j.key("scenario").value(s.name);
  j.key("source").value(s.source);
  j.key("plant").value("box2d");
  j.key("seed").value(r.seed);
  j.key("task").value(s.task);
  j.key("status").value(r.status);
  j.key("reason").value(r.reason);
  j.key("collisions").value(e.collisions);
  j.key("collision_events").begin_array();
  for (const std::string& c : e.collision_events) j.value(c);
  j.end_array();
  j.key("min_clearance").value(e.min_clearance);
  experiment::clearance_by_kind_json(j, e.clearance_by_kind);
  j.key("sim_time_s").value(e.sim_time);
  j.key("steps").value(static_cast<std::int64_t>(e.steps));
  j.key("dt_s").value(s.simulation.dt);
  j.key("wall_time_s").value(r.wall_time_s);
  // rearm's controller_time_s is its computation; the baselines' is their planning.
  j.key("controller_time_s").value(r.planning_time_s);
  j.key("real_time_factor").value(e.wall_time > 0 ? e.sim_time / e.wall_time : 0.0);
  j.key("fix_mode_entries").value(0);
  j.key("recoveries").begin_object();  // rearm's robust variant only
  for (const std::string& k : experiment::recovery_names()) j.key(k).value(0);
  j.end_object();
  j.key("robot_path_length_m").value(e.robot_path_length);
  j.key("object_path_length_m").value(e.object_path_length);
  j.key("rebuilds").value(0);
  j.key("topology_checks").value(0);
  j.key("actions").begin_array();
  for (const auto& a : e.actions) {
    j.begin_object();
    j.key("action").value(a.action);
    j.key("fix_mode").value(false);
    j.key("outcome").value(a.outcome);
    j.key("reason").value("");
    j.key("t_start_s").value(a.t_start);
    j.key("t_end_s").value(a.t_end);
    j.end_object();
  }
  j.end_array();
  j.key("objects").begin_array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    j.begin_object();
    j.key("name").value(s.objects[i].name);
    const auto& st = s.objects[i].disk.center;
    j.key("start").begin_array().value(st.x()).value(st.y()).end_array();
    const geometry::Point end = i < e.objects_end.size() ? e.objects_end[i] : st;
    j.key("end").begin_array().value(end.x()).value(end.y()).end_array();
    j.end_object();
  }
  j.end_array();
  j.key("method").value(to_string(r.method));
  j.key("time_limit_s").value(r.time_limit);
  j.key("plan_status").value(to_string(r.plan_status));
  j.key("planning_time_s").value(r.planning_time_s);
  j.key("subqueries").value(static_cast<std::int64_t>(r.subqueries));
  j.key("nodes").value(static_cast<std::int64_t>(r.nodes));
  j.key("arrangement_nodes").value(static_cast<std::int64_t>(r.arrangement_nodes));
  j.key("replans").value(r.replans);
  j.key("plan_moves").value(static_cast<std::int64_t>(r.plan.moves.size()));
  j.key("moves_executed").value(static_cast<std::int64_t>(e.moves_done));
  j.key("executed").value(r.executed);
  j.key("goals_reached").value(r.executed && e.goals_reached);
  j.key("violations").begin_array();
  for (const auto& v : r.violations) j.value(v);
  j.end_array();
  j.end_object();
  return j.str();
}

std::string baseline_trajectory_json(const scenario::Scenario& s, const BaselineRecord& r,
                                     int stride) {
  if (stride < 1) throw Error("trajectory: stride must be >= 1");
  const ExecutionLog& e = r.execution;
  experiment::JsonWriter j;
  j.begin_object();
  j.key("scenario").value(s.name);
  j.key("task").value(s.task);
  j.key("status").value(r.status);
  j.key("robot_radius").value(s.robot.radius);
  j.key("sensor_range").value(s.robot.sensor_range);
  j.key("workspace");
  polygon(j, s.workspace);
  j.key("familiar").begin_array();
  for (const auto& f : s.familiar) {
    j.begin_object().key("name").value(f.name).key("polygon");
    polygon(j, f.polygon);
    j.key("localized_at").value(0.0).end_object();
  }
  j.end_array();
  j.key("unknown").begin_array();
  for (const auto& u : s.unknown) {
    j.begin_object().key("name").value(u.name).key("polygon");
    polygon(j, u.polygon);
    j.end_object();
  }
  j.end_array();
  j.key("regions").begin_array();
  for (const auto& g : s.regions) {
    j.begin_object().key("name").value(g.name).key("polygon");
    polygon(j, g.polygon);
    j.end_object();
  }
  j.end_array();
  j.key("objects").begin_array();
  for (const auto& o : s.objects)
    j.begin_object().key("name").value(o.name).key("radius").value(o.disk.radius).end_object();
  j.end_array();
  j.key("dt").value(s.simulation.dt * stride);
  const auto st = static_cast<std::size_t>(stride);
  j.key("robot").begin_array();
  for (std::size_t k = 0; k < e.robot.size(); k += st)
    j.begin_array()
        .value(e.robot[k].x.x())
        .value(e.robot[k].x.y())
        .value(e.robot[k].psi)
        .end_array();
  j.end_array();
  j.key("object_paths").begin_array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    j.begin_array();
    for (std::size_t k = 0; k < e.objects.size(); k += st)
      j.begin_array().value(e.objects[k][i].x()).value(e.objects[k][i].y()).end_array();
    j.end_array();
  }
  j.end_array();
  j.key("actions").begin_array();
  for (const auto& a : e.actions) {
    j.begin_object().key("action").value(a.action).key("fix_mode").value(false);
    j.key("outcome").value(a.outcome);
    j.key("t_start").value(a.t_start).key("t_end").value(a.t_end).end_object();
  }
  j.end_array();
  j.end_object();
  return j.str();
}

}  // namespace rearm::baselines
