// An enum's names (or other values it maps to) as a table, instead of a switch statement per
// enum: each value once, beside what it maps to, and one lookup for all of them. Used by both
// protocols (pod and PSDK), the simulator and the driver.
//   const char* to_string(LinkState s) {
//     static constexpr EnumName<LinkState> kNames[] = {{LinkState::kClosed, "closed"}, ...};
//     return name_in(kNames, s, "invalid link state");
//   }
#pragma once

#include <cstddef>

namespace k40t {

template <class Enum, class To>
struct EnumTo {
  Enum value;
  To to;
};

template <class Enum>
using EnumName = EnumTo<Enum, const char*>;

// What `value` maps to in `table`, or `otherwise` for a value the table lacks (a byte off the
// wire cast to the enum, or the values a mapping leaves to a default).
template <class Enum, class To, size_t N>
constexpr To lookup(const EnumTo<Enum, To> (&table)[N], Enum value, To otherwise) {
  for (const EnumTo<Enum, To>& entry : table) {
    if (entry.value == value) return entry.to;
  }
  return otherwise;
}

template <class Enum, size_t N>
constexpr const char* name_in(const EnumName<Enum> (&table)[N], Enum value,
                              const char* unknown = "?") {
  return lookup(table, value, unknown);
}

// The value of `code` in `values`, which belong to the codes first, first + 1, ... in turn;
// `none` for a code outside them.
template <class Enum, class To, size_t N>
constexpr To by_code(Enum code, int first, const To (&values)[N], To none) {
  const int index = static_cast<int>(code) - first;
  return index >= 0 && index < static_cast<int>(N) ? values[index] : none;
}

// The name of `code` in `names` (as by_code), or nullptr: for an enum whose codes have no gaps,
// most of the documents' coded values.
//   return consecutive_name(v, 0, {"stopped", "recording"});
template <class Enum, size_t N>
constexpr const char* consecutive_name(Enum code, int first, const char* const (&names)[N]) {
  return by_code<Enum, const char*>(code, first, names, nullptr);
}

}  // namespace k40t
