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
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"

namespace k40t::protocol {

struct CameraGpsRequest;

// The field groups the four messages share, in the message's byte order but where `deg_e7` says
// otherwise.
namespace gps_fields {
// Hour 0-23, minute 0-59, second 0-59, uint16 millisecond 0-999 (0x000310 and its ACK).
template <class S, class V>
void time_of_day(S& s, V& v) {
  v("hour", s.hour, wire::u8.range(0, 23));
  v("minute", s.minute, wire::u8.range(0, 59));
  v("second", s.second, wire::u8.range(0, 59));
  v("millisecond", s.millisecond, wire::u16.range(0, 999));
}
// int32 longitude and latitude, degrees x1e7.
template <class S, class V>
void longitude_latitude(S& s, V& v, wire::Scaled<int32_t> deg_e7 = wire::scaled<int32_t>(1e7)) {
  v("longitude_deg", s.longitude_deg, deg_e7.range(-180, 180, "deg"));
  v("latitude_deg", s.latitude_deg, deg_e7.range(-90, 90, "deg"));
}
// 0x000320 and its ACK: the position, then int32 relative height and altitude m x1000, all low
// byte first.
template <class S, class V>
void position(S& s, V& v) {
  constexpr double kInt32MilliMax = 2147483.647;
  constexpr auto milli_m =
      wire::scaled<int32_t>(1000).little().range(-kInt32MilliMax, kInt32MilliMax, "m");
  longitude_latitude(s, v, wire::scaled<int32_t>(1e7).little());
  v("relative_height_m", s.relative_height_m, milli_m);
  v("altitude_m", s.altitude_m, milli_m);
}
// int16 yaw, roll, pitch deg x100: yaw cannot reach 360, so its range is -180..180.
template <class S, class V>
void attitude(S& s, V& v) {
  constexpr auto centi_deg = wire::scaled<int16_t>(100);
  v("yaw_deg", s.yaw_deg, centi_deg.range(-180, 180, "deg"));
  v("roll_deg", s.roll_deg, centi_deg.range(-180, 180, "deg"));
  v("pitch_deg", s.pitch_deg, centi_deg.range(-90, 90, "deg"));
}
}  // namespace gps_fields

// ACK 0x010310, section 3.2.4.15, host -> camera: response code; the request's time of day
// echoed; int32 longitude/latitude deg x1e7; int16 relative height and altitude m x10; int16
// yaw, roll, pitch deg x100 (25 bytes). int16 x100 limits yaw to -180..180.
struct CameraGpsAck {
  K40T_POD_DATA_ACK(0x010310, "camera_gps_request_ack", "3.2.4.15", kHostToPod, 25);

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

  K40T_LAYOUT(s, v) {
    constexpr auto deci_m = wire::scaled<int16_t>(10).range(-3276.8, 3276.7, "m");
    v("code", s.code, wire::response_code);
    gps_fields::time_of_day(s, v);
    gps_fields::longitude_latitude(s, v);
    v("relative_height_m", s.relative_height_m, deci_m);
    v("altitude_m", s.altitude_m, deci_m);
    gps_fields::attitude(s, v);
  }
  Status finish_decode(size_t payload_size) const {
    return code_alone_or_at_least(kName, kId, payload_size, kSize);
  }
};

// 0x000310, section 3.2.4.15, camera -> flight controller: lens enable (0/1; any non-zero byte
// reads as enabled), hour 0-23, minute 0-59, second 0-59, uint16 millisecond 0-999.
struct CameraGpsRequest {
  K40T_POD_HEADER(0x000310, "camera_gps_request", "3.2.4.15", kPodToHost, 6, 6);
  using Ack = CameraGpsAck;

  bool lens_enabled = true;
  uint8_t hour = 0;
  uint8_t minute = 0;
  uint8_t second = 0;
  uint16_t millisecond = 0;

  K40T_LAYOUT(s, v) {
    v("lens_enabled", s.lens_enabled, wire::u8);  // 1 / 0 sent, any non-zero read as enabled
    gps_fields::time_of_day(s, v);
  }
};

// ACK 0x010320, section 3.2.4.24, camera -> host: response code (ack_byte_order), mount byte
// (the document says it is always 0x1F), then low byte first: uint64 UTC ms, int32
// longitude/latitude deg x1e7, int32 relative height and altitude m x1000 (27 bytes).
struct TargetGpsAck {
  K40T_POD_DATA_ACK(0x010320, "target_gps_request_ack", "3.2.4.24", kPodToHost, 27);

  ResponseCode code = ResponseCode::kOk;
  uint8_t mount_mask = 0x1F;
  uint64_t utc_time_ms = 0;
  double longitude_deg = 0;
  double latitude_deg = 0;
  double relative_height_m = 0;
  double altitude_m = 0;

  K40T_LAYOUT(s, v) {
    v("code", s.code, wire::response_code);
    v("mount_mask", s.mount_mask, wire::u8);
    v("utc_time_ms", s.utc_time_ms, wire::u64.little());
    gps_fields::position(s, v);
  }
  Status finish_decode(size_t payload_size) const {
    return code_alone_or_at_least(kName, kId, payload_size, kSize);
  }
};

// 0x000320, section 3.2.4.24, flight controller (the host) -> camera, 42 bytes low byte first:
// mount bits (bit n = mount n+1; default mount 1), GPS fix status, uint64 UTC ms, int32
// longitude/latitude deg x1e7, int32 relative height and altitude m x1000, int16 yaw/roll/pitch
// deg x100, then x100: airspeed and ground speed m/s, heading 0-360 deg, throttle 0-100 %, climb
// rate m/s. The document gives no signedness for the last five; heading (up to 36000) only fits
// unsigned, so airspeed, ground speed, heading and throttle are uint16 and climb rate int16.
struct TargetGpsRequest {
  K40T_POD_HEADER(0x000320, "target_gps_request", "3.2.4.24", kHostToPod, 42, 42);
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

  K40T_LAYOUT(s, v) {
    constexpr auto centi_m_s = wire::scaled<uint16_t>(100).range(0, 655.35, "m/s");
    v("mount_mask", s.mount_mask, wire::u8.range(1, 0xFF));
    v("fix", s.fix, wire::u8);
    v("utc_time_ms", s.utc_time_ms, wire::u64);
    gps_fields::position(s, v);
    gps_fields::attitude(s, v);
    v("airspeed_m_s", s.airspeed_m_s, centi_m_s);
    v("ground_speed_m_s", s.ground_speed_m_s, centi_m_s);
    v("heading_deg", s.heading_deg, wire::scaled<uint16_t>(100).range(0, 360, "deg"));
    v("throttle_percent", s.throttle_percent, wire::scaled<uint16_t>(100).range(0, 100, "%"));
    v("climb_rate_m_s", s.climb_rate_m_s, wire::scaled<int16_t>(100).range(-327.68, 327.67, "m/s"));
  }
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using FlightControllerMessages =
    MessageList<CameraGpsRequest, CameraGpsAck, TargetGpsRequest, TargetGpsAck>;

}  // namespace k40t::protocol
