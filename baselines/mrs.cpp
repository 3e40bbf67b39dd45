#include "baselines/mrs.h"

#include <map>
#include <set>

#include "core/error.h"

namespace rearm::baselines {

namespace {

struct Search {
  const MovePlanner& planner;
  const std::vector<std::size_t>& which;
  const Arrangement& targets;
  const std::vector<std::optional<geometry::Polygon>>& regions;
  std::optional<Point> robot_goal;
  QueryContext& ctx;
  std::set<std::uint64_t> failed;  // sets of moved objects (bit k: which[k]) that led nowhere
  bool all_proven = true;
  bool only_occupied = true;  // every failure: a goal occupied by another object
  bool timeout = false;
  std::set<std::string> reasons;
  std::vector<ObjectMove> moves;
  std::vector<Point> final_transit;
  Arrangement reached;
  std::optional<Point> robot_after;

  std::string name(std::size_t i) const { return planner.problem().object_names[i]; }

  bool dfs(std::uint64_t moved, const Arrangement& a, std::optional<Point> robot) {
    if (ctx.expired()) {
      timeout = true;
      return false;
    }
    if (moved == (std::uint64_t{1} << which.size()) - 1) {
      if (robot_goal && robot) {
        const QueryResult t = planner.transit(a, *robot, *robot_goal, ctx);
        if (t.status != QueryStatus::kSolved) {
          if (t.status == QueryStatus::kTimeout) timeout = true;
          all_proven = false;
          only_occupied = false;
          reasons.insert(std::string("final transit: ") + to_string(t.status));
          return false;
        }
        final_transit = t.path;
      }
      reached = a;
      robot_after = robot;
      return true;
    }
    if (failed.count(moved)) return false;
    for (std::size_t k = 0; k < which.size(); ++k) {
      if (moved & (std::uint64_t{1} << k)) continue;
      const std::size_t i = which[k];
      const MoveOutcome m = planner.plan(a, robot, i, targets[i], regions[i], ctx);
      if (!m.move) {
        if (m.failure == MoveFailure::kTimeout) {
          timeout = true;
          return false;
        }
        if (!proves_impossible(m.failure)) all_proven = false;
        if (m.failure != MoveFailure::kTargetOccupied) only_occupied = false;
        std::string why = name(i) + ": " + to_string(m.failure);
        if (m.failure == MoveFailure::kTargetOccupied)
          for (std::size_t j = 0; j < a.size(); ++j)
            if (j != i && (a[j] - targets[i]).norm() < planner.problem().object_radii[i] +
                                                           planner.problem().object_radii[j] +
                                                           planner.params().placement_margin)
              why += " (" + name(j) + ")";
        reasons.insert(why);
        continue;
      }
      Arrangement b = a;
      b[i] = m.move->to;
      moves.push_back(*m.move);
      if (dfs(moved | (std::uint64_t{1} << k), b,
              robot ? std::optional<Point>(m.robot_after) : std::nullopt))
        return true;
      moves.pop_back();
      if (timeout) return false;
    }
    failed.insert(moved);
    return false;
  }
};

}  // namespace

MonotoneResult monotone_search(const MovePlanner& planner, const Arrangement& a,
                               std::optional<Point> robot, const std::vector<std::size_t>& which,
                               const Arrangement& targets,
                               const std::vector<std::optional<geometry::Polygon>>& regions,
                               std::optional<Point> robot_goal, QueryContext& ctx) {
  if (which.size() > 63) throw Error("monotone search: at most 63 objects");
  Search s{planner, which, targets, regions, robot_goal, ctx, {}, true,
           true,    false, {},      {},      {},         {},  {}};
  MonotoneResult out;
  out.solved = s.dfs(0, a, robot);
  out.timeout = s.timeout;
  out.proven_impossible = !out.solved && !s.timeout && s.all_proven;
  out.non_monotone = out.proven_impossible && s.only_occupied;
  if (out.solved) {
    out.moves = std::move(s.moves);
    out.final_transit = std::move(s.final_transit);
    out.reached = std::move(s.reached);
    out.robot_after = s.robot_after;
  } else {
    for (const auto& r : s.reasons) out.reason += (out.reason.empty() ? "" : "; ") + r;
  }
  return out;
}

bool search_plan_result(const MonotoneResult& m, const QueryContext& ctx, double time_limit,
                        PlanResult& out) {
  out.planning_time_s = ctx.elapsed();
  out.planning_wall_s = ctx.wall_elapsed();
  out.wall_net = ctx.cut_by_wall();
  out.subqueries = ctx.subqueries;
  out.nodes = ctx.nodes;
  out.queries = ctx.queries;
  if (m.solved) {
    out.status = PlanStatus::kSolved;
    out.plan.moves = m.moves;
    out.plan.final_transit = m.final_transit;
    out.plan.final_arrangement = m.reached;
  } else if (m.timeout && ctx.out_of_queries()) {
    out.status = PlanStatus::kUnsolved;
    out.reason = "query limit of " + std::to_string(ctx.max_queries()) + " reached";
  } else if (m.timeout) {
    out.status = PlanStatus::kTimeout;
    out.reason = "time limit of " + seconds_text(time_limit) + " reached";
  } else {
    return false;
  }
  return true;
}

PlanResult plan_mrs(const RearrangementProblem& problem, const BaselineParams& params,
                    const PlannerOptions& options) {
  QueryContext ctx(options.time_limit, options.seed, options.max_queries);
  ctx.iterations_per_query = options.iterations_per_query;
  const MovePlanner planner(problem, params);
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < problem.object_count(); ++i)
    if (problem.goals[i] && !geometry::contains(*problem.goal_regions[i], problem.start[i]))
      which.push_back(i);
  const MonotoneResult m =
      monotone_search(planner, problem.start, problem.robot_start, which,
                      problem.goal_arrangement(), problem.goal_regions, problem.robot_goal, ctx);
  PlanResult out;
  if (search_plan_result(m, ctx, options.time_limit, out)) return out;
  if (m.non_monotone) {
    out.status = PlanStatus::kInfeasible;
    out.reason =
        "non-monotone instance: in every order some object's goal is occupied by an object not "
        "yet moved, so mRS (each object moved once, straight to its goal) cannot solve it (" +
        m.reason + ")";
  } else if (m.proven_impossible) {
    out.status = PlanStatus::kInfeasible;
    out.reason = "infeasible for mRS: in every order some move is impossible by exact geometry (" +
                 m.reason + ")";
  } else {
    out.status = PlanStatus::kUnsolved;
    out.reason =
        "no monotone order found; some motion queries failed (RRTConnect's iteration "
        "cap), so this is not a proof (" +
        m.reason + ")";
  }
  return out;
}

}  // namespace rearm::baselines
