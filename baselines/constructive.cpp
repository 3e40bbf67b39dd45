#include "baselines/constructive.h"

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "baselines/move_planner.h"
#include "baselines/plan_json.h"
#include "baselines/validator.h"
#include "core/error.h"
#include "core/rng.h"
#include "geometry/box.h"
#include "scenario/scenario_io.h"
#include "scenario/solvability.h"

namespace rearm::baselines {
namespace {

// Rng::derive streams of the spec's seed, past the room's (random_instance.cpp uses < 400).
constexpr std::uint64_t kScatterStream = 1000;
constexpr std::uint64_t kQueryStream = 2000;
constexpr std::uint64_t kRoomStream = 3000;  // seeds of the rooms drawn again
// s of CPU time: no budget (queries are capped by iterations, so timing never decides).
constexpr double kNoTimeLimit = 1e6;  // (its wall-clock net, 10x, still fits steady_clock)
// Steps of the robot's start behind the first pre-grasp pose, largest first (kStartBackoff).
constexpr int kBackoffSteps = 6;
// Points per side of the lattice of other targets in a goal region, and its inset (m).
constexpr int kRegionLattice = 5;
constexpr double kRegionInset = 0.02;

// m: the scatter checks each move back with the placement and transfer margins grown by this
// much, so that the witness, whose landings lie a few cm from the scatter's points (plan.h: the
// off-axis law's heading), finds the same moves free. (The transit margin stays: the pre-grasp
// pose keeps only `standoff` from its own object.)
constexpr double kScatterSlack = 0.04;
// Grasp and release headings the witness tries (the baselines try 16): in crowded rooms the
// pair's straight release approach fits only in narrow cones of directions.
constexpr int kWitnessDirections = 48;
// The witness's straight release approach, in pair offsets ℓ (the baselines: 3): the heading
// error decays like exp(−s/ℓ) along it, so the object lands within mm of its target.
constexpr double kWitnessApproachFactor = 4.5;
// m: a move back whose landing the scatter's check finds farther than this from its target is
// refused (kScatterSlack covers what is left).
constexpr double kLandingTolerance = 0.015;

BaselineParams slack(BaselineParams p) {
  p.placement_margin += 2 * kScatterSlack;
  p.transfer_margin += kScatterSlack / 2;
  return p;
}

// The baselines' primitives with kWitnessDirections grasp and release headings.
BaselineParams witness_params() {
  BaselineParams p;
  p.directions = kWitnessDirections;
  p.approach_factor = kWitnessApproachFactor;
  return p;
}

struct ScatterMove {
  std::size_t object = 0;
  Point from = Point::Zero(), to = Point::Zero();
  bool to_goal = false;  // its reverse ends the object's scatter: back into its goal region
};

std::string name_of(const scenario::InstanceSpec& spec) {
  return "constructive instance (N=" + std::to_string(spec.objects) +
         ", K=" + std::to_string(spec.scatter_move_count()) + ", seed " +
         std::to_string(spec.seed) + ")";
}

// The room with every object standing at its goal point.
scenario::Scenario room_at_goals(const scenario::GeneratedInstance& room) {
  scenario::Scenario s = room.scenario;
  for (std::size_t i = 0; i < room.goals.size(); ++i) s.objects[i].disk.center = room.goals[i];
  return s;
}

class Scatter {
 public:
  Scatter(const scenario::InstanceSpec& spec, const RearrangementProblem& problem, int redraw)
      : spec_(spec),
        problem_(problem),
        planner_(problem, params_),
        checker_(problem, slack(params_)),
        rng_(Rng::derive(spec.seed, kScatterStream + static_cast<std::uint64_t>(redraw))),
        ctx_(kNoTimeLimit,
             Rng::derive(spec.seed, kQueryStream + static_cast<std::uint64_t>(redraw)).next()) {
    ctx_.iterations_per_query = kScatterIterations;
  }

