#include "baselines/executor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "sim/sim_config.h"

namespace rearm::baselines {
namespace {

// A vertex this close to the robot (or the pair centre) is reached: its leg is skipped. Plans
// are continuous to 1e-6 m (validator.h), and a straight drive's last step lands on its target
// to rounding (v = remaining / dt, the world's exact unicycle step).
constexpr double kVertexTolerance = 1e-6;  // m
// A turn in place ends within this of its heading. Its last step lands on it to rounding
// (ω = error / dt), so this only absorbs the rounding.
constexpr double kHeadingTolerance = 1e-9;  // rad
// k of the transfer law u = s·t̂ + k·(p_ref − p): the tracking error decays like exp(−α·k·t)
// (α the saturation factor). The law is exact up to the sinc(ω·dt/2) shortening of a step
// (< 1e-5 relative), so the gain only has to absorb ~1e-8 m per step and float contacts; 2/s
// leaves α·k·dt <= 0.02, far from the discrete-time stability limit 2.
constexpr double kTransferGain = 2.0;  // 1/s
// The mean heading ψ + ω·dt/2 at which v and ω are computed is a fixed point of ω; each
// iteration shrinks its error by ~|u|·dt/(2ℓ) (< 0.05 for ℓ >= 4 cm), so 4 leave < 1e-6 of the
// first iterate's 5 mrad.
constexpr int kMeanHeadingIterations = 4;
// After the reference reaches the transfer's last vertex the pair centre converges to it until
// within kSettleTolerance, for at most kSettleTime (then it goes on if within the tracking
// tolerance; only contacts keep it away that long).
constexpr double kSettleTolerance = 1e-6;  // m
constexpr double kSettleTime = 2.0;        // s
// A straight drive that has not come kStallProgress closer to its target in kStallTime is
// blocked (a contact head-on; sideways contacts trip the tracking tolerance first).
constexpr double kStallProgress = 1e-4;  // m
constexpr double kStallTime = 3.0;       // s
// Relative slack of the time budget and of the check of ExecutionOptions::dt against the world.
constexpr double kTimeSlack = 1e-9;

constexpr double kPi = std::numbers::pi;

std::string str(double x) {
  std::ostringstream os;
  os.precision(6);
  os << x;
  return os.str();
}
std::string str(const Point& p) { return "(" + str(p.x()) + ", " + str(p.y()) + ")"; }

double wrap(double a) { return std::remainder(a, 2 * kPi); }
Point perp(const Point& h) { return Point(-h.y(), h.x()); }

// Distance from x to the line through a and b (to a when they coincide).
double line_distance(const Point& a, const Point& b, const Point& x) {
  const Point d = b - a;
  const double n = d.norm();
  if (n == 0) return (x - a).norm();
  return std::abs(d.x() * (x - a).y() - d.y() * (x - a).x()) / n;
}

bool finite(const std::vector<Point>& path) {
  return std::all_of(path.begin(), path.end(), [](const Point& p) { return p.allFinite(); });
}

enum class Phase {
  kIdle,         // nothing loaded, or the plan ended
  kStartMove,    // about to begin moves[move]
  kTransit,      // following moves[move].transit
  kTurnToGrasp,  // turning in place to grasp_heading
  kDock,         // driving straight to the grip gap
  kTransfer,     // tracking moves[move].transfer with the pair centre
  kStill,        // the still step before the release
  kBackOff,      // driving straight back from the released object
  kFinalTransit,
};

struct Command {
  double v = 0, omega = 0;
};

enum class Outcome { kArrived, kCommand, kFailed };

// What a tick of a phase gave: a command to step, the next phase (entered this tick), or the
// plan's end (completed or failed, the log says which).
enum class Step { kCommand, kNext, kEnd };

// kCommand and kFailed as steps; kArrived: nullopt, the phase goes on to its next.
std::optional<Step> unless_arrived(Outcome o) {
  if (o == Outcome::kCommand) return Step::kCommand;
  if (o == Outcome::kFailed) return Step::kEnd;
  return std::nullopt;
}

}  // namespace

const char* to_string(ExecStatus s) {
  switch (s) {
    case ExecStatus::kCompleted:
      return "completed";
    case ExecStatus::kFailed:
      return "failed";
    case ExecStatus::kTimeout:
      return "timeout";
    case ExecStatus::kInterrupted:
      return "interrupted";
  }
  return "?";
}

struct PlanExecutor::Impl {
  sim::SimWorld& world;
  const RearrangementProblem& problem;
  BaselineParams params;
  ExecutionOptions options;
  ExecutionLog log;

