#include "baselines/validator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <sstream>

#include "geometry/convex.h"
#include "geometry/distance.h"

namespace rearm::baselines {
namespace {

// Rounding slack of the exact tests (distance of a segment to the handled object, placements):
// r + ρ + gap − |x − o| loses a few ulps of metres-sized numbers.
constexpr double kRoundingSlack = 1e-12;  // m
// A held object's centre against the grip pose of the robot's start (held_at_start): the
// replanning variant reads both from Box2D, which keeps positions in float (5e-7 m at 10 m from
// the origin), after a dock that stops within 1e-6 m of its gap.
constexpr double kHeldTolerance = 1e-5;  // m

std::string str(double x) {
  std::ostringstream os;
  os.precision(6);
  os << x;
  return os.str();
}
std::string str(const Point& p) { return "(" + str(p.x()) + ", " + str(p.y()) + ")"; }

// The robot's heading at the end of a pair-centre polyline tracked by the off-axis law from
// heading psi0: along a segment of direction θ, dψ/ds = sin(θ − ψ)/ℓ (ω = u·h⊥/ℓ with u along
// the segment, per unit of arc length). Integrated numerically by RK4 with steps <= ℓ/
// kHeadingStepsPerOffset (global error ~1e-10 rad), independently of the planners' closed form.
constexpr double kHeadingStepsPerOffset = 50;
double integrated_heading(const std::vector<Point>& path, double psi0, double ell) {
  double psi = psi0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Point d = path[k + 1] - path[k];
    const double len = d.norm();
    if (len == 0) continue;
    const double theta = std::atan2(d.y(), d.x());
    const auto f = [&](double p) { return std::sin(theta - p) / ell; };
    const int n = std::max(1, static_cast<int>(std::ceil(len * kHeadingStepsPerOffset / ell)));
    const double h = len / n;
    for (int j = 0; j < n; ++j) {
      const double k1 = f(psi), k2 = f(psi + 0.5 * h * k1), k3 = f(psi + 0.5 * h * k2),
                   k4 = f(psi + h * k3);
      psi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  return psi;
}

class Walker {
 public:
  Walker(const RearrangementProblem& problem, const BaselineParams& params)
      : pb_(problem), pr_(params), a_(problem.start), x_(problem.robot_start) {}

  std::vector<std::string> run(const Plan& plan) {
    if (!consistent() || !finite(plan)) return msgs_;
    for (std::size_t k = 0; k < plan.moves.size(); ++k) {
      if (plan.moves[k].object >= pb_.object_count()) {
        add("move " + std::to_string(k) + ": object index " + std::to_string(plan.moves[k].object) +
            " out of range (" + std::to_string(pb_.object_count()) + " objects)");
        return msgs_;
      }
    }
    for (std::size_t k = 0; k < plan.moves.size(); ++k) walk_move(k, plan.moves[k]);
    walk_end(plan);
    return msgs_;
  }

 private:
  const RearrangementProblem& pb_;
  const BaselineParams& pr_;
  std::vector<std::string> msgs_;
  Arrangement a_;  // the walked arrangement
  Point x_;        // the walked robot centre (or, during a transfer, pair centre)

  void add(const std::string& m) { msgs_.push_back(m); }
  double r() const { return pb_.robot_radius; }

  // --- input ---
  bool consistent() {
    const std::size_t n = pb_.object_count();
    if (pb_.object_radii.size() != n || pb_.object_names.size() != n || pb_.goals.size() != n ||
        pb_.goal_regions.size() != n || pb_.goal_region_names.size() != n) {
      add("problem: the object lists (start, radii, names, goals) differ in size");
      return false;
    }
    return true;
  }

  void check_number(double v, const std::string& what, bool& ok) {
    if (!std::isfinite(v)) {
      add(what + " is not finite (" + str(v) + ")");
      ok = false;
    }
  }
  void check_point(const Point& p, const std::string& what, bool& ok) {
    if (!p.allFinite()) {
      add(what + " is not finite " + str(p));
      ok = false;
    }
  }
  void check_path(const std::vector<Point>& path, const std::string& what, bool& ok) {
    for (std::size_t j = 0; j < path.size(); ++j) {
      check_point(path[j], what + " vertex " + std::to_string(j), ok);
    }
  }

  bool finite(const Plan& plan) {
    bool ok = true;
    check_point(pb_.robot_start, "problem: the robot's start", ok);
    check_number(pb_.robot_heading, "problem: the robot's start heading", ok);
    check_number(pb_.robot_radius, "problem: the robot radius", ok);
    for (std::size_t i = 0; i < pb_.object_count(); ++i) {
      check_point(pb_.start[i], "problem: the start of " + pb_.object_names[i], ok);
      check_number(pb_.object_radii[i], "problem: the radius of " + pb_.object_names[i], ok);
    }
    check_number(pr_.standoff, "params: standoff", ok);
    check_number(pr_.grip_gap, "params: grip_gap", ok);
    check_number(pr_.approach_min, "params: approach_min", ok);
    check_number(pr_.approach_factor, "params: approach_factor", ok);
    for (std::size_t k = 0; k < plan.moves.size(); ++k) {
      const ObjectMove& m = plan.moves[k];
      const std::string w = "move " + std::to_string(k) + ":";
      check_point(m.from, w + " from", ok);
      check_point(m.to, w + " to", ok);
      check_number(m.grasp_heading, w + " grasp_heading", ok);
      check_number(m.release_heading, w + " release_heading", ok);
      check_path(m.transit, w + " transit", ok);
      check_path(m.transfer, w + " transfer", ok);
    }
    check_path(plan.final_transit, "the final transit", ok);
    check_path(plan.final_arrangement, "final_arrangement: object", ok);
    return ok;
  }

  // --- geometry ---
  std::vector<geometry::Disk> disks() const {
    std::vector<geometry::Disk> d(a_.size());
    for (std::size_t i = 0; i < a_.size(); ++i) d[i] = geometry::Disk{a_[i], pb_.object_radii[i]};
    return d;
  }
  double clearance(const Point& c, double radius, std::optional<std::size_t> skip) const {
    return geometry::disk_clearance(pb_.workspace, pb_.obstacles, disks(), c, radius, skip);
  }
  // What the disk at c is nearest to (for the messages).
  std::string nearest(const Point& c, double radius, std::optional<std::size_t> skip) const {
    std::string what = "the workspace boundary";
    double best = -geometry::signed_distance(pb_.workspace, c) - radius;
    for (std::size_t j = 0; j < pb_.obstacles.size(); ++j) {
      const double d = geometry::signed_distance(pb_.obstacles[j], c) - radius;
      if (d < best) {
        best = d;
        what = "obstacle '" +
               (j < pb_.obstacle_names.size() ? pb_.obstacle_names[j] : std::to_string(j)) + "'";
      }
    }
    for (std::size_t i = 0; i < a_.size(); ++i) {
      if (skip && *skip == i) continue;
      const double d = (a_[i] - c).norm() - pb_.object_radii[i] - radius;
      if (d < best) {
        best = d;
        what = "object " + pb_.object_names[i];
      }
    }
    return what;
  }

  // The sweep proof of validator.h for the disk from a to b; a message when it fails.
  void sweep(const Point& a, const Point& b, double radius, std::optional<std::size_t> skip,
             const std::string& what) {
    const double len = (b - a).norm();
    const std::size_t m =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / kSampleSpacing)));
    const double delta = len / static_cast<double>(m);
    double prev = clearance(a, radius, skip);
    double worst_bound = prev;  // lower bound of the clearance on the worst piece
    Point worst_at = a;
    double worst_c = prev;
    for (std::size_t j = 1; j <= m; ++j) {
      const Point s = a + (b - a) * (static_cast<double>(j) / static_cast<double>(m));
      const double c = clearance(s, radius, skip);
      const double bound = 0.5 * (prev + c - delta);
      if (bound < worst_bound) {
        worst_bound = bound;
        worst_at =
            c < prev ? s : a + (b - a) * (static_cast<double>(j - 1) / static_cast<double>(m));
        worst_c = std::min(c, prev);
      }
      prev = c;
    }
    if (worst_bound < 0) {
      add(what + " from " + str(a) + " to " + str(b) + ": the disk of radius " + str(radius) +
          " has clearance " + str(worst_c) + " m to " + nearest(worst_at, radius, skip) + " at " +
          str(worst_at) +
          (worst_c >= 0 ? " (too close to prove >= 0 by " + str(kSampleSpacing) + " m samples)"
                        : ""));
    }
  }
  void sweep_path(const std::vector<Point>& path, double radius, std::optional<std::size_t> skip,
                  const std::string& what) {
    if (path.size() == 1) sweep(path[0], path[0], radius, skip, what + " vertex 0");
    for (std::size_t j = 0; j + 1 < path.size(); ++j) {
      sweep(path[j], path[j + 1], radius, skip, what + " segment " + std::to_string(j));
    }
  }
  // Exact: the robot disk along [a, b] keeps clearance >= 0 to object i.
  void keep_off(const Point& a, const Point& b, std::size_t i, const std::string& what) {
    const Point n = geometry::nearest_on_segment(a, b, a_[i]);
    const double c = (a_[i] - n).norm() - r() - pb_.object_radii[i];
    if (c < -kRoundingSlack) {
      add(what + " from " + str(a) + " to " + str(b) + ": the robot overlaps " +
          pb_.object_names[i] + " (clearance " + str(c) + " m at " + str(n) + ")");
    }
  }
  void near(const Point& p, const Point& q, const std::string& what) {
    const double d = (p - q).norm();
    if (d > kContinuityTolerance) {
      add(what + ": " + str(p) + " is " + str(d) + " m from " + str(q));
    }
  }

