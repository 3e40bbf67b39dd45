#include "baselines/birrt.h"

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "core/rng.h"

namespace rearm::baselines {

namespace {

struct Node {
  Arrangement a;
  std::optional<Point> robot;  // start tree only: the robot's centre on arrival
  int parent = -1;
  // Start tree: the moves from the parent to this node (forward). Goal tree: the objects that
  // moved from the parent to this node (to be moved back, forward in time, at assembly).
  std::vector<ObjectMove> moves;
  std::vector<std::size_t> moved;
};

double arrangement_distance(const Arrangement& a, const Arrangement& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d += (a[i] - b[i]).norm();
  return d;
}

int nearest(const std::vector<Node>& tree, const Arrangement& a) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < tree.size(); ++k) {
    const double d = arrangement_distance(tree[k].a, a);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

class Birrt {
 public:
  Birrt(const RearrangementProblem& p, const BaselineParams& params, const PlannerOptions& o,
        const BirrtOptions& b)
      : p_(p),
        planner_(p, params),
        o_(o),
        b_(b),
        ctx_(o.time_limit, o.seed, o.max_queries),
        rng_(Rng::derive(o.seed, kSamplerStream)) {
    ctx_.iterations_per_query = o.iterations_per_query;
    no_regions_.assign(p.object_count(), std::nullopt);
    if (b.extension == BirrtOptions::Extension::kFmrs) fmrs_.emplace(planner_, b.fmrs);
  }

  PlanResult run() {
    PlanResult out;
    start_.push_back(Node{p_.start, p_.robot_start, -1, {}, {}});
    goal_.push_back(Node{p_.goal_arrangement(), std::nullopt, -1, {}, {}});
    bool solved = try_connect(0, 0);
    bool from_start = true;
    while (!solved && !ctx_.expired()) {
      ++iterations_;
      std::vector<Node>& tree = from_start ? start_ : goal_;
      const int c = extend(tree, from_start);
      if (c >= 0) {
        if (from_start) {
          solved = try_goal_directly(c) || try_connect(c, nearest(goal_, start_[c].a));
        } else {
          solved = try_connect(nearest(start_, goal_[c].a), c);
        }
      }
      from_start = !from_start;
    }
    out.planning_time_s = ctx_.elapsed();
    out.planning_wall_s = ctx_.wall_elapsed();
    out.wall_net = ctx_.cut_by_wall();
    out.subqueries = ctx_.subqueries;
    out.arrangement_nodes = static_cast<long>(start_.size() + goal_.size());
    out.nodes = ctx_.nodes + out.arrangement_nodes;
    out.queries = ctx_.queries;
    if (solved) {
      out.status = PlanStatus::kSolved;
      out.plan = std::move(plan_);
    } else if (ctx_.out_of_queries()) {
      out.status = PlanStatus::kUnsolved;
      out.reason = "query limit of " + std::to_string(ctx_.max_queries()) + " reached after " +
                   std::to_string(iterations_) + " iterations (" + std::to_string(start_.size()) +
                   " + " + std::to_string(goal_.size()) + " arrangement nodes)";
    } else {
      out.status = PlanStatus::kTimeout;
      out.reason = "time limit of " + seconds_text(o_.time_limit) + " reached after " +
                   std::to_string(iterations_) + " iterations (" + std::to_string(start_.size()) +
                   " + " + std::to_string(goal_.size()) + " arrangement nodes)";
    }
    return out;
  }

 private:
  static constexpr std::uint64_t kSamplerStream = 0xB1;

  // The extension primitive: mRS's monotone search or fmRS (BirrtOptions::extension).
  MonotoneResult local(const Arrangement& a, std::optional<Point> robot,
                       const std::vector<std::size_t>& which, const Arrangement& targets,
                       const std::vector<std::optional<geometry::Polygon>>& regions,
                       std::optional<Point> robot_goal) {
    if (fmrs_) return fmrs_->solve(a, robot, which, targets, regions, robot_goal, ctx_);
    return monotone_search(planner_, a, robot, which, targets, regions, robot_goal, ctx_);
  }

  // A random placement of object i in arrangement a (nullopt after placement_tries misses).
  std::optional<Point> random_placement(const Arrangement& a, std::size_t i) {
    const Point lo = planner_.world().lower(), hi = planner_.world().upper();
    for (int t = 0; t < b_.placement_tries; ++t) {
      const Point q(rng_.uniform(lo.x(), hi.x()), rng_.uniform(lo.y(), hi.y()));
      if (planner_.placement_free(a, i, q)) return q;
    }
    return std::nullopt;
  }

  // Extends `tree` towards a random arrangement; returns the new node's index or -1.
  int extend(std::vector<Node>& tree, bool forward) {
    const std::size_t n = p_.object_count();
    if (n == 0) return -1;
    Arrangement sample(n);
    const Point lo = planner_.world().lower(), hi = planner_.world().upper();
    for (std::size_t i = 0; i < n; ++i)
      sample[i] = Point(rng_.uniform(lo.x(), hi.x()), rng_.uniform(lo.y(), hi.y()));
    const int near = nearest(tree, sample);
    // Move up to max_extend random objects to random free places near the sample's.
    const std::size_t k =
        1 + rng_.index(static_cast<std::uint64_t>(std::min<std::size_t>(b_.max_extend, n)));
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng_.index(i)]);
    Arrangement target = tree[static_cast<std::size_t>(near)].a;
    std::vector<std::size_t> which;
    for (std::size_t m = 0; m < k; ++m) {
      const std::size_t i = order[m];
      std::optional<Point> q;
      if (planner_.placement_free(target, i, sample[i]))
        q = sample[i];
      else
        q = random_placement(target, i);
      if (!q) continue;
      target[i] = *q;
      which.push_back(i);
    }
    if (which.empty()) return -1;
    const Node& from = tree[static_cast<std::size_t>(near)];
    // Goal tree: searched outwards from the parent, with no robot position (its transits are
    // planned when a connection is replayed forward).
    const MonotoneResult m = local(from.a, forward ? from.robot : std::nullopt, which, target,
                                   no_regions_, std::nullopt);
    if (!m.solved) return -1;
    Node c;
    c.a = m.reached;
    c.parent = near;
    if (forward) {
      c.robot = m.robot_after;
      c.moves = m.moves;
    } else {
      c.moved = which;
    }
    tree.push_back(std::move(c));
    return static_cast<int>(tree.size()) - 1;
  }

