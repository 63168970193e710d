// A FieldSink that records every field of a message, in wire order, and THE comparison of
// recorded fields with expected values spelled as in the golden files' '=' lines
// (test/data/golden/README.md). Used by the unit tests and by fuzz/fuzz_decoders.cpp, so it is
// header-only and does not depend on gtest.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "k40t_driver/codec/layout.h"
#include "k40t_driver/protocol/field_assign.h"
#include "k40t_driver/protocol/field_visit.h"

namespace k40t::testing {

// name=value pairs in wire order, values spelled as in the golden files.
using FieldValues = std::vector<std::pair<std::string, std::string>>;

class FieldRecorder : public protocol::FieldSink {
 public:
  enum class Kind { kSigned, kUnsigned, kReal, kBool, kText, kEnum, kBytes };
  struct Field {
    std::string name;
    Kind kind = Kind::kSigned;
    int64_t i = 0;     // signed, bool (0/1), enum code
    uint64_t u = 0;    // unsigned
    double d = 0;      // real
    std::string text;  // text, enum label
    std::vector<uint8_t> bytes;
  };

  void integer(const char* name, int64_t value) override { add(name, Kind::kSigned).i = value; }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, Kind::kUnsigned).u = value;
  }
  void real(const char* name, double value) override { add(name, Kind::kReal).d = value; }
  void boolean(const char* name, bool value) override { add(name, Kind::kBool).i = value ? 1 : 0; }
  void text(const char* name, const std::string& value) override {
    add(name, Kind::kText).text = value;
  }
  void enumeration(const char* name, int64_t code, const char* label) override {
    Field& field = add(name, Kind::kEnum);
    field.i = code;
    field.text = label ? label : "";
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    add(name, Kind::kBytes).bytes.assign(data, data + size);
  }

  const std::vector<Field>& fields() const { return fields_; }

  // The fields spelled as a golden file's '=' line would: integers in decimal, reals with 17
  // significant digits, bools 0/1, enums by code, text as is, bytes as "1,2,3".
  FieldValues values() const {
    FieldValues out;
    for (const Field& field : fields_) out.emplace_back(field.name, spell(field));
    return out;
  }

  static std::string spell(const Field& field) {
    switch (field.kind) {
      case Kind::kSigned:
      case Kind::kBool:
      case Kind::kEnum:
        return std::to_string(field.i);
      case Kind::kUnsigned:
        return std::to_string(field.u);
      case Kind::kReal: {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", field.d);
        return buffer;
      }
      case Kind::kText:
        return field.text;
      case Kind::kBytes: {
        std::string out;
        for (uint8_t b : field.bytes) out += (out.empty() ? "" : ",") + std::to_string(b);
        return out;
      }
    }
    return "?";
  }

 private:
  Field& add(const char* name, Kind kind) {
    fields_.push_back(Field{name, kind, 0, 0, 0, {}, {}});
    return fields_.back();
  }
  std::vector<Field> fields_;
};

namespace detail {
template <class T, class V, class = void>
struct HasFields : std::false_type {};
template <class T, class V>
struct HasFields<T, V, std::void_t<decltype(T::fields(std::declval<T&>(), std::declval<V&>()))>>
    : std::true_type {};
}  // namespace detail

// v(name, field) for every field of `message`: the pod's fields(), or the flattened fields of a
// PSDK layout() (the same FieldLister the pod's fields() is made of).
template <class T, class V>
void visit_named_fields(T& message, V& v) {
  using Message = std::remove_const_t<T>;
  if constexpr (detail::HasFields<Message, V>::value) {
    Message::fields(message, v);
  } else {
    Message::layout(message, codec::FieldLister<V>(v));
  }
}

// Every field of `message` with its value: a pod message's or a PSDK command's.
template <class T>
FieldRecorder record_fields(const T& message) {
  FieldRecorder recorder;
  protocol::detail::SinkAdapter adapter{recorder};
  visit_named_fields(message, adapter);
  return recorder;
}

// "" if `field` has the value `expected` spells, else why not. Numbers compare as numbers (reals
// within 1e-9 relative, for decimal fractions such as 0.01 deg); bools also as true/false; enums
// by code or by label.
inline std::string value_difference(const FieldRecorder::Field& field,
                                    const std::string& expected) {
  using Kind = FieldRecorder::Kind;
  const char* name = field.name.c_str();
  bool same = false;
  switch (field.kind) {
    case Kind::kSigned: {
      Result<int64_t> e = protocol::parse_signed_field(name, expected, INT64_MIN, INT64_MAX);
      same = e && e.value() == field.i;
      break;
    }
    case Kind::kUnsigned: {
      Result<uint64_t> e = protocol::parse_unsigned_field(name, expected, UINT64_MAX);
      same = e && e.value() == field.u;
      break;
    }
    case Kind::kReal: {
      Result<double> e = protocol::parse_real_field(name, expected);
      same = e && std::fabs(e.value() - field.d) <= 1e-9 * std::max(1.0, std::fabs(e.value()));
      break;
    }
    case Kind::kBool: {
      Result<bool> e = protocol::parse_bool_field(name, expected);
      same = e && (e.value() ? 1 : 0) == field.i;
      break;
    }
    case Kind::kText:
      same = expected == field.text;
      break;
    case Kind::kEnum: {
      Result<int64_t> e = protocol::parse_signed_field(name, expected, INT64_MIN, INT64_MAX);
      same = (e && e.value() == field.i) ||
             (!field.text.empty() &&
              protocol::normalize_label(expected) == protocol::normalize_label(field.text));
      break;
    }
    case Kind::kBytes: {
      std::vector<uint8_t> e(field.bytes.size());
      same = protocol::parse_bytes_field(name, expected, e.data(), e.size()) && e == field.bytes;
      break;
    }
  }
  if (same) return "";
  std::string got = FieldRecorder::spell(field);
  if (field.kind == Kind::kText) got = "\"" + got + "\"";
  if (field.kind == Kind::kEnum) got += " (" + field.text + ")";
  return "field '" + field.name + "': expected " + expected + ", got " + got;
}

// "" if `actual` has exactly the fields of `expected`, in the same order, with the same values;
// otherwise one line per difference, each naming the field, the expected and the actual value.
inline std::string field_differences(const FieldValues& expected, const FieldRecorder& actual) {
  std::string out;
  const auto& got = actual.fields();
  for (size_t i = 0; i < std::max(expected.size(), got.size()); ++i) {
    std::string problem;
    if (i >= got.size()) {
      problem = "field '" + expected[i].first + "': expected " + expected[i].second +
                ", but the message has no field #" + std::to_string(i);
    } else if (i >= expected.size()) {
      problem = "field '" + got[i].name + "' = " + FieldRecorder::spell(got[i]) +
                " is not expected (only " + std::to_string(expected.size()) + " fields are)";
    } else if (expected[i].first != got[i].name) {
      problem = "field #" + std::to_string(i) + " is '" + got[i].name + "', expected '" +
                expected[i].first + "' (fields in wire order)";
    } else {
      problem = value_difference(got[i], expected[i].second);
    }
    if (!problem.empty()) out += "  " + problem + "\n";
  }
  return out;
}

inline std::string field_differences(const FieldRecorder& expected, const FieldRecorder& actual) {
  return field_differences(expected.values(), actual);
}

}  // namespace k40t::testing
