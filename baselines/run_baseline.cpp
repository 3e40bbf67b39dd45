#include "baselines/run_baseline.h"

#include <chrono>
#include <cmath>

#include "baselines/validator.h"
#include "core/error.h"
#include "core/rng.h"
#include "experiment/json_internal.h"
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
  switch (m) {
    case Method::kMrs:
      return plan_mrs(p, o.params, po);
    case Method::kBuffer:
      return plan_buffer(p, o.params, po, o.buffer);
    case Method::kBufferStrict: {
      BufferOptions b = o.buffer;
      b.lifetime_spots = false;
      return plan_buffer(p, o.params, po, b);
    }
    case Method::kFmrs:
      return plan_fmrs(p, o.params, po, o.fmrs);
    case Method::kBirrtFmrs: {
      BirrtOptions b = o.birrt;
      b.extension = BirrtOptions::Extension::kFmrs;
      b.fmrs = o.fmrs;
      return plan_birrt(p, o.params, po, b);
    }
    case Method::kBirrt:
    case Method::kReplan:
      break;
  }
  return plan_birrt(p, o.params, po, o.birrt);
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
  r.planning_wall_s += p.planning_wall_s;
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
      r.status = p.wall_net ? "timeout_wall" : "timeout";
      break;
  }
  r.reason = p.reason;
  if (p.wall_net) {
    r.reason += " (cut by the wall-clock safety net with CPU budget left: the machine was loaded)";
  }
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
  r.first_action_time_s = r.planning_time_s;
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
  r.planning_wall_s += ctx.wall_elapsed();
  r.subqueries += ctx.subqueries;
  r.queries += ctx.queries;
  r.nodes += ctx.nodes;
  if (!c.move) {
    // A spent query budget is the deterministic limit (unsolved), not the wall clock.
    const bool clock = c.failure == MoveFailure::kTimeout && !ctx.out_of_queries();
    r.status = !clock ? "unsolved" : ctx.cut_by_wall() ? "timeout_wall" : "timeout";
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
    if (std::isnan(r.first_action_time_s)) r.first_action_time_s = r.planning_time_s;
    if (!execute_until_invalidated(exec, world, map, full.workspace, plan, current_move)) break;
    ++r.replans;
  }
  r.execution = exec.finish();
  if (r.status.empty()) set_status_from_execution(r, full);
}

// The pieces of rearm run's files (experiment/json_internal.h): the same key order and numbers.
using experiment::json::Json;
using experiment::json::kIndent;
using experiment::json::named_polygons;
using experiment::json::point;
using experiment::json::polygon;
using experiment::json::text;

}  // namespace

const char* to_string(Method m) {
  switch (m) {
    case Method::kMrs:
      return "mrs";
    case Method::kBirrt:
      return "birrt";
    case Method::kReplan:
      return "replan";
    case Method::kBuffer:
      return "buffer";
    case Method::kFmrs:
      return "fmrs";
    case Method::kBirrtFmrs:
      return "birrt-fmrs";
    case Method::kBufferStrict:
      return "buffer-strict";
  }
  return "?";
}

