// System requests of the common camera family (document sections 3.2.4.11-3.2.4.14, 3.2.4.16,
// 3.2.4.17, 3.2.4.20, 3.2.4.21): TF-card upgrade, SD format, time sync, factory reset, IP
// address, shutdown and version. Host 0x01/0x01 -> camera 0x04/0x01; request fields low byte
// first (section 2.1), ACK fields in CodecOptions::ack_byte_order (docs/protocol/decisions.md#a2);
// reserved bytes sent as zero (docs/protocol/decisions.md#a11) and optional on receive.
#pragma once

#include <string>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"

namespace k40t::protocol {

// What six requests share: byte 1 is a fixed command code 0x01 ("start TF-card upgrade", "format
// SD card", ...), byte 2 reserved; nothing to set. Decoding another byte 1 fails: the struct has
// no field that could report it.
struct FixedCommandRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;
  static constexpr uint8_t kCommandByte = 0x01;
  using Ack = PlainAck;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self&, V&&) {}
};

// 0x00030C, section 3.2.4.11: upgrade the visible camera from its TF card (byte 1 = 1; 0 is
// "invalid"). Progress in status frame 0x02030C.
struct TfCardUpgradeRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x00030C, "tf_card_upgrade", "3.2.4.11");
};

// 0x00030D, section 3.2.4.12: format the SD card. Progress in status frame 0x02030D at 5 Hz.
struct FormatSdRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x00030D, "format_sd", "3.2.4.12");
};

// 0x00030F, section 3.2.4.14: restore factory settings; the camera restarts one second later.
struct FactoryResetRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x00030F, "factory_reset", "3.2.4.14");
};

// 0x000316, section 3.2.4.20: the camera is about to be powered off.
struct ShutdownRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x000316, "shutdown", "3.2.4.20");
};

// ACK 0x010312: response code, then address, netmask and gateway (docs/protocol/decisions.md#a2:
// with the default big ack_byte_order the first octet comes first, as in the document's example).
struct GetIpAck {
  K40T_POD_MESSAGE(0x010312, "get_ip_ack", "3.2.4.17");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 14;
  static constexpr size_t kMinSize = 2;  // a refusal may carry the code only

  ResponseCode code = ResponseCode::kOk;
  std::string address = "0.0.0.0";
  std::string netmask = "0.0.0.0";
  std::string gateway = "0.0.0.0";

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
    v("address", self.address);
    v("netmask", self.netmask);
    v("gateway", self.gateway);
  }
};

// 0x000312, section 3.2.4.17: query the camera's IP settings (byte 1 = 1).
struct GetIpRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x000312, "get_ip", "3.2.4.17");
  using Ack = GetIpAck;
};

// ACK 0x010317: response code, major, minor, patch version bytes.
struct CameraVersionAck {
  K40T_POD_MESSAGE(0x010317, "camera_version_ack", "3.2.4.21");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 5;
  static constexpr size_t kMinSize = 2;  // a refusal may carry the code only

  ResponseCode code = ResponseCode::kOk;
  uint8_t major = 0;
  uint8_t minor = 0;
  uint8_t patch = 0;

  std::string version_text() const;  // "major.minor.patch"

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
    v("major", self.major);
    v("minor", self.minor);
    v("patch", self.patch);
  }
};

// 0x000317, section 3.2.4.21: ask for the camera's version (byte 1 = 1).
struct CameraVersionRequest : FixedCommandRequest {
  K40T_POD_MESSAGE(0x000317, "camera_version", "3.2.4.21");
  using Ack = CameraVersionAck;
};

// 0x00030E, section 3.2.4.13, docs/protocol/decisions.md#a8: int64 milliseconds since 1970-01-01
// 00:00:00 UTC, int32 tz_minuteswest and int32 tz_dsttime as in struct timezone, all low byte
// first. Sent every 10 s right after a pulse on the RTC_IO pin when that pin is wired.
struct TimeSyncRequest {
  K40T_POD_MESSAGE(0x00030E, "time_sync", "3.2.4.13");
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 16;
  static constexpr size_t kMinSize = 16;
  using Ack = PlainAck;

  int64_t unix_time_ms = 0;
  int32_t tz_minutes_west = 0;  // minutes west of Greenwich: UTC+8 is -480
  int32_t tz_dst_type = 0;      // type of DST correction (0 = none)

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("unix_time_ms", self.unix_time_ms);
    v("tz_minutes_west", self.tz_minutes_west);
    v("tz_dst_type", self.tz_dst_type);
  }
};

// 0x000311, section 3.2.4.16: static (0) or DHCP (1), then address, netmask and gateway, first
// octet first (the example's mask reads 255 255 255 0). The document marks netmask and gateway
// "0x00: NULL": 0.0.0.0 leaves them unset. A static address must not be 0.0.0.0 and a netmask
// must be contiguous ones.
struct SetIpRequest {
  K40T_POD_MESSAGE(0x000311, "set_ip", "3.2.4.16");
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 13;
  static constexpr size_t kMinSize = 13;
  using Ack = PlainAck;

  IpMode mode = IpMode::kStatic;
  std::string address = "192.168.144.64";  // the pod's factory address (section 2.3.1)
  std::string netmask = "255.255.255.0";
  std::string gateway = "0.0.0.0";

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("mode", self.mode);
    v("address", self.address);
    v("netmask", self.netmask);
    v("gateway", self.gateway);
  }
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraSystemMessages = MessageList<TfCardUpgradeRequest, FormatSdRequest, TimeSyncRequest,
                                         FactoryResetRequest, SetIpRequest, GetIpRequest, GetIpAck,
                                         ShutdownRequest, CameraVersionRequest, CameraVersionAck>;

}  // namespace k40t::protocol
