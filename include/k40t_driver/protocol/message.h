// The contract every typed message struct follows, and the helpers they share.
//
// A message struct T (one per message id of the document's message list, including every ACK that
// carries data) is a plain aggregate whose fields are in physical units (names end in _deg,
// _deg_s, _degC, _m, _mm, _s, _ms, _x for ratios...) or enums for coded values, and has:
//
//   static constexpr MessageId kId;         // wire id; ACK structs use 0x01xxxx, status 0x02xxxx
//   static constexpr const char* kName;     // unique snake_case name (CLI, JSON, ROS `send`)
//   static constexpr const char* kSection;  // the document's section, e.g. "3.2.4.5"
//     (these three in one line: K40T_POD_MESSAGE(0x000304, "zoom_ratio", "3.2.4.5");)
//   static constexpr Direction kDirection;  // who sends it
//   static constexpr size_t kSize;          // payload bytes encode() writes
//   static constexpr size_t kMinSize;       // fewest payload bytes decode() accepts (<= kSize)
//   Status validate() const;                // every range the document gives; the message names
//                                           // the field and its allowed range
//   (optional) Status validate(const CodecOptions&) const;  // the same, and what the options
//                                           // make unencodable; encode_payload prefers it
//   void encode(ByteWriter&, const CodecOptions&) const;  // only called after validate() passed
//   Status decode(ByteReader&, const CodecOptions&);      // reads kSize bytes (kMinSize at least);
//                                           // no range checks: what the pod says is reported
//   template <class Self, class V> static void fields(Self& self, V&& v) {
//     v("yaw_deg", self.yaw_deg); ...       // every field in wire order (reserved bytes excluded)
//   }
//
// encode_payload()/decode_payload() below wrap these with the size and validation checks, and
// field_visit.h turns fields() into JSON, CLI arguments and generic round-trip tests.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/codec/value_checks.h"
#include "k40t_driver/protocol/byte_io.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/response_code.h"

// A message's wire id, name and document section, in one line (the first three members of the
// contract above); written out, they were the same three lines in every one of ~90 structs.
#define K40T_POD_MESSAGE(id, name, section)  \
  static constexpr MessageId kId = id;       \
  static constexpr const char* kName = name; \
  static constexpr const char* kSection = section

// The first six members of the contract in one line, for the two common shapes:
//   K40T_POD_REQUEST(0x00010D, "thermal_set_denoise", "3.2.2.8", 3, 2);
//     host -> pod, kSize 3, kMinSize 2, and `using Ack = PlainAck` (the bare response code; the
//     file must include messages/ack.h);
//   K40T_POD_REPORT(0x000004, "thermal_status", "3.2.2.12", 28, 28);
//     pod -> host (reports, status frames and data ACKs).
// A message of any other shape writes the members out.
#define K40T_POD_HEADER(id, name, section, direction, size, min_size) \
  K40T_POD_MESSAGE(id, name, section);                                \
  static constexpr Direction kDirection = Direction::direction;       \
  static constexpr size_t kSize = size;                               \
  static constexpr size_t kMinSize = min_size
#define K40T_POD_REQUEST(id, name, section, size, min_size)       \
  K40T_POD_HEADER(id, name, section, kHostToPod, size, min_size); \
  using Ack = PlainAck
#define K40T_POD_REPORT(id, name, section, size, min_size) \
  K40T_POD_HEADER(id, name, section, kPodToHost, size, min_size)

namespace k40t::protocol {

enum class Direction {
  kPodToHost,  // periodic reports, status frames, ACKs of host requests, pod's own requests
               // (0x000310)
  kHostToPod,  // requests, and the host's ACKs of the pod's requests (0x010310)
};
const char* to_string(Direction direction);

// A payload in a fixed buffer (no heap).
struct Payload {
  std::array<uint8_t, kMaxPayloadSize> bytes{};
  size_t size = 0;
  const uint8_t* data() const { return bytes.data(); }
};

// The checks validate() is made of and the scaling onto wire integers are the codec's (they are
// shared with the PSDK); these names keep them reachable as protocol::check_range, ...
using codec::check_enum;
using codec::check_range;
using codec::check_text;
using codec::first_failure;
using codec::to_wire;

namespace message_detail {
template <class T, class = void>
struct ValidatesOptions : std::false_type {};
template <class T>
struct ValidatesOptions<
    T, std::void_t<decltype(std::declval<const T&>().validate(std::declval<CodecOptions>()))>>
    : std::true_type {};
// validate(options) where the message has it (layouts: what a CodecOptions value makes
// unencodable, such as an angle x angle_command_scale beyond 16 bits), else validate().
template <class T>
Status validate_for(const T& message, const CodecOptions& options) {
  if constexpr (ValidatesOptions<T>::value) return message.validate(options);
  return message.validate();
}
}  // namespace message_detail

template <class T>
Result<Payload> encode_payload(const T& message, const CodecOptions& options = {}) {
  const Status valid = message_detail::validate_for(message, options);
  if (!valid) return Result<Payload>::fail(std::string(T::kName) + ": " + valid.message());
  Payload payload;
  ByteWriter writer(payload.bytes.data(), payload.bytes.size());
  message.encode(writer, options);
  if (!writer.ok()) return Result<Payload>::fail(std::string(T::kName) + ": payload overflow");
  payload.size = writer.size();
  return payload;
}

Status payload_size_error(const char* name, MessageId id, size_t got, size_t min_size);

template <class T>
Result<T> decode_payload(const uint8_t* data, size_t size, const CodecOptions& options = {}) {
  if (size < T::kMinSize) return payload_size_error(T::kName, T::kId, size, T::kMinSize);
  ByteReader reader(data, size);
  T message{};
  const Status decoded = message.decode(reader, options);
  if (!decoded) return Result<T>::fail(std::string(T::kName) + ": " + decoded.message());
  if (!reader.ok()) return payload_size_error(T::kName, T::kId, size, T::kMinSize);
  return message;
}

template <class T>
Result<T> decode_payload(const FrameView& frame, const CodecOptions& options = {}) {
  return decode_payload<T>(frame.payload, frame.payload_size, options);
}

}  // namespace k40t::protocol
