#include "executive/executive.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/stopwatch.h"
#include "core/text.h"
#include "executive/navigate.h"
#include "executive/phases.h"
#include "executive/targets.h"
#include "reactive/local_freespace.h"

namespace rearm::executive {
namespace {

// Phase changes allowed in one tick before the executive gives up (each action takes a handful:
// plan, reach, align, dock, …); more means a bug, reported as stuck rather than a hang.
constexpr int kMaxTransitionsPerTick = 64;

}  // namespace

const char* to_string(TaskStatus s) {
  switch (s) {
    case TaskStatus::kRunning:
      return "running";
    case TaskStatus::kCompleted:
      return "completed";
    case TaskStatus::kInfeasible:
      return "infeasible";
    case TaskStatus::kStuck:
      return "stuck";
    case TaskStatus::kTimeout:
      return "timeout";
  }
  return "?";
}

const char* to_string(ActionOutcome o) {
  switch (o) {
    case ActionOutcome::kSucceeded:
      return "succeeded";
    case ActionOutcome::kInfeasible:
      return "infeasible";
    case ActionOutcome::kStuck:
      return "stuck";
    case ActionOutcome::kAbandoned:
      return "abandoned";
  }
  return "?";
}

Executive::Executive(const ExecutiveParams& params, const std::vector<RegionOfInterest>& regions,
                     symbolic::MissionController& mission, const perception::SemanticMap& map)
    : p_(params),
      regions_(validated(regions, map.workspace())),
      mission_(mission),
      map_(map),
      controller_(params.diffeo, params.nav),
      ctx_{p_,          regions_,        map_,
           controller_, topology_cache_, drop_dilations_,
           times_,      recoveries_,     topology_checks_,
           last_u_,     keep_clear_,     fix_ways_} {
  validate(p_);
  controller_.set_convex_fallback(p_.robust.convex_fallback);
  controller_.set_miter_limit(miter_limit(p_));
  topology_cache_.set_miter_limit(miter_limit(p_));
  drop_dilations_.set_miter_limit(miter_limit(p_));
}

ActionState* Executive::current() {
  if (!fix_.empty()) return &fix_.back();
  return ltl_ ? &*ltl_ : nullptr;
}

std::string Executive::current_action() const {
  if (!fix_.empty()) return fix_.back().name();
  return ltl_ ? ltl_->name() : std::string();
}

bool Executive::fetch_ltl(double t) {
  if (p_.max_ltl_actions > 0 && ltl_done_ >= p_.max_ltl_actions) {
    const std::string n = std::to_string(ltl_done_);
    if (mission_.status() == symbolic::MissionStatus::Accepting) {
      finish(TaskStatus::kCompleted,
             "mission accepting after " + n + " actions (the configured action limit)", t);
    } else {
      finish(TaskStatus::kTimeout,
             "the action limit (" + n + ") was reached before the mission was accepting", t);
    }
    return false;
  }
  std::optional<symbolic::Action> next;
  {
    const ScopedStopwatch sw(times_.mission_s);
    next = mission_.next_action();
  }
  if (!next) {
    switch (mission_.status()) {
      case symbolic::MissionStatus::Infeasible:
        if (!stuck_.empty()) {
          // The alternatives ran out after actions the controller could not complete: the
          // task ends stuck (a controller failure), not proven infeasible.
          finish(TaskStatus::kStuck, stuck_ + "; no alternative action: " + mission_.reason(), t);
        } else {
          finish(TaskStatus::kInfeasible, "mission infeasible: " + mission_.reason(), t);
        }
        break;
      case symbolic::MissionStatus::Accepting:
        if (const auto r = restores_.next(map_, regions_)) {
          // Robust variant (RobustParams::restore): an object an LTL RELEASE placed and Fix mode
          // moved is released into its region again, as an interface-layer action.
          ++recoveries_.restores;
          keep_clear_.clear();
          fix_ways_.clear();
          fix_.push_back(
              make_action(ActionKind::kRelease, r->first, r->second, true, t, p_.progress));
          return true;
        }
        finish_accepting(t);
        break;
      case symbolic::MissionStatus::InProgress:
        finish(TaskStatus::kStuck, "the mission controller returned no action", t);
        break;
    }
    return false;
  }
  switch (next->kind) {
    case symbolic::ActionKind::Move:
      ltl_ = make_action(ActionKind::kMove, "", next->region, false, t, p_.progress);
      break;
    case symbolic::ActionKind::Grasp:
      ltl_ = make_action(ActionKind::kGrasp, next->object, "", false, t, p_.progress);
      break;
    case symbolic::ActionKind::Release:
      ltl_ = make_action(ActionKind::kRelease, next->object, next->region, false, t, p_.progress);
      break;
  }
  ltl_->ltl = *next;
  fix_rounds_ = 0;
  keep_clear_.clear();
  fix_ways_.clear();
  // Unknown names fail here, with the name, rather than deep inside a phase.
  if (!ltl_->region.empty()) region(ctx_, ltl_->region);
  if (!ltl_->object.empty()) object_radius(ctx_, ltl_->object);
  return true;
}

Command Executive::step(const Pose& pose, double t, double dt) {
  if (finished()) return {};
  if (!pose.x.allFinite() || !std::isfinite(pose.psi) || !std::isfinite(t) || !std::isfinite(dt) ||
      !(dt > 0)) {
    throw Error("executive: non-finite pose or time, or dt <= 0");
  }
  law_command_ = false;
  for (int guard = 0; guard < kMaxTransitionsPerTick && !finished(); ++guard) {
    ActionState* a = current();
    if (a == nullptr) {
      if (!fetch_ltl(t)) break;
      continue;
    }
    Advance r;
    try {
      r = a->phase == ActionPhase::kNavigate ? prerequisites_then_navigate(*a, pose, t, dt)
                                             : advance(ctx_, *a, pose, t, dt);
    } catch (const Error& e) {
      r.kind = Advance::kStuck;
      r.reason = e.what();
    }
    switch (r.kind) {
      case Advance::kCommand:
        last_u_ = r.u;
        law_command_ = r.law;
        return Command{r.u, r.gripper, r.grip_object};
      case Advance::kRestart:
        break;
      case Advance::kDone:
        end_current(ActionOutcome::kSucceeded, r.reason, t);
        break;
      case Advance::kInfeasible:
        end_current(ActionOutcome::kInfeasible, r.reason, t);
        break;
      case Advance::kBlocked:
        enter_fix(r.blocking, t);
        break;
      case Advance::kStuck:
        end_stuck(r.reason, t);
        break;
    }
  }
  if (!finished()) {
    finish(TaskStatus::kStuck,
           "no motion command after " + std::to_string(kMaxTransitionsPerTick) +
               " action transitions in one tick (at " + current_action() + ")",
           t);
  }
  last_u_ = Twist{};
  return Command{};
}

// Gripper prerequisites (interface-layer steps, beyond the paper; see the header), then the
// navigation phase.
Advance Executive::prerequisites_then_navigate(ActionState& a, const Pose& pose, double t,
                                               double dt) {
  Advance out;
  const std::optional<std::string> carried = map_.carried();
  std::vector<ActionState> before;  // execution order
  if (a.kind == ActionKind::kGrasp && carried) {
    if (*carried == a.object) {
      out.kind = Advance::kDone;
      out.reason = "already in the gripper";
      return out;
    }
    before.push_back(make_action(ActionKind::kDisassemble, *carried, "", true, t, p_.progress));
  } else if (a.kind == ActionKind::kRelease && carried != a.object) {
    if (carried)
      before.push_back(make_action(ActionKind::kDisassemble, *carried, "", true, t, p_.progress));
    before.push_back(make_action(ActionKind::kGrasp, a.object, "", true, t, p_.progress));
  } else if (a.kind == ActionKind::kDisassemble && carried != a.object) {
    out.kind = Advance::kInfeasible;
    out.reason = "the object is not in the gripper";
    return out;
  }
  if (!before.empty()) {
    // `a` may live in fix_: nothing touches it after the push.
    for (auto it = before.rbegin(); it != before.rend(); ++it) fix_.push_back(*it);
    out.kind = Advance::kRestart;
    return out;
  }
  return navigate(ctx_, a, pose, t, dt);
}

std::optional<std::string> Executive::law_invariant_violation() const {
  if (!law_command_) return std::nullopt;
  const reactive::ReactiveController::LawSample& s = controller_.last_law_sample();
  if (!(s.det > 0)) return "det Dh = " + rearm::fixed(s.det, 3) + " <= 0 at x = " + point_text(s.x);
  if (std::optional<std::string> why =
          reactive::outside_model_freespace(controller_.diffeo().model(), s.y)) {
    return "the law's model point of x = " + point_text(s.x) + ": " + *why;
  }
  return std::nullopt;
}

// The mission is accepting and no restore is left to try. The objects an LTL RELEASE placed and
// Fix mode later moved, as the map locates them, are named. With the restores on, the task then
// ends stuck: the executive could not keep the end state it set out to restore (a restore that
// ended infeasible, or restores that ran out, two objects each in the other's way in turn).
// Without them (the paper variant) the formula, which speaks of actions only, holds: completed,
// with the objects named in the reason.
void Executive::finish_accepting(double t) {
  const std::string done = "mission complete: the automaton stays in an accepting state";
  const std::string moved = restores_.moved(map_, regions_);
  if (moved.empty()) return finish(TaskStatus::kCompleted, done, t);
  if (p_.robust.restore) {
    return finish(TaskStatus::kStuck,
                  "objects an LTL RELEASE placed and Fix mode moved are not back after " +
                      std::to_string(restores_.count()) + " restore(s) (at most " +
                      std::to_string(Restores::limit(map_)) + "): " + moved +
                      " (the formula holds)",
                  t);
  }
  finish(TaskStatus::kCompleted, done + "; Fix mode moved placed objects: " + moved, t);
}

RecoveryCounts Executive::recoveries() const {
  RecoveryCounts c = recoveries_;
  c.fallbacks = controller_.fallbacks();
  return c;
}

void Executive::enter_fix(const std::vector<std::string>& blocking, double t) {
  ActionState* a = current();
  a->interruptions++;
  a->planned = false;
  a->built = false;
  if (a->fix && a->interruptions > p_.max_fix_rounds) {
    // A Fix-mode action is not counted in fix_rounds_; without this bound an object dropped
    // back into the way it blocks is moved forever (measured: one object moved 1,500 times).
    end_stuck("Fix mode entered " + std::to_string(p_.max_fix_rounds) +
                  " times for this Fix-mode action without clearing the way",
              t);
    return;
  }
  if (!a->fix) {
    ++fix_entries_;
    if (++fix_rounds_ > p_.max_fix_rounds) {
      // Stuck (paper §III-A): the mission controller is asked for an alternative.
      end_stuck("Fix mode entered " + std::to_string(p_.max_fix_rounds) +
                    " times for this action without clearing the way",
                t);
      return;
    }
  }
  if (a->blocked_way && p_.robust.drop) {
    Way way = *a->blocked_way;
    for (const std::string& id : blocking) {
      const auto& ids = map_.movable_ids();
      const auto it = std::find(ids.begin(), ids.end(), id);
      if (it == ids.end()) continue;
      way.movers.push_back(map_.movable()[it - ids.begin()]);
      way.mover_ids.push_back(id);
    }
    way.path = way_path(ctx_, way);
    fix_ways_.push_back(std::move(way));
  }
  a->blocked_way.reset();
  std::vector<ActionState> exec;  // execution order
  const std::optional<std::string> carried = map_.carried();
  if (carried)
    exec.push_back(make_action(ActionKind::kDisassemble, *carried, "", true, t, p_.progress));
  for (auto it = blocking.rbegin(); it != blocking.rend(); ++it) {  // back() is B_M's top
    restores_.displaced(*it, p_.robust.restore);
    exec.push_back(make_action(ActionKind::kGrasp, *it, "", true, t, p_.progress));
    exec.push_back(make_action(ActionKind::kDisassemble, *it, "", true, t, p_.progress));
  }
  if (carried) exec.push_back(make_action(ActionKind::kGrasp, *carried, "", true, t, p_.progress));
  const std::size_t limit = 2 * (map_.ground_truth().movable.size() + 1);
  if (fix_.size() + exec.size() > limit) {
    end_stuck("Fix mode would stack " + std::to_string(fix_.size() + exec.size()) +
                  " actions (limit " + std::to_string(limit) +
                  "): the blocking objects keep blocking each other",
              t);
    return;
  }
  for (auto it = exec.rbegin(); it != exec.rend(); ++it) fix_.push_back(std::move(*it));
}

// An action ended stuck. Paper §III-A: when the continuous controller fails at a sub-task, the
// symbolic controller is asked for an alternative; so an LTL action that ended stuck (itself, or
// in a Fix-mode action serving it) is reported infeasible to the mission controller, the Fix
// stack is dropped, and the next action is the controller's alternative, if any. A stuck
// interface-layer action with no LTL action behind it (a restore) ends the task stuck.
void Executive::end_stuck(const std::string& reason, double t) {
  ActionState* a = current();
  const std::string what = a->name() + ": " + reason;
  if (!ltl_) {
    end_current(ActionOutcome::kStuck, reason, t);
    finish(TaskStatus::kStuck, what, t);
    return;
  }
  log_.push_back(ActionRecord{a->name(), a->fix, ActionOutcome::kStuck, reason, a->t_start, t,
                              a->interruptions, a->target});
  if (a->fix) {
    const std::string why = "gave up after " + what;
    fix_.pop_back();
    abandon_fix(why, t);
    log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kStuck, why, ltl_->t_start, t,
                                ltl_->interruptions, ltl_->target});
  }
  stuck_ = stuck_.empty() ? what : stuck_ + "; " + what;
  {
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_infeasible(ltl_->ltl);
  }
  ltl_.reset();
}

