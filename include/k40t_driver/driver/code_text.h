// A protocol enum as the (code, text) pair the status messages carry: the raw code and the
// document's words for it, or "unknown code N" for a code the document does not list.
#pragma once

#include <cstdint>
#include <string>

namespace k40t::driver {

template <class E>
std::string text_of(E value) {
  const char* name = to_string(value);
  return name ? name : "unknown code " + std::to_string(static_cast<int>(value));
}

template <class E>
uint8_t code_of(E value) {
  return static_cast<uint8_t>(value);
}

}  // namespace k40t::driver