  // The start-tree path root → s as moves.
  std::vector<ObjectMove> start_moves(int s) const {
    std::vector<const Node*> chain;
    for (int k = s; k >= 0; k = start_[static_cast<std::size_t>(k)].parent)
      chain.push_back(&start_[static_cast<std::size_t>(k)]);
    std::vector<ObjectMove> out;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
      out.insert(out.end(), (*it)->moves.begin(), (*it)->moves.end());
    return out;
  }

  // A start-tree node whose arrangement already meets every goal: only the robot's final
  // transit is missing.
  bool try_goal_directly(int s) {
    const Node& n = start_[static_cast<std::size_t>(s)];
    if (!p_.goals_reached(n.a)) return false;
    std::vector<Point> final_transit;
    if (p_.robot_goal) {
      const QueryResult t = planner_.transit(n.a, *n.robot, *p_.robot_goal, ctx_);
      if (t.status != QueryStatus::kSolved) return false;
      final_transit = t.path;
    }
    plan_.moves = start_moves(s);
    plan_.final_transit = std::move(final_transit);
    plan_.final_arrangement = n.a;
    return true;
  }

  // Connects start node s to goal node g: a monotone search from s to g's arrangement, then
  // the goal tree's moves replayed forward to its root, then the robot's final transit.
  bool try_connect(int s, int g) {
    const Node& ns = start_[static_cast<std::size_t>(s)];
    std::vector<ObjectMove> moves = start_moves(s);
    Arrangement a = ns.a;
    std::optional<Point> robot = ns.robot;
    // Walk g → root; at each node, move the objects that differ to that node's places.
    int k = g;
    while (k >= 0) {
      const Node& ng = goal_[static_cast<std::size_t>(k)];
      const bool root = ng.parent < 0;
      std::vector<std::size_t> which;
      for (std::size_t i = 0; i < a.size(); ++i) {
        if (root && p_.goals[i]) {
          if (!geometry::contains(*p_.goal_regions[i], a[i])) which.push_back(i);
        } else if ((a[i] - ng.a[i]).norm() > b_.connect_tolerance) {
          which.push_back(i);
        }
      }
      const MonotoneResult m = local(a, robot, which, ng.a, root ? p_.goal_regions : no_regions_,
                                     root ? p_.robot_goal : std::nullopt);
      if (!m.solved) return false;
      moves.insert(moves.end(), m.moves.begin(), m.moves.end());
      a = m.reached;
      robot = m.robot_after;
      if (root) {
        if (!p_.goals_reached(a)) return false;
        plan_.moves = std::move(moves);
        plan_.final_transit = m.final_transit;
        plan_.final_arrangement = a;
        return true;
      }
      k = ng.parent;
    }
    return false;
  }

  const RearrangementProblem& p_;
  MovePlanner planner_;
  std::optional<Fmrs> fmrs_;  // set for BiRRT(fmRS)
  PlannerOptions o_;
  BirrtOptions b_;
  QueryContext ctx_;
  Rng rng_;
  std::vector<std::optional<geometry::Polygon>> no_regions_;
  std::vector<Node> start_, goal_;
  Plan plan_;
  long iterations_ = 0;
};

}  // namespace

PlanResult plan_birrt(const RearrangementProblem& problem, const BaselineParams& params,
                      const PlannerOptions& options, const BirrtOptions& birrt) {
  if (birrt.max_extend < 1 || birrt.placement_tries < 1 || !(birrt.connect_tolerance >= 0))
    throw Error(
        "BiRRT options: max_extend and placement_tries must be >= 1, "
        "connect_tolerance >= 0");
  return Birrt(problem, params, options, birrt).run();
}

}  // namespace rearm::baselines
