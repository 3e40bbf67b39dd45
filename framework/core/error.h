// Error tiers of docs/architecture.md (house style 3):
//  - REARM_DEMAND: always-on invariant; a violation is a bug in rearm and aborts.
//  - REARM_ASSERT: the same, checked in debug builds only.
//  - rearm::Error (and subclasses): bad caller or user input, with a precise message;
//    REARM_REQUIRE checks such input and formats the values it names.
// Expected outcomes (infeasible, timeout, a candidate that does not work, ...) are values
// (core/outcome.h), never exceptions.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

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

// The pieces of a REARM_REQUIRE message: text as is, numbers exactly (a double in its shortest
// round-trip form, "nan", "inf"), so a message's "got" value is the value that was passed.
inline void append(std::string& s, std::string_view text) { s += text; }
inline void append(std::string& s, const char* text) { s += text; }  // not the bool overload
void append(std::string& s, double x);
void append(std::string& s, long long x);
void append(std::string& s, unsigned long long x);
inline void append(std::string& s, bool b) { s += b ? "true" : "false"; }
inline void append(std::string& s, char c) { s += c; }
template <class T>
requires(std::is_integral_v<T> && !std::is_same_v<T, bool> &&
         !std::is_same_v<T, char>) void append(std::string& s, T x) {
  if constexpr (std::is_signed_v<T>) {
    append(s, static_cast<long long>(x));
  } else {
    append(s, static_cast<unsigned long long>(x));
  }
}
inline void append(std::string& s, float x) { append(s, static_cast<double>(x)); }

template <class... Parts>
[[noreturn]] void input_failed(const Parts&... parts) {
  std::string message;
  (append(message, parts), ...);
  throw Error(message);
}
}  // namespace detail

}  // namespace rearm

#define REARM_DEMAND(cond, msg)                                                    \
  do {                                                                             \
    if (!(cond)) ::rearm::detail::demand_failed(#cond, __FILE__, __LINE__, (msg)); \
  } while (false)

// Bad caller input (house style 3): when cond is false, throws rearm::Error whose message is the
// remaining arguments joined, e.g.
//   REARM_REQUIRE(r > 0 && std::isfinite(r), "dilate: radius must be finite and > 0, got ", r);
#define REARM_REQUIRE(cond, ...)                             \
  do {                                                       \
    if (!(cond)) ::rearm::detail::input_failed(__VA_ARGS__); \
  } while (false)

#ifdef NDEBUG
#define REARM_ASSERT(cond, msg) \
  do {                          \
  } while (false)
#else
#define REARM_ASSERT(cond, msg) REARM_DEMAND(cond, msg)
#endif
