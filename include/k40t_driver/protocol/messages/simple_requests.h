// Two request shapes the document repeats many times, so each message that has them is a few
// lines (its id, name and section) on top of one tested implementation:
//   CommandRequest<C>  "Byte1 = C (the command), Byte2 reserved", e.g. 0x000013 drift calibration
//                      (C = 0x01) or 0x00002D servo off (C = 0x00). No fields.
//   SwitchRequest      "Byte1 = 0 off / 1 on, Byte2 reserved", e.g. 0x000033 stabilisation,
//                      0x000400/0x000406 laser ranging. One field, `enable`.
// Usage: struct GimbalRestartRequest : CommandRequest<0x01> { kId, kName, kSection };
#pragma once

#include <string>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {

template <uint8_t kCommandByte, class AckType = PlainAck>
struct CommandRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;  // the reserved byte is optional on receive
  static constexpr uint8_t kCommand = kCommandByte;
  using Ack = AckType;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions&) const {
    w.u8(kCommand);
    w.zeros(1);
  }
  // A different first byte is some other (undocumented) command: refuse it rather than act on it.
  Status decode(ByteReader& r, const CodecOptions&) {
    const uint8_t v = r.u8();
    if (r.ok() && v != kCommand) {
      return Status::fail("byte 1 must be the command code " + std::to_string(kCommand) + ", got " +
                          std::to_string(v));
    }
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self&, V&&) {}
};

template <class AckType = PlainAck>
struct SwitchRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;
  using Ack = AckType;

  bool enable = true;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions&) const {
    w.u8(enable ? 1 : 0);
    w.zeros(1);
  }
  Status decode(ByteReader& r, const CodecOptions&) {
    const uint8_t v = r.u8();
    if (v > 1) return Status::fail("byte 1 must be 0 (off) or 1 (on), got " + std::to_string(v));
    enable = v == 1;
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("enable", self.enable);
  }
};

}  // namespace k40t::protocol
