#include "baselines/fmrs.h"

#include <algorithm>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace rearm::baselines {

namespace {

// Candidate headings, evenly spaced (grasp and release headings, as move_planner.h tries).
std::vector<double> headings(int n) {
  std::vector<double> out;
  for (int k = 0; k < n; ++k) out.push_back(wrap_angle(2 * std::numbers::pi * k / n));
  return out;
}

// The constraints of object which[k]'s paths: every other moving object at its current place
// (constraint 2m) and at its target (2m + 1); the objects that stay are hard obstacles.
void add_objects(McrQuery& q, const MovePlanner& planner, const Arrangement& a,
                 const std::vector<std::size_t>& which, const Arrangement& targets, std::size_t k) {
  const auto& radii = planner.problem().object_radii;
  std::vector<bool> moving(a.size(), false);
  for (std::size_t m = 0; m < which.size(); ++m) {
    moving[which[m]] = true;
    const std::size_t j = which[m];
    // Object i is not its own constraint: two disks no path meets keep the indices 2m, 2m + 1.
    const double rho = m == k ? -std::numeric_limits<double>::infinity() : radii[j];
    q.constraints.push_back({a[j], rho});
    q.constraints.push_back({targets[j], rho});
  }
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (!moving[j]) q.hard.push_back({a[j], radii[j]});
  }
}

std::string names(const MovePlanner& planner, const std::vector<std::size_t>& which,
                  const std::vector<std::size_t>& ks, const char* sep) {
  std::string out;
  for (const std::size_t k : ks) {
    out += (out.empty() ? "" : sep) + planner.problem().object_names[which[k]];
  }
  return out;
}

}  // namespace

TopologicalOrder topological_order(const std::vector<std::vector<std::size_t>>& before) {
  const std::size_t n = before.size();
  std::vector<bool> done(n, false);
  TopologicalOrder out;
  auto ready = [&](std::size_t k) {
    return std::all_of(before[k].begin(), before[k].end(), [&](std::size_t m) { return done[m]; });
  };
  while (out.order.size() < n) {
    std::size_t next = n;
    for (std::size_t k = 0; k < n && next == n; ++k) {
      if (!done[k] && ready(k)) next = k;
    }
    if (next == n) break;
    done[next] = true;
    out.order.push_back(next);
  }
  if (out.order.size() == n) return out;
  // Every object left waits for another one left: walking back from any finds a cycle.
  std::size_t k = 0;
  while (done[k]) ++k;
  std::vector<std::size_t> seen(n, n);
  std::vector<std::size_t> walk;
  while (seen[k] == n) {
    seen[k] = walk.size();
    walk.push_back(k);
    const auto& b = before[k];
    k = *std::find_if(b.begin(), b.end(), [&](std::size_t m) { return !done[m]; });
  }
  out.cycle.assign(walk.begin() + static_cast<long>(seen[k]), walk.end());
  std::reverse(out.cycle.begin(), out.cycle.end());  // each before the next
  out.order.clear();
  return out;
}

Fmrs::Fmrs(const MovePlanner& planner, const FmrsOptions& options)
    : planner_(planner), roadmap_(planner.world(), options.grid_step) {}

// The pair disk from its grip on object i (any heading) to the start of a release at `target`.
McrQuery Fmrs::transfer_query(const Arrangement& a, std::size_t i, const Point& target) const {
  const BaselineParams& bp = planner_.params();
  const double r = planner_.problem().robot_radius, rho = planner_.problem().object_radii[i];
  const double ell = pair_offset(rho, bp), reach = r + 0.5 * bp.grip_gap;
  McrQuery q;
  q.radius = pair_radius(r, rho, bp);
  q.margin = bp.transfer_margin;
  for (const double psi : headings(bp.directions)) {
    const Point u = heading_vector(psi);
    q.sources.push_back(grip_position(a[i], r, rho, psi, bp) + ell * u);
    q.targets.push_back(target - reach * u);
  }
  return q;
}

// The robot disk from where it stands to a pre-grasp pose at object i (any heading).
McrQuery Fmrs::transit_query(const Arrangement& a, const Point& robot, std::size_t i) const {
  const BaselineParams& bp = planner_.params();
  const double r = planner_.problem().robot_radius, rho = planner_.problem().object_radii[i];
  McrQuery q;
  q.radius = r;
  q.margin = bp.transit_margin;
  q.sources.push_back(robot);
  for (const double psi : headings(bp.directions)) {
    q.targets.push_back(standoff_position(a[i], r, rho, psi, bp));
  }
  q.hard.push_back({a[i], rho});  // the object itself, not yet gripped
  return q;
}