  Plan plan;
  Phase phase = Phase::kIdle;
  std::size_t move = 0;
  std::optional<std::size_t> open_action;  // index into log.actions
  bool dt_checked = false;
  int collisions_before = 0;  // the world's count when the executor took it over

  // Polyline following (transit, final transit): the vertices, the next one, and the leg's start
  // once the robot turned towards it.
  std::vector<Point> vertices;
  std::size_t next = 0;
  bool turning = true;
  Point leg_start = Point::Zero();
  // A straight drive (transit legs, dock, back-off): from a to b; stall monitor.
  Point drive_from = Point::Zero(), drive_to = Point::Zero();
  double best_remaining = 0, best_time = 0;
  // Transfer: the pair centre's polyline, its cumulative lengths, the reference's arc length σ.
  std::vector<Point> track;
  std::vector<double> cumulative;
  double sigma = 0, ell = 0;
  double arrived_time = -1;    // when σ reached the end (< 0: not yet)
  double pending_advance = 0;  // σ's advance once the step is taken

  // The previous step's state, for the path lengths.
  Point prev_robot = Point::Zero();
  Arrangement prev_objects;

  Impl(sim::SimWorld& w, const RearrangementProblem& p, const BaselineParams& b,
       const ExecutionOptions& o)
      : world(w), problem(p), params(b), options(o) {}

  double now() const { return world.time(); }
  double r() const { return problem.robot_radius; }
  double rho(std::size_t i) const { return problem.object_radii[i]; }
  const ObjectMove& current() const { return plan.moves[move]; }
  std::string name(std::size_t i) const { return problem.object_names[i]; }
  std::string what() const {
    return "move " + std::to_string(move) + " (" + name(current().object) + ")";
  }
  bool running() const { return phase != Phase::kIdle; }

  Arrangement objects() const {
    Arrangement a(world.object_count());
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = world.object_center(i);
    return a;
  }
  Point pair_center() const {
    const sim::Pose p = world.pose();
    return p.x + ell * heading_vector(p.psi);
  }

  // --- actions and endings ---
  void open(const std::string& action) {
    close("interrupted");
    log.actions.push_back(ExecutedAction{action, now(), now(), ""});
    open_action = log.actions.size() - 1;
  }
  void close(const std::string& outcome) {
    if (!open_action) return;
    log.actions[*open_action].t_end = now();
    log.actions[*open_action].outcome = outcome;
    open_action.reset();
  }
  void end(ExecStatus status, const std::string& reason, const std::string& outcome) {
    close(outcome);
    log.status = status;
    log.reason = reason;
    phase = Phase::kIdle;
  }
  Outcome fail(const std::string& reason) {
    end(ExecStatus::kFailed, reason, "failed");
    return Outcome::kFailed;
  }

  // --- primitives ---
  Outcome turn_to(double theta, Command& c) {
    const double err = wrap(theta - world.pose().psi);
    if (std::abs(err) <= kHeadingTolerance) return Outcome::kArrived;
    c.v = 0;
    c.omega = std::clamp(err / options.dt, -problem.omega_max, problem.omega_max);
    return Outcome::kCommand;
  }

  void start_drive(const Point& a, const Point& b) {
    drive_from = a;
    drive_to = b;
    best_remaining = (b - a).norm();
    best_time = now();
  }
  // Straight along the heading (forward or backward) to drive_to.
  Outcome drive(const std::string& what, Command& c) {
    const sim::Pose p = world.pose();
    const double off = line_distance(drive_from, drive_to, p.x);
    if (off > options.tracking_tolerance) {
      return fail(what + ": the robot is " + str(off) + " m off its segment at " + str(p.x));
    }
    const double remaining = (drive_to - p.x).dot(heading_vector(p.psi));
    if (std::abs(remaining) <= kVertexTolerance) return Outcome::kArrived;
    if (std::abs(remaining) < best_remaining - kStallProgress) {
      best_remaining = std::abs(remaining);
      best_time = now();
    } else if (now() - best_time > kStallTime) {
      return fail(what + ": blocked at " + str(p.x) + ", " + str(std::abs(remaining)) +
                  " m before " + str(drive_to));
    }
    c.v = std::clamp(remaining / options.dt, -problem.v_max, problem.v_max);
    c.omega = 0;
    return Outcome::kCommand;
  }

