// The vehicle's position and attitude as the pod's protocol wants them: what the driver answers
// the pod's GPS requests (0x000310) with and sends in laser-target requests (0x000320). ROS-free;
// the glue fills it from the fix (NavSatFix) and attitude (Imu) topics.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace k40t::driver {

struct VehicleState {
  bool has_fix = false;
  uint8_t gps_status = 0;   // 0x000320 byte 2: 0 none .. 3 3D fix .. 6 RTK fixed
  int64_t utc_ms = 0;       // the fix's stamp (ROS time), ms since 1970-01-01
  double latitude_deg = 0;  // WGS 84
  double longitude_deg = 0;
  double altitude_m = 0;           // above the WGS 84 ellipsoid, as NavSatFix gives it
  double altitude_msl_m = 0;       // above mean sea level (EGM96 geoid): what the pod is sent
  double relative_altitude_m = 0;  // above the first fix (the take-off point)
  // ENU, m^2 (NavSatFix's); when the fix gives none: 2 m horizontal, 4 m vertical (1 sigma).
  std::array<double, 9> position_covariance{4, 0, 0, 0, 4, 0, 0, 0, 16};

  bool has_attitude = false;
  // Aviation convention (the pod's): heading clockwise from north 0..360, nose-up pitch positive,
  // right-wing-down roll positive.
  double heading_deg = 0;
  double pitch_deg = 0;
  double roll_deg = 0;

  bool has_velocity = false;  // from the velocity input, or derived from the fixes
  double ground_speed_m_s = 0;
  double climb_rate_m_s = 0;  // up positive
};

// Copies the position and (if known) attitude into a message with the fields longitude_deg,
// latitude_deg, relative_height_m, altitude_m, yaw_deg, roll_deg, pitch_deg: the GPS answer
// (0x010310) and the laser-target request (0x000320) both carry them. Heights: the pod's
// altitude is above mean sea level, its relative height above the take-off point.
template <class Msg>
void fill_position(Msg& out, const VehicleState& state) {
  out.longitude_deg = state.longitude_deg;
  out.latitude_deg = state.latitude_deg;
  out.relative_height_m = state.relative_altitude_m;
  out.altitude_m = state.altitude_msl_m;  // the pod's 海拔高度: above mean sea level
  if (!state.has_attitude) return;
  out.yaw_deg = std::remainder(state.heading_deg, 360.0);  // int16 x100 on the wire: -180..180
  out.roll_deg = state.roll_deg;
  out.pitch_deg = state.pitch_deg;
}

}  // namespace k40t::driver
