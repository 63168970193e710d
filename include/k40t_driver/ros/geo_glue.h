// What laser/target_local and locate_pixel share, as ROS glue: a ray of a sensor frame in the
// vehicle frame from TF, a NavSatFix of a located point, the laser target report, and the
// uncertainty parameters. The vehicle pose and the report's covariance are driver/vehicle_geo.h's.
#pragma once

#include <optional>
#include <string>

#include <sensor_msgs/NavSatFix.h>

#include <tf2_ros/buffer.h>
#include "k40t_driver/LaserTarget.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/flight_controller.h"

#include "k40t_driver/driver/vehicle_geo.h"
#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/geo/ray_locator.h"

namespace k40t::driver {

// The ray from `sensor_frame`'s origin along `direction` (in that frame) expressed in
// `vehicle_frame`, at `stamp` or, when TF has nothing that old or new, the latest transform.
Result<geo::BodyRay> ray_in_vehicle(const tf2_ros::Buffer& tf, const std::string& vehicle_frame,
                                    const std::string& sensor_frame, const ros::Time& stamp,
                                    const geo::Vector3& direction);

sensor_msgs::NavSatFix to_nav_sat_fix(const geo::Located& located, const ros::Time& stamp,
                                      const std::string& frame_id);

// Every field of the pod's laser-target answer (ACK 0x010320), with an approximated covariance
// when the vehicle state at its stamp has a fix: the fix's variances plus, in every direction,
// (slant range x the default attitude sigma)^2 and the default range sigma^2 (docs/geo.md);
// without a fix (replay, `k40t bag`) the covariance is unknown (all -1). An OK answer that is
// "no return" under `zeros` (laser_target_zeros) is no position: its fields as sent, the
// ellipsoid altitude NaN and the covariance all -1, whatever the vehicle state.
k40t_driver::LaserTarget to_laser_target(const protocol::TargetGpsAck& target,
                                         const ros::Time& stamp, const std::string& frame_id,
                                         const VehicleState& vehicle,
                                         protocol::LaserTargetZeros zeros);

// ~attitude_sigma (deg), ~pointing_sigma (deg), ~range_sigma (m).
geo::RayUncertainty read_uncertainty(const ros::NodeHandle& private_nh);

}  // namespace k40t::driver
