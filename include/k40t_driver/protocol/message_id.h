// Message ids (document section 2.1): 24-bit, sent low byte first. The high byte says what the
// frame is: 0x00 a request or periodic report, 0x01 the ACK of request 0x00xxxx, 0x02 a status
// frame that follows request 0x00xxxx.
#pragma once

#include <cstdint>

namespace k40t::protocol {

using MessageId = uint32_t;

enum class MessageKind : uint8_t { kRequestOrReport = 0x00, kAck = 0x01, kStatus = 0x02, kOther };

constexpr MessageId kMaxMessageId = 0xFFFFFF;

constexpr MessageKind kind_of(MessageId id) {
  switch ((id >> 16) & 0xFF) {
    case 0x00:
      return MessageKind::kRequestOrReport;
    case 0x01:
      return MessageKind::kAck;
    case 0x02:
      return MessageKind::kStatus;
    default:
      return MessageKind::kOther;
  }
}
// The request id an ACK or status frame belongs to.
constexpr MessageId request_id_of(MessageId id) {
  return id & 0xFFFF;
}
constexpr MessageId ack_id_of(MessageId request) {
  return (request & 0xFFFF) | 0x010000;
}
constexpr MessageId status_id_of(MessageId request) {
  return (request & 0xFFFF) | 0x020000;
}

// Periodic reports occupy 0x000001..0x00000F (sections 3.1.1 and 3.2.1).
constexpr bool is_periodic_report(MessageId id) {
  return id >= 0x000001 && id <= 0x00000F;
}

// Addresses of section 2.1 (see docs/protocol/decisions.md#a3 for the gimbal's 0x03).
struct Address {
  uint8_t system = 0;
  uint8_t component = 0;
  bool operator==(const Address& o) const { return system == o.system && component == o.component; }
  bool operator!=(const Address& o) const { return !(*this == o); }
};
constexpr Address kHostAddress{0x01, 0x01};
constexpr Address kFlightControllerAddress{0x02, 0x01};
constexpr Address kGimbalAddress{0x03, 0x01};
constexpr Address kCameraAddress{0x04, 0x01};

}  // namespace k40t::protocol
