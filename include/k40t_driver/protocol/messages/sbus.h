// SBUS messages (document section 3.2.6, system 0x04): how the pod reads an SBUS remote control
// plugged into it. 0x000500 sets the channel value range, 0x000501 which channel drives which
// function, 0x000502 reads both back (data ACK 0x010502). The pod applies changes only after a
// power cycle (the document's note).
//
// Channels: the wire carries 0..15 for channels 1..16; the structs hold the channel NUMBER 1..16,
// as printed on a remote control.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/simple_requests.h"

namespace k40t::protocol {

// 0x000500, section 3.2.6.1: uint16 maximum, uint16 minimum (both 0..2047, minimum < maximum),
// 1 reserved byte. Values are raw SBUS channel values (11 bit), no unit.
struct SbusRangeRequest {
  K40T_POD_REQUEST(0x000500, "sbus_range", "3.2.6.1", 5, 4);

  static constexpr int64_t kMaxSbusValue = 2047;

  uint16_t max_value = 1811;  // common SBUS transmitter end points
  uint16_t min_value = 172;

  K40T_LAYOUT(s, v) {
    body(s, v);
    v("reserved", wire::gap, wire::reserved(1));
  }
  // The two values alone, shared with the ACK of 0x000502 (which carries them in the ACK byte
  // order, docs/protocol/decisions.md#a2; the request is little-endian).
  template <class S, class V>
  static void body(S& s, V&& v) {
    v("max_value", s.max_value, wire::u16.range(0, kMaxSbusValue));
    v("min_value", s.min_value, wire::u16.range(0, kMaxSbusValue));
  }
  Status extra_checks() const;  // minimum < maximum
};

// 0x000501, section 3.2.6.2: one channel per function, bytes 1..7, byte 8 reserved. The document
// numbers all of bytes 3..8 "Byte3" (a copy-paste slip); the table header gives their order.
struct SbusChannelsRequest {
  K40T_POD_REQUEST(0x000501, "sbus_channels", "3.2.6.2", 8, 7);

  static constexpr int kChannelCount = 7;
  static constexpr int64_t kMaxChannel = 16;

  int stream_channel = 1;  // image mode: thermal / visible / split screen in turn, per switch
  int zoom_channel = 2;    // centre stops, maximum zooms out, minimum zooms in
  int photo_channel = 3;   // one photo per switch
  int record_channel = 4;  // start / stop recording per switch
  int pitch_channel = 5;   // centre stops; the further from centre, the faster
  int yaw_channel = 6;
  int centre_channel = 7;  // one "gimbal back to centre" per switch

  K40T_LAYOUT(s, v) {
    body(s, v);
    v("reserved", wire::gap, wire::reserved(1));
  }
  // The seven channel bytes alone (shared with the ACK of 0x000502).
  template <class S, class V>
  static void body(S& s, V&& v) {
    constexpr auto channel = wire::u8.offset(1).range(1, kMaxChannel, "(channel number)");
    v("stream_channel", s.stream_channel, channel);
    v("zoom_channel", s.zoom_channel, channel);
    v("photo_channel", s.photo_channel, channel);
    v("record_channel", s.record_channel, channel);
    v("pitch_channel", s.pitch_channel, channel);
    v("yaw_channel", s.yaw_channel, channel);
    v("centre_channel", s.centre_channel, channel);
  }
};

// ACK 0x010502, section 3.2.6.3: response code, uint16 maximum, uint16 minimum
// (docs/protocol/decisions.md#a2 byte order, like the code), the seven channel bytes of 0x000501, 1
// reserved byte.
struct SbusConfigAck {
  K40T_POD_DATA_ACK(0x010502, "sbus_config_ack", "3.2.6.3", kPodToHost, 14);

  K40T_FIELDS((ResponseCode, code, wire::response_code, ResponseCode::kOk),
              (SbusRangeRequest, range, wire::nested),
              (SbusChannelsRequest, channels, wire::nested), (reserved, wire::reserved(1)));
  Status extra_checks() const { return range.extra_checks(); }
  // A refusal without the configuration reports none (all zeros), not the defaults.
  Status finish_decode(size_t payload_size);
};

// 0x000502, section 3.2.6.3: byte 1 = 0x01 "get the SBUS configuration".
struct SbusConfigRequest : CommandRequest<0x01, SbusConfigAck> {
  K40T_POD_MESSAGE(0x000502, "sbus_config", "3.2.6.3");
};

// Every message struct of the SBUS family: the catalogue, the catalogue tests and the fuzz target
// take their entries from this list (message_list.h).
using SbusMessages =
    MessageList<SbusRangeRequest, SbusChannelsRequest, SbusConfigRequest, SbusConfigAck>;

}  // namespace k40t::protocol
