// An expected outcome as a value (docs/architecture.md, house style 3): the result of a
// computation whose failure is a normal event its caller acts on (a decomposition that does not
// exist, a purge whose collar cannot be built, a diffeomorphism no candidate tree admits),
// never bad input. Holds either the value or the reason there is none; a search over
// candidates tries the next one on a failure instead of catching an exception.
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "core/error.h"

namespace rearm {

// Why an Outcome holds no value.
struct Failure {
  std::string reason;
};

template <class T>
class [[nodiscard]] Outcome {
 public:
  Outcome(T value) : v_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit
  Outcome(Failure f) : v_(std::in_place_index<1>, std::move(f)) {}    // NOLINT: implicit

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  // The value; asking a failure for it is a bug (REARM_DEMAND).
  T& operator*() & { return std::get<0>(checked()); }
  const T& operator*() const& { return std::get<0>(checked()); }
  T* operator->() { return &**this; }
  const T* operator->() const { return &**this; }

  // The reason; asking a value for it is a bug.
  const std::string& reason() const {
    REARM_DEMAND(!ok(), "Outcome::reason() of a value");
    return std::get<1>(v_).reason;
  }

  // For a caller to whom the failure is bad input: the value, or rearm::Error with the reason.
  T or_throw() && {
    if (!ok()) throw Error(std::get<1>(v_).reason);
    return std::move(std::get<0>(v_));
  }

 private:
  std::variant<T, Failure>& checked() {
    REARM_DEMAND(ok(), "Outcome: the value of a failure (" + std::get<1>(v_).reason + ")");
    return v_;
  }
  const std::variant<T, Failure>& checked() const {
    REARM_DEMAND(ok(), "Outcome: the value of a failure (" + std::get<1>(v_).reason + ")");
    return v_;
  }

  std::variant<T, Failure> v_;
};

}  // namespace rearm
