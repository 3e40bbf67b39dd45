#include "executive/progress_monitor.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "core/text.h"

namespace rearm::executive {
namespace {}  // namespace

void validate(const ProgressParams& p) {
  const std::pair<const char*, double> fields[] = {
      {"stall_time", p.stall_time},           {"progress_step", p.progress_step},
      {"revisit_period", p.revisit_period},   {"revisit_distance", p.revisit_distance},
      {"revisit_heading", p.revisit_heading}, {"revisit_min_age", p.revisit_min_age}};
  for (const auto& [name, v] : fields) {
    REARM_REQUIRE(std::isfinite(v) && v > 0, "progress monitor: ", name,
                  " must be finite and > 0, got ", v);
  }
}

ProgressMonitor::ProgressMonitor(const ProgressParams& p) : p_(p) { validate(p_); }

void ProgressMonitor::reset(double t) {
  if (!std::isfinite(t)) throw Error("progress monitor: time is not finite");
  started_ = false;
  t0_ = last_t_ = t;
  records_.clear();
}

std::optional<std::string> ProgressMonitor::observe(double t, const reactive::Pose& pose,
                                                    double distance, std::uint64_t map_version) {
  if (!std::isfinite(t) || !std::isfinite(distance) || !pose.x.allFinite() ||
      !std::isfinite(pose.psi)) {
    throw Error("progress monitor: non-finite observation");
  }
  if (t < last_t_) throw Error("progress monitor: time went backwards");
  last_t_ = t;
  if (!started_) {
    started_ = true;
    best_ = best_mark_ = distance;
    best_t_ = t;
  }
  best_ = std::min(best_, distance);
  if (best_ <= best_mark_ - p_.progress_step) {
    best_mark_ = best_;
    best_t_ = t;
  }
  if (t - best_t_ > p_.stall_time) {
    return "no progress toward the target for " + significant(t - best_t_, 3) +
           " s (best distance " + significant(best_, 3) + " m)";
  }
  for (const Record& r : records_) {
    if (t - r.t < p_.revisit_min_age) break;  // records are in time order
    if (r.version != map_version) continue;
    if ((r.pose.x - pose.x).norm() > p_.revisit_distance) continue;
    if (std::abs(std::remainder(r.pose.psi - pose.psi, 2 * std::acos(-1.0))) > p_.revisit_heading) {
      continue;
    }
    if (best_ > r.best - p_.progress_step) {
      return "revisited the configuration (" + significant(pose.x.x(), 3) + ", " +
             significant(pose.x.y(), 3) + ", " + significant(pose.psi, 3) +
             " rad) of t = " + significant(r.t, 3) + " s without coming closer to the " +
             "target (distance " + significant(distance, 3) + " m)";
    }
  }
  if (records_.empty() || t - records_.back().t >= p_.revisit_period) {
    records_.push_back(Record{t, pose, map_version, best_});
  }
  return std::nullopt;
}

}  // namespace rearm::executive
