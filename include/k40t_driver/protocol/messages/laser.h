// Laser rangefinder messages (document section 3.2.5, system 0x04): single ranging 0x000400 with
// its distance-carrying ACK, periodic ranging 0x000406 and its 1 Hz status frame 0x020406.
//
// Byte order. The ACK 0x010400 follows CodecOptions::ack_byte_order (docs/protocol/decisions.md#a2,
// big by default). The status frame 0x020406 is not an ACK: section 2.1 makes every non-ACK payload
// low byte first, and the project reads every 0x02xxxx frame that way (camera_status.h). Its
// payload looks like the ACK's (it starts with a response code), which is no reason to read it as
// one: it follows CodecOptions::laser_status_byte_order, little by default (decision L1 in
// docs/protocol/gimbal_laser_sbus.md), so 87.6 m (876 = 0x036C) arrives as 6C 03.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/simple_requests.h"

namespace k40t::protocol {

// Response code + uint16 distance x0.1 m (0 = no return), both in the byte order kOrder selects:
// the payload of ACK 0x010400 and of status frame 0x020406. From byte kMinSizeT on the payload is
// optional (a refusal may carry the code only; the distance then reads as 0).
template <ByteOrder CodecOptions::*kOrder, size_t kMinSizeT>
struct LaserDistancePayload {
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 4;
  static constexpr size_t kMinSize = kMinSizeT;
  static constexpr auto kByteOrder = kOrder;
  static constexpr double kMaxDistanceM = 6553.5;  // uint16 x0.1

  ResponseCode code = ResponseCode::kOk;
  double distance_m = 0;  // 0 = no return

  K40T_LAYOUT(s, v) {
    v("code", s.code, wire::response_code);
    v("distance_m", s.distance_m, wire::scaled<uint16_t>(10).range(0, kMaxDistanceM, "m"));
  }
};

// ACK 0x010400, section 3.2.5.1.
struct LaserRangeAck : LaserDistancePayload<&CodecOptions::ack_byte_order, 2> {
  K40T_POD_MESSAGE(0x010400, "laser_range_ack", "3.2.5.1");
};

// 0x000400, section 3.2.5.1: byte 1 = 0 disable, 1 single ranging; byte 2 reserved.
struct LaserRangeRequest : SwitchRequest<LaserRangeAck> {
  K40T_POD_MESSAGE(0x000400, "laser_range", "3.2.5.1");
};

// 0x000406, section 3.2.5.2: byte 1 = 0 disable, 1 range once a second; byte 2 reserved. The ACK
// is the bare response code; the distances then come as status frames 0x020406.
struct LaserPeriodicRangeRequest : SwitchRequest<> {
  K40T_POD_MESSAGE(0x000406, "laser_periodic_range", "3.2.5.2");
};

// Status frame 0x020406, section 3.2.5.2, 1 Hz while periodic ranging is on. Byte order: see the
// top of this file.
struct LaserPeriodicRangeStatus : LaserDistancePayload<&CodecOptions::laser_status_byte_order, 4> {
  K40T_POD_MESSAGE(0x020406, "laser_periodic_range_status", "3.2.5.2");
};

// Every message struct of the laser family: the catalogue, the catalogue tests and the fuzz target
// take their entries from this list (message_list.h).
using LaserMessages = MessageList<LaserRangeRequest, LaserRangeAck, LaserPeriodicRangeRequest,
                                  LaserPeriodicRangeStatus>;

}  // namespace k40t::protocol
