// Laser rangefinder messages (document section 3.2.5, system 0x04): single ranging 0x000400 with
// its distance-carrying ACK, periodic ranging 0x000406 and its 1 Hz status frame 0x020406.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {

// ACK 0x010400: response code, uint16 distance x0.1 m (0 = no return). Byte order: NOTES A2.
struct LaserRangeAck {
  static constexpr MessageId kId = 0x010400;
  static constexpr const char* kName = "laser_range_ack";
  static constexpr const char* kSection = "3.2.5.1";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 4;
  static constexpr size_t kMinSize = 2;  // a refusal may carry the code only

  ResponseCode code = ResponseCode::kOk;
  double distance_m = 0;  // 0 = no return

  Status validate() const { return check_range("distance_m", distance_m, 0.0, 6553.5, "m"); }
  void encode(ByteWriter& w, const CodecOptions& o) const {
    w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
    w.u16(to_wire<uint16_t>(distance_m, 10), o.ack_byte_order);
  }
  Status decode(ByteReader& r, const CodecOptions& o) {
    code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
    distance_m = r.remaining() >= 2 ? r.u16(o.ack_byte_order) / 10.0 : 0.0;
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
    v("distance_m", self.distance_m);
  }
};

// 0x000400, section 3.2.5.1: byte 1 = 0 disable, 1 single ranging; byte 2 reserved.
struct LaserRangeRequest {
  static constexpr MessageId kId = 0x000400;
  static constexpr const char* kName = "laser_range";
  static constexpr const char* kSection = "3.2.5.1";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;
  using Ack = LaserRangeAck;

  bool enable = true;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions&) const {
    w.u8(enable ? 1 : 0);
    w.zeros(1);
  }
  Status decode(ByteReader& r, const CodecOptions&) {
    const uint8_t v = r.u8();
    if (v > 1) return Status::fail("byte 1 must be 0 (disable) or 1 (single ranging), got " + std::to_string(v));
    enable = v == 1;
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("enable", self.enable);
  }
};

}  // namespace k40t::protocol
