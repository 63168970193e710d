// Sets a message's fields from a golden frame's '=' values (the inverse of field_recorder.h's
// spelling), written independently of protocol/field_assign so that a golden frame's expected
// values can build the struct whose encoding must give the hand-written bytes.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

#include "field_recorder.h"

namespace k40t::testing {

namespace detail {
struct FieldAssigner {
  const FieldValues& values;
  std::vector<std::string>& used;
  std::string& error;

  template <class F>
  void operator()(const char* name, F& field) const {
    for (const auto& [key, text] : values) {
      if (key != name) continue;
      used.push_back(key);
      if (!assign(text, field))
        error += std::string(" cannot read '") + text + "' as " + name + ";";
      return;
    }
  }

  static bool assign(const std::string& text, std::string& field) {
    field = text;
    return true;
  }
  static bool assign(const std::string& text, bool& field) {
    if (text != "0" && text != "1") return false;
    field = text == "1";
    return true;
  }
  static bool assign(const std::string& text, double& field) {
    char* end = nullptr;
    field = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0';
  }
  template <class F>
  static bool assign(const std::string& text, F& field) {
    static_assert(std::is_integral_v<F> || std::is_enum_v<F>, "unsupported field type");
    using Wire = typename Underlying<F>::type;
    char* end = nullptr;
    if constexpr (std::is_signed_v<Wire>) {
      field = static_cast<F>(static_cast<Wire>(std::strtoll(text.c_str(), &end, 10)));
    } else {
      field = static_cast<F>(static_cast<Wire>(std::strtoull(text.c_str(), &end, 10)));
    }
    return !text.empty() && *end == '\0';
  }
  template <class F, bool = std::is_enum_v<F>>
  struct Underlying {
    using type = F;
  };
  template <class F>
  struct Underlying<F, true> {
    using type = std::underlying_type_t<F>;
  };
};
}  // namespace detail

// Sets each field of `message` named in `values`; fails if a value cannot be read or a name is
// not a field of T.
template <class T>
::testing::AssertionResult assign_fields(T& message, const FieldValues& values) {
  std::vector<std::string> used;
  std::string error;
  T::fields(message, detail::FieldAssigner{values, used, error});
  if (used.size() != values.size())
    error += " some names are not fields of " + std::string(T::kName) + ";";
  if (!error.empty()) return ::testing::AssertionFailure() << error;
  return ::testing::AssertionSuccess();
}

}  // namespace k40t::testing