  // --- the walk ---
  void walk_move(std::size_t k, const ObjectMove& m) {
    const std::size_t i = m.object;
    const std::string w = "move " + std::to_string(k) + " (" + pb_.object_names[i] + ")";
    const double rho = pb_.object_radii[i];
    const double ell = pair_offset(rho, pr_);
    near(m.from, a_[i], w + ": from is not the object's position");

    Point pair_start;
    if (m.held_at_start) {
      if (k != 0) add(w + ": held_at_start on a move other than the first");
      const Point h = heading_vector(pb_.robot_heading);
      const Point held = pb_.robot_start + (r() + rho + pr_.grip_gap) * h;
      if ((m.from - held).norm() > kHeldTolerance) {
        add(w + ": held_at_start, but the object is not where the robot's start pose holds it: " +
            str(m.from) + " is " + str((m.from - held).norm()) + " m from " + str(held));
      }
      pair_start = pb_.robot_start + ell * h;
    } else {
      const Point standoff = standoff_position(m.from, r(), rho, m.grasp_heading, pr_);
      const Point grip = grip_position(m.from, r(), rho, m.grasp_heading, pr_);
      if (m.transit.empty()) {
        add(w + ": empty transit");
      } else {
        near(m.transit.front(), x_, w + ": the transit does not start where the robot is");
        near(m.transit.back(), standoff,
             w + ": the transit does not end at the standoff pose for the grasp heading");
        sweep_path(m.transit, r(), std::nullopt, w + ": transit");
      }
      sweep(standoff, grip, r(), i, w + ": dock");
      keep_off(standoff, grip, i, w + ": dock");
      pair_start = grip + ell * heading_vector(m.grasp_heading);
    }

    const Point hr = heading_vector(m.release_heading);
    const Point pair_end = m.to - (r() + 0.5 * pr_.grip_gap) * hr;
    if (m.transfer.size() < 2) {
      add(w + ": the transfer has " + std::to_string(m.transfer.size()) +
          " vertices; it needs a start and the approach");
    } else {
      near(m.transfer.front(), pair_start,
           w + ": the transfer does not start at the pair centre of the grip");
      near(m.transfer.back(), pair_end,
           w + ": the transfer does not end at the pair centre of the release");
      const double approach = (m.transfer.back() - m.transfer[m.transfer.size() - 2]).norm();
      const double need = std::max(pr_.approach_min, pr_.approach_factor * ell);
      if (approach < need - kContinuityTolerance) {
        add(w + ": the transfer's last segment (the approach) is " + str(approach) +
            " m long; it needs >= " + str(need) + " m");
      }
      const double psi0 = m.held_at_start ? pb_.robot_heading : m.grasp_heading;
      const double psi = integrated_heading(m.transfer, psi0, ell);
      const double off = std::abs(std::remainder(m.release_heading - psi, 2 * std::numbers::pi));
      if (off > kReleaseHeadingTolerance) {
        add(w + ": the release heading " + str(m.release_heading) +
            " rad is not the heading the off-axis law reaches along the transfer, " + str(psi) +
            " rad (off by " + str(off) + " rad): the object would not land at `to`");
      }
      sweep_path(m.transfer, pair_radius(r(), rho, pr_), i, w + ": transfer");
    }

    // The release: the object at `to`.
    a_[i] = m.to;
    const double placed = clearance(m.to, rho, i);
    if (placed < -kRoundingSlack) {
      add(w + ": the object released at " + str(m.to) + " overlaps " + nearest(m.to, rho, i) +
          " (clearance " + str(placed) + " m)");
    }
    const Point release = grip_position(m.to, r(), rho, m.release_heading, pr_);
    const Point back = standoff_position(m.to, r(), rho, m.release_heading, pr_);
    sweep(release, back, r(), i, w + ": back-off");
    keep_off(release, back, i, w + ": back-off");
    x_ = back;
  }

