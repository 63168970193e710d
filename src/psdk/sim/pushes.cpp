#include "k40t_driver/psdk/sim/pushes.h"

#include <cmath>

namespace k40t::psdk::sim {
namespace {
constexpr double kRadPerDeg = M_PI / 180.0;
}

AttitudePush attitude_push(const AirframeState& s) {
  const Quaternion q = quaternion_from_euler(s.roll_rad, s.pitch_rad, s.yaw_rad);
  AttitudePush p;
  p.q0 = static_cast<float>(q.w);
  p.q1 = static_cast<float>(q.x);
  p.q2 = static_cast<float>(q.y);
  p.q3 = static_cast<float>(q.z);
  return p;
}

GpsPush gps_push(const AirframeState& s, uint8_t satellites) {
  GpsPush p;
  p.longitude_rad = s.longitude_deg * kRadPerDeg;
  p.latitude_rad = s.latitude_deg * kRadPerDeg;
  p.relative_height_m = std::round(s.relative_height_m * 10.0) / 10.0;
  p.satellites = satellites;
  p.signal = satellites >= 10  ? GpsSignal::kVeryStrong
             : satellites >= 6 ? GpsSignal::kMedium
                               : GpsSignal::kVeryWeak;
  return p;
}

RawGpsPush raw_gps_push(const AirframeState& s, uint16_t counter) {
  const UtcTime utc = utc_from_unix_us(s.utc_us);
  const DateTime& d = utc.date_time;
  RawGpsPush p;
  p.date_yyyymmdd = static_cast<uint32_t>(d.year * 10000 + d.month * 100 + d.day);
  p.time_hhmmss = static_cast<uint32_t>(d.hour * 10000 + d.minute * 100 + d.second);
  p.longitude_deg = std::round(s.longitude_deg * 1e7) / 1e7;
  p.latitude_deg = std::round(s.latitude_deg * 1e7) / 1e7;
  p.height_m = std::round(s.altitude_msl_m * 1000.0) / 1000.0;
  p.velocity_north_cm_s = static_cast<float>(s.velocity_north_m_s * 100.0);
  p.velocity_east_cm_s = static_cast<float>(s.velocity_east_m_s * 100.0);
  p.velocity_down_cm_s = static_cast<float>(s.velocity_down_m_s * 100.0);
  p.hdop = 0.8f;
  p.pdop = 1.4f;
  p.fix_state = 3.0f;
  p.vertical_accuracy_mm = 1500.0f;
  p.horizontal_accuracy_mm = 900.0f;
  p.speed_accuracy_cm_s = 12.0f;
  p.gps_satellites = 12;
  p.glonass_satellites = 8;
  p.total_satellites = 20;
  p.counter = counter;
  return p;
}

RawRtkPush raw_rtk_push(const AirframeState& s) {
  RawRtkPush p;
  p.longitude_deg = s.longitude_deg;
  p.latitude_deg = s.latitude_deg;
  p.height_m = static_cast<float>(s.altitude_msl_m);
  p.velocity_north_cm_s = static_cast<float>(s.velocity_north_m_s * 100.0);
  p.velocity_east_cm_s = static_cast<float>(s.velocity_east_m_s * 100.0);
  p.velocity_down_cm_s = static_cast<float>(s.velocity_down_m_s * 100.0);
  p.azimuth = static_cast<int16_t>(std::lround(s.yaw_rad / kRadPerDeg));
  p.position_type = 50;  // fixed solution, as 3.7.1 numbers solutions
  p.orientation_type = 50;
  return p;
}

BarometricAltitudePush barometric_altitude_push(const AirframeState& s) {
  BarometricAltitudePush p;
  p.altitude_m = static_cast<float>(s.altitude_msl_m);
  return p;
}

BatteryInfoPush battery_push(const AirframeState& s) {
  BatteryInfoPush p;
  p.percentage = static_cast<uint8_t>(std::lround(s.battery_percent));
  p.power_off_soon = s.power_off_soon;
  return p;
}

UavStatePush uav_state_push(const AirframeState& s, DroneType type) {
  UavStatePush p;
  p.state.motors_rotating = s.motors_rotating;
  p.state.landing = s.landing;
  p.flight_time_s = std::floor(s.flight_time_s * 10.0) / 10.0;
  p.drone_type = type;
  return p;
}

LinkBandwidthPush link_bandwidth_push(const AirframeState&) {
  LinkBandwidthPush p;
  p.image_link_normal = true;
  p.max_image_link_bandwidth = 8;
  p.connection = {true, true, true, true};
  p.msdk_uplink_max_bytes_s = 1024;
  p.msdk_downlink_max_bytes_s = 2048;
  p.network_max_kbit_s = 8192;
  p.msdk_flags = {true, true, true};
  p.msdk_uplink_bytes_s = 120;
  p.msdk_downlink_bytes_s = 640;
  p.network_video_kbit_s = 4000;
  p.network_data_kbit_s = 64;
  p.osdk_uplink_max_bytes_s = 1024;
  p.osdk_flags = {true};
  p.osdk_uplink_bytes_s = 0;
  return p;
}

AppDateTimePush app_date_time_push(const AirframeState& s) {
  AppDateTimePush p;
  p.time = utc_from_unix_us(s.utc_us).date_time;
  return p;
}

UtcTimePush utc_time_push(const AirframeState& s) {
  UtcTimePush p;
  const int64_t pps_us = s.utc_us - ((s.utc_us % 1000000) + 1000000) % 1000000;
  const UtcTime utc = utc_from_unix_us(pps_us);
  p.time = utc.date_time;
  p.microsecond = utc.microsecond;
  return p;
}

}  // namespace k40t::psdk::sim
