// pw::Result<T>: a value or an error a person can act on.
//
// Anything a user can cause (a missing file, bad VRML, degenerate corners, a
// missing device feature) comes back as an Error, never as an exception across a
// module boundary. The message is one line, starts with what was being done or the
// file it concerns, and says what to change:
//   "shot.json: corner P5 lies on the line P3-P4; the floor plane is degenerate"
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace pw {

struct Error {
  std::string message;
};

inline Error makeError(std::string message) { return Error{std::move(message)}; }

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}
  Result(Error error) : state_(std::move(error)) {}

  bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & { assert(ok()); return std::get<0>(state_); }
  const T& value() const& { assert(ok()); return std::get<0>(state_); }
  T&& value() && { assert(ok()); return std::get<0>(std::move(state_)); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  const Error& error() const { assert(!ok()); return std::get<1>(state_); }
  const std::string& message() const { return error().message; }

 private:
  std::variant<T, Error> state_;
};

template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)), ok_(false) {}

  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const { assert(!ok_); return error_; }
  const std::string& message() const { return error().message; }

 private:
  Error error_;
  bool ok_ = true;
};

using Status = Result<void>;

}  // namespace pw

// Returns the error of a Result/Status expression from the enclosing function.
#define PW_TRY(expr)                                   \
  do {                                                 \
    auto pwTryResult_ = (expr);                        \
    if (!pwTryResult_.ok()) return pwTryResult_.error(); \
  } while (0)
