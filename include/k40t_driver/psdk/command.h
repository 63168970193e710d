// THE CONTRACT every PSDK command struct follows, and the generic codec built on it.
//
// One struct per command of protocol document chapter 3, and one per ACK that carries data:
//
//   struct SetGimbalMode : Command<CommandSet::kGimbal, 0x02, Sender::kAdapter, PlainAck> {
//     static constexpr const char* kName = "set_gimbal_mode";   // unique snake_case name
//     static constexpr const char* kSection = "3.5.2";          // the document's section
//     GimbalMode mode = GimbalMode::kFree;                      // physical units / enums
//     Status validate() const;         // optional: ranges the document gives beyond the layout's
//     K40T_PSDK_LAYOUT(s, v) { v("mode", s.mode, wire::u8); }  // see layout.h
//   };
//
// Command<Set, Id, Sender, Ack> gives kSet, kId, kPacket = kCommand, kSender and `Ack`: the ACK
// struct, PlainAck (return code only) or NoAck (the document says the command gets no ACK).
// Reply<Set, Id, Sender> is the base of ACK structs: it holds the return code, which the codec
// writes and reads first; layout() lists only what follows it.
//
// commands/declare.h writes the repeated forms once: K40T_PSDK_NAMED(name, section) for the
// kName/kSection pair, K40T_PSDK_SETTING(...) for a Set/Get/ACK triple sharing one value struct,
// K40T_PSDK_GET(...) for a Get/ACK pair, K40T_PSDK_NO_DATA(...) for a command without data,
// K40T_PSDK_TRANSPARENT(...) for transparent data, K40T_PSDK_FLAGS(...) for a byte of one-bit
// flags and K40T_PSDK_VARIABLE_LENGTH() for the members listed below.
//
// Variable-length commands (hand-shake data, transparent data, widget lists, positioning) have
// no layout(); they define kMinBodySize, kMaxBodySize, encode(ByteWriter&) const,
// decode(ByteReader&) -> Status and describe(FieldSink&) const instead.
//
// encode_data() validates, then encodes (return code first for ACKs); decode_data() checks the
// size and decodes without range checks (what the other side says is reported as is). An ACK whose
// code is not OK may be the code alone (docs/psdk.md#frames: "unsupported" is one byte).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/psdk/frame.h"
#include "k40t_driver/psdk/layout.h"

namespace k40t::psdk {

using codec::check_enum;
using codec::first_failure;

// codec::check_range without the int/double overload ambiguity of small unsigned fields.
inline Status check_int(const char* field, int64_t value, int64_t lo, int64_t hi,
                        const char* unit = "") {
  return codec::check_range(field, value, lo, hi, unit);
}
inline Status check_real(const char* field, double value, double lo, double hi,
                         const char* unit = "") {
  return codec::check_range(field, value, lo, hi, unit);
}

enum class Sender : uint8_t { kAdapter, kPayload };
const char* to_string(Sender sender);
constexpr Sender other_side(Sender s) {
  return s == Sender::kAdapter ? Sender::kPayload : Sender::kAdapter;
}

// Section 2.2.
enum class AckCode : uint8_t { kOk = 0x00, kError = 0x01, kUnsupported = 0x02 };
const char* to_string(AckCode code);
std::string ack_code_text(
    uint8_t code);  // "executed successfully", ... or "unknown return code 0x.."

// The document says this command is not ACKed.
struct NoAck {};

template <CommandSet Set, uint8_t Id, Sender From, class AckType>
struct Command {
  static constexpr CommandSet kSet = Set;
  static constexpr uint8_t kId = Id;
  static constexpr PacketType kPacket = PacketType::kCommand;
  static constexpr Sender kSender = From;
  using Ack = AckType;
  static constexpr CommandKey key() { return key_of(Set, Id); }
};

template <CommandSet Set, uint8_t Id, Sender From>
struct Reply {
  static constexpr CommandSet kSet = Set;
  static constexpr uint8_t kId = Id;
  static constexpr PacketType kPacket = PacketType::kAck;
  static constexpr Sender kSender = From;
  static constexpr CommandKey key() { return key_of(Set, Id); }
  AckCode code = AckCode::kOk;
};

// The ACK of every command whose ACK is the return code alone. It stands for many keys, so it
// has none of its own; the catalogue lists it under each such command as "<command>_ack".
struct PlainAck;

// Up to N bytes of opaque data (hand-shake, transparent transmission), without heap.
template <size_t N>
struct Blob {
  std::array<uint8_t, N> bytes{};
  size_t size = 0;
  size_t dropped = 0;  // bytes from() could not keep; validation reports them
  static Blob from(const uint8_t* data, size_t n) {
    Blob b;
    b.size = std::min(n, N);
    b.dropped = n - b.size;
    if (b.size > 0) std::memcpy(b.bytes.data(), data, b.size);
    return b;
  }
  static Blob from(const std::string& text) {
    return from(reinterpret_cast<const uint8_t*>(text.data()), text.size());
  }
  const uint8_t* data() const { return bytes.data(); }
  bool operator==(const Blob& o) const {
    return size == o.size && std::equal(data(), data() + size, o.data());
  }
};

// "field 'data' must be 1..32 bytes, got 0"
Status check_length(const char* field, size_t size, size_t lo, size_t hi);

// Mixin for commands without data.
struct NoData {
  K40T_PSDK_LAYOUT(s, v) {}
};

// Mixin for commands whose data is Min..Max opaque bytes (hand-shake, transparent data).
template <size_t Min, size_t Max>
struct OpaqueData {
  static constexpr size_t kMinBodySize = Min;
  static constexpr size_t kMaxBodySize = Max;
  Blob<Max> data;

