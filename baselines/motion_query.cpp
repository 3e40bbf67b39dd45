#include "baselines/motion_query.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/datastructures/NearestNeighborsSqrtApprox.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <mutex>

#include "core/error.h"
#include "core/rng.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace rearm::baselines {

using geometry::Point;

namespace {

// How many OMPL termination checks pass between two reads of the budget's clocks.
constexpr unsigned kBudgetCheckStride = 16;

// OMPL's console output would flood sweeps with one line per query; errors still show.
void quiet_ompl() {
  static std::once_flag once;
  std::call_once(once, [] { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); });
}

Point point_of(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return Point(v->values[0], v->values[1]);
}

// The uniform sampler with its own seeded RNG (StateSampler::rng_ is protected).
class SeededSampler : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::uint32_t seed) : RealVectorStateSampler(space) {
    rng_.setLocalSeed(seed);
  }
};

// RRTConnect with its own seeded RNG and a deterministic nearest-neighbour structure.
class SeededRRTConnect : public og::RRTConnect {
 public:
  SeededRRTConnect(const ob::SpaceInformationPtr& si, std::uint32_t seed) : RRTConnect(si) {
    rng_.setLocalSeed(seed);
    setNearestNeighbors<ompl::NearestNeighborsSqrtApprox>();
  }
};

// Exact capsule test (disk_world.h) for every motion RRTConnect tries.
class CapsuleValidator : public ob::MotionValidator {
 public:
  CapsuleValidator(const ob::SpaceInformationPtr& si, std::function<bool(Point, Point)> free)
      : MotionValidator(si), free_(std::move(free)) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool ok = free_(point_of(s1), point_of(s2));
    if (ok)
      ++valid_;
    else
      ++invalid_;
    return ok;
  }
  // The last valid state by bisection on the exact test (RRTConnect does not call it).
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    if (checkMotion(s1, s2)) return true;
    const Point a = point_of(s1), b = point_of(s2);
    double lo = 0, hi = 1;
    constexpr int kBisections = 30;
    for (int k = 0; k < kBisections; ++k) {
      const double mid = 0.5 * (lo + hi);
      (free_(a, a + mid * (b - a)) ? lo : hi) = mid;
    }
    if (last_valid.first != nullptr) {
      auto* v = last_valid.first->as<ob::RealVectorStateSpace::StateType>();
      const Point q = a + lo * (b - a);
      v->values[0] = q.x();
      v->values[1] = q.y();
    }
    last_valid.second = lo;
    return false;
  }

 private:
  std::function<bool(Point, Point)> free_;
};

}  // namespace