FmrsDependencies Fmrs::dependencies(const Arrangement& a, std::optional<Point> robot,
                                    const std::vector<std::size_t>& which,
                                    const Arrangement& targets) const {
  FmrsDependencies out;
  out.before.resize(which.size());
  auto add = [&](std::size_t first, std::size_t then) {
    auto& b = out.before[then];
    if (std::find(b.begin(), b.end(), first) == b.end()) b.push_back(first);
  };
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::size_t i = which[k];
    std::vector<McrQuery> queries{transfer_query(a, i, targets[i])};
    if (robot) queries.push_back(transit_query(a, *robot, i));
    for (McrQuery& q : queries) {
      add_objects(q, planner_, a, which, targets, k);
      const McrPath p = roadmap_.search(q);
      if (!p.found) {
        out.unreachable.push_back(k);
        break;
      }
      for (std::size_t m = 0; m < which.size(); ++m) {
        if (p.crossed.test(2 * m)) add(m, k);      // crosses j where it is: j first
        if (p.crossed.test(2 * m + 1)) add(k, m);  // crosses j's target: j after
      }
    }
  }
  for (auto& b : out.before) std::sort(b.begin(), b.end());
  return out;
}

MonotoneResult Fmrs::solve(const Arrangement& a, std::optional<Point> robot,
                           const std::vector<std::size_t>& which, const Arrangement& targets,
                           const std::vector<std::optional<geometry::Polygon>>& regions,
                           std::optional<Point> robot_goal, QueryContext& ctx) const {
  if (which.size() > kMaxConstraints / 2) throw Error("fmRS: at most 64 objects to move");
  MonotoneResult out;
  const FmrsDependencies d = dependencies(a, robot, which, targets);
  if (!d.unreachable.empty()) {
    out.reason = "no path for " + names(planner_, which, d.unreachable, ", ") +
                 " even with every moving object removed (fixed obstacles and objects that stay)";
    return out;
  }
  const TopologicalOrder order = topological_order(d.before);
  if (!order.cycle.empty()) {
    out.reason = "dependency cycle " + names(planner_, which, order.cycle, " -> ") +
                 " (fmRS moves each object once and does not backtrack)";
    return out;
  }
  Arrangement now = a;
  for (const std::size_t k : order.order) {
    const std::size_t i = which[k];
    const MoveOutcome m = planner_.plan(now, robot, i, targets[i], regions[i], ctx);
    if (!m.move) {
      out.timeout = m.failure == MoveFailure::kTimeout;
      out.reason = planner_.problem().object_names[i] + ": " + to_string(m.failure) +
                   " (in the dependency graph's order; fmRS does not backtrack)";
      return out;
    }
    now[i] = m.move->to;
    out.moves.push_back(*m.move);
    if (robot) robot = m.robot_after;
  }
  if (robot_goal && robot) {
    const QueryResult t = planner_.transit(now, *robot, *robot_goal, ctx);
    if (t.status != QueryStatus::kSolved) {
      out.timeout = t.status == QueryStatus::kTimeout;
      out.reason = std::string("final transit: ") + to_string(t.status);
      out.moves.clear();
      return out;
    }
    out.final_transit = t.path;
  }
  out.solved = true;
  out.reached = std::move(now);
  out.robot_after = robot;
  return out;
}

PlanResult plan_fmrs(const RearrangementProblem& problem, const BaselineParams& params,
                     const PlannerOptions& options, const FmrsOptions& fmrs) {
  QueryContext ctx(options.time_limit, options.seed, options.max_queries);
  ctx.iterations_per_query = options.iterations_per_query;
  const MovePlanner planner(problem, params);
  const Fmrs f(planner, fmrs);
  PlanResult out;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < problem.object_count(); ++i) {
    if (!problem.goals[i]) continue;
    if (!planner.world().disk_free(*problem.goals[i], problem.object_radii[i],
                                   params.placement_margin, {})) {
      out.status = PlanStatus::kInfeasible;
      out.reason = "infeasible: " + problem.object_names[i] +
                   "'s goal is not free of fixed obstacles and the boundary (exact geometry)";
      return out;
    }
    if (!geometry::contains(*problem.goal_regions[i], problem.start[i])) which.push_back(i);
  }
  const MonotoneResult m =
      f.solve(problem.start, problem.robot_start, which, problem.goal_arrangement(),
              problem.goal_regions, problem.robot_goal, ctx);
  if (!search_plan_result(m, ctx, options.time_limit, out)) {
    out.status = PlanStatus::kUnsolved;
    out.reason = m.reason;
  }
  return out;
}

}  // namespace rearm::baselines
