// Setting a message's fields from text (CLI arguments `name=value`, golden files): the inverse of
// field_visit.h, generic over T::fields(). Every accepted spelling:
//   integers  decimal or 0x-hex, range-checked against the field's C++ type
//   reals     anything strtod reads fully, finite
//   bools     0, 1, true, false
//   text      taken as is (the message's validate() checks the width)
//   enums     the numeric code, or the to_string() name (case, spaces, '-' and '_' ignored:
//             "white_hot" matches "white hot")
//   bytes     std::array<uint8_t, N> as N numbers separated by ',' or '.' ("192.168.144.64")
// A name that is not one of the message's fields is an error listing the fields. Fields not
// given keep the struct's default.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

using FieldArgs = std::map<std::string, std::string>;

// The text parsers, one per field kind; failures name the field and what was expected.
Result<int64_t> parse_signed_field(const char* name, const std::string& text, int64_t lo,
                                   int64_t hi);
Result<uint64_t> parse_unsigned_field(const char* name, const std::string& text, uint64_t hi);
Result<double> parse_real_field(const char* name, const std::string& text);
Result<bool> parse_bool_field(const char* name, const std::string& text);
Status parse_bytes_field(const char* name, const std::string& text, uint8_t* out, size_t count);
// Lower case, with every run of non-alphanumerics turned into one '_' and trimmed at the ends.
std::string normalize_label(const std::string& label);
bool looks_numeric(const std::string& text);  // starts like a number: digit or sign
std::string unknown_fields_error(const char* message, const std::vector<std::string>& unknown,
                                 const std::vector<std::string>& fields);

namespace detail {

template <class E>
Result<E> parse_enum_field(const char* name, const std::string& text) {
  using U = std::underlying_type_t<E>;
  const uint64_t last =
      std::numeric_limits<U>::max() > 0xFFFF ? 0xFFFF : std::numeric_limits<U>::max();
  // Names first, so that a label starting with a digit ("1080p30") is still found by name.
  const std::string wanted = normalize_label(text);
  std::string allowed;
  for (uint64_t code = 0; code <= last; ++code) {
    const char* label = to_string(static_cast<E>(static_cast<U>(code)));
    if (label == nullptr) continue;
    if (normalize_label(label) == wanted) return static_cast<E>(static_cast<U>(code));
    if (!allowed.empty()) allowed += ", ";
    allowed += std::to_string(code) + " " + normalize_label(label);
  }
  Result<int64_t> code =
      parse_signed_field(name, text, static_cast<int64_t>(std::numeric_limits<U>::min()),
                         static_cast<int64_t>(std::numeric_limits<U>::max()));
  if (code) return static_cast<E>(static_cast<U>(code.value()));
  if (looks_numeric(text)) return code.status();  // a number out of the code's range
  return Result<E>::fail(std::string("field '") + name + "': no code named '" + text +
                         "'; allowed: " + allowed);
}

// The assigning visitor: applies the arguments that name a field, remembers every field name.
struct ArgAssigner {
  explicit ArgAssigner(const FieldArgs& given) : args(given) {}
  const FieldArgs& args;
  Status status = Status::ok();
  size_t used = 0;
  std::vector<std::string> names;

  template <class T>
  void operator()(const char* name, T& field) {
    names.emplace_back(name);
    const auto found = args.find(name);
    if (found == args.end() || !status) return;
    ++used;
    status = assign(name, found->second, field);
  }

  template <class T>
  static Status assign(const char* name, const std::string& text, T& field) {
    if constexpr (std::is_same_v<T, bool>) {
      return store(parse_bool_field(name, text), field);
    } else if constexpr (std::is_enum_v<T>) {
      return store(parse_enum_field<T>(name, text), field);
    } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
      return store(parse_signed_field(name, text, std::numeric_limits<T>::min(),
                                      std::numeric_limits<T>::max()),
                   field);
    } else if constexpr (std::is_integral_v<T>) {
      return store(parse_unsigned_field(name, text, std::numeric_limits<T>::max()), field);
    } else if constexpr (std::is_floating_point_v<T>) {
      return store(parse_real_field(name, text), field);
    } else if constexpr (std::is_same_v<T, std::string>) {
      field = text;
      return Status::ok();
    } else if constexpr (IsByteArray<T>::value) {
      return parse_bytes_field(name, text, field.data(), field.size());
    } else {
      static_assert(sizeof(T) == 0, "field type not supported by encode_args");
    }
  }

  template <class V, class T>
  static Status store(const Result<V>& parsed, T& field) {
    if (!parsed) return parsed.status();
    field = static_cast<T>(parsed.value());
    return Status::ok();
  }
};

}  // namespace detail

// The message T with the fields named in `args` set; fails on unknown names or bad values.
template <class T>
Result<T> message_from_args(const FieldArgs& args) {
  T message{};
  detail::ArgAssigner assigner(args);
  T::fields(message, assigner);
  if (!assigner.status)
    return Result<T>::fail(std::string(T::kName) + ": " + assigner.status.message());
  if (assigner.used < args.size()) {
    std::vector<std::string> unknown;
    for (const auto& arg : args) {
      bool known = false;
      for (const std::string& n : assigner.names) known = known || n == arg.first;
      if (!known) unknown.push_back(arg.first);
    }
    return Result<T>::fail(unknown_fields_error(T::kName, unknown, assigner.names));
  }
  return message;
}

// From text to payload bytes, validated (MessageInfo::encode_args).
template <class T>
Result<Payload> encode_args(const FieldArgs& args, const CodecOptions& options) {
  Result<T> message = message_from_args<T>(args);
  if (!message) return message.status();
  return encode_payload(message.value(), options);
}

}  // namespace k40t::protocol
