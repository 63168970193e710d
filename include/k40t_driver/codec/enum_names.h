// An enum's names as a table, instead of a switch statement per enum: each value once, beside its
// text, and one lookup for all of them.
//   const char* to_string(LinkState s) {
//     static constexpr EnumName<LinkState> kNames[] = {{LinkState::kClosed, "closed"}, ...};
//     return name_in(kNames, s, "invalid link state");
//   }
#pragma once

#include <cstddef>

namespace k40t {

template <class Enum>
struct EnumName {
  Enum value;
  const char* name;
};

// The name of `value` in `table`, or `unknown` for a value the table lacks (a byte off the wire
// cast to the enum).
template <class Enum, size_t N>
constexpr const char* name_in(const EnumName<Enum> (&table)[N], Enum value,
                              const char* unknown = "?") {
  for (const EnumName<Enum>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return unknown;
}

}  // namespace k40t