std::string seconds_text(double s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

const char* to_string(QueryStatus s) {
  switch (s) {
    case QueryStatus::kSolved:
      return "solved";
    case QueryStatus::kStartInvalid:
      return "start invalid";
    case QueryStatus::kGoalInvalid:
      return "goal invalid";
    case QueryStatus::kNoPath:
      return "no path";
    case QueryStatus::kTimeout:
      return "timeout";
  }
  return "?";
}

double thread_cpu_seconds() {
  timespec t{};
  REARM_DEMAND(clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0, "no thread CPU clock");
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

QueryContext::QueryContext(double time_limit, std::uint64_t seed, long max_queries)
    : seed_(seed), max_queries_(max_queries) {
  if (max_queries < 0) throw Error("the query limit must be >= 0");
  if (!std::isfinite(time_limit) || time_limit <= 0)
    throw Error("time limit must be a positive finite number of seconds");
  limit_ = time_limit;
  cpu_start_ = thread_cpu_seconds();
  start_ = Clock::now();
  wall_deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>(kWallSafetyFactor * time_limit));
}

double QueryContext::remaining() const { return std::max(0.0, limit_ - elapsed()); }

double QueryContext::elapsed() const { return thread_cpu_seconds() - cpu_start_; }

double QueryContext::wall_elapsed() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::uint32_t QueryContext::next_seed() {
  Rng r = Rng::derive(seed_, counter_++);
  // OMPL seeds are 32 bits; 0 would make OMPL pick its own seed.
  const auto s = static_cast<std::uint32_t>(r.next() >> 32);
  return s == 0 ? 1u : s;
}

QueryResult plan_motion(const DiskWorld& world, const std::vector<geometry::Disk>& disks,
                        std::optional<std::size_t> skip, double radius, double margin,
                        const Point& start, const Point& goal, QueryContext& ctx, double range) {
  quiet_ompl();
  QueryResult out;
  const std::uint32_t seed = ctx.next_seed();  // drawn even for trivial queries: stable indices
  auto free = [&](Point a, Point b) {
    return world.segment_free(a, b, radius, margin, disks, skip);
  };
  if (!world.disk_free(start, radius, margin, disks, skip)) {
    out.status = QueryStatus::kStartInvalid;
    return out;
  }
  if (!world.disk_free(goal, radius, margin, disks, skip)) {
    out.status = QueryStatus::kGoalInvalid;
    return out;
  }
  if (ctx.out_of_queries()) {
    out.status = QueryStatus::kTimeout;
    return out;
  }
  ++ctx.queries;
  if (free(start, goal)) {  // the straight segment: no sampling needed
    out.status = QueryStatus::kSolved;
    out.path = {start, goal};
    return out;
  }
  if (ctx.expired()) {
    out.status = QueryStatus::kTimeout;
    return out;
  }
  ++ctx.subqueries;

  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, world.lower().x());
  bounds.setLow(1, world.lower().y());
  bounds.setHigh(0, world.upper().x());
  bounds.setHigh(1, world.upper().y());
  space->setBounds(bounds);
  space->setStateSamplerAllocator([seed](const ob::StateSpace* s) -> ob::StateSamplerPtr {
    return std::make_shared<SeededSampler>(s, seed);
  });
  og::SimpleSetup ss(space);
  auto si = ss.getSpaceInformation();
  ss.setStateValidityChecker([&](const ob::State* s) {
    return world.disk_free(point_of(s), radius, margin, disks, skip);
  });
  si->setMotionValidator(std::make_shared<CapsuleValidator>(si, free));
  auto planner = std::make_shared<SeededRRTConnect>(si, seed ^ 0x9e3779b9u);
  if (range > 0) planner->setRange(range);
  ss.setPlanner(planner);
  ob::ScopedState<> s0(space), s1(space);
  s0[0] = start.x();
  s0[1] = start.y();
  s1[0] = goal.x();
  s1[1] = goal.y();
  ss.setStartAndGoalStates(s0, s1);
  ss.setup();

  ob::IterationTerminationCondition iterations(static_cast<unsigned>(ctx.iterations_per_query));
  // The trial's budget (the thread's CPU time, the wall-clock net), read every
  // kBudgetCheckStride checks: a thread CPU clock read is a system call.
  unsigned checks = 0;
  const ob::PlannerTerminationCondition budget(
      [&ctx, &checks] { return ++checks % kBudgetCheckStride == 0 && ctx.expired(); });
  const ob::PlannerTerminationCondition ptc = ob::plannerOrTerminationCondition(iterations, budget);
  ss.solve(ptc);
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  out.nodes = static_cast<long>(data.numVertices());
  ctx.nodes += out.nodes;
  if (!ss.haveExactSolutionPath()) {
    out.status = ctx.expired() ? QueryStatus::kTimeout : QueryStatus::kNoPath;
    return out;
  }
  std::vector<Point> raw;
  for (const ob::State* s : ss.getSolutionPath().getStates()) raw.push_back(point_of(s));
  raw.front() = start;  // exact ends (OMPL copies them, but be explicit)
  raw.back() = goal;
  // Greedy shortcut: from each kept vertex, jump to the farthest later vertex in sight.
  std::size_t i = 0;
  out.path.push_back(raw[0]);
  while (i + 1 < raw.size()) {
    std::size_t j = raw.size() - 1;
    while (j > i + 1 && !free(raw[i], raw[j])) --j;
    out.path.push_back(raw[j]);
    i = j;
  }
  out.status = QueryStatus::kSolved;
  return out;
}

}  // namespace rearm::baselines
