#include "baselines/mcr.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "core/error.h"

namespace rearm::baselines {

namespace {

using geometry::Point;

// The eight grid directions; 0..3 are stored per vertex, 4..7 are their reverses.
constexpr std::array<std::array<int, 2>, 8> kDirs{
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

// What the disk swept from a to b meets: a hard disk (nullopt) or these constraints.
std::optional<ConstraintSet> crossing(const McrQuery& q, const Point& a, const Point& b) {
  for (const geometry::Disk& h : q.hard) {
    if (segment_distance(a, b, h.center, h.center) < q.radius + h.radius + q.margin) {
      return std::nullopt;
    }
  }
  ConstraintSet s;
  for (std::size_t k = 0; k < q.constraints.size(); ++k) {
    const geometry::Disk& c = q.constraints[k];
    if (segment_distance(a, b, c.center, c.center) < q.radius + c.radius + q.margin) s.set(k);
  }
  return s;
}

struct State {
  std::size_t node;  // grid vertex, or V + source, or V + S + target
  ConstraintSet set;
  double g;
  int parent;
  bool stale = false;  // a later label at its vertex dominates it: not expanded
};

struct Label {
  ConstraintSet set;
  double g;
  std::size_t state;
};

// Label a crossed a subset of b's constraints at no greater length.
bool dominates(const ConstraintSet& a, double ga, const ConstraintSet& b, double gb) {
  return (a & ~b).none() && ga <= gb;
}

}  // namespace

McrRoadmap::McrRoadmap(const DiskWorld& world, double grid_step) : world_(world), step_(grid_step) {
  if (!(grid_step > 0) || !std::isfinite(grid_step)) {
    throw Error("MCR roadmap: grid_step must be positive and finite");
  }
  const Point size = world.upper() - world.lower();
  const double cells = (std::floor(size.x() / step_) + 2) * (std::floor(size.y() / step_) + 2);
  if (!(cells <= static_cast<double>(kMaxVertices))) {
    throw Error("MCR roadmap: grid_step " + std::to_string(grid_step) + " m gives more than " +
                std::to_string(kMaxVertices) + " vertices for this workspace");
  }
  nx_ = static_cast<std::size_t>(std::floor(size.x() / step_)) + 2;
  ny_ = static_cast<std::size_t>(std::floor(size.y() / step_)) + 2;
}

Point McrRoadmap::position(std::size_t v) const {
  return world_.lower() + step_ * Point(static_cast<double>(v % nx_), static_cast<double>(v / nx_));
}

McrRoadmap::Cache& McrRoadmap::cache(double clearance) const {
  Cache& c = caches_[clearance];
  if (c.vertex.empty()) {
    c.vertex.assign(vertex_count(), 0);
    c.edge.assign(4 * vertex_count(), 0);
  }
  return c;
}

bool McrRoadmap::vertex_free(Cache& c, std::size_t v, double radius, double margin) const {
  if (c.vertex[v] == 0) c.vertex[v] = world_.disk_free(position(v), radius, margin, {}) ? 1 : 2;
  return c.vertex[v] == 1;
}

// The cache index of the edge from v to its neighbour w in direction dir (0..7): directions
// 0..3 are stored at v, 4..7 as their reverses at w.
std::size_t McrRoadmap::edge_key(std::size_t v, std::size_t w, int dir) {
  return dir < 4 ? 4 * v + static_cast<std::size_t>(dir)
                 : 4 * w + static_cast<std::size_t>(dir - 4);
}

bool McrRoadmap::edge_free(Cache& c, std::size_t v, std::size_t w, int dir, double radius,
                           double margin) const {
  const std::size_t key = edge_key(v, w, dir);
  if (c.edge[key] == 0) {
    c.edge[key] = world_.segment_free(position(v), position(w), radius, margin, {}) ? 1 : 2;
  }
  return c.edge[key] == 1;
}

// The grid vertices within 1.5 steps of p (at most the 16 of the surrounding 4 x 4 block).
std::vector<std::size_t> McrRoadmap::near_vertices(const Point& p) const {
  std::vector<std::size_t> out;
  const Point g = (p - world_.lower()) / step_;
  const long i0 = static_cast<long>(std::floor(g.x())), j0 = static_cast<long>(std::floor(g.y()));
  for (long j = j0 - 1; j <= j0 + 2; ++j) {
    for (long i = i0 - 1; i <= i0 + 2; ++i) {
      if (i < 0 || j < 0 || i >= static_cast<long>(nx_) || j >= static_cast<long>(ny_)) continue;
      const std::size_t v = static_cast<std::size_t>(j) * nx_ + static_cast<std::size_t>(i);
      if ((position(v) - p).norm() <= 1.5 * step_ * std::sqrt(2.0)) out.push_back(v);
    }
  }
  return out;
}

// Hauser's label search over (node, crossed set) states for one query (see mcr.h). Nodes are
// the grid vertices [0, V), the sources [V, V + S) and the targets [V + S, ...).
class McrSearch {
 public:
  McrSearch(const McrRoadmap& r, const McrQuery& q)
      : r_(r),
        q_(q),
        c_(r.cache(q.radius + q.margin)),
        V_(r.vertex_count()),
        S_(q.sources.size()),
        labels_(V_) {
    for (std::size_t t = 0; t < q.targets.size(); ++t) {
      if (!r_.world_.disk_free(q.targets[t], q.radius, q.margin, {})) continue;
      for (const std::size_t v : r_.near_vertices(q.targets[t])) joins_[v].push_back(t);
    }
  }

