#include "k40t_driver/psdk/sim/flight_model.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::psdk::sim {
namespace {

constexpr double kGravity = 9.80665;

}  // namespace

AirframeState FlightModel::state_at(double t_s) const {
  const FlightModelOptions& o = options_;
  AirframeState s;
  s.t_s = t_s;
  s.utc_us = o.start_utc_us + static_cast<int64_t>(std::llround(t_s * 1e6));
  s.flight_time_s = std::max(0.0, t_s);
  s.motors_rotating = true;
  s.battery_percent =
      std::clamp(o.battery_start_percent - o.battery_drain_percent_per_min * s.flight_time_s / 60.0,
                 0.0, 100.0);
  s.power_off_soon = o.power_off_after_s && t_s >= *o.power_off_after_s;

  double north_m = 0;
  double east_m = 0;
  if (t_s < o.climb_s) {
    // Straight up from home at constant speed; level attitude, nose north.
    s.relative_height_m = o.altitude_m * std::max(0.0, t_s) / o.climb_s;
    s.velocity_down_m_s = -o.altitude_m / o.climb_s;
    north_m = 0;
    east_m = 0;
  } else {
    const double omega = o.speed_m_s / o.circle_radius_m;  // rad/s, clockwise seen from above
    const double angle = omega * (t_s - o.climb_s);
    // Position on a circle centred `radius` east of home, starting at home, moving north first.
    north_m = o.circle_radius_m * std::sin(angle);
    east_m = o.circle_radius_m * (1.0 - std::cos(angle));
    s.velocity_north_m_s = o.speed_m_s * std::cos(angle);
    s.velocity_east_m_s = o.speed_m_s * std::sin(angle);
    s.relative_height_m = o.altitude_m;
    s.yaw_rad = std::atan2(s.velocity_east_m_s, s.velocity_north_m_s);
    // A coordinated turn banks by atan(v^2 / (r g)), right wing down for a clockwise circle.
    s.roll_rad = std::atan(o.speed_m_s * o.speed_m_s / (o.circle_radius_m * kGravity));
    s.pitch_rad = -0.05;  // a multirotor leans forward to fly forward
  }
  s.landing = t_s >= 1.0 ? LandingState::kInTheSky : LandingState::kLanded;
  // Home's ENU frame. Its origin height is home's MSL height: an origin tens of metres off in
  // height moves a point 50 m away by well under a millimetre, and the height above home comes
  // back through the same frame.
  const geo::Geodetic home{o.home_latitude_deg, o.home_longitude_deg, o.home_altitude_msl_m};
  const Result<geo::LocalFrame> frame = geo::LocalFrame::at(home);
  const geo::Geodetic here =
      frame ? frame->to_geodetic({east_m, north_m, s.relative_height_m}) : home;
  s.latitude_deg = here.latitude_deg;
  s.longitude_deg = here.longitude_deg;
  s.altitude_msl_m = here.height_ellipsoid_m;  // home MSL + height above home's tangent plane
  return s;
}

Quaternion quaternion_from_euler(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2);
  const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
          cr * cp * sy - sr * sp * cy};
}

UtcTime utc_from_unix_us(int64_t unix_us) {
  // Days-from-civil inverse (Howard Hinnant's algorithm), valid for the proleptic Gregorian
  // calendar; no leap seconds (Unix time has none).
  int64_t seconds = unix_us / 1000000;
  int64_t micro = unix_us % 1000000;
  if (micro < 0) {
    micro += 1000000;
    --seconds;
  }
  int64_t days = seconds / 86400;
  int64_t second_of_day = seconds % 86400;
  if (second_of_day < 0) {
    second_of_day += 86400;
    --days;
  }
  days += 719468;
  const int64_t era = (days >= 0 ? days : days - 146096) / 146097;
  const int64_t doe = days - era * 146097;
  const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const int64_t mp = (5 * doy + 2) / 153;
  const int64_t day = doy - (153 * mp + 2) / 5 + 1;
  const int64_t month = mp < 10 ? mp + 3 : mp - 9;
  const int64_t year = yoe + era * 400 + (month <= 2 ? 1 : 0);
  UtcTime out;
  out.date_time.year = static_cast<uint16_t>(year);
  out.date_time.month = static_cast<uint8_t>(month);
  out.date_time.day = static_cast<uint8_t>(day);
  out.date_time.hour = static_cast<uint8_t>(second_of_day / 3600);
  out.date_time.minute = static_cast<uint8_t>(second_of_day / 60 % 60);
  out.date_time.second = static_cast<uint8_t>(second_of_day % 60);
  out.microsecond = static_cast<uint32_t>(micro);
  return out;
}

}  // namespace k40t::psdk::sim