  // Starts following `path` (robot centre) from the robot's position.
  Outcome start_polyline(const std::vector<Point>& path, const std::string& what) {
    const Point x = world.pose().x;
    if (!path.empty() && (path.front() - x).norm() > options.tracking_tolerance) {
      return fail(what + " starts at " + str(path.front()) + ", " + str((path.front() - x).norm()) +
                  " m from the robot at " + str(x));
    }
    vertices = path;
    next = 1;
    turning = true;
    return Outcome::kCommand;
  }
  Outcome follow_polyline(const std::string& what, Command& c) {
    while (next < vertices.size()) {
      const Point x = world.pose().x;
      const Point b = vertices[next];
      if (turning) {
        if ((b - x).norm() <= kVertexTolerance) {
          ++next;
          continue;
        }
        const Point d = b - x;
        const Outcome o = turn_to(std::atan2(d.y(), d.x()), c);
        if (o == Outcome::kCommand) return o;
        turning = false;
        start_drive(x, b);
      }
      const Outcome o = drive(what + ", leg " + std::to_string(next), c);
      if (o != Outcome::kArrived) return o;
      ++next;
      turning = true;
    }
    return Outcome::kArrived;
  }

  // --- the transfer ---
  Outcome start_transfer() {
    const ObjectMove& m = current();
    ell = pair_offset(rho(m.object), params);
    const Point p = pair_center();
    if (m.transfer.empty()) return fail(what() + ": empty transfer");
    if ((m.transfer.front() - p).norm() > options.tracking_tolerance) {
      return fail(what() + ": the transfer starts at " + str(m.transfer.front()) + ", " +
                  str((m.transfer.front() - p).norm()) + " m from the pair centre " + str(p));
    }
    track = m.transfer;
    track.front() = p;
    cumulative.assign(track.size(), 0);
    for (std::size_t k = 1; k < track.size(); ++k) {
      cumulative[k] = cumulative[k - 1] + (track[k] - track[k - 1]).norm();
    }
    sigma = 0;
    arrived_time = -1;
    return Outcome::kCommand;
  }
  // The segment σ lies on, preferring the one that starts at σ.
  std::size_t segment_at(double s) const {
    std::size_t k = 0;
    while (k + 2 < track.size() && cumulative[k + 1] <= s) ++k;
    return k;
  }
  Point reference(double s) const {
    if (track.size() == 1) return track.front();
    const std::size_t k = segment_at(s);
    const double len = cumulative[k + 1] - cumulative[k];
    if (len == 0) return track[k + 1];
    const double t = std::clamp((s - cumulative[k]) / len, 0.0, 1.0);
    return track[k] + t * (track[k + 1] - track[k]);
  }
  Outcome transfer(Command& c) {
    const double total = cumulative.back();
    const sim::Pose pose = world.pose();
    const Point p = pose.x + ell * heading_vector(pose.psi);
    const Point e = reference(sigma) - p;
    if (e.norm() > options.tracking_tolerance) {
      return fail(what() + ": the pair centre is " + str(e.norm()) + " m off its reference at " +
                  str(p));
    }
    double s = 0;
    Point tangent = Point::Zero();
    if (sigma >= total) {
      if (arrived_time < 0) arrived_time = now();
      if (e.norm() <= kSettleTolerance || now() - arrived_time >= kSettleTime) {
        return Outcome::kArrived;
      }
    } else {
      const std::size_t k = segment_at(sigma);
      const double len = cumulative[k + 1] - cumulative[k];
      if (len > 0) tangent = (track[k + 1] - track[k]) / len;
      // The reference stops exactly on the next vertex, so p turns the corner there.
      s = std::min(problem.v_max, (cumulative[k + 1] - sigma) / options.dt);
      if (len == 0) {  // a repeated vertex: step over it
        sigma = cumulative[k + 1];
        return transfer(c);
      }
    }
    const Point u = s * tangent + kTransferGain * e;
    // The gripping Jacobian at the step's mean heading: the exact unicycle step then moves p by
    // dt·sinc(ω·dt/2)·α·u.
    double alpha = 1, v = 0, omega = 0;
    for (int it = 0; it < kMeanHeadingIterations; ++it) {
      const Point h = heading_vector(pose.psi + 0.5 * omega * options.dt);
      const double vh = u.dot(h);
      const double wh = u.dot(perp(h)) / ell;
      alpha = 1;
      if (std::abs(vh) > problem.v_max) alpha = problem.v_max / std::abs(vh);
      if (std::abs(wh) > problem.omega_max)
        alpha = std::min(alpha, problem.omega_max / std::abs(wh));
      v = alpha * vh;
      omega = alpha * wh;
    }
    c.v = v;
    c.omega = omega;
    pending_advance = alpha * s * options.dt;
    return Outcome::kCommand;
  }