  Status validate() const { return check_length("data", data.size + data.dropped, Min, Max); }
  void encode(ByteWriter& w) const {
    for (size_t i = 0; i < data.size; ++i) w.u8(data.bytes[i]);
  }
  Status decode(ByteReader& r) {
    const size_t n = std::min(r.remaining(), Max);  // longer DATA: the rest is ignored
    for (size_t i = 0; i < n; ++i) data.bytes[i] = r.u8();
    data.size = n;
    return Status::ok();
  }
  void describe(FieldSink& sink) const { sink.bytes("data", data.data(), data.size); }
};

struct PlainAck : NoData {
  static constexpr PacketType kPacket = PacketType::kAck;
  static constexpr const char* kName = "ack";
  static constexpr const char* kSection = "2.2";
  AckCode code = AckCode::kOk;
};

// --- the generic codec ------------------------------------------------------------------------
namespace detail {
template <class T, class = void>
struct HasLayout : std::false_type {};
template <class T>
struct HasLayout<
    T, std::void_t<decltype(T::layout(std::declval<const T&>(), std::declval<LayoutSizer&>()))>>
    : std::true_type {};
template <class T, class = void>
struct HasValidate : std::false_type {};
template <class T>
struct HasValidate<T, std::void_t<decltype(std::declval<const T&>().validate())>> : std::true_type {
};

template <class T>
size_t layout_size() {
  static const size_t size = [] {
    T sample{};
    size_t n = 0;
    T::layout(sample, LayoutSizer(n));
    return n;
  }();
  return size;
}
}  // namespace detail

template <class T>
constexpr bool is_ack_v = T::kPacket == PacketType::kAck;

// DATA bytes after the return code (ACKs) or all DATA bytes (commands), at least and at most: a
// layout's one size, or the bounds a struct without a layout gives.
template <class T>
std::pair<size_t, size_t> body_size_bounds() {
  if constexpr (detail::HasLayout<T>::value) {
    const size_t size = detail::layout_size<T>();
    return {size, size};
  } else {
    return {T::kMinBodySize, T::kMaxBodySize};
  }
}
template <class T>
size_t min_body_size() {
  return body_size_bounds<T>().first;
}
template <class T>
size_t max_body_size() {
  return body_size_bounds<T>().second;
}
template <class T>
size_t min_data_size() {
  return min_body_size<T>() + (is_ack_v<T> ? 1 : 0);
}
template <class T>
size_t max_data_size() {
  return max_body_size<T>() + (is_ack_v<T> ? 1 : 0);
}

template <class T>
Status validate(const T& message) {
  Status result = Status::ok();
  if constexpr (detail::HasLayout<T>::value) T::layout(message, LayoutValidator(result));
  if constexpr (detail::HasValidate<T>::value) {
    if (result.is_ok()) result = message.validate();
  }
  return result;
}

template <class T>
void describe(const T& message, FieldSink& sink) {
  if constexpr (is_ack_v<T>) codec::detail::SinkAdapter{sink}("code", message.code);
  if constexpr (detail::HasLayout<T>::value)
    T::layout(message, LayoutSink(sink));
  else
    message.describe(sink);
}

std::string describe_size_error(const char* name, size_t got, size_t need);

template <class T>
Result<Data> encode_data(const T& message) {
  const Status valid = validate(message);
  if (!valid) return Result<Data>::fail(std::string(T::kName) + ": " + valid.message());
  Data data;
  ByteWriter w(data.bytes.data(), data.bytes.size());
  if constexpr (is_ack_v<T>) w.u8(static_cast<uint8_t>(message.code));
  if constexpr (detail::HasLayout<T>::value)
    T::layout(message, LayoutWriter(w));
  else
    message.encode(w);
  if (!w.ok()) return Result<Data>::fail(std::string(T::kName) + ": DATA longer than 256 bytes");
  data.size = w.size();
  return data;
}

template <class T>
Result<T> decode_data(const uint8_t* bytes, size_t size) {
  T message{};
  ByteReader r(bytes, size);
  if constexpr (is_ack_v<T>) {
    if (size < 1) return Result<T>::fail(describe_size_error(T::kName, size, 1));
    message.code = static_cast<AckCode>(r.u8());
    if (message.code != AckCode::kOk && r.remaining() == 0) return message;  // a refusal, code only
  }
  if (r.remaining() < min_body_size<T>())
    return Result<T>::fail(describe_size_error(T::kName, size, min_data_size<T>()));
  if constexpr (detail::HasLayout<T>::value) {
    T::layout(message, LayoutReader(r));
  } else {
    const Status decoded = message.decode(r);
    if (!decoded) return Result<T>::fail(std::string(T::kName) + ": " + decoded.message());
  }
  if (!r.ok()) return Result<T>::fail(describe_size_error(T::kName, size, min_data_size<T>()));
  return message;
}

template <class T>
Result<T> decode_data(const Data& data) {
  return decode_data<T>(data.data(), data.size);
}

}  // namespace k40t::psdk
