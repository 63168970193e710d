// Test support for the camera family's golden frames (test/data/golden/camera.txt): reading the
// file, recording a message's fields as text, and setting a message's fields from the file's
// "= name=value" lines, so one hand-written frame checks both decode and encode.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/message.h"

namespace k40t::protocol::testing {

using FieldValues = std::vector<std::pair<std::string, std::string>>;  // in wire order

struct GoldenFrame {
  int line = 0;         // of the "# <section> <name>:" comment, for failure messages
  std::string section;  // "3.2.4.3"
  std::string name;     // catalogue name, "take_photo"
  std::vector<uint8_t> bytes;
  FieldValues expected;
};

// Reads every entry of a golden file; fails the calling test on a malformed entry.
std::vector<GoldenFrame> load_golden(const std::string& path);
std::vector<GoldenFrame> load_camera_golden();  // K40T_TEST_DATA_DIR/golden/camera.txt
const GoldenFrame* find_golden(const std::vector<GoldenFrame>& all, const std::string& name);

// A FieldSink that writes each field the way golden files do: enums by numeric code, bools 0/1,
// text as-is, numbers in decimal; reals are also kept as doubles for a tolerant comparison.
class RecordedFields : public FieldSink {
 public:
  void integer(const char* name, int64_t value) override;
  void unsigned_integer(const char* name, uint64_t value) override;
  void real(const char* name, double value) override;
  void boolean(const char* name, bool value) override;
  void text(const char* name, const std::string& value) override;
  void enumeration(const char* name, int64_t code, const char* label) override;
  void bytes(const char* name, const uint8_t* data, size_t size) override;

  const FieldValues& values() const { return values_; }

 private:
  FieldValues values_;
  std::map<std::string, double> reals_;
  friend ::testing::AssertionResult fields_match(const RecordedFields&, const FieldValues&);
};

template <class T>
RecordedFields record_fields(const T& message) {
  RecordedFields recorded;
  visit_fields(message, recorded);
  return recorded;
}

// Same names in the same order, equal texts; reals equal within 1e-9 relative.
::testing::AssertionResult fields_match(const RecordedFields& actual, const FieldValues& expected);

// Sets each field of `message` named in `values` from its text (the inverse of RecordedFields).
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
  static bool assign(const std::string& text, double& field);
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

}  // namespace k40t::protocol::testing
