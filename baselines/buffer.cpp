#include "baselines/buffer.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "baselines/buffer_order.h"
#include "core/error.h"
#include "core/rng.h"
#include "geometry/distance.h"

namespace rearm::baselines {
namespace {

constexpr std::uint64_t kSpotStream = 0xB5F;
// clear_way's `arriving` when no goal object's move is under way (the final transit).
constexpr std::size_t kNoneArriving = static_cast<std::size_t>(-1);

// A way to keep clear: a disk of `radius` swept along `path`, with `margin`.
struct Way {
  std::vector<Point> path;
  double radius = 0, margin = 0;

  // A disk of radius rho at x meets the swept disk (its margin included).
  bool meets(const Point& x, double rho) const {
    for (std::size_t s = 0; s + 1 < path.size(); ++s) {
      if (segment_distance(path[s], path[s + 1], x, x) < radius + rho + margin) return true;
    }
    return false;
  }
};

// Where the walk of the order stands: the arrangement, the robot, the moves so far and the
// objects parked in buffers (local indices).
struct Walk {
  Arrangement a;
  Point robot = Point::Zero();
  std::vector<ObjectMove> moves;
  ObjectSet parked = 0;
};

class BufferPlanner {
 public:
  BufferPlanner(const RearrangementProblem& p, const BaselineParams& params,
                const PlannerOptions& o, const BufferOptions& b)
      : p_(p), planner_(p, params), o_(o), b_(b), ctx_(o.time_limit, o.seed, o.max_queries) {
    ctx_.iterations_per_query = o.iterations_per_query;
  }

  PlanResult run();

 private:
  void choose_objects();
  DependencyGraph dependency_graph() const;
  std::optional<std::string> blocked_goal() const;
  bool dfs(ObjectSet at_goal, const Walk& w);
  bool advance(std::size_t i, ObjectSet at_goal, Walk& w);
  bool park(std::size_t j, ObjectSet filled, Walk& w, const std::vector<Way>& ways = {});
  ObjectSet filled_while_parked(std::size_t j, std::size_t arriving, ObjectSet at_goal) const;
  std::vector<std::size_t> path_blockers(const Walk& w, const Point& from, const Point& to,
                                         double radius, double margin, std::size_t skip,
                                         std::vector<Way>& ways);
  std::vector<std::size_t> objects_meeting(const Walk& w, const Way& way, std::size_t skip) const;
  std::vector<std::size_t> near_blockers(const Walk& w, std::size_t k, const Point& target,
                                         bool grasp, std::vector<Way>& ways) const;
  bool clear_way(const std::vector<std::size_t>& blockers, std::size_t arriving, ObjectSet at_goal,
                 Walk& w, const std::vector<Way>& ways);
  MoveOutcome move_to_goal(std::size_t i, ObjectSet at_goal, Walk& w);
  std::vector<Point> spots(std::size_t j, ObjectSet filled, const Walk& w,
                           const std::vector<Way>& ways);
  bool spot_clear(std::size_t j, const Point& q, ObjectSet filled, const Walk& w, bool strict,
                  const std::vector<Way>& ways) const;
  bool finish(Walk w);
  PlanResult result(bool solved);

  std::string name(std::size_t local) const { return p_.object_names[objects_[local]]; }
  // Whether a spot must keep clear of problem object m's goal region (spot_clear).
  bool must_keep_clear(std::size_t m, ObjectSet filled) const {
    if (!b_.lifetime_spots) return true;
    const std::size_t l = local_[m];
    return l != std::string::npos && l < goal_count_ && (filled & (ObjectSet{1} << l));
  }
  Point goal(std::size_t local) const { return *p_.goals[objects_[local]]; }
  bool overlap(std::size_t i, const Point& at_i, std::size_t j, const Point& at_j) const;

