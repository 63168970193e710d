// A FieldSink that writes every field down as text, in order, so that tests can compare decoded
// messages with each other and with the '=' lines of the golden files.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "k40t_driver/protocol/field_visit.h"

namespace k40t::testing {

class FieldRecorder : public protocol::FieldSink {
 public:
  using Fields = std::vector<std::pair<std::string, std::string>>;

  void integer(const char* name, int64_t value) override { add(name, std::to_string(value)); }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, std::to_string(value));
  }
  void real(const char* name, double value) override {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    add(name, buffer);
  }
  void boolean(const char* name, bool value) override { add(name, value ? "1" : "0"); }
  void text(const char* name, const std::string& value) override { add(name, value); }
  void enumeration(const char* name, int64_t code, const char*) override {
    add(name, std::to_string(code));
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    std::string hex;
    char b[4];
    for (size_t i = 0; i < size; ++i) {
      std::snprintf(b, sizeof b, "%02X", data[i]);
      hex += b;
    }
    add(name, hex);
  }

  const Fields& fields() const { return fields_; }

 private:
  void add(const char* name, std::string value) { fields_.emplace_back(name, std::move(value)); }
  Fields fields_;
};

template <class T>
FieldRecorder::Fields record_fields(const T& message) {
  FieldRecorder recorder;
  protocol::visit_fields(message, recorder);
  return recorder.fields();
}

// Values are equal as numbers (relative tolerance for decimal fractions such as 0.01 deg, and
// "true"/"false" standing for 1/0) or else as text.
inline bool same_value(const std::string& expected, const std::string& actual) {
  auto number = [](const std::string& s, double* v) {
    if (s == "true") return *v = 1, true;
    if (s == "false") return *v = 0, true;
    char* end = nullptr;
    *v = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size();
  };
  double e = 0;
  double a = 0;
  if (number(expected, &e) && number(actual, &a)) {
    return std::fabs(e - a) <= 1e-9 * std::fmax(1.0, std::fabs(e));
  }
  return expected == actual;
}

// Describes the differences between two field lists, or returns "" if they agree.
inline std::string field_differences(const FieldRecorder::Fields& expected,
                                     const FieldRecorder::Fields& actual) {
  std::string out;
  const size_t n = std::max(expected.size(), actual.size());
  for (size_t i = 0; i < n; ++i) {
    const std::string e =
        i < expected.size() ? expected[i].first + "=" + expected[i].second : "(none)";
    const std::string a = i < actual.size() ? actual[i].first + "=" + actual[i].second : "(none)";
    if (i < expected.size() && i < actual.size() && expected[i].first == actual[i].first &&
        same_value(expected[i].second, actual[i].second)) {
      continue;
    }
    out += "  field " + std::to_string(i) + ": expected " + e + ", got " + a + "\n";
  }
  return out;
}

}  // namespace k40t::testing
