// Motion queries on OMPL (docs/experiments.md, "Baseline"): a disk in the plane — the robot
// alone (transit) or the robot–object pair (transfer, radius r + ρ_i) — from a start to a goal
// among the obstacles and the arrangement's other disks, with og::SimpleSetup + og::RRTConnect
// in a 2-D RealVectorStateSpace. Validity is exact (disk_world.h), states and motions alike.
//
// Determinism (docs: "ompl::RNG::setSeed is process-global and breaks under threads"): every
// query seeds its own state sampler's and planner's RNGs with setLocalSeed, uses the
// deterministic NearestNeighborsSqrtApprox (GNAT's pivot selection draws from an unseeded RNG),
// and is capped by a number of planner iterations, not by time. The trial's time budget ends a
// query early through plannerOrTerminationCondition, and only then can timing change a result.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "baselines/disk_world.h"

namespace rearm::baselines {

// The wall-clock safety net of a planning budget: this many times the CPU time limit.
inline constexpr double kWallSafetyFactor = 10;

// CPU time (s) the calling thread has used (CLOCK_THREAD_CPUTIME_ID).
double thread_cpu_seconds();

// One planner run's budget, seeds and counters (one per trial; used by the thread that built
// it only: its clock is that thread's CPU time).
class QueryContext {
 public:
  using Clock = std::chrono::steady_clock;
  // time_limit in s of the planning thread's CPU time (> 0, finite); seed: the trial's.
  // max_queries: the query budget (0: none), PlannerOptions::max_queries.
  QueryContext(double time_limit, std::uint64_t seed, long max_queries = 0);
  // The CPU time limit passed, the wall-clock safety net fired, or the query budget is spent.
  bool expired() const { return out_of_queries() || elapsed() >= limit_ || wall_net_fired(); }
  bool out_of_queries() const { return max_queries_ > 0 && queries >= max_queries_; }
  // The wall clock reached kWallSafetyFactor times the limit.
  bool wall_net_fired() const { return Clock::now() >= wall_deadline_; }
  // The safety net fired with CPU budget left: the machine, not the search, ended the run.
  bool cut_by_wall() const { return wall_net_fired() && elapsed() < limit_; }
  long max_queries() const { return max_queries_; }
  double remaining() const;     // s of CPU time, >= 0
  double elapsed() const;       // s of the thread's CPU time since construction
  double wall_elapsed() const;  // s of wall time since construction
  // The next query's seed: a function of the trial seed and the query's index only.
  std::uint32_t next_seed();
  long queries = 0;                  // motion queries, straight-line checks included
  long subqueries = 0;               // motion queries posed to OMPL
  long nodes = 0;                    // states in their trees, summed
  int iterations_per_query = 20000;  // RRTConnect iterations before a query gives up

 private:
  double limit_ = 0;      // s of CPU time
  double cpu_start_ = 0;  // the thread's CPU time at construction
  Clock::time_point start_, wall_deadline_;
  std::uint64_t seed_;
  std::uint64_t counter_ = 0;
  long max_queries_ = 0;
};

// "1 s", "0.25 s": a duration for messages.
std::string seconds_text(double s);

enum class QueryStatus { kSolved, kStartInvalid, kGoalInvalid, kNoPath, kTimeout };
const char* to_string(QueryStatus s);

struct QueryResult {
  QueryStatus status = QueryStatus::kNoPath;
  std::vector<geometry::Point> path;  // start ... goal, shortcut; when solved
  long nodes = 0;
};

// Plans a path for the disk (radius, with `margin` of clearance) from start to goal among the
// world and `disks` (but `skip`). kNoPath: RRTConnect's iteration cap passed without an exact
// solution (haveExactSolutionPath); kTimeout: the trial's budget ran out. The returned path is
// shortcut greedily (deterministic: each vertex joined to the farthest later one it sees).
QueryResult plan_motion(const DiskWorld& world, const std::vector<geometry::Disk>& disks,
                        std::optional<std::size_t> skip, double radius, double margin,
                        const geometry::Point& start, const geometry::Point& goal,
                        QueryContext& ctx, double range = 0.0);

}  // namespace rearm::baselines
