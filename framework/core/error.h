// Error tiers of docs/architecture.md (house style 3):
//  - REARM_DEMAND: always-on invariant; a violation is a bug in rearm and aborts.
//  - REARM_ASSERT: the same, checked in debug builds only.
//  - rearm::Error (and subclasses): bad caller or user input, with a precise message.
// Expected outcomes (infeasible, timeout, ...) are values, never exceptions.
#pragma once

#include <stdexcept>
#include <string>

namespace rearm {

// Bad input from a caller or a user: malformed text, unknown names, invalid numbers.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

// A computation stopped because it exceeded an explicit budget (states, time).
class BudgetExceeded : public Error {
 public:
  explicit BudgetExceeded(const std::string& what) : Error(what) {}
};

// The closed loop's checked mode found an invariant broken (executive/task_runner.h,
// TaskOptions::check_invariants): a bug in rearm, caught per trial (the sweep's status
// `error`, with this message) instead of aborting the whole process as REARM_DEMAND does.
class InvariantViolation : public std::logic_error {
 public:
  explicit InvariantViolation(const std::string& what) : std::logic_error(what) {}
};

namespace detail {
[[noreturn]] void demand_failed(const char* condition, const char* file, int line,
                                const std::string& message);
}  // namespace detail

}  // namespace rearm

#define REARM_DEMAND(cond, msg)                                                    \
  do {                                                                             \
    if (!(cond)) ::rearm::detail::demand_failed(#cond, __FILE__, __LINE__, (msg)); \
  } while (false)

#ifdef NDEBUG
#define REARM_ASSERT(cond, msg) \
  do {                          \
  } while (false)
#else
#define REARM_ASSERT(cond, msg) REARM_DEMAND(cond, msg)
#endif
