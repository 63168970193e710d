// The simulated airframe behind the simulated SKYPORT adapter: a deterministic function of time,
// so every push is consistent with every other (the GPS position moves with the velocity, the
// attitude's yaw follows the track, the battery drains with flight time, the UTC time ticks).
//
// The flight: motors start at t = 0, a vertical climb to `altitude_m` over `climb_s`, then a
// circle of `circle_radius_m` around home at `speed_m_s`, nose along the track, banked for the
// turn. The battery drains linearly; from `power_off_after_s` on it announces power-off.
#pragma once

#include <cstdint>
#include <optional>

#include "k40t_driver/psdk/commands/data_push.h"

namespace k40t::psdk::sim {

struct FlightModelOptions {
  double home_latitude_deg = 22.5790;  // DJI's Shenzhen HQ, as good as anywhere
  double home_longitude_deg = 113.9434;
  double home_altitude_msl_m = 40.0;
  double altitude_m = 30.0;  // above home, after the climb
  double climb_s = 10.0;
  double circle_radius_m = 50.0;
  double speed_m_s = 5.0;
  double battery_start_percent = 95.0;
  double battery_drain_percent_per_min = 1.0;
  std::optional<double> power_off_after_s;  // power-off warning from then on
  DroneType drone_type = DroneType::kM210RtkV2;
  int64_t start_utc_us = 1719792000000000;  // 2024-07-01 00:00:00 UTC
};

struct AirframeState {
  double t_s = 0;
  double latitude_deg = 0;
  double longitude_deg = 0;
  double relative_height_m = 0;  // above home
  double altitude_msl_m = 0;
  double velocity_north_m_s = 0;
  double velocity_east_m_s = 0;
  double velocity_down_m_s = 0;
  double roll_rad = 0;
  double pitch_rad = 0;
  double yaw_rad = 0;  // from north, clockwise
  double battery_percent = 0;
  bool power_off_soon = false;
  bool motors_rotating = true;
  LandingState landing = LandingState::kLanded;
  double flight_time_s = 0;
  int64_t utc_us = 0;  // microseconds since the Unix epoch
};

class FlightModel {
 public:
  explicit FlightModel(FlightModelOptions options = {}) : options_(options) {}
  AirframeState state_at(double t_s) const;
  const FlightModelOptions& options() const { return options_; }

 private:
  FlightModelOptions options_;
};

// Unit quaternion (scalar first) of the ZYX (yaw, pitch, roll) rotation body -> NED.
struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};
Quaternion quaternion_from_euler(double roll_rad, double pitch_rad, double yaw_rad);

// Civil UTC date and time of a Unix time in microseconds.
struct UtcTime {
  DateTime date_time;
  uint32_t microsecond = 0;
};
UtcTime utc_from_unix_us(int64_t unix_us);

}  // namespace k40t::psdk::sim
