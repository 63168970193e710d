// The ACK every request gets (document sections 2.1 and 3.3): id 0x01xxxx, payload starting with
// the 2-byte response code (big-endian by default, docs/protocol/decisions.md#a2). Requests whose
// ACK carries nothing else use PlainAck; the others have their own struct whose first field is the
// code.
#pragma once

#include "k40t_driver/protocol/message.h"

namespace k40t::protocol {

struct PlainAck {
  static constexpr MessageId kId = 0x010000;  // stands for every 0x01xxxx; see catalogue
  static constexpr const char* kName = "ack";
  static constexpr const char* kSection = "3.3";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 2;

  ResponseCode code = ResponseCode::kOk;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions& o) const {
    w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  }
  Status decode(ByteReader& r, const CodecOptions& o) {
    code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
  }
};

// Reads just the response code of any ACK payload (all ACKs start with it). A payload too short
// for one gives kAckUnreadable, the driver's own code, not the pod's 0x0007 "length mismatch".
inline ResponseCode ack_response_code(const uint8_t* payload, size_t size, const CodecOptions& o) {
  ByteReader r(payload, size);
  const uint16_t code = r.u16(o.ack_byte_order);
  return r.ok() ? static_cast<ResponseCode>(code) : ResponseCode::kAckUnreadable;
}

}  // namespace k40t::protocol