  // The K moves, or nullopt when a move found no object and target, or (K >= N) an object
  // was never moved.
  std::optional<std::vector<ScatterMove>> moves(Arrangement& a) {
    std::vector<ScatterMove> out;
    std::vector<bool> moved(a.size(), false);
    const int k = spec_.scatter_move_count();
    while (static_cast<int>(out.size()) < k) {
      std::optional<ScatterMove> m;
      for (const std::size_t o : candidates(moved, out.empty() ? a.size() : out.back().object)) {
        if ((m = move(a, o, !moved[o]))) break;
      }
      if (!m) {
        why_ = "scatter move " + std::to_string(out.size() + 1) + ": no object found a target in " +
               std::to_string(kScatterTargetTries) + " draws (last: " + last_ + ")";
        return std::nullopt;
      }
      moved[m->object] = true;
      a[m->object] = m->to;
      out.push_back(*m);
    }
    const auto unmoved = std::count(moved.begin(), moved.end(), false);
    if (k >= static_cast<int>(a.size()) && unmoved > 0) {
      why_ = std::to_string(unmoved) + " objects could not leave their goals";
      return std::nullopt;
    }
    return out;
  }

  // The witness: the moves reversed, planned from the robot's start; nullopt when one fails.
  std::optional<Plan> witness(const Arrangement& start, const Point& robot,
                              const std::vector<ScatterMove>& moves) {
    Plan p;
    Arrangement a = start;
    Point x = robot;
    for (auto m = moves.rbegin(); m != moves.rend(); ++m) {
      const std::optional<MoveOutcome> o = back_from(a, x, *m);
      if (!o) {
        why_ = "witness move " + std::to_string(p.moves.size() + 1) + " (" +
               problem_.object_names[m->object] + "): " + last_;
        return std::nullopt;
      }
      a[m->object] = o->move->to;
      x = o->robot_after;
      p.moves.push_back(*o->move);
    }
    p.final_arrangement = a;
    return p;
  }

  // Where the robot starts, and its heading: behind the pre-grasp pose of the witness's first
  // move (the last object the scatter set down), facing the object.
  std::optional<std::pair<Point, double>> robot_start(const Arrangement& a, const ScatterMove& m) {
    const std::optional<MoveOutcome> o = back(planner_, a, std::nullopt, m);
    if (!o) {
      why_ = "the first witness move: " + last_;
      return std::nullopt;
    }
    const double psi = o->move->grasp_heading;
    const double r = problem_.robot_radius, rho = problem_.object_radii[m.object];
    const Point xs = standoff_position(a[m.object], r, rho, psi, params_);
    const auto disks = planner_.disks(a);
    for (int k = kBackoffSteps; k >= 0; --k) {
      const Point x = xs - (kStartBackoff * k / kBackoffSteps) * heading_vector(psi);
      if (planner_.world().segment_free(x, xs, r, params_.transit_margin, disks))
        return std::make_pair(x, psi);
    }
    why_ = "no free robot start at the first pre-grasp pose";
    return std::nullopt;
  }

  // Where each object starts the scatter, inside its goal region: the goal point or, when the
  // pair has no free straight release approach there (approachable; the baselines release along
  // one of `directions` headings), the nearest point of a kRegionLattice² lattice over the
  // region (inset kRegionInset) that has one.
  // Two passes: the second sees every other object at its first-pass home.
  Arrangement homes(const Arrangement& goals) const {
    Arrangement out = goals;
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t i = 0; i < goals.size(); ++i) {
        for (const Point& q : home_candidates(*problem_.goal_regions[i], goals[i])) {
          if (approachable(out, i, q)) {
            out[i] = q;
            break;
          }
        }
      }
    }
    return out;
  }

  const BaselineParams& params() const { return params_; }
  const std::string& why() const { return why_; }  // the last failure

 private:
  std::optional<geometry::Polygon> region(const ScatterMove& m) const {
    return m.to_goal ? problem_.goal_regions[m.object] : std::nullopt;
  }

  // The move that undoes m in arrangement a (its object at m.to), the robot at `robot` (nullopt:
  // no transit), aimed at m.from; with `tolerance`, refused when it lands farther from m.from.
  std::optional<MoveOutcome> back(const MovePlanner& with, const Arrangement& a,
                                  std::optional<Point> robot, const ScatterMove& m,
                                  std::optional<double> tolerance = std::nullopt) {
    MoveOutcome o = with.plan(a, robot, m.object, m.from, region(m), ctx_);
    if (!o.move) {
      last_ = to_string(o.failure);
      return std::nullopt;
    }
    if (tolerance && (o.move->to - m.from).norm() > *tolerance) {
      last_ = "landing off its target";
      return std::nullopt;
    }
    return o;
  }

