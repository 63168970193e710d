// System requests of the common camera family (document sections 3.2.4.11-3.2.4.14, 3.2.4.16,
// 3.2.4.17, 3.2.4.20, 3.2.4.21): TF-card upgrade, SD format, time sync, factory reset, IP
// address, shutdown and version. Host 0x01/0x01 -> camera 0x04/0x01; request fields low byte
// first (section 2.1), ACK fields in CodecOptions::ack_byte_order (docs/protocol/decisions.md#a2);
// reserved bytes sent as zero (docs/protocol/decisions.md#a11) and optional on receive.
#pragma once

#include <string>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/ipv4_field.h"
#include "k40t_driver/protocol/messages/simple_requests.h"

namespace k40t::protocol {

// Address, netmask and gateway: what 0x000311 and the ACK 0x010312 end with.
template <class S, class V>
void ip_settings(S& s, V&& v) {
  constexpr auto ipv4 = wire::custom<Ipv4Field>;
  v("address", s.address, ipv4);
  v("netmask", s.netmask, ipv4);
  v("gateway", s.gateway, ipv4);
}

// Six requests are CommandRequest<0x01> (messages/simple_requests.h): byte 1 is the fixed command
// code 0x01 ("start TF-card upgrade", "format SD card", ...), byte 2 reserved; nothing to set.
// Decoding another byte 1 fails: the struct has no field that could report it.

// 0x00030C, section 3.2.4.11: upgrade the visible camera from its TF card (byte 1 = 1; 0 is
// "invalid"). Progress in status frame 0x02030C.
struct TfCardUpgradeRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x00030C, "tf_card_upgrade", "3.2.4.11");
};

// 0x00030D, section 3.2.4.12: format the SD card. Progress in status frame 0x02030D at 5 Hz.
struct FormatSdRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x00030D, "format_sd", "3.2.4.12");
};

// 0x00030E, section 3.2.4.13, docs/protocol/decisions.md#a8: int64 milliseconds since 1970-01-01
// 00:00:00 UTC, int32 tz_minuteswest and int32 tz_dsttime as in struct timezone, all low byte
// first. Sent every 10 s right after a pulse on the RTC_IO pin when that pin is wired.
struct TimeSyncRequest {
  K40T_POD_REQUEST(0x00030E, "time_sync", "3.2.4.13", 16, 16);
  // Time zones run from UTC-12 (720 minutes west) to UTC+14 (840 minutes east).
  K40T_FIELDS((int64_t, unix_time_ms, wire::i64),
              (int32_t, tz_minutes_west,
               wire::i32.range(-840, 720, "min")),  // minutes west of Greenwich: UTC+8 is -480
              (int32_t, tz_dst_type, wire::i32));   // type of DST correction (0 = none)
  // unix_time_ms >= 0 (an int64 range is beyond what a layout's double limits hold exactly).
  Status extra_checks() const;
};

// 0x00030F, section 3.2.4.14: restore factory settings; the camera restarts one second later.
struct FactoryResetRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x00030F, "factory_reset", "3.2.4.14");
};

// 0x000311, section 3.2.4.16: static (0) or DHCP (1), then address, netmask and gateway, first
// octet first (the example's mask reads 255 255 255 0). The document marks netmask and gateway
// "0x00: NULL": 0.0.0.0 leaves them unset. A static address must not be 0.0.0.0 and a netmask
// must be contiguous ones.
struct SetIpRequest {
  K40T_POD_REQUEST(0x000311, "set_ip", "3.2.4.16", 13, 13);
  IpMode mode = IpMode::kStatic;
  std::string address = "192.168.144.64";  // the pod's factory address (section 2.3.1)
  std::string netmask = "255.255.255.0";
  std::string gateway = "0.0.0.0";

  K40T_LAYOUT(s, v) {
    v("mode", s.mode, wire::u8);
    ip_settings(s, v);
  }
  Status extra_checks() const;  // the netmask's ones are contiguous; a static address is set
};

// ACK 0x010312: response code, then address, netmask and gateway (docs/protocol/decisions.md#a2:
// the code in the ACK byte order; the octets are bytes of their own, first octet first, as in the
// document's example). A refusal may carry the code only.
struct GetIpAck {
  K40T_POD_REPORT(0x010312, "get_ip_ack", "3.2.4.17", 14, 2);
  static constexpr auto kByteOrder = &CodecOptions::ack_byte_order;
  ResponseCode code = ResponseCode::kOk;
  std::string address = "0.0.0.0";
  std::string netmask = "0.0.0.0";
  std::string gateway = "0.0.0.0";

  K40T_LAYOUT(s, v) {
    v("code", s.code, wire::response_code);
    ip_settings(s, v);
  }
  Status finish_decode(size_t payload_size) const;  // the code alone, or all of it
};

// 0x000312, section 3.2.4.17: query the camera's IP settings (byte 1 = 1).
struct GetIpRequest : CommandRequest<0x01, GetIpAck> {
  K40T_POD_MESSAGE(0x000312, "get_ip", "3.2.4.17");
};

// 0x000316, section 3.2.4.20: the camera is about to be powered off.
struct ShutdownRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x000316, "shutdown", "3.2.4.20");
};

// ACK 0x010317: response code, major, minor, patch version bytes. A refusal may carry the code
// only.
struct CameraVersionAck {
  K40T_POD_REPORT(0x010317, "camera_version_ack", "3.2.4.21", 5, 2);
  static constexpr auto kByteOrder = &CodecOptions::ack_byte_order;
  ResponseCode code = ResponseCode::kOk;
  uint8_t major = 0;
  uint8_t minor = 0;
  uint8_t patch = 0;

  std::string version_text() const;  // "major.minor.patch"
  K40T_LAYOUT(s, v) {
    v("code", s.code, wire::response_code);
    v("major", s.major, wire::u8);
    v("minor", s.minor, wire::u8);
    v("patch", s.patch, wire::u8);
  }
  Status finish_decode(size_t payload_size) const;  // the code alone, or all of it
};

// 0x000317, section 3.2.4.21: ask for the camera's version (byte 1 = 1).
struct CameraVersionRequest : CommandRequest<0x01, CameraVersionAck> {
  K40T_POD_MESSAGE(0x000317, "camera_version", "3.2.4.21");
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraSystemMessages = MessageList<TfCardUpgradeRequest, FormatSdRequest, TimeSyncRequest,
                                         FactoryResetRequest, SetIpRequest, GetIpRequest, GetIpAck,
                                         ShutdownRequest, CameraVersionRequest, CameraVersionAck>;

}  // namespace k40t::protocol
