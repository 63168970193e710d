// Protocol structs -> ROS messages, and the vehicle topics -> VehicleState. Pure functions: no
// node handles, no clocks (the stamp is an argument), so replay regenerates identical messages.
//
// Sign conventions. The pod reports pitch positive up and yaw positive right (clockwise seen from
// above), like its commands (protocol/messages/gimbal.h). ROS uses REP 103 (x forward, y left,
// z up, right-handed), so:
//   REP 103 yaw   (about z)  = -pod yaw     positive = turning left
//   REP 103 pitch (about y)  = -pod pitch   positive = looking down
//   REP 103 roll  (about x)  =  pod roll    positive = right side down
// and rates alike. Every joint angle, TF rotation and attitude quaternion goes through
// rep103_from_pod(); the inverse is used for commands.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/Range.h>

#include "k40t_driver/CameraStatus.h"
#include "k40t_driver/Frame.h"
#include "k40t_driver/GimbalStatus.h"
#include "k40t_driver/PhotoStatus.h"
#include "k40t_driver/RecordStatus.h"
#include "k40t_driver/ThermalStats.h"
#include "k40t_driver/VisibleStatus.h"
#include "k40t_driver/driver/pod_frames.h"
#include "k40t_driver/driver/vehicle_inputs.h"
#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/camera_status.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

sensor_msgs::JointState to_joint_state(const protocol::GimbalAttitude& attitude,
                                       const ros::Time& stamp, const FrameIds& ids);
// The stabilised attitude (yaw, roll, pitch attitude angles) as a quaternion in ids.level,
// composed in the order the pod means (attitude_order, docs/protocol/decisions.md#conventions).
geometry_msgs::QuaternionStamped to_attitude(
    const protocol::GimbalAttitude& attitude, const ros::Time& stamp, const FrameIds& ids,
    protocol::AttitudeOrder order = protocol::AttitudeOrder::kZyx);
// base -> yaw -> roll -> pitch from the joint angles.
std::vector<geometry_msgs::TransformStamped> gimbal_transforms(
    const protocol::GimbalAttitude& attitude, const ros::Time& stamp, const FrameIds& ids,
    const GimbalGeometry& geometry);
// pitch link -> tele, wide, thermal optical frames and the laser frame.
std::vector<geometry_msgs::TransformStamped> sensor_transforms(const ros::Time& stamp,
                                                               const FrameIds& ids,
                                                               const GimbalGeometry& geometry);

k40t_driver::GimbalStatus to_msg(const protocol::GimbalStatus& status, const ros::Time& stamp);
k40t_driver::CameraStatus to_msg(const protocol::CameraSystemStatus& status,
                                 const ros::Time& stamp);
k40t_driver::VisibleStatus to_msg(const protocol::VisibleStatus& status, const ros::Time& stamp);
k40t_driver::ThermalStats to_msg(const protocol::ThermalStatus& status, const ros::Time& stamp,
                                 const FrameIds& ids);
k40t_driver::PhotoStatus to_msg(const protocol::PhotoStatus& status, const ros::Time& stamp);
k40t_driver::RecordStatus to_msg(const protocol::RecordStatus& status, const ros::Time& stamp);

// A laser distance (0 = no return, published as +Inf per REP 117).
sensor_msgs::Range to_range(double distance_m, const ros::Time& stamp, const FrameIds& ids,
                            const RangeLimits& limits);
// The laser target's position (0x010320) with `covariance` (ENU m^2, laser/target_report's
// approximation) as COVARIANCE_TYPE_APPROXIMATED; a negative diagonal (the report's "no fix")
// gives COVARIANCE_TYPE_UNKNOWN and zeros. A "no return" under `zeros` (laser_target_zeros,
// docs/protocol/decisions.md#conventions) is STATUS_NO_FIX with a NaN altitude.
sensor_msgs::NavSatFix to_nav_sat_fix(const protocol::TargetGpsAck& target, const ros::Time& stamp,
                                      const FrameIds& ids,
                                      const boost::array<double, 9>& covariance,
                                      protocol::LaserTargetZeros zeros);

k40t_driver::Frame to_frame_msg(const uint8_t* bytes, size_t size, const ros::Time& stamp,
                                uint8_t direction);

// Vehicle topics -> VehicleState, by driver/vehicle_inputs.h's rules. The first fix with a
// position sets the reference of relative_altitude_m (the take-off point).
void update_from_fix(VehicleState& state, const sensor_msgs::NavSatFix& fix,
                     double* reference_altitude_m);
// Orientation in ENU (REP 103) -> aviation heading/pitch/roll; the angular velocity is ignored.
void update_from_imu(VehicleState& state, const sensor_msgs::Imu& imu);

}  // namespace k40t::driver
