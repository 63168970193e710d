// The two requests of the common camera family that involve the flight controller (address
// 0x02/0x01), whose part the host plays (document sections 3.2.4.15 and 3.2.4.24):
//
//   0x000310  camera 0x04/0x01 -> flight controller: "GPS at this time of day, please" (sent
//             before each photo). The host answers with ACK 0x010310 (host -> camera), which
//             carries the position and attitude that geotag the photo.
//   0x000320  flight controller -> camera: the aircraft's fix and attitude; ACK 0x010320 (camera
//             -> host) carries the position of the target the laser is aimed at.
//
// Byte order: requests low byte first (section 2.1). ACK 0x010310 is an ACK like any other, so
// all its multi-byte fields follow CodecOptions::ack_byte_order (docs/protocol/decisions.md#a2).
// ACK 0x010320 says "low byte first" for each of its data fields, which therefore ignore
// ack_byte_order; its response code, which the section names "ACK response code" without a byte
// order, stays in ack_byte_order like every ACK's code, so one reader (ack_response_code) serves
// every ACK.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"

namespace k40t::protocol {

struct CameraGpsRequest;

// ACK 0x010310, section 3.2.4.15, host -> camera: response code; the request's time of day
// echoed; int32 longitude/latitude deg x1e7; int16 relative height and altitude m x10; int16
// yaw, roll, pitch deg x100 (25 bytes). int16 x100 limits yaw to -180..180.
struct CameraGpsAck {
  K40T_POD_MESSAGE(0x010310, "camera_gps_request_ack", "3.2.4.15");
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 25;
  static constexpr size_t kMinSize = 2;  // a refusal (no fix) may carry the code only

  ResponseCode code = ResponseCode::kOk;
  uint8_t hour = 0;
  uint8_t minute = 0;
  uint8_t second = 0;
  uint16_t millisecond = 0;
  double longitude_deg = 0;
  double latitude_deg = 0;
  double relative_height_m = 0;  // above take-off
  double altitude_m = 0;         // above sea level
  double yaw_deg = 0;
  double roll_deg = 0;
  double pitch_deg = 0;

  // An OK answer that echoes the request's time of day; the caller fills in the rest.
  static CameraGpsAck answering(const CameraGpsRequest& request);

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
    v("hour", self.hour);
    v("minute", self.minute);
    v("second", self.second);
    v("millisecond", self.millisecond);
    v("longitude_deg", self.longitude_deg);
    v("latitude_deg", self.latitude_deg);
    v("relative_height_m", self.relative_height_m);
    v("altitude_m", self.altitude_m);
    v("yaw_deg", self.yaw_deg);
    v("roll_deg", self.roll_deg);
    v("pitch_deg", self.pitch_deg);
  }
};

// 0x000310, section 3.2.4.15, camera -> flight controller: lens enable (0/1; any non-zero byte
// reads as enabled), hour 0-23, minute 0-59, second 0-59, uint16 millisecond 0-999.
struct CameraGpsRequest {
  K40T_POD_MESSAGE(0x000310, "camera_gps_request", "3.2.4.15");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 6;
  static constexpr size_t kMinSize = 6;
  using Ack = CameraGpsAck;

  bool lens_enabled = true;
  uint8_t hour = 0;
  uint8_t minute = 0;
  uint8_t second = 0;
  uint16_t millisecond = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("lens_enabled", self.lens_enabled);
    v("hour", self.hour);
    v("minute", self.minute);
    v("second", self.second);
    v("millisecond", self.millisecond);
  }
};

// ACK 0x010320, section 3.2.4.24, camera -> host: response code (ack_byte_order), mount byte
// (the document says it is always 0x1F), then low byte first: uint64 UTC ms, int32
// longitude/latitude deg x1e7, int32 relative height and altitude m x1000 (27 bytes).
struct TargetGpsAck {
  K40T_POD_MESSAGE(0x010320, "target_gps_request_ack", "3.2.4.24");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 27;
  static constexpr size_t kMinSize = 2;  // a refusal may carry the code only

  ResponseCode code = ResponseCode::kOk;
  uint8_t mount_mask = 0x1F;
  uint64_t utc_time_ms = 0;
  double longitude_deg = 0;
  double latitude_deg = 0;
  double relative_height_m = 0;
  double altitude_m = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("code", self.code);
    v("mount_mask", self.mount_mask);
    v("utc_time_ms", self.utc_time_ms);
    v("longitude_deg", self.longitude_deg);
    v("latitude_deg", self.latitude_deg);
    v("relative_height_m", self.relative_height_m);
    v("altitude_m", self.altitude_m);
  }
};

// 0x000320, section 3.2.4.24, flight controller (the host) -> camera, 42 bytes low byte first:
// mount bits (bit n = mount n+1; default mount 1), GPS fix status, uint64 UTC ms, int32
// longitude/latitude deg x1e7, int32 relative height and altitude m x1000, int16 yaw/roll/pitch
// deg x100, then x100: airspeed and ground speed m/s, heading 0-360 deg, throttle 0-100 %, climb
// rate m/s. The document gives no signedness for the last five; heading (up to 36000) only fits
// unsigned, so airspeed, ground speed, heading and throttle are uint16 and climb rate int16.
struct TargetGpsRequest {
  K40T_POD_MESSAGE(0x000320, "target_gps_request", "3.2.4.24");
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 42;
  static constexpr size_t kMinSize = 42;
  using Ack = TargetGpsAck;

  uint8_t mount_mask = 0x01;
  GpsFixStatus fix = GpsFixStatus::kFix3d;
  uint64_t utc_time_ms = 0;
  double longitude_deg = 0;
  double latitude_deg = 0;
  double relative_height_m = 0;
  double altitude_m = 0;
  double yaw_deg = 0;
  double roll_deg = 0;
  double pitch_deg = 0;
  double airspeed_m_s = 0;
  double ground_speed_m_s = 0;
  double heading_deg = 0;
  double throttle_percent = 0;
  double climb_rate_m_s = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("mount_mask", self.mount_mask);
    v("fix", self.fix);
    v("utc_time_ms", self.utc_time_ms);
    v("longitude_deg", self.longitude_deg);
    v("latitude_deg", self.latitude_deg);
    v("relative_height_m", self.relative_height_m);
    v("altitude_m", self.altitude_m);
    v("yaw_deg", self.yaw_deg);
    v("roll_deg", self.roll_deg);
    v("pitch_deg", self.pitch_deg);
    v("airspeed_m_s", self.airspeed_m_s);
    v("ground_speed_m_s", self.ground_speed_m_s);
    v("heading_deg", self.heading_deg);
    v("throttle_percent", self.throttle_percent);
    v("climb_rate_m_s", self.climb_rate_m_s);
  }
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using FlightControllerMessages =
    MessageList<CameraGpsRequest, CameraGpsAck, TargetGpsRequest, TargetGpsAck>;

}  // namespace k40t::protocol
