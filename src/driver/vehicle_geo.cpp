#include "k40t_driver/driver/vehicle_geo.h"

#include <cmath>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::driver {

Result<geo::VehiclePose> vehicle_pose(const VehicleState& state) {
  if (!state.has_fix) return Result<geo::VehiclePose>::fail("no vehicle fix (topic fix)");
  if (!state.has_attitude)
    return Result<geo::VehiclePose>::fail("no vehicle attitude (topic attitude)");
  geo::VehiclePose pose;
  pose.position = {state.latitude_deg, state.longitude_deg, state.altitude_m};
  pose.position_covariance = state.position_covariance;
  pose.heading_deg = state.heading_deg;
  pose.pitch_deg = state.pitch_deg;
  pose.roll_deg = state.roll_deg;
  return pose;
}

Result<double> plane_height_ellipsoid(const VehicleState& vehicle, PlaneReference reference,
                                      double height_m) {
  if (reference == PlaneReference::kAboveTakeoff)
    return vehicle.altitude_m - vehicle.relative_altitude_m + height_m;
  return geo::Geoid::egm96().ellipsoid_from_msl(vehicle.latitude_deg, vehicle.longitude_deg,
                                                height_m);
}

std::optional<geo::Covariance3> laser_target_covariance(const geo::Geodetic& target,
                                                        const VehicleState& vehicle,
                                                        const geo::RayUncertainty& u) {
  if (!vehicle.has_fix) return std::nullopt;
  const double slant =
      geo::distance_m({vehicle.latitude_deg, vehicle.longitude_deg, vehicle.altitude_m}, target);
  if (std::isnan(slant)) return std::nullopt;  // not a position a local frame can be set at
  const double angular = slant * u.attitude_sigma_deg * M_PI / 180.0;
  const double extra = angular * angular + u.range_sigma_m * u.range_sigma_m;
  geo::Covariance3 covariance = vehicle.position_covariance;
  for (size_t i = 0; i < 3; ++i) covariance[i * 4] += extra;
  return covariance;
}

}  // namespace k40t::driver