  McrPath run() {
    for (std::size_t s = 0; s < S_; ++s) {
      if (!r_.world_.disk_free(q_.sources[s], q_.radius, q_.margin, {})) continue;
      if (const auto x = crossing(q_, q_.sources[s], q_.sources[s])) push(V_ + s, *x, 0.0, -1);
    }
    while (!open_.empty()) {
      const std::size_t k = std::get<2>(open_.top());
      open_.pop();
      const std::size_t node = states_[k].node;
      if (states_[k].stale) continue;
      if (node >= V_ + S_) return path(k);  // the first target popped crossed the fewest
      if (node >= V_) {
        expand_source(k);
      } else {
        expand_vertex(k);
      }
    }
    return {};
  }

 private:
  Point point_of(std::size_t node) const {
    return node < V_        ? r_.position(node)
           : node < V_ + S_ ? q_.sources[node - V_]
                            : q_.targets[node - V_ - S_];
  }
  // The distance to the nearest target (admissible), computed once per node.
  double heuristic(std::size_t node) {
    if (node >= h_.size()) h_.resize(node + 1, -1.0);
    if (h_[node] < 0) {
      double h = std::numeric_limits<double>::infinity();
      for (const Point& t : q_.targets) h = std::min(h, (t - point_of(node)).norm());
      h_[node] = h;
    }
    return h_[node];
  }
  bool segment_free(const Point& a, const Point& b) const {
    return r_.world_.segment_free(a, b, q_.radius, q_.margin, {});
  }
  void push(std::size_t node, const ConstraintSet& s, double g, int parent) {
    if (node < V_) {
      auto& labels = labels_[node];
      for (const Label& l : labels) {
        if (dominates(l.set, l.g, s, g)) return;
      }
      std::erase_if(labels, [&](const Label& l) {
        const bool beaten = dominates(s, g, l.set, l.g);
        if (beaten) states_[l.state].stale = true;
        return beaten;
      });
      if (labels.size() >= McrRoadmap::kMaxLabels) return;
      labels.push_back({s, g, states_.size()});
    }
    states_.push_back({node, s, g, parent});
    open_.emplace(s.count(), g + heuristic(node), states_.size() - 1);
  }
  // The straight segment from state k to `node`, already checked against the fixed geometry;
  // `edge`: its key when a grid edge, whose crossing is then computed once per search.
  void relax(std::size_t k, std::size_t node, std::optional<std::size_t> edge = std::nullopt) {
    const State from = states_[k];
    const Point a = point_of(from.node), b = point_of(node);
    std::optional<ConstraintSet> x;
    if (edge) {
      auto [it, fresh] = crossings_.try_emplace(*edge);
      if (fresh) it->second = crossing(q_, a, b);
      x = it->second;
    } else {
      x = crossing(q_, a, b);
    }
    if (x) push(node, from.set | *x, from.g + (b - a).norm(), static_cast<int>(k));
  }
  // A source joins the grid vertices around it, or a target within three steps directly.
  void expand_source(std::size_t k) {
    const Point p = point_of(states_[k].node);
    for (const std::size_t v : r_.near_vertices(p)) {
      if (r_.vertex_free(c_, v, q_.radius, q_.margin) && segment_free(p, r_.position(v)))
        relax(k, v);
    }
    for (std::size_t t = 0; t < q_.targets.size(); ++t) {
      if ((q_.targets[t] - p).norm() <= 3 * r_.step_ && segment_free(p, q_.targets[t]))
        relax(k, V_ + S_ + t);
    }
  }
  void expand_vertex(std::size_t k) {
    const std::size_t node = states_[k].node;
    const long i = static_cast<long>(node % r_.nx_), j = static_cast<long>(node / r_.nx_);
    for (int dir = 0; dir < 8; ++dir) {
      const long ni = i + kDirs[static_cast<std::size_t>(dir)][0];
      const long nj = j + kDirs[static_cast<std::size_t>(dir)][1];
      if (ni < 0 || nj < 0 || ni >= static_cast<long>(r_.nx_) || nj >= static_cast<long>(r_.ny_))
        continue;
      const std::size_t w = static_cast<std::size_t>(nj) * r_.nx_ + static_cast<std::size_t>(ni);
      if (r_.vertex_free(c_, w, q_.radius, q_.margin) &&
          r_.edge_free(c_, node, w, dir, q_.radius, q_.margin))
        relax(k, w, McrRoadmap::edge_key(node, w, dir));
    }
    if (const auto it = joins_.find(node); it != joins_.end()) {
      for (const std::size_t t : it->second) {
        if (segment_free(r_.position(node), q_.targets[t])) relax(k, V_ + S_ + t);
      }
    }
  }
  McrPath path(std::size_t k) const {
    McrPath out;
    out.found = true;
    out.crossed = states_[k].set;
    for (int i = static_cast<int>(k); i >= 0; i = states_[static_cast<std::size_t>(i)].parent) {
      out.path.push_back(point_of(states_[static_cast<std::size_t>(i)].node));
    }
    std::reverse(out.path.begin(), out.path.end());
    return out;
  }

  using Key = std::tuple<std::size_t, double, std::size_t>;  // |set|, g + h, state
  const McrRoadmap& r_;
  const McrQuery& q_;
  McrRoadmap::Cache& c_;
  std::size_t V_, S_;
  std::vector<std::vector<Label>> labels_;
  std::map<std::size_t, std::vector<std::size_t>> joins_;  // grid vertex -> targets it joins
  std::unordered_map<std::size_t, std::optional<ConstraintSet>> crossings_;  // grid edges
  std::vector<double> h_;
  std::vector<State> states_;
  std::priority_queue<Key, std::vector<Key>, std::greater<>> open_;
};

McrPath McrRoadmap::search(const McrQuery& q) const {
  if (q.constraints.size() > kMaxConstraints) {
    throw Error("MCR: at most " + std::to_string(kMaxConstraints) + " constraints");
  }
  return McrSearch(*this, q).run();
}

}  // namespace rearm::baselines
