#include "k40t_driver/ros/command_input.h"

#include <ros/console.h>

#include "k40t_driver/geo/body_velocity.h"
#include "k40t_driver/operations/gimbal_operations.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/ros/conversions.h"

namespace k40t::driver {

namespace {

// A message's stamp, or its time of arrival when it has none.
StampNs stamp_of(const std_msgs::Header& header) {
  const ros::Time t = header.stamp.isZero() ? ros::Time::now() : header.stamp;
  return static_cast<StampNs>(t.toNSec());
}
}  // namespace

CommandInput::CommandInput(ros::NodeHandle nh, PodDriver& driver) : driver_(driver) {
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  cmd_angle_ = nh.subscribe("gimbal/cmd_angle", 1, &CommandInput::on_cmd_angle, this, hints);
  cmd_rate_ = nh.subscribe("gimbal/cmd_rate", 1, &CommandInput::on_cmd_rate, this, hints);
  fix_ = nh.subscribe("fix", 10, &CommandInput::on_fix, this, hints);
  attitude_ = nh.subscribe("attitude", 10, &CommandInput::on_attitude, this, hints);
  time_reference_ =
      nh.subscribe("time_reference", 1, &CommandInput::on_time_reference, this, hints);
  // Queues of 10: every sample counts for the history, not only the latest.
  velocity_ = nh.subscribe("velocity", 10, &CommandInput::on_velocity, this, hints);
  velocity_odom_ = nh.subscribe("velocity_odom", 10, &CommandInput::on_velocity_odom, this, hints);
}

void CommandInput::on_cmd_angle(const geometry_msgs::Vector3Stamped::ConstPtr& msg) {
  // Checked in the topic's units and signs (REP 103 radians), as gimbal/set_angle does: an error
  // in the pod's degrees and signs would name values the caller never sent.
  const Result<protocol::GimbalAngleRequest> request =
      operations::angle_request_from_rep103(msg->vector.y, msg->vector.z);
  if (!request) {
    ROS_WARN_THROTTLE(1.0, "gimbal/cmd_angle not applied: %s", request.error().c_str());
    return;
  }
  driver_.request_async(request.value(), [](const session::AckResult& result) {
    if (!result.ok())
      ROS_WARN_THROTTLE(1.0, "gimbal/cmd_angle not applied: %s", result.message.c_str());
  });
}

void CommandInput::on_cmd_rate(const geometry_msgs::Twist::ConstPtr& msg) {
  const PodAngles pod = pod_from_rep103({msg->angular.z, msg->angular.x, msg->angular.y});
  driver_.command_rate(pod.pitch_deg, pod.yaw_deg);
}

void CommandInput::on_fix(const sensor_msgs::NavSatFix::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  VehicleState state = driver_.vehicle_state();
  update_from_fix(state, *msg, &reference_altitude_m_);
  driver_.set_vehicle_state(state);
  if (state.has_fix)
    driver_.record_position(stamp_of(msg->header),
                            {state.latitude_deg, state.longitude_deg, state.altitude_m});
}

void CommandInput::on_attitude(const sensor_msgs::Imu::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  VehicleState state = driver_.vehicle_state();
  update_from_imu(state, *msg);
  driver_.set_vehicle_state(state);
  if (state.has_attitude)
    driver_.record_attitude(stamp_of(msg->header),
                            {state.heading_deg, state.pitch_deg, state.roll_deg});
}

void CommandInput::on_velocity(const geometry_msgs::TwistStamped::ConstPtr& msg) {
  const geometry_msgs::Vector3& v = msg->twist.linear;
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    ROS_WARN_THROTTLE(5.0, "velocity ignored: not finite");
    return;
  }
  driver_.record_velocity(stamp_of(msg->header), {v.x, v.y, v.z});
}

void CommandInput::on_velocity_odom(const nav_msgs::Odometry::ConstPtr& msg) {
  const geometry_msgs::Quaternion& q = msg->pose.pose.orientation;
  const geometry_msgs::Vector3& v = msg->twist.twist.linear;
  const Result<geo::VelocitySample> enu =
      geo::enu_velocity_from_body({q.x, q.y, q.z, q.w}, v.x, v.y, v.z);
  if (!enu) {
    ROS_WARN_THROTTLE(5.0, "velocity_odom: %s", enu.error().c_str());
    return;
  }
  driver_.record_velocity(stamp_of(msg->header), enu.value());
}

void CommandInput::on_time_reference(const sensor_msgs::TimeReference::ConstPtr& msg) {
  // The stamp is the system (ROS) time at which the reference clock read time_ref.
  const int64_t offset_ns = static_cast<int64_t>(msg->time_ref.toNSec()) -
                            static_cast<int64_t>(msg->header.stamp.toNSec());
  driver_.set_clock_offset_ms(offset_ns / 1000000);
}

}  // namespace k40t::driver
