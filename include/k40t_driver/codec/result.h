// Status and Result<T>: error values without exceptions, for code that must never throw on bad
// bytes or bad arguments. Messages are meant for humans: they name the field and the range.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace k40t {

class Status {
 public:
  static Status ok() { return Status(); }
  static Status fail(std::string message) { return Status(std::move(message)); }

  bool is_ok() const { return !message_.has_value(); }
  explicit operator bool() const { return is_ok(); }
  const std::string& message() const {
    static const std::string kEmpty;
    return message_ ? *message_ : kEmpty;
  }

 private:
  Status() = default;
  explicit Status(std::string message) : message_(std::move(message)) {}
  std::optional<std::string> message_;
};

template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose, like expected<T>
  Result(Status failure) : error_(failure.message()) {}  // NOLINT

  static Result fail(std::string message) { return Result(Status::fail(std::move(message))); }

  bool is_ok() const { return value_.has_value(); }
  explicit operator bool() const { return is_ok(); }
  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const T* operator->() const { return &*value_; }
  T* operator->() { return &*value_; }
  const T& operator*() const { return *value_; }
  const std::string& error() const { return error_; }
  Status status() const { return is_ok() ? Status::ok() : Status::fail(error_); }

 private:
  std::optional<T> value_;
  std::string error_;
};

}  // namespace k40t
