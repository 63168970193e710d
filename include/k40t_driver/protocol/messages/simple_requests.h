// Two request shapes the document repeats many times, so each message that has them is a few
// lines (its id, name and section) on top of one tested implementation:
//   CommandRequest<C>  "Byte1 = C (the command), Byte2 reserved", e.g. 0x000013 drift calibration
//                      (C = 0x01) or 0x00002D servo off (C = 0x00). No fields.
//   SwitchRequest      "Byte1 = 0 off / 1 on, Byte2 reserved", e.g. 0x000033 stabilisation,
//                      0x000400/0x000406 laser ranging. One field, `enable`.
// Usage: struct GimbalRestartRequest : CommandRequest<0x01> { kId, kName, kSection };
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {

template <uint8_t kCommandByte, class AckType = PlainAck>
struct CommandRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;  // the reserved byte is optional on receive
  static constexpr uint8_t kCommand = kCommandByte;
  using Ack = AckType;

  // A different first byte is some other (undocumented) command: decoding refuses it rather
  // than act on it.
  K40T_LAYOUT(s, v) {
    v("command", wire::gap, wire::command(kCommand));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

template <class AckType = PlainAck>
struct SwitchRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;
  using Ack = AckType;

  K40T_FIELDS((bool, enable, wire::on_off, true), (reserved, wire::reserved(1)));
};

}  // namespace k40t::protocol