  // Phase::kStartMove: the next move's first phase (or the final transit); false when the plan
  // ended (completed, or failed with its reason).
  bool start_move() {
    if (move >= plan.moves.size()) {
      if (world.held()) {
        fail("the plan ends with " + name(*world.held()) + " held");
        return false;
      }
      if (plan.final_transit.empty()) {
        end(ExecStatus::kCompleted, "", "succeeded");
        return false;
      }
      open(problem.robot_goal ? "move(" + problem.robot_goal_name + ")" : "move");
      if (start_polyline(plan.final_transit, "the final transit") == Outcome::kFailed) {
        return false;
      }
      phase = Phase::kFinalTransit;
      return true;
    }
    const ObjectMove& m = current();
    const std::optional<std::size_t> held = world.held();
    if (m.held_at_start) {
      if (held != m.object) {
        fail(what() + " starts holding " + name(m.object) + " but the robot holds " +
             (held ? name(*held) : std::string("nothing")));
        return false;
      }
      open_release();
      if (start_transfer() == Outcome::kFailed) return false;
      phase = Phase::kTransfer;
      return true;
    }
    if (held) {
      fail(what() + " starts with a transit but the robot holds " + name(*held));
      return false;
    }
    open("grasp(" + name(m.object) + ")");
    if (start_polyline(m.transit, what() + ": the transit") == Outcome::kFailed) return false;
    phase = Phase::kTransit;
    return true;
  }

  // Phase::kDock: drives to the object, then grips it and starts the transfer (kArrived, the
  // phase now kTransfer); kCommand while docking; kFailed with the reason.
  Outcome dock(Command& c) {
    const Outcome o = drive(what() + ": dock", c);
    if (o != Outcome::kArrived) return o;
    const std::size_t i = current().object;
    if (!world.grip(i)) {
      const sim::Pose p = world.pose();
      const Point rel = world.object_center(i) - p.x;
      fail("grip of " + name(i) + " failed: gap " + str(rel.norm() - r() - rho(i)) +
           " m, bearing " + str(wrap(std::atan2(rel.y(), rel.x()) - p.psi)) +
           " rad from the heading");
      return Outcome::kFailed;
    }
    close("succeeded");
    open_release();
    if (start_transfer() == Outcome::kFailed) return Outcome::kFailed;
    phase = Phase::kTransfer;
    return Outcome::kArrived;
  }

