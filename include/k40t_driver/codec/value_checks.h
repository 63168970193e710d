// The range, text and enum checks every message's validate() is made of, and the scaling of a
// physical value onto a wire integer: shared by the pod protocol (protocol/) and DJI PSDK (psdk/),
// so they live here, below both. Failures name the field and its allowed range, for humans.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "k40t_driver/codec/result.h"

namespace k40t::codec {

// "field 'palette' must be 1..20, got 25"
Status check_range(const char* field, int64_t value, int64_t lo, int64_t hi, const char* unit = "");
Status check_range(const char* field, double value, double lo, double hi, const char* unit = "");
// Text fields of fixed width: at most `max_bytes` bytes, no NUL.
Status check_text(const char* field, const std::string& value, size_t max_bytes);

// Enum check: the value must be one the enum's to_string() knows (found by ADL, returns nullptr
// for codes the document does not define). The message lists the allowed codes.
template <class E>
Status check_enum(const char* field, E value);

// Returns the first failure, or ok.
template <class... S>
Status first_failure(const S&... statuses) {
  Status result = Status::ok();
  ((result.is_ok() && !statuses.is_ok() ? (result = statuses, 0) : 0), ...);
  return result;
}

// Physical value -> scaled integer on the wire (rounded to nearest). Validation must have checked
// the range; out-of-range values saturate rather than wrap.
template <class Int>
Int to_wire(double value, double scale) {
  const double scaled = std::round(value * scale);
  if (scaled <= static_cast<double>(std::numeric_limits<Int>::min()))
    return std::numeric_limits<Int>::min();
  if (scaled >= static_cast<double>(std::numeric_limits<Int>::max()))
    return std::numeric_limits<Int>::max();
  return static_cast<Int>(scaled);
}

// --- implementation of check_enum -----------------------------------------------------------
std::string describe_allowed_codes(const char* field, int64_t value, const std::string& allowed);

template <class E>
Status check_enum(const char* field, E value) {
  static_assert(std::is_enum_v<E>, "check_enum needs an enum");
  using U = std::underlying_type_t<E>;
  if (to_string(value) != nullptr) return Status::ok();
  std::string allowed;
  const int64_t last = sizeof(U) == 1 ? 0xFF : 0xFFFF;
  for (int64_t code = 0; code <= last; ++code) {
    const char* name = to_string(static_cast<E>(code));
    if (name == nullptr) continue;
    if (!allowed.empty()) allowed += ", ";
    allowed += std::to_string(code) + " (" + name + ")";
  }
  return Status::fail(
      describe_allowed_codes(field, static_cast<int64_t>(static_cast<U>(value)), allowed));
}

}  // namespace k40t::codec
