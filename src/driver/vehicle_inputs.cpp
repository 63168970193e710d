#include "k40t_driver/driver/vehicle_inputs.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::driver {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// 0x000320 byte 2 (section 3.2.4.24): 1 connected, no position; 2 2D; 3 3D; 4 3D with DGPS/SBAS;
// 5 float RTK; 6 fixed RTK. NavSatFix cannot tell 2D from 3D but by a missing altitude, and
// its GBAS ("ground-based augmentation") covers DGPS and float RTK as well as fixed RTK, so it is
// sent as 4: the pod's target solver must not be told of more accuracy than there is.
uint8_t pod_gps_status(const GnssFix& fix) {
  switch (fix.quality) {
    case GnssFix::Quality::kFix:
      return std::isfinite(fix.altitude_m) ? 3 : 2;
    case GnssFix::Quality::kSbas:
    case GnssFix::Quality::kGbas:
      return std::isfinite(fix.altitude_m) ? 4 : 2;
    case GnssFix::Quality::kNone:
      break;
  }
  return 1;
}

}  // namespace

void apply_fix(VehicleState& state, const GnssFix& fix, double* reference_altitude_m) {
  const bool usable = fix.quality != GnssFix::Quality::kNone && std::isfinite(fix.latitude_deg) &&
                      std::isfinite(fix.longitude_deg);
  state.has_fix = usable;
  state.gps_status = pod_gps_status(fix);
  if (!usable) return;
  const double altitude = std::isfinite(fix.altitude_m) ? fix.altitude_m : 0.0;
  // Fix heights are above the ellipsoid; the pod wants sea level. Without the geoid (no
  // proj-data) there is no height to send: the fix is not usable.
  const Result<double> msl =
      geo::Geoid::egm96().msl_from_ellipsoid(fix.latitude_deg, fix.longitude_deg, altitude);
  if (!msl) {
    state.has_fix = false;
    return;
  }
  if (reference_altitude_m && std::isnan(*reference_altitude_m)) *reference_altitude_m = altitude;
  state.utc_ms = fix.stamp_ns / 1000000;
  state.latitude_deg = fix.latitude_deg;
  state.longitude_deg = fix.longitude_deg;
  state.altitude_m = altitude;
  state.altitude_msl_m = msl.value();
  if (fix.covariance) state.position_covariance = *fix.covariance;
  state.relative_altitude_m = reference_altitude_m ? altitude - *reference_altitude_m : 0.0;
}

void apply_enu_orientation(VehicleState& state, const geo::Orientation& q) {
  const double norm2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (norm2 < 1e-6) return;  // an Imu without orientation (all zeros)
  const double n = std::sqrt(norm2);
  const double x = q.x / n, y = q.y / n, z = q.z / n, w = q.w / n;
  // Roll, pitch, yaw of R = Rz(yaw) Ry(pitch) Rx(roll) (REP 103's fixed-axis RPY).
  const double roll = std::atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
  const double pitch = std::asin(std::clamp(2 * (w * y - z * x), -1.0, 1.0));
  const double yaw = std::atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  // ENU yaw is counter-clockwise from east; a heading is clockwise from north.
  state.heading_deg = std::fmod(90.0 - yaw * kRadToDeg + 720.0, 360.0);
  state.pitch_deg = -pitch * kRadToDeg;  // REP 103 pitch is nose-down positive
  state.roll_deg = roll * kRadToDeg;     // right side down positive in both
  state.has_attitude = true;
}

}  // namespace k40t::driver