  // True when object i fits at q, clear of the others in `out` (checker's margins), and some
  // heading offers the pair a free straight release approach among the fixed obstacles and the
  // other objects where `out` has them (homes before i, goal points after).
  bool approachable(const Arrangement& out, std::size_t i, const Point& q) const {
    const BaselineParams& c = checker_.params();
    for (std::size_t j = 0; j < out.size(); ++j) {
      if (j == i) continue;
      if ((out[j] - q).norm() <
          problem_.object_radii[i] + problem_.object_radii[j] + c.placement_margin)
        return false;
    }
    const double r = problem_.robot_radius, rho = problem_.object_radii[i];
    if (!checker_.world().disk_free(q, rho, c.placement_margin, {})) return false;
    const double reach = r + 0.5 * c.grip_gap, pr = pair_radius(r, rho, c);
    const double approach = std::max(c.approach_min, c.approach_factor * pair_offset(rho, c));
    const auto others = checker_.disks(out);
    for (int k = 0; k < c.directions; ++k) {
      const Point u = heading_vector(2 * std::numbers::pi * k / c.directions);
      const Point p_goal = q - reach * u;
      if (checker_.world().segment_free(p_goal - approach * u, p_goal, pr, c.transfer_margin,
                                        others, i))
        return true;
    }
    return false;
  }

  // The goal point, then the lattice points in the region, nearest to the goal point first.
  static std::vector<Point> home_candidates(const geometry::Polygon& region, const Point& goal) {
    const geometry::Box box = geometry::box_of(region);
    const Point lo = box.lo + Point(kRegionInset, kRegionInset);
    const Point size = box.hi - box.lo - Point(2 * kRegionInset, 2 * kRegionInset);
    std::vector<Point> out;
    for (int i = 0; i < kRegionLattice; ++i)
      for (int j = 0; j < kRegionLattice; ++j) {
        const Point q = lo + Point((i + 0.5) / kRegionLattice * size.x(),
                                   (j + 0.5) / kRegionLattice * size.y());
        if (geometry::contains(region, q) && q != goal) out.push_back(q);
      }
    std::stable_sort(out.begin(), out.end(), [&](const Point& x, const Point& y) {
      return (x - goal).squaredNorm() < (y - goal).squaredNorm();
    });
    out.insert(out.begin(), goal);
    return out;
  }

  // The witness's move undoing m from robot position x: MovePlanner::plan from x (grasp
  // headings nearest the robot's bearing first) or, when that finds no way, the grasp the
  // scatter's check took (headings nearest the target's bearing first) reached by a transit.
  std::optional<MoveOutcome> back_from(const Arrangement& a, const Point& x, const ScatterMove& m) {
    if (std::optional<MoveOutcome> o = back(planner_, a, x, m)) return o;
    std::optional<MoveOutcome> o = back(planner_, a, std::nullopt, m);
    if (!o) return std::nullopt;
    const double r = problem_.robot_radius, rho = problem_.object_radii[m.object];
    const Point xs = standoff_position(a[m.object], r, rho, o->move->grasp_heading, params_);
    const QueryResult q = planner_.transit(a, x, xs, ctx_);
    if (q.status != QueryStatus::kSolved) {
      last_ = to_string(MoveFailure::kTransitFailed);
      return std::nullopt;
    }
    o->move->transit = q.path;
    return o;
  }

  // The objects a move tries, in order: those not moved yet, then the others but `last` (the
  // one just moved, unless it is the only object), each group in a random order.
  std::vector<std::size_t> candidates(const std::vector<bool>& moved, std::size_t last) {
    std::vector<std::size_t> fresh, again;
    for (std::size_t i = 0; i < moved.size(); ++i) {
      if (!moved[i])
        fresh.push_back(i);
      else if (i != last || moved.size() == 1)
        again.push_back(i);
    }
    shuffle(fresh);
    shuffle(again);
    fresh.insert(fresh.end(), again.begin(), again.end());
    return fresh;
  }