  // --- the phases, one member each (kPhases below lists them with their sweeps) ---
  Step idle_step(Command&) { return Step::kEnd; }
  Step start_step(Command&) { return start_move() ? Step::kNext : Step::kEnd; }
  Step transit_step(Command& c) {
    if (const auto s = unless_arrived(follow_polyline(what() + ": transit", c))) return *s;
    phase = Phase::kTurnToGrasp;
    return Step::kNext;
  }
  Step turn_step(Command& c) {
    if (turn_to(current().grasp_heading, c) == Outcome::kCommand) return Step::kCommand;
    start_dock();
    phase = Phase::kDock;
    return Step::kNext;
  }
  Step dock_step(Command& c) {
    if (const auto s = unless_arrived(dock(c))) return *s;
    return Step::kNext;
  }
  Step transfer_step(Command& c) {
    if (const auto s = unless_arrived(transfer(c))) return *s;
    phase = Phase::kStill;
    c = Command{};  // the still step; the release follows it
    return Step::kCommand;
  }
  Step still_step(Command&) {
    world.release();
    const sim::Pose p = world.pose();
    start_drive(p.x, p.x - (params.standoff - params.grip_gap) * heading_vector(p.psi));
    phase = Phase::kBackOff;
    return Step::kNext;
  }
  Step back_off_step(Command& c) {
    if (const auto s = unless_arrived(drive(what() + ": back-off", c))) return *s;
    close("succeeded");
    ++log.moves_done;
    ++move;
    phase = Phase::kStartMove;
    return Step::kNext;
  }
  Step final_step(Command& c) {
    if (const auto s = unless_arrived(follow_polyline("the final transit", c))) return *s;
    end(ExecStatus::kCompleted, "", "succeeded");
    return Step::kEnd;
  }

  // Advances through instantaneous phase changes (grip, release) until a command is due;
  // nullopt when the plan ended.
  std::optional<Command> next_command();

  void open_release() {
    const std::size_t i = current().object;
    const std::string& region = problem.goal_region_names[i];
    open("release(" + name(i) + (region.empty() ? "" : "," + region) + ")");
  }

  // The dock drives standoff − grip_gap ahead, corrected to the object's actual position (it may
  // rest a few mm from where the plan put it) when the correction is within the tracking
  // tolerance: the robot stops with its boundary grip_gap from the object's.
  void start_dock() {
    const ObjectMove& m = current();
    const sim::Pose p = world.pose();
    const Point h = heading_vector(p.psi);
    double d = params.standoff - params.grip_gap;
    const Point rel = world.object_center(m.object) - p.x;
    const double along = rel.dot(h);
    const double across2 = rel.squaredNorm() - along * along;
    const double reach = r() + rho(m.object) + params.grip_gap;
    if (along > 0 && reach * reach >= across2) {
      const double adjusted = along - std::sqrt(reach * reach - across2);
      if (adjusted >= 0 && std::abs(adjusted - d) <= options.tracking_tolerance) d = adjusted;
    }
    start_drive(p.x, p.x + d * h);
  }

