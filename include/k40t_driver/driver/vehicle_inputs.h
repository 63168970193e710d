// The vehicle topics' content applied to VehicleState, ROS-free: ros/conversions.h copies a
// NavSatFix or an Imu's numbers into these (ros/command_input.cpp subscribes), and the rules live
// here: which fixes are usable, the pod's GPS status, sea-level heights, the take-off reference,
// aviation angles from an ENU orientation.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/geo/body_velocity.h"

namespace k40t::driver {

struct GnssFix {
  // NavSatStatus's status: no fix, a fix, SBAS-augmented, ground-based augmentation (RTK).
  enum class Quality { kNone, kFix, kSbas, kGbas };
  Quality quality = Quality::kNone;
  int64_t stamp_ns = 0;  // when the fix was taken (ROS time)
  double latitude_deg = std::nan("");
  double longitude_deg = std::nan("");
  double altitude_m = std::nan("");  // above the WGS 84 ellipsoid; not finite: unknown (0 is used)
  std::optional<std::array<double, 9>> covariance;  // ENU m^2, when the fix gives one
};

// The first usable fix sets *reference_altitude_m (NaN until then) for relative_altitude_m, the
// take-off point. A fix without a finite position, or whose height has no sea-level height (no
// geoid grid), leaves the state without a fix.
void apply_fix(VehicleState& state, const GnssFix& fix, double* reference_altitude_m);

// An orientation in ENU (REP 103, body -> ENU) -> aviation heading/pitch/roll. A zero quaternion
// (an Imu without orientation) is ignored.
void apply_enu_orientation(VehicleState& state, const geo::Orientation& body_to_enu);

}  // namespace k40t::driver
