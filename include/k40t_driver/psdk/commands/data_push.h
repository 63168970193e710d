// Data push command set 0x03 (protocol document section 3.3): the adapter pushes the airframe's
// state to the payload. Only the battery push is ACKed (its power-off warning).
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

// Calendar date and time of day, as the time pushes and the positioning set carry them.
struct DateTime {
  K40T_PSDK_FIELDS((uint16_t, year, wire::u16, 2000), (uint8_t, month, wire::u8, 1),
                   (uint8_t, day, wire::u8, 1), (uint8_t, hour, wire::u8),
                   (uint8_t, minute, wire::u8), (uint8_t, second, wire::u8));
  Status validate() const;
};

// 3.3.1 byte 4.
K40T_PSDK_FLAGS(LinkConnectionState, remote_controller_connected, image_downlink_connected,
                data_downlink_connected, app_connected);

// 3.3.1 byte 17: 1 = real-time bandwidth within the limit.
K40T_PSDK_FLAGS(MsdkBandwidthFlags, msdk_uplink_within_limit, msdk_downlink_within_limit,
                network_within_limit);

// 3.3.1 byte 38.
K40T_PSDK_FLAGS(OsdkBandwidthFlags, osdk_uplink_within_limit);

// 3.3.1 (link bandwidth). MSDK uplink is mobile -> payload; OSDK uplink is payload -> onboard.
struct LinkBandwidthPush : Command<CommandSet::kDataPush, 0x01, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("link_bandwidth_push", "3.3.1");
  K40T_PSDK_FIELDS(
      (bool, image_link_normal, wire::u8),
      (uint8_t, max_image_link_bandwidth, wire::u8),  // the document gives no unit
      (reserved, wire::Reserved{1}), (LinkConnectionState, connection, wire::packed8),
      (uint32_t, msdk_uplink_max_bytes_s, wire::u32),
      (uint32_t, msdk_downlink_max_bytes_s, wire::u32), (uint32_t, network_max_kbit_s, wire::u32),
      (MsdkBandwidthFlags, msdk_flags, wire::packed8), (uint32_t, msdk_uplink_bytes_s, wire::u32),
      (uint32_t, msdk_downlink_bytes_s, wire::u32), (uint32_t, network_video_kbit_s, wire::u32),
      (uint32_t, network_data_kbit_s, wire::u32), (uint32_t, osdk_uplink_max_bytes_s, wire::u32),
      (OsdkBandwidthFlags, osdk_flags, wire::packed8), (uint32_t, osdk_uplink_bytes_s, wire::u32));
};

// 3.3.2: the airframe's attitude quaternion (q0 is the scalar part).
struct AttitudePush : Command<CommandSet::kDataPush, 0x02, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("attitude_push", "3.3.2");
  K40T_PSDK_FIELDS((float, q0, wire::f32, 1.0f), (float, q1, wire::f32), (float, q2, wire::f32),
                   (float, q3, wire::f32));
};

// 3.3.3 ACK: read only when the push announced power-off.
struct BatteryInfoAck : Reply<CommandSet::kDataPush, 0x03, Sender::kPayload> {
  K40T_PSDK_NAMED("battery_info_push_ack", "3.3.3");
  K40T_PSDK_FIELDS((bool, power_off_ready, wire::u8));  // preparation for power-off complete
};

// 3.3.3.
struct BatteryInfoPush : Command<CommandSet::kDataPush, 0x03, Sender::kAdapter, BatteryInfoAck> {
  K40T_PSDK_NAMED("battery_info_push", "3.3.3");
  K40T_PSDK_FIELDS((uint8_t, percentage, wire::u8), (bool, power_off_soon, wire::u8));
  Status validate() const { return check_int("percentage", percentage, 0, 100, "%"); }
};

enum class GpsSignal : uint8_t { kNone = 0, kVeryWeak = 1, kMedium = 2, kVeryStrong = 3 };
const char* to_string(GpsSignal signal);

// 3.3.4.
struct GpsPush : Command<CommandSet::kDataPush, 0x04, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("gps_push", "3.3.4");
  K40T_PSDK_FIELDS((double, longitude_rad, wire::f64), (double, latitude_rad, wire::f64),
                   (double, relative_height_m,
                    wire::scaled<int16_t>(10)),  // above the take-off point; 0.1 m on the wire
                   (uint8_t, satellites, wire::u8),
                   (GpsSignal, signal, wire::u8, GpsSignal::kNone));
  Status validate() const;
};

enum class LandingState : uint8_t { kUnknown = 0, kLanded = 1, kInTheSky = 2 };
const char* to_string(LandingState state);

enum class DroneType : uint8_t {
  kUnknown = 0,
  kM200 = 1,
  kM210 = 2,
  kM210Rtk = 3,
  kM600 = 4,
  kM600Pro = 5,
  kM200V2 = 6,
  kM210V2 = 7,
  kM210RtkV2 = 8,
};
const char* to_string(DroneType type);

// 3.3.5 byte 1.
struct UavFunctionState {
  K40T_PSDK_FIELDS((bool, compass_abnormal, wire::bit(0)), (bool, motors_rotating, wire::bit(1)),
                   (LandingState, landing, wire::bits(2, 2), LandingState::kUnknown));
};