  void shuffle(std::vector<std::size_t>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng_.index(i)]);
  }

  std::optional<ScatterMove> move(const Arrangement& a, std::size_t o, bool first) {
    const geometry::Box box = geometry::box_of(problem_.workspace);
    const double rho = problem_.object_radii[o];
    for (int t = 0; t < kScatterTargetTries; ++t) {
      const Point b(rng_.uniform(box.lo.x() + rho, box.hi.x() - rho),
                    rng_.uniform(box.lo.y() + rho, box.hi.y() - rho));
      if (geometry::contains(*problem_.goal_regions[o], b)) continue;
      if (!checker_.placement_free(a, o, b)) {
        last_ = "no room for the object";
        continue;
      }
      const ScatterMove m{o, a[o], b, first};
      Arrangement after = a;
      after[o] = b;
      if (back(checker_, after, std::nullopt, m, kLandingTolerance)) return m;
    }
    return std::nullopt;
  }

  const scenario::InstanceSpec& spec_;
  const RearrangementProblem& problem_;
  BaselineParams params_ = witness_params();
  MovePlanner planner_;  // the witness's moves
  MovePlanner checker_;  // the scatter's checks, with kScatterSlack more room
  Rng rng_;
  QueryContext ctx_;
  std::string last_ = "none", why_;
};

// The instance of one scatter stream, or nullopt when the scatter or its witness failed.
std::optional<ConstructiveInstance> draw(const scenario::InstanceSpec& spec,
                                         const scenario::GeneratedInstance& room,
                                         const RearrangementProblem& at_goals, int redraw,
                                         std::string& why) {
  Scatter sc(spec, at_goals, redraw);
  Arrangement a = sc.homes(at_goals.start);
  const auto moves = sc.moves(a);
  const auto start = moves ? sc.robot_start(a, moves->back()) : std::nullopt;
  const auto plan = start ? sc.witness(a, start->first, *moves) : std::nullopt;
  if (!plan) {
    why = sc.why();
    return std::nullopt;
  }

  ConstructiveInstance out;
  out.instance = room;
  scenario::Scenario& s = out.instance.scenario;
  for (std::size_t i = 0; i < a.size(); ++i) s.objects[i].disk.center = a[i];
  s.robot.start = start->first;
  s.robot.heading = start->second;
  s.description += "; constructive: objects scattered from their goals by " +
                   std::to_string(moves->size()) + " moves, witness plan of as many";
  scenario::validate(s);
  const RearrangementProblem p = problem_from_scenario(s);
  const std::vector<std::string> violations = validate_plan(p, *plan, sc.params());
  if (!violations.empty()) {
    why = "the validator: " + violations.front();
    return std::nullopt;
  }
  out.instance.solvability = scenario::check_solvability(s);
  out.instance.witness = plan_to_json(*plan, p.object_names);
  out.witness = *plan;
  out.scatter_redraws = redraw;
  return out;
}

}  // namespace

ConstructiveInstance constructive_instance(const scenario::InstanceSpec& spec) {
  if (spec.goal_class != scenario::GoalClass::kConstructive) {
    throw Error(std::string("constructive_instance: class ") +
                scenario::to_string(spec.goal_class) + " is not constructive");
  }
  std::string why;
  for (int room_redraw = 0; room_redraw <= kRoomRedraws; ++room_redraw) {
    scenario::InstanceSpec room_spec = spec;
    if (room_redraw > 0) {
      room_spec.seed =
          Rng::derive(spec.seed, kRoomStream + static_cast<std::uint64_t>(room_redraw)).next();
    }
    const scenario::GeneratedInstance room = scenario::generate_room(room_spec);
    const RearrangementProblem at_goals = problem_from_scenario(room_at_goals(room));
    for (int redraw = 0; redraw <= kScatterRedraws; ++redraw) {
      if (auto out = draw(spec, room, at_goals, redraw, why)) {
        out->room_redraws = room_redraw;
        if (room_redraw > 0) {
          out->instance.scenario.description +=
              "; room drawn " + std::to_string(room_redraw + 1) + " times";
        }
        return std::move(*out);
      }
    }
  }
  throw Error(name_of(spec) + ": in " + std::to_string(kRoomRedraws + 1) +
              " rooms, no scatter of " + std::to_string(kScatterRedraws + 1) +
              " draws found a target for every move and a witness that reverses it (the last: " +
              why + "); use fewer scatter_moves or a lower footprint_density");
}

scenario::GeneratedInstance generate_constructive(const scenario::InstanceSpec& spec) {
  return constructive_instance(spec).instance;
}

}  // namespace rearm::baselines
