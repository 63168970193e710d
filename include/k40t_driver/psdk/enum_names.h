// The names of an enum's codes as a table that its to_string() looks up, instead of a switch
// statement per enum. Codes that run without gaps (most of the document's enums) list their
// names in code order from the first code; the others pair each code with its name:
//
//   const char* to_string(GpsSignal v) {  // kNone = 0, kVeryWeak = 1, ...
//     return name_in_order(v, 0, {"none", "very_weak", "medium", "very_strong"});
//   }
//   const char* to_string(ShootPhotoType v) {
//     return name_in(v, {{ShootPhotoType::kSingle, "single"}, {ShootPhotoType::kBurst, "burst"}});
//   }
#pragma once

#include <cstddef>
#include <initializer_list>

namespace k40t::psdk {

template <class E>
struct EnumName {
  E code;
  const char* name;
};

// The name of `code` in `names`, or nullptr for a code the table does not list: the codec's
// check_enum() reports such a code as out of range, and describe() shows it as a number.
template <class E>
const char* name_in(E code, std::initializer_list<EnumName<E>> names) {
  for (const EnumName<E>& n : names) {
    if (n.code == code) return n.name;
  }
  return nullptr;
}

// The name of `code` when the codes are first, first + 1, ... and `names` lists them in that
// order; nullptr for a code outside the list.
template <class E>
const char* name_in_order(E code, int first, std::initializer_list<const char*> names) {
  const int index = static_cast<int>(code) - first;
  if (index < 0 || static_cast<size_t>(index) >= names.size()) return nullptr;
  return names.begin()[index];
}

}  // namespace k40t::psdk
