// Generic access to a message's fields through T::fields(self, visitor).
//
// FieldSink is the type-erased, read-only view used by the catalogue (JSON output of `k40t
// decode`, the monitor's one-line summaries, ROS raw decoding). visit_fields() adapts the typed
// visitor calls to it: integers, reals, booleans, text, enums (code + name) and byte arrays.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <type_traits>

namespace k40t::codec {

class FieldSink {
 public:
  virtual ~FieldSink() = default;
  virtual void integer(const char* name, int64_t value) = 0;
  virtual void unsigned_integer(const char* name, uint64_t value) = 0;
  virtual void real(const char* name, double value) = 0;
  virtual void boolean(const char* name, bool value) = 0;
  virtual void text(const char* name, const std::string& value) = 0;
  // `label` is the document's name for the code, or nullptr if the code is not defined.
  virtual void enumeration(const char* name, int64_t code, const char* label) = 0;
  virtual void bytes(const char* name, const uint8_t* data, size_t size) = 0;
};

namespace detail {
template <class T>
struct IsByteArray : std::false_type {};
template <size_t N>
struct IsByteArray<std::array<uint8_t, N>> : std::true_type {};

struct SinkAdapter {
  FieldSink& sink;
  template <class T>
  void operator()(const char* name, const T& value) const {
    if constexpr (std::is_same_v<T, bool>) {
      sink.boolean(name, value);
    } else if constexpr (std::is_enum_v<T>) {
      using U = std::underlying_type_t<T>;
      sink.enumeration(name, static_cast<int64_t>(static_cast<U>(value)), to_string(value));
    } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
      sink.integer(name, static_cast<int64_t>(value));
    } else if constexpr (std::is_integral_v<T>) {
      sink.unsigned_integer(name, static_cast<uint64_t>(value));
    } else if constexpr (std::is_floating_point_v<T>) {
      sink.real(name, static_cast<double>(value));
    } else if constexpr (std::is_same_v<T, std::string>) {
      sink.text(name, value);
    } else if constexpr (IsByteArray<T>::value) {
      sink.bytes(name, value.data(), value.size());
    } else {
      static_assert(sizeof(T) == 0, "field type not supported by FieldSink");
    }
  }
};
}  // namespace detail

template <class T>
void visit_fields(const T& message, FieldSink& sink) {
  T::fields(message, detail::SinkAdapter{sink});
}

}  // namespace k40t::codec