Method method_from_string(const std::string& s) {
  if (s == "mrs") return Method::kMrs;
  if (s == "birrt") return Method::kBirrt;
  if (s == "replan") return Method::kReplan;
  if (s == "buffer") return Method::kBuffer;
  if (s == "fmrs") return Method::kFmrs;
  if (s == "birrt-fmrs") return Method::kBirrtFmrs;
  if (s == "buffer-strict") return Method::kBufferStrict;
  throw Error("unknown baseline method '" + s +
              "' (expected mrs, birrt, replan, buffer, fmrs, birrt-fmrs or buffer-strict)");
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

namespace {

// "actions" and "objects" of metrics.json, in the layout of rearm run's.
Json actions_json(const ExecutionLog& e) {
  Json a = Json::array();
  for (const auto& r : e.actions) {
    a.push_back({{"action", r.action},
                 {"fix_mode", false},
                 {"outcome", r.outcome},
                 {"reason", ""},
                 {"t_start_s", r.t_start},
                 {"t_end_s", r.t_end}});
  }
  return a;
}

Json objects_json(const scenario::Scenario& s, const ExecutionLog& e) {
  Json a = Json::array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const geometry::Point start = s.objects[i].disk.center;
    const geometry::Point end = i < e.objects_end.size() ? e.objects_end[i] : start;
    a.push_back({{"name", s.objects[i].name}, {"start", point(start)}, {"end", point(end)}});
  }
  return a;
}

// The keys every metrics.json has (those of rearm run's, experiment::metrics_json).
Json common_metrics(const scenario::Scenario& s, const BaselineRecord& r) {
  const ExecutionLog& e = r.execution;
  Json recoveries = Json::object();
  for (const std::string& k : experiment::recovery_names()) recoveries[k] = 0;  // rearm's only
  return {{"scenario", s.name},
          {"source", s.source},
          {"plant", "box2d"},
          {"seed", r.seed},
          {"task", s.task},
          {"status", r.status},
          {"reason", r.reason},
          {"collisions", e.collisions},
          {"collision_events", e.collision_events},
          {"min_clearance", e.min_clearance},
          {"min_clearance_by_kind", experiment::json::clearance_by_kind(e.clearance_by_kind)},
          {"sim_time_s", e.sim_time},
          {"steps", e.steps},
          {"dt_s", s.simulation.dt},
          {"wall_time_s", r.wall_time_s},
          // rearm's controller_time_s is its computation; the baselines' is their planning.
          {"controller_time_s", r.planning_time_s},
          {"first_action_time_s", r.first_action_time_s},
          {"real_time_factor", e.wall_time > 0 ? e.sim_time / e.wall_time : 0.0},
          {"fix_mode_entries", 0},
          {"recoveries", recoveries},
          {"robot_path_length_m", e.robot_path_length},
          {"object_path_length_m", e.object_path_length},
          {"rebuilds", 0},
          {"topology_checks", 0},
          {"topology_time_s", 0.0},
          {"actions", actions_json(e)},
          {"objects", objects_json(s, e)}};
}

}  // namespace

std::string baseline_metrics_json(const scenario::Scenario& s, const BaselineRecord& r) {
  const ExecutionLog& e = r.execution;
  Json j = common_metrics(s, r);
  j["method"] = to_string(r.method);
  j["time_limit_s"] = r.time_limit;
  j["plan_status"] = to_string(r.plan_status);
  j["planning_time_s"] = r.planning_time_s;  // the planning thread's CPU time (budgeted)
  j["planning_wall_s"] = r.planning_wall_s;
  j["subqueries"] = r.subqueries;
  j["nodes"] = r.nodes;
  j["arrangement_nodes"] = r.arrangement_nodes;
  j["replans"] = r.replans;
  j["plan_moves"] = r.plan.moves.size();
  j["moves_executed"] = e.moves_done;
  j["executed"] = r.executed;
  j["goals_reached"] = r.executed && e.goals_reached;
  j["violations"] = r.violations;
  return text(j, kIndent);
}

std::string baseline_trajectory_json(const scenario::Scenario& s, const BaselineRecord& r,
                                     int stride) {
  if (stride < 1) throw Error("trajectory: stride must be >= 1");
  const ExecutionLog& e = r.execution;
  const auto st = static_cast<std::size_t>(stride);
  Json familiar = Json::array(), objects = Json::array(), robot = Json::array();
  for (const auto& f : s.familiar)  // known from the start: localized at 0
    familiar.push_back({{"name", f.name}, {"polygon", polygon(f.polygon)}, {"localized_at", 0.0}});
  for (const auto& o : s.objects) objects.push_back({{"name", o.name}, {"radius", o.disk.radius}});
  for (std::size_t k = 0; k < e.robot.size(); k += st)
    robot.push_back({e.robot[k].x.x(), e.robot[k].x.y(), e.robot[k].psi});
  Json object_paths = Json::array();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    Json& p = object_paths.emplace_back(Json::array());
    for (std::size_t k = 0; k < e.objects.size(); k += st) p.push_back(point(e.objects[k][i]));
  }
  Json actions = Json::array();
  for (const auto& a : e.actions) {
    actions.push_back({{"action", a.action},
                       {"fix_mode", false},
                       {"outcome", a.outcome},
                       {"t_start", a.t_start},
                       {"t_end", a.t_end}});
  }
  const Json j = {{"scenario", s.name},
                  {"task", s.task},
                  {"status", r.status},
                  {"robot_radius", s.robot.radius},
                  {"sensor_range", s.robot.sensor_range},
                  {"workspace", polygon(s.workspace)},
                  {"familiar", familiar},
                  {"unknown", named_polygons(s.unknown)},
                  {"regions", named_polygons(s.regions)},
                  {"objects", objects},
                  {"dt", s.simulation.dt * stride},
                  {"robot", robot},
                  {"object_paths", object_paths},
                  {"actions", actions}};
  return text(j);
}

}  // namespace rearm::baselines