void Executive::abandon_fix(const std::string& why, double t) {
  for (auto it = fix_.rbegin(); it != fix_.rend(); ++it) {
    log_.push_back(ActionRecord{it->name(), true, ActionOutcome::kAbandoned, why, it->t_start, t,
                                it->interruptions, it->target});
  }
  fix_.clear();
}

void Executive::end_current(ActionOutcome outcome, const std::string& reason, double t) {
  ActionState* a = current();
  if (a == nullptr) return;
  log_.push_back(
      ActionRecord{a->name(), a->fix, outcome, reason, a->t_start, t, a->interruptions, a->target});
  if (a->fix) {
    fix_.pop_back();
    if (outcome == ActionOutcome::kInfeasible) {
      // The Fix mode cannot clear the way: the LTL action it served is infeasible.
      const std::string why = "Fix mode failed: " + reason;
      abandon_fix(why, t);
      if (ltl_) {
        log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kInfeasible, why,
                                    ltl_->t_start, t, ltl_->interruptions, ltl_->target});
        {
          const ScopedStopwatch sw(times_.mission_s);
          mission_.report_infeasible(ltl_->ltl);
        }
        ltl_.reset();
      }
    }
    if (fix_.empty() && ltl_) {
      // Back to LTL mode: re-run the topology check (docs/executive.md, Fix mode).
      ltl_->planned = false;
      ltl_->built = false;
      ltl_->monitor.reset(t);
    }
    return;
  }
  if (outcome == ActionOutcome::kSucceeded) {
    // What the LTL actions placed (robust variant: restored if Fix mode moves it).
    if (a->kind == ActionKind::kRelease) restores_.placed(a->object, a->region);
    if (a->kind == ActionKind::kGrasp) restores_.grasped(a->object);
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_success();
    ++ltl_done_;
  } else if (outcome == ActionOutcome::kInfeasible) {
    const ScopedStopwatch sw(times_.mission_s);
    mission_.report_infeasible(ltl_->ltl);
  }
  ltl_.reset();
}

void Executive::finish(TaskStatus status, const std::string& reason, double t) {
  if (finished()) return;
  status_ = status;
  reason_ = reason;
  const std::string why = "task ended: " + reason;
  abandon_fix(why, t);
  if (ltl_) {
    log_.push_back(ActionRecord{ltl_->name(), false, ActionOutcome::kAbandoned, why, ltl_->t_start,
                                t, ltl_->interruptions, ltl_->target});
    ltl_.reset();
  }
}

void Executive::abort(TaskStatus status, const std::string& reason, double t) {
  if (status == TaskStatus::kRunning) throw Error("executive: abort needs a final status");
  finish(status, reason, t);
}

}  // namespace rearm::executive
