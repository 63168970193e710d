// PodDriver's vehicle state: the latest one, the history of the inputs it is interpolated in for
// time-matched answers (geo/state_history.h), and the conversions between the Clock's stamps and
// the pod's clock (docs/geo.md). Split from pod_driver.cpp, which keeps the link's duties.
#include <chrono>
#include <cmath>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/geo/geodesy.h"

namespace k40t::driver {

namespace {

int64_t unix_time_ns_now() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

int64_t floor_div(int64_t a, int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

}  // namespace

void PodDriver::set_vehicle_state(const VehicleState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  vehicle_ = state;
}

VehicleState PodDriver::vehicle_state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return vehicle_;
}

void PodDriver::record_position(StampNs stamp, const geo::PositionSample& sample) {
  std::lock_guard<std::mutex> lock(mutex_);
  history_.add_position(stamp, sample);
}
void PodDriver::record_attitude(StampNs stamp, const geo::AttitudeSample& sample) {
  std::lock_guard<std::mutex> lock(mutex_);
  history_.add_attitude(stamp, sample);
}
void PodDriver::record_velocity(StampNs stamp, const geo::VelocitySample& sample) {
  std::lock_guard<std::mutex> lock(mutex_);
  history_.add_velocity(stamp, sample);
}

VehicleState PodDriver::vehicle_state_at(StampNs stamp, bool* in_history, double* gap_s) const {
  VehicleState out;
  std::optional<geo::Lookup<geo::PositionSample>> position;
  std::optional<geo::Lookup<geo::AttitudeSample>> attitude;
  std::optional<geo::Lookup<geo::VelocitySample>> velocity;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    out = vehicle_;
    position = history_.position_at(stamp);
    attitude = history_.attitude_at(stamp);
    velocity = history_.velocity_at(stamp);
  }
  if (in_history) *in_history = true;
  if (gap_s) *gap_s = -1;
  if (!position || !out.has_fix) return out;  // no history: the latest state as it is
  const geo::PositionSample& p = position->value;
  // The take-off reference of the relative height, as the latest state holds it.
  const double reference_m = out.altitude_m - out.relative_altitude_m;
  const Result<double> msl =
      geo::Geoid::egm96().msl_from_ellipsoid(p.latitude_deg, p.longitude_deg, p.height_ellipsoid_m);
  out.has_fix = msl.is_ok();
  out.utc_ms = floor_div(stamp, 1000000);
  out.latitude_deg = p.latitude_deg;
  out.longitude_deg = p.longitude_deg;
  out.altitude_m = p.height_ellipsoid_m;
  out.altitude_msl_m = msl ? msl.value() : 0.0;
  out.relative_altitude_m = p.height_ellipsoid_m - reference_m;
  bool inside = position->in_history;
  if (attitude) {
    out.has_attitude = true;
    out.heading_deg = attitude->value.heading_deg;
    out.pitch_deg = attitude->value.pitch_deg;
    out.roll_deg = attitude->value.roll_deg;
    inside = inside && attitude->in_history;
  }
  if (velocity) {
    out.has_velocity = true;
    out.ground_speed_m_s = std::hypot(velocity->value.east, velocity->value.north);
    out.climb_rate_m_s = velocity->value.up;
  }
  if (in_history) *in_history = inside;
  if (gap_s) *gap_s = position->gap_s;
  return out;
}

StampNs PodDriver::stamp_of_pod_time(int64_t pod_unix_ms) const {
  int64_t offset_ms = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    offset_ms = clock_offset_ms_;
  }
  // The Clock (ROS time, possibly simulated) minus the system clock, read now.
  const StampNs clock_minus_system = clock_() - unix_time_ns_now();
  return (pod_unix_ms - offset_ms) * 1000000 + clock_minus_system;
}

int64_t PodDriver::pod_time_of_stamp(StampNs stamp) const {
  int64_t offset_ms = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    offset_ms = clock_offset_ms_;
  }
  const StampNs clock_minus_system = clock_() - unix_time_ns_now();
  return floor_div(stamp - clock_minus_system, 1000000) + offset_ms;
}

}  // namespace k40t::driver
