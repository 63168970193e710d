// The driver's time-matched VehicleState in the geo layer's terms, ROS-free: the vehicle pose that
// laser/target_local and locate_pixel start from, and the uncertainty of the pod's own laser
// target report (laser/target_report). ros/geo_glue.h adds TF and the messages.
#pragma once

#include <optional>

#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/geo/ray_locator.h"

namespace k40t::driver {

// The pose, or a reason: no fix, no attitude.
Result<geo::VehiclePose> vehicle_pose(const VehicleState& state);

// What a horizontal plane's height is given above (LocatePixel's plane_reference).
enum class PlaneReference { kAboveTakeoff, kMeanSeaLevel };
// The height above the ellipsoid of a plane `height_m` above the take-off point (the first fix:
// the vehicle's height less its relative height) or above mean sea level at the vehicle's
// position (EGM96; fails without the geoid grid).
Result<double> plane_height_ellipsoid(const VehicleState& vehicle, PlaneReference reference,
                                      double height_m);

// The pod's laser target position's covariance (ENU m^2, an approximation): the vehicle's position
// covariance, plus on the diagonal the attitude error (uncertainty.attitude_sigma_deg) over the
// slant range from the vehicle to the target and the laser's range error. Nothing without a
// vehicle fix or when the target is where no local frame can be set up.
std::optional<geo::Covariance3> laser_target_covariance(
    const geo::Geodetic& target, const VehicleState& vehicle,
    const geo::RayUncertainty& uncertainty = geo::RayUncertainty());

}  // namespace k40t::driver