  // The robot's disk and the held object's, per kind of thing (ExecutionLog::clearance_by_kind).
  void lower_by_kind(const Point& x, const Arrangement& a) {
    std::vector<geometry::Disk> disks(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      disks[i] = geometry::Disk{a[i], problem.object_radii[i]};
    const std::optional<std::size_t> held = world.held();
    geometry::ClearanceByKind& c = log.clearance_by_kind;
    c.lower(problem.workspace, problem.obstacles, problem.familiar_count, disks, x,
            problem.robot_radius, held);
    if (held) {
      c.lower(problem.workspace, problem.obstacles, problem.familiar_count, disks, a[*held],
              disks[*held].radius, held);
    }
  }

  // --- one step ---
  void record_step() {
    const sim::Pose p = world.pose();
    const Arrangement a = objects();
    log.robot_path_length += (p.x - prev_robot).norm();
    for (std::size_t i = 0; i < a.size(); ++i)
      log.object_path_length += (a[i] - prev_objects[i]).norm();
    prev_robot = p.x;
    prev_objects = a;
    log.min_clearance = std::min(log.min_clearance, world.clearance());
    lower_by_kind(p.x, a);
    log.collisions = world.collisions() - collisions_before;
    log.collision_events = world.collision_events();
    ++log.steps;
    log.sim_time = now();
    if (options.record) {
      log.robot.push_back(p);
      log.objects.push_back(a);
    }
  }

  // --- what remains ---
  std::vector<Sweep> sweeps_of(std::size_t k, bool with_transit) const {
    const ObjectMove& m = plan.moves[k];
    const double rr = rho(m.object);
    std::vector<Sweep> out;
    if (with_transit && !m.held_at_start) {
      out.push_back(Sweep{SweepKind::kTransit, k, m.transit, r(), std::nullopt});
      out.push_back(Sweep{SweepKind::kDock,
                          k,
                          {standoff_position(m.from, r(), rr, m.grasp_heading, params),
                           grip_position(m.from, r(), rr, m.grasp_heading, params)},
                          r(),
                          std::nullopt});
    }
    out.push_back(
        Sweep{SweepKind::kTransfer, k, m.transfer, pair_radius(r(), rr, params), m.object});
    out.push_back(Sweep{SweepKind::kBackOff,
                        k,
                        {grip_position(m.to, r(), rr, m.release_heading, params),
                         standoff_position(m.to, r(), rr, m.release_heading, params)},
                        r(),
                        std::nullopt});
    return out;
  }

  // What the current phase still sweeps from where the robot is, with the rest of its move.
  Point grip_of_current() const {
    const ObjectMove& mv = current();
    return grip_position(mv.from, r(), rho(mv.object), mv.grasp_heading, params);
  }
  std::vector<Point> polyline_ahead() const {
    std::vector<Point> path{world.pose().x};
    for (std::size_t k = next; k < vertices.size(); ++k) path.push_back(vertices[k]);
    return path;
  }
  void rest_of_move(std::vector<Sweep>& out) const {
    const std::vector<Sweep> rest = sweeps_of(move, false);
    out.insert(out.end(), rest.begin(), rest.end());
  }
  void nothing_ahead(std::vector<Sweep>&) const {}
  void transit_ahead(std::vector<Sweep>& out) const {
    const std::vector<Point> path = polyline_ahead();
    out.push_back(Sweep{SweepKind::kTransit, move, path, r(), std::nullopt});
    out.push_back(
        Sweep{SweepKind::kDock, move, {path.back(), grip_of_current()}, r(), std::nullopt});
    rest_of_move(out);
  }
  void turn_ahead(std::vector<Sweep>& out) const {
    out.push_back(
        Sweep{SweepKind::kDock, move, {world.pose().x, grip_of_current()}, r(), std::nullopt});
    rest_of_move(out);
  }
  void dock_ahead(std::vector<Sweep>& out) const {
    out.push_back(Sweep{SweepKind::kDock, move, {world.pose().x, drive_to}, r(), std::nullopt});
    rest_of_move(out);
  }
  void transfer_ahead(std::vector<Sweep>& out) const {
    std::vector<Point> path{pair_center()};
    const std::size_t k = segment_at(sigma);
    for (std::size_t j = k + 1; j < track.size(); ++j) path.push_back(track[j]);
    const double pair = pair_radius(r(), rho(current().object), params);
    out.push_back(Sweep{SweepKind::kTransfer, move, path, pair, current().object});
    out.push_back(sweeps_of(move, false).back());  // the back-off
  }
  void still_ahead(std::vector<Sweep>& out) const {
    const sim::Pose p = world.pose();
    const double back = params.standoff - params.grip_gap;
    out.push_back(Sweep{
        SweepKind::kBackOff, move, {p.x, p.x - back * heading_vector(p.psi)}, r(), std::nullopt});
  }
  void back_off_ahead(std::vector<Sweep>& out) const {
    out.push_back(Sweep{SweepKind::kBackOff, move, {world.pose().x, drive_to}, r(), std::nullopt});
  }
  void final_ahead(std::vector<Sweep>& out) const {
    out.push_back(
        Sweep{SweepKind::kFinalTransit, std::nullopt, polyline_ahead(), r(), std::nullopt});
  }

  // One row per phase (row_of lists them).
  struct PhaseRow {
    Phase phase;
    Step (Impl::*tick)(Command&);
    void (Impl::*ahead)(std::vector<Sweep>&) const;
    bool of_move;      // part of moves[move]: the later moves' sweeps follow its own
    bool final_leg;    // the plan's final transit: its sweep stands for the plan's
    bool tracks_pair;  // the transfer: the reference's arc length σ advances with each step
  };
  static const PhaseRow& row_of(Phase p);
};

// The phases of a plan's execution, in the order of a move, indexed by Phase: what a tick of
// each does, what it still sweeps (PlanExecutor::remaining), and how it relates to the plan.
const PlanExecutor::Impl::PhaseRow& PlanExecutor::Impl::row_of(Phase p) {
  static constexpr PhaseRow kPhases[] = {
      {Phase::kIdle, &Impl::idle_step, &Impl::nothing_ahead, false, false, false},
      {Phase::kStartMove, &Impl::start_step, &Impl::nothing_ahead, false, false, false},
      {Phase::kTransit, &Impl::transit_step, &Impl::transit_ahead, true, false, false},
      {Phase::kTurnToGrasp, &Impl::turn_step, &Impl::turn_ahead, true, false, false},
      {Phase::kDock, &Impl::dock_step, &Impl::dock_ahead, true, false, false},
      {Phase::kTransfer, &Impl::transfer_step, &Impl::transfer_ahead, true, false, true},
      {Phase::kStill, &Impl::still_step, &Impl::still_ahead, true, false, false},
      {Phase::kBackOff, &Impl::back_off_step, &Impl::back_off_ahead, true, false, false},
      {Phase::kFinalTransit, &Impl::final_step, &Impl::final_ahead, false, true, false},
  };
  static_assert(
      [] {
        for (std::size_t i = 0; i < std::size(kPhases); ++i) {
          if (static_cast<std::size_t>(kPhases[i].phase) != i) return false;
        }
        return true;
      }(),
      "kPhases lists every Phase once, in the enum's order");
  return kPhases[static_cast<std::size_t>(p)];
}

std::optional<Command> PlanExecutor::Impl::next_command() {
  Command c;
  for (;;) {
    switch ((this->*row_of(phase).tick)(c)) {
      case Step::kCommand:
        return c;
      case Step::kEnd:
        return std::nullopt;
      case Step::kNext:
        continue;
    }
  }
}

PlanExecutor::PlanExecutor(sim::SimWorld& world, const RearrangementProblem& problem,
                           const BaselineParams& params, const ExecutionOptions& options)
    : impl_(std::make_unique<Impl>(world, problem, params, options)) {
  const std::size_t n = problem.object_count();
  if (problem.object_radii.size() != n || problem.object_names.size() != n ||
      problem.goals.size() != n || problem.goal_regions.size() != n ||
      problem.goal_region_names.size() != n || world.object_count() != n) {
    throw Error("executor: the problem's object lists and the world's " +
                std::to_string(world.object_count()) + " objects differ in size");
  }
  if (!(options.dt > 0) || !std::isfinite(options.dt) || !(options.time_budget > 0) ||
      !(options.tracking_tolerance > 0) || !std::isfinite(options.tracking_tolerance)) {
    throw Error(
        "executor: dt, time_budget and tracking_tolerance must be > 0 (dt and the "
        "tolerance finite)");
  }
  if (!(problem.v_max > 0) || !(problem.omega_max > 0) || !std::isfinite(problem.v_max) ||
      !std::isfinite(problem.omega_max)) {
    throw Error("executor: v_max and omega_max must be finite and > 0");
  }
  if (!(params.standoff >= params.grip_gap) || !(params.grip_gap >= 0) ||
      !std::isfinite(params.standoff)) {
    throw Error("executor: need 0 <= grip_gap <= standoff, finite");
  }
  Impl& m = *impl_;
  const sim::Pose p = world.pose();
  m.prev_robot = p.x;
  m.prev_objects = m.objects();
  m.log.min_clearance = world.clearance();
  m.lower_by_kind(p.x, m.prev_objects);
  m.collisions_before = world.collisions();
  m.log.sim_time = world.time();
  if (options.record) {
    m.log.robot.push_back(p);
    m.log.objects.push_back(m.prev_objects);
  }
}

PlanExecutor::~PlanExecutor() = default;

void PlanExecutor::load(const Plan& plan) {
  Impl& m = *impl_;
  const std::size_t n = m.problem.object_count();
  for (std::size_t k = 0; k < plan.moves.size(); ++k) {
    const ObjectMove& mv = plan.moves[k];
    if (mv.object >= n) {
      throw Error("executor: move " + std::to_string(k) + " names object " +
                  std::to_string(mv.object) + " of " + std::to_string(n));
    }
    if (!mv.from.allFinite() || !mv.to.allFinite() || !finite(mv.transit) || !finite(mv.transfer) ||
        !std::isfinite(mv.grasp_heading) || !std::isfinite(mv.release_heading)) {
      throw Error("executor: move " + std::to_string(k) + " has a non-finite number");
    }
  }
  if (!finite(plan.final_transit)) throw Error("executor: the final transit is not finite");
  if (m.running()) m.close("interrupted");
  m.plan = plan;
  m.move = 0;
  m.phase = Phase::kStartMove;
  m.log.status = ExecStatus::kCompleted;
  m.log.reason.clear();
}

bool PlanExecutor::tick() {
  Impl& m = *impl_;
  if (!m.running()) return false;
  const auto wall0 = std::chrono::steady_clock::now();
  const std::optional<Command> c = m.next_command();
  bool stepped = false;
  if (c) {
    const double t0 = m.world.time();
    if (t0 + m.options.dt > m.options.time_budget * (1 + kTimeSlack)) {
      m.end(ExecStatus::kTimeout,
            "the time budget of " + str(m.options.time_budget) + " s ran out at " +
                (Impl::row_of(m.phase).final_leg ? std::string("the final transit") : m.what()),
            "timeout");
    } else {
      m.world.step(c->v, c->omega);
      if (!m.dt_checked) {
        const double dt = m.world.time() - t0;
        if (std::abs(dt - m.options.dt) > kTimeSlack * std::max(1.0, m.world.time())) {
          throw Error("executor: ExecutionOptions::dt = " + str(m.options.dt) +
                      " s but the world steps " + str(dt) + " s");
        }
        m.dt_checked = true;
      }
      if (Impl::row_of(m.phase).tracks_pair) {
        m.sigma = std::min(m.cumulative.back(), m.sigma + m.pending_advance);
      }
      m.pending_advance = 0;
      m.record_step();
      stepped = true;
    }
  }
  m.log.wall_time +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return stepped;
}

bool PlanExecutor::finished() const { return !impl_->running(); }

void PlanExecutor::interrupt() {
  Impl& m = *impl_;
  if (!m.running()) return;
  m.end(ExecStatus::kInterrupted, "interrupted", "interrupted");
}

std::vector<PlanExecutor::Sweep> PlanExecutor::remaining() const {
  const Impl& m = *impl_;
  std::vector<Sweep> out;
  if (!m.running()) return out;
  const Impl::PhaseRow& row = Impl::row_of(m.phase);
  (m.*row.ahead)(out);
  for (std::size_t k = m.move + (row.of_move ? 1 : 0); k < m.plan.moves.size(); ++k) {
    const std::vector<Sweep> s = m.sweeps_of(k, true);
    out.insert(out.end(), s.begin(), s.end());
  }
  if (!row.final_leg && !m.plan.final_transit.empty()) {
    out.push_back(
        Sweep{SweepKind::kFinalTransit, std::nullopt, m.plan.final_transit, m.r(), std::nullopt});
  }
  return out;
}

std::size_t PlanExecutor::move_index() const { return impl_->move; }

std::optional<std::size_t> PlanExecutor::held() const { return impl_->world.held(); }

const ExecutionLog& PlanExecutor::log() const { return impl_->log; }

ExecutionLog PlanExecutor::finish() {
  Impl& m = *impl_;
  interrupt();
  m.log.collisions = m.world.collisions() - m.collisions_before;
  m.log.collision_events = m.world.collision_events();
  m.log.sim_time = m.world.time();
  m.log.objects_end = m.objects();
  m.log.goals_reached = m.problem.goals_reached(m.log.objects_end);
  m.log.robot_goal_reached = !m.problem.robot_goal_region ||
                             geometry::contains(*m.problem.robot_goal_region, m.world.pose().x);
  return m.log;
}

ExecutionLog execute_plan(const scenario::Scenario& s, const RearrangementProblem& problem,
                          const Plan& plan, const BaselineParams& params,
                          const ExecutionOptions& options) {
  sim::SimWorld world(s, sim::config_for(s));
  ExecutionOptions o = options;
  o.dt = s.simulation.dt;
  PlanExecutor executor(world, problem, params, o);
  executor.load(plan);
  while (executor.tick()) {
  }
  return executor.finish();
}

}  // namespace rearm::baselines
