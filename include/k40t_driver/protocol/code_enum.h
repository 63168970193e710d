// Coded values of the document: enums whose enumerators are the wire codes, each with a
// to_string() that gives the code's meaning, or nullptr for a code the document does not define
// (check_enum and the field visitor rely on that).
#pragma once

#include <cstddef>
#include <cstdint>

// Declares `enum class Name : uint8_t { enumerators }` and its to_string().
#define K40T_CODE_ENUM(Name, ...)            \
  enum class Name : uint8_t { __VA_ARGS__ }; \
  const char* to_string(Name v)

namespace k40t::protocol {

// The value of `code` in `values`, which belong to the codes first, first + 1, ... in turn;
// `none` for a code outside them.
template <class E, class T, size_t N>
T by_code(E code, int first, const T (&values)[N], T none) {
  const int index = static_cast<int>(code) - first;
  return index >= 0 && index < static_cast<int>(N) ? values[index] : none;
}

// The name of `code` in `names` (as by_code), or nullptr. For a to_string() whose codes have no
// gaps: return consecutive_name(v, 0, {"stopped", "recording"});
template <class E, size_t N>
const char* consecutive_name(E code, int first, const char* const (&names)[N]) {
  return by_code<E, const char*>(code, first, names, nullptr);
}

}  // namespace k40t::protocol