  void walk_end(const Plan& plan) {
    if (!plan.final_transit.empty()) {
      near(plan.final_transit.front(), x_, "the final transit does not start where the robot is");
      sweep_path(plan.final_transit, r(), std::nullopt, "the final transit");
      x_ = plan.final_transit.back();
    }
    if (pb_.robot_goal_region && !geometry::contains(*pb_.robot_goal_region, x_)) {
      add("the robot ends at " + str(x_) + ", outside its goal region '" + pb_.robot_goal_name +
          "'");
    }
    if (plan.final_arrangement.size() != a_.size()) {
      add("final_arrangement has " + std::to_string(plan.final_arrangement.size()) +
          " objects, the problem " + std::to_string(a_.size()));
    } else {
      for (std::size_t i = 0; i < a_.size(); ++i) {
        near(plan.final_arrangement[i], a_[i],
             "final_arrangement: " + pb_.object_names[i] + " is not where the moves leave it");
      }
    }
    for (std::size_t i = 0; i < a_.size(); ++i) {
      if (pb_.goal_regions[i] && !geometry::contains(*pb_.goal_regions[i], a_[i])) {
        add(pb_.object_names[i] + " ends at " + str(a_[i]) + ", outside its goal region '" +
            pb_.goal_region_names[i] + "': goal not reached");
      }
    }
  }
};

}  // namespace

std::vector<std::string> validate_plan(const RearrangementProblem& problem, const Plan& plan,
                                       const BaselineParams& params) {
  return Walker(problem, params).run(plan);
}

}  // namespace rearm::baselines