// 3.3.5.
struct UavStatePush : Command<CommandSet::kDataPush, 0x05, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("uav_state_push", "3.3.5");
  K40T_PSDK_FIELDS(
      (UavFunctionState, state, wire::packed8),
      (double, flight_time_s,
       wire::scaled<uint16_t>(10)),  // since the motors last started; 0.1 s on the wire
      (DroneType, drone_type, wire::u8, DroneType::kUnknown));
};

// 3.3.6: the mobile app's local date and time, when an app is connected.
struct AppDateTimePush : Command<CommandSet::kDataPush, 0x06, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("app_date_time_push", "3.3.6");
  DateTime time;
  Status validate() const { return time.validate(); }
  K40T_PSDK_LAYOUT(s, v) { DateTime::layout(s.time, v); }
};

// 3.3.7. The document gives no unit; metres (like the RTK height) is this project's reading.
struct BarometricAltitudePush : Command<CommandSet::kDataPush, 0x07, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("barometric_altitude_push", "3.3.7");
  K40T_PSDK_FIELDS((float, altitude_m, wire::f32));
};

// 3.3.8: the GPS receiver's own solution.
struct RawGpsPush : Command<CommandSet::kDataPush, 0x08, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("raw_gps_push", "3.3.8");
  K40T_PSDK_FIELDS(
      (uint32_t, date_yyyymmdd, wire::u32),                 // GMT, decimal digits
      (uint32_t, time_hhmmss, wire::u32),                   // GMT, decimal digits
      (double, longitude_deg, wire::scaled<int32_t>(1e7)),  // 1e-7 deg on the wire
      (double, latitude_deg, wire::scaled<int32_t>(1e7)),   // 1e-7 deg on the wire
      (double, height_m, wire::scaled<int32_t>(1000)),      // above sea level; mm on the wire
      (float, velocity_north_cm_s, wire::f32), (float, velocity_east_cm_s, wire::f32),
      (float, velocity_down_cm_s, wire::f32), (float, hdop, wire::f32), (float, pdop, wire::f32),
      (float, fix_state, wire::f32),             // 3 = 3D fix
      (float, vertical_accuracy_mm, wire::f32),  // unit not given; taken to be the horizontal one's
      (float, horizontal_accuracy_mm, wire::f32), (float, speed_accuracy_cm_s, wire::f32),
      (uint32_t, gps_satellites, wire::u32), (uint32_t, glonass_satellites, wire::u32),
      (uint16_t, total_satellites, wire::u16),
      (uint16_t, counter, wire::u16));  // increments per push, wraps at 65535
  Status validate() const;
};

// 3.3.9: the RTK solution.
struct RawRtkPush : Command<CommandSet::kDataPush, 0x09, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("raw_rtk_push", "3.3.9");
  K40T_PSDK_FIELDS((double, longitude_deg, wire::f64), (double, latitude_deg, wire::f64),
                   (float, height_m, wire::f32),  // above sea level
                   (float, velocity_north_cm_s, wire::f32), (float, velocity_east_cm_s, wire::f32),
                   (float, velocity_down_cm_s, wire::f32),
                   (int16_t, azimuth, wire::i16),  // the document gives no unit
                   (uint8_t, position_type,
                    wire::u8),  // solution type; the document's value table is a copy of DOP's
                   (uint8_t, orientation_type, wire::u8));  // likewise
  Status validate() const;
};

// 3.3.10: the UTC time of the last PPS rising edge (discard it when it arrives more than 500 ms
// after the edge).
struct UtcTimePush : Command<CommandSet::kDataPush, 0x0A, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("utc_time_push", "3.3.10");
  DateTime time;
  uint32_t microsecond = 0;
  Status validate() const {
    return first_failure(time.validate(), check_int("microsecond", microsecond, 0, 999999, "us"));
  }
  K40T_PSDK_LAYOUT(s, v) {
    DateTime::layout(s.time, v);
    v("microsecond", s.microsecond, wire::u32);
  }
};

enum class OtherPayloadType : uint8_t { kUnknown = 0, kZenmuseX5s = 1, kZenmuseZ30 = 2 };
const char* to_string(OtherPayloadType type);

// 3.3.11: what is mounted on the airframe's main gimbal port.
struct OtherPayloadTypePush : Command<CommandSet::kDataPush, 0x0B, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("other_payload_type_push", "3.3.11");
  K40T_PSDK_FIELDS((OtherPayloadType, type, wire::u8, OtherPayloadType::kUnknown));
};

// 3.3.12: the main gimbal payload's focal length. The table says byte "1" for a uint16; read
// as bytes 1:2.
struct OtherPayloadFocalLengthPush : Command<CommandSet::kDataPush, 0x0C, Sender::kAdapter, NoAck> {
  K40T_PSDK_NAMED("other_payload_focal_length_push", "3.3.12");
  K40T_PSDK_FIELDS((double, focal_length_mm, wire::scaled<uint16_t>(10)));  // 0.1 mm on the wire
};

}  // namespace k40t::psdk
