// The ACK every request gets (document sections 2.1 and 3.3): id 0x01xxxx, payload starting with
// the 2-byte response code (big-endian by default, docs/protocol/decisions.md#a2). Requests whose
// ACK carries nothing else use PlainAck; the others have their own struct whose first field is the
// code.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"

// A data ACK's first members in one line: its header with kMinSize 2 (a refusal may carry the
// response code alone) and the ACK byte order (docs/protocol/decisions.md#a2):
//   K40T_POD_DATA_ACK(0x010018, "gimbal_version_ack", "3.1.2.5", kPodToHost, 9);
#define K40T_POD_DATA_ACK(id, name, section, direction, size) \
  K40T_POD_HEADER(id, name, section, direction, size, 2);     \
  static constexpr auto kByteOrder = &CodecOptions::ack_byte_order

namespace k40t::protocol {

struct PlainAck {
  static constexpr MessageId kId = 0x010000;  // stands for every 0x01xxxx; see catalogue
  static constexpr const char* kName = "ack";
  static constexpr const char* kSection = "3.3";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 2;

  static constexpr auto kByteOrder = &CodecOptions::ack_byte_order;

  K40T_FIELDS((ResponseCode, code, wire::response_code, ResponseCode::kOk));
};

// The payload of a data ACK, which a refusal may cut to the response code: the code alone, or at
// least `full_size` bytes (a data ACK's finish_decode(); payload_size_error() otherwise).
inline Status code_alone_or_at_least(const char* name, MessageId id, size_t payload_size,
                                     size_t full_size) {
  if (payload_size == PlainAck::kSize || payload_size >= full_size) return Status::ok();
  return payload_size_error(name, id, payload_size, full_size);
}

// Reads just the response code of any ACK payload (all ACKs start with it). A payload too short
// for one gives kAckUnreadable, the driver's own code, not the pod's 0x0007 "length mismatch".
inline ResponseCode ack_response_code(const uint8_t* payload, size_t size, const CodecOptions& o) {
  ByteReader r(payload, size);
  const uint16_t code = r.u16(o.ack_byte_order);
  return r.ok() ? static_cast<ResponseCode>(code) : ResponseCode::kAckUnreadable;
}

}  // namespace k40t::protocol