  const RearrangementProblem& p_;
  MovePlanner planner_;
  PlannerOptions o_;
  BufferOptions b_;
  QueryContext ctx_;
  std::vector<std::size_t> objects_;  // local index -> problem index; goal objects first
  std::vector<std::size_t> local_;    // problem index -> local index (npos: never moved)
  std::size_t goal_count_ = 0;
  std::optional<BufferOrder> order_;
  std::set<ObjectSet> failed_;
  std::set<std::string> reasons_;
  bool timeout_ = false;
  long parkings_ = 0;
  Plan plan_;
};

bool BufferPlanner::overlap(std::size_t i, const Point& at_i, std::size_t j,
                            const Point& at_j) const {
  return (at_i - at_j).norm() <
         p_.object_radii[i] + p_.object_radii[j] + planner_.params().placement_margin;
}

// The objects the plan moves: those with a goal they are not inside, then (closing over the
// graph) any object whose start overlaps a moved object's goal, and every object without a goal
// (parked when it blocks a goal or a way, and then it stays parked).
void BufferPlanner::choose_objects() {
  std::vector<bool> moved(p_.object_count(), false);
  for (std::size_t i = 0; i < p_.object_count(); ++i) {
    moved[i] = p_.goals[i] && !geometry::contains(*p_.goal_regions[i], p_.start[i]);
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < p_.object_count(); ++i) {
      if (!moved[i]) continue;
      for (std::size_t j = 0; j < p_.object_count(); ++j) {
        if (!moved[j] && j != i && overlap(i, *p_.goals[i], j, p_.start[j])) {
          moved[j] = grew = true;
        }
      }
    }
  }
  for (const bool with_goal : {true, false}) {
    for (std::size_t i = 0; i < p_.object_count(); ++i) {
      // Goal-less objects may be parked to clear a way even when they block no goal.
      if ((moved[i] || !p_.goals[i]) && p_.goals[i].has_value() == with_goal) {
        objects_.push_back(i);
      }
    }
  }
  local_.assign(p_.object_count(), std::string::npos);
  for (std::size_t l = 0; l < objects_.size(); ++l) local_[objects_[l]] = l;
  goal_count_ = static_cast<std::size_t>(
      std::count_if(objects_.begin(), objects_.end(), [&](std::size_t i) { return p_.goals[i]; }));
}

// TRLB's graph: goal object i depends on every moved object whose start overlaps i's goal.
DependencyGraph BufferPlanner::dependency_graph() const {
  DependencyGraph g;
  g.object_count = objects_.size();
  g.goal_count = goal_count_;
  g.blockers.resize(goal_count_);
  for (std::size_t i = 0; i < goal_count_; ++i) {
    for (std::size_t j = 0; j < objects_.size(); ++j) {
      if (j != i && overlap(objects_[i], goal(i), objects_[j], p_.start[objects_[j]])) {
        g.blockers[i].push_back(j);
      }
    }
  }
  return g;
}

// A goal point that fixed obstacles or the boundary overlap: no order and no buffer places the
// object there (exact geometry), the proof of infeasibility this method can give.
std::optional<std::string> BufferPlanner::blocked_goal() const {
  for (std::size_t i = 0; i < goal_count_; ++i) {
    const double rho = p_.object_radii[objects_[i]];
    if (!planner_.world().disk_free(goal(i), rho, planner_.params().placement_margin, {})) {
      return name(i) + "'s goal is not free of fixed obstacles and the boundary";
    }
  }
  return std::nullopt;
}

// The move of goal object i to its goal. When it fails for want of room made by other objects,
// those objects are parked and the move is tried once more: no path (the transit to the object
// and the transfer to the goal, each planned among the fixed obstacles alone: the objects they
// cross, the mobile robot's version of fmRS's constraints), no free release approach (the
// objects on the straight approach to the goal), no free grasp (the objects on the dock from
// the robot's side). A way closed by an object already at its goal is not cleared.
MoveOutcome BufferPlanner::move_to_goal(std::size_t i, ObjectSet at_goal, Walk& w) {
  const std::size_t k = objects_[i];
  MoveOutcome m = planner_.plan(w.a, w.robot, k, goal(i), p_.goal_regions[k], ctx_);
  if (m.move) return m;
  std::vector<Way> ways;
  std::vector<std::size_t> blockers;
  auto add = [&](const std::vector<std::size_t>& more) {
    for (const std::size_t b : more) {
      if (std::find(blockers.begin(), blockers.end(), b) == blockers.end()) blockers.push_back(b);
    }
  };
  const BaselineParams& prm = planner_.params();
  const double pr = pair_radius(p_.robot_radius, p_.object_radii[k], prm);
  switch (m.failure) {
    case MoveFailure::kTransitFailed:
    case MoveFailure::kTransferFailed:
      add(path_blockers(w, w.robot, w.a[k], p_.robot_radius, prm.transit_margin, k, ways));
      add(path_blockers(w, w.a[k], goal(i), pr, prm.transfer_margin, k, ways));
      break;
    case MoveFailure::kTargetBlocked:
    case MoveFailure::kNoGrasp:
      add(near_blockers(w, k, goal(i), m.failure == MoveFailure::kNoGrasp, ways));
      break;
    default:
      return m;
  }
  if (blockers.empty() || !clear_way(blockers, i, at_goal, w, ways)) return m;
  return planner_.plan(w.a, w.robot, k, goal(i), p_.goal_regions[k], ctx_);
}

// The objects (but k) on object k's straight release approach to `target` (the pair disk swept
// along it, for the heading from the object to the target, as move_planner.h tries first) or,
// with `grasp`, on its dock (the robot disk from the standoff to the grip, heading from the
// robot, and the gripped pair's disk).
std::vector<std::size_t> BufferPlanner::near_blockers(const Walk& w, std::size_t k,
                                                      const Point& target, bool grasp,
                                                      std::vector<Way>& ways) const {
  const BaselineParams& prm = planner_.params();
  const double r = p_.robot_radius, rho = p_.object_radii[k];
  const double ell = pair_offset(rho, prm), pr = pair_radius(r, rho, prm);
  const Point o = w.a[k];
  const Point from = grasp ? w.robot : o, to = grasp ? o : target;
  if ((to - from).norm() == 0) return {};
  const double psi = std::atan2(to.y() - from.y(), to.x() - from.x());
  const Point u = heading_vector(psi);
  Way way;
  if (grasp) {
    const Point xg = grip_position(o, r, rho, psi, prm);
    way = Way{{standoff_position(o, r, rho, psi, prm), xg, xg + ell * u}, pr, prm.transit_margin};
  } else {
    const Point p_goal = target - (r + 0.5 * prm.grip_gap) * u;
    const double approach = std::max(prm.approach_min, prm.approach_factor * ell);
    way = Way{{p_goal - approach * u, p_goal}, pr, prm.transfer_margin};
  }
  ways.push_back(std::move(way));
  return objects_meeting(w, ways.back(), k);
}

// The objects (problem indices, but `skip`) whose disks meet the way.
std::vector<std::size_t> BufferPlanner::objects_meeting(const Walk& w, const Way& way,
                                                        std::size_t skip) const {
  std::vector<std::size_t> out;
  for (std::size_t m = 0; m < w.a.size(); ++m) {
    if (m != skip && way.meets(w.a[m], p_.object_radii[m])) out.push_back(m);
  }
  return out;
}

// The objects (problem indices, but `skip`) within reach of a disk of `radius` swept along a path
// from `from` to `to` planned among the fixed obstacles alone; none when no such path exists.
std::vector<std::size_t> BufferPlanner::path_blockers(const Walk& w, const Point& from,
                                                      const Point& to, double radius, double margin,
                                                      std::size_t skip, std::vector<Way>& ways) {
  const QueryResult q = plan_motion(planner_.world(), {}, std::nullopt, radius, margin, from, to,
                                    ctx_, planner_.params().range);
  if (q.status != QueryStatus::kSolved) return {};
  ways.push_back(Way{q.path, radius, margin});
  return objects_meeting(w, ways.back(), skip);
}

// Parks the blockers (problem indices) of goal object `arriving`'s move; false when one cannot
// be parked: it never moves, it is a goal object already at its goal, or (without
// lifetime_spots) it is parked already. With lifetime_spots a parked blocker is parked again,
// off the ways (TRLB: a buffer that a new constraint needs is moved).
bool BufferPlanner::clear_way(const std::vector<std::size_t>& blockers, std::size_t arriving,
                              ObjectSet at_goal, Walk& w, const std::vector<Way>& ways) {
  for (const std::size_t k : blockers) {
    const std::size_t j = local_[k];
    if (j == std::string::npos) return false;
    const ObjectSet bj = ObjectSet{1} << j;
    if (j < goal_count_ && (at_goal & bj)) return false;
    if ((w.parked & bj) && !b_.lifetime_spots) return false;
    if (!park(j, filled_while_parked(j, arriving, at_goal), w, ways)) return false;
  }
  return true;
}

// The goal objects that arrive while object j (local) waits in a buffer: `arriving` (the move
// under way), then the order's first choices from there, up to j's own turn (every remaining
// goal object when j has no goal; none when nothing arrives, kNoneArriving).
ObjectSet BufferPlanner::filled_while_parked(std::size_t j, std::size_t arriving,
                                             ObjectSet at_goal) const {
  const ObjectSet all = all_goals(order_->graph());
  ObjectSet filled = 0;
  if (arriving == kNoneArriving) return filled;
  for (std::size_t next = arriving; next != j;) {
    filled |= ObjectSet{1} << next;
    at_goal |= ObjectSet{1} << next;
    if (at_goal == all) break;
    const std::vector<std::size_t> c = order_->candidates(at_goal);
    if (c.empty()) break;
    next = c.front();
  }
  return filled;
}

// Depth-first over the order's ranking: from the set of arrived objects, each candidate in turn
// (its blockers parked, then itself to its goal); a set from which every candidate failed is
// remembered and not searched again.
bool BufferPlanner::dfs(ObjectSet at_goal, const Walk& w) {
  if (ctx_.expired()) {
    timeout_ = true;
    return false;
  }
  const ObjectSet all = all_goals(order_->graph());
  if (at_goal == all) return finish(w);
  if (failed_.count(at_goal)) return false;
  for (const std::size_t i : order_->candidates(at_goal)) {
    Walk next = w;
    if (advance(i, at_goal, next) && dfs(at_goal | (ObjectSet{1} << i), next)) return true;
    if (timeout_) return false;
  }
  failed_.insert(at_goal);
  return false;
}

// Parks i's blockers still at their starts, then moves i to its goal.
bool BufferPlanner::advance(std::size_t i, ObjectSet at_goal, Walk& w) {
  for (const std::size_t j : order_->graph().blockers[i]) {
    const ObjectSet bj = ObjectSet{1} << j;
    if ((at_goal & bj) || (w.parked & bj)) continue;
    if (!park(j, filled_while_parked(j, i, at_goal), w)) return false;
  }
  const std::size_t k = objects_[i];
  const MoveOutcome m = move_to_goal(i, at_goal, w);
  if (!m.move) {
    if (m.failure == MoveFailure::kTimeout) timeout_ = true;
    reasons_.insert(name(i) + " to its goal: " + to_string(m.failure));
    return false;
  }
  w.a[k] = m.move->to;
  w.robot = m.robot_after;
  w.moves.push_back(*m.move);
  w.parked &= ~(ObjectSet{1} << i);
  return true;
}

// Object j (local) to a buffer spot: the acceptable spots nearest it first, spot_tries of them.
// `filled`: the goal objects that arrive while it is parked (filled_while_parked).
bool BufferPlanner::park(std::size_t j, ObjectSet filled, Walk& w, const std::vector<Way>& ways) {
  const std::size_t k = objects_[j];
  int tried = 0;
  for (const Point& q : spots(j, filled, w, ways)) {
    if (tried++ == b_.spot_tries) break;
    const MoveOutcome m = planner_.plan(w.a, w.robot, k, q, std::nullopt, ctx_);
    if (m.move) {
      w.a[k] = m.move->to;
      w.robot = m.robot_after;
      w.moves.push_back(*m.move);
      w.parked |= ObjectSet{1} << j;
      return true;
    }
    if (m.failure == MoveFailure::kTimeout) {
      timeout_ = true;
      return false;
    }
  }
  reasons_.insert(name(j) + ": no buffer spot reached (" + std::to_string(tried) + " tried)");
  return false;
}

// Candidate spots for object j, nearest its place first: drawn from the trial's seed and the
// count of parkings so far (deterministic). Spots that keep the pair disk clear of every other
// object and of the goal regions it must not block (TRLB's rule: with lifetime_spots those of
// the goal objects in `filled`, which arrive while it is parked; without, every goal region)
// come first; if none is drawn, spots that keep the object disk clear of them.
std::vector<Point> BufferPlanner::spots(std::size_t j, ObjectSet filled, const Walk& w,
                                        const std::vector<Way>& ways) {
  Rng rng = Rng::derive(o_.seed, kSpotStream + static_cast<std::uint64_t>(parkings_++));
  const Point lo = planner_.world().lower(), hi = planner_.world().upper();
  std::vector<Point> drawn;
  for (int n = 0; n < b_.spot_samples; ++n) {
    drawn.emplace_back(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
  }
  const Point from = w.a[objects_[j]];
  for (const bool strict : {true, false}) {
    std::vector<Point> out;
    for (const Point& q : drawn) {
      if (spot_clear(j, q, filled, w, strict, ways)) out.push_back(q);
    }
    if (out.empty()) continue;
    std::stable_sort(out.begin(), out.end(), [&](const Point& a, const Point& b) {
      return (a - from).squaredNorm() < (b - from).squaredNorm();
    });
    return out;
  }
  return {};
}

bool BufferPlanner::spot_clear(std::size_t j, const Point& q, ObjectSet filled, const Walk& w,
                               bool strict, const std::vector<Way>& ways) const {
  const std::size_t k = objects_[j];
  if (!planner_.placement_free(w.a, k, q)) return false;
  const double rho = p_.object_radii[k];
  for (const Way& way : ways) {  // off the way being cleared
    if (way.meets(q, rho)) return false;
  }
  const double keep = strict ? pair_radius(p_.robot_radius, rho, planner_.params()) : rho;
  for (std::size_t m = 0; m < p_.object_count(); ++m) {
    if (m != k && (q - w.a[m]).norm() < keep + p_.object_radii[m]) return false;
    if (p_.goal_regions[m] && must_keep_clear(m, filled) &&
        geometry::signed_distance(*p_.goal_regions[m], q) < keep) {
      return false;
    }
  }
  return true;
}

// Every goal reached: the robot's final transit, if the task has one.
bool BufferPlanner::finish(Walk w) {
  std::vector<Point> final_transit;
  if (p_.robot_goal) {
    QueryResult t = planner_.transit(w.a, w.robot, *p_.robot_goal, ctx_);
    if (t.status == QueryStatus::kNoPath) {
      const ObjectSet all = all_goals(order_->graph());
      std::vector<Way> ways;
      const auto blockers = path_blockers(w, w.robot, *p_.robot_goal, p_.robot_radius,
                                          planner_.params().transit_margin, w.a.size(), ways);
      if (!blockers.empty() && clear_way(blockers, kNoneArriving, all, w, ways)) {
        t = planner_.transit(w.a, w.robot, *p_.robot_goal, ctx_);
      }
    }
    if (t.status != QueryStatus::kSolved) {
      if (t.status == QueryStatus::kTimeout) timeout_ = true;
      reasons_.insert(std::string("final transit: ") + to_string(t.status));
      return false;
    }
    final_transit = t.path;
  }
  if (!p_.goals_reached(w.a)) {
    reasons_.insert("an object landed outside its goal region");
    return false;
  }
  plan_.moves = w.moves;
  plan_.final_transit = std::move(final_transit);
  plan_.final_arrangement = w.a;
  return true;
}

PlanResult BufferPlanner::result(bool solved) {
  PlanResult out;
  out.planning_time_s = ctx_.elapsed();
  out.planning_wall_s = ctx_.wall_elapsed();
  out.wall_net = ctx_.cut_by_wall();
  out.subqueries = ctx_.subqueries;
  out.nodes = ctx_.nodes;
  out.queries = ctx_.queries;
  std::string why;
  for (const auto& r : reasons_) why += (why.empty() ? "" : "; ") + r;
  if (solved) {
    out.status = PlanStatus::kSolved;
    out.plan = std::move(plan_);
  } else if (timeout_ && ctx_.out_of_queries()) {
    out.status = PlanStatus::kUnsolved;
    out.reason = "query limit of " + std::to_string(ctx_.max_queries()) + " reached";
  } else if (timeout_) {
    out.status = PlanStatus::kTimeout;
    out.reason = "time limit of " + seconds_text(o_.time_limit) + " reached";
  } else {
    out.status = PlanStatus::kUnsolved;
    out.reason = "every order tried failed (" + why + ")";
  }
  return out;
}

PlanResult BufferPlanner::run() {
  choose_objects();
  if (objects_.size() > kMaxOrderObjects) {
    throw Error("buffer: at most " + std::to_string(kMaxOrderObjects) + " objects to move");
  }
  if (const auto blocked = blocked_goal()) {
    PlanResult out = result(false);
    out.status = PlanStatus::kInfeasible;
    out.reason = "infeasible: " + *blocked + " (exact geometry), so no order places it";
    return out;
  }
  order_.emplace(dependency_graph());
  Walk w{p_.start, p_.robot_start, {}, 0};
  return result(dfs(0, w));
}

}  // namespace

PlanResult plan_buffer(const RearrangementProblem& problem, const BaselineParams& params,
                       const PlannerOptions& options, const BufferOptions& buffer) {
  if (buffer.spot_samples < 1 || buffer.spot_tries < 1) {
    throw Error("buffer options: spot_samples and spot_tries must be >= 1");
  }
  return BufferPlanner(problem, params, options, buffer).run();
}

}  // namespace rearm::baselines
