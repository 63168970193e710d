#include "k40t_driver/ros/command_input.h"

#include <ros/console.h>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/ros/conversions.h"

namespace k40t::driver {

namespace {
constexpr double kRadToDeg = 180.0 / M_PI;
}  // namespace

CommandInput::CommandInput(ros::NodeHandle nh, PodDriver& driver) : driver_(driver) {
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  cmd_angle_ = nh.subscribe("gimbal/cmd_angle", 1, &CommandInput::on_cmd_angle, this, hints);
  cmd_rate_ = nh.subscribe("gimbal/cmd_rate", 1, &CommandInput::on_cmd_rate, this, hints);
  fix_ = nh.subscribe("fix", 1, &CommandInput::on_fix, this, hints);
  attitude_ = nh.subscribe("attitude", 1, &CommandInput::on_attitude, this, hints);
  time_reference_ =
      nh.subscribe("time_reference", 1, &CommandInput::on_time_reference, this, hints);
}

void CommandInput::on_cmd_angle(const geometry_msgs::Vector3Stamped::ConstPtr& msg) {
  protocol::GimbalAngleRequest request;
  request.pitch_deg = -msg->vector.y * kRadToDeg;  // REP 103 down-positive -> pod up-positive
  request.yaw_deg = -msg->vector.z * kRadToDeg;    // REP 103 left-positive -> pod right-positive
  driver_.request_async(request, [](const session::AckResult& result) {
    if (!result.ok())
      ROS_WARN_THROTTLE(1.0, "gimbal/cmd_angle not applied: %s", result.message.c_str());
  });
}

void CommandInput::on_cmd_rate(const geometry_msgs::Twist::ConstPtr& msg) {
  driver_.command_rate(-msg->angular.y * kRadToDeg, -msg->angular.z * kRadToDeg);
}

void CommandInput::on_fix(const sensor_msgs::NavSatFix::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  VehicleState state = driver_.vehicle_state();
  update_from_fix(state, *msg, &reference_altitude_m_);
  driver_.set_vehicle_state(state);
}

void CommandInput::on_attitude(const sensor_msgs::Imu::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  VehicleState state = driver_.vehicle_state();
  update_from_imu(state, *msg);
  driver_.set_vehicle_state(state);
}

void CommandInput::on_time_reference(const sensor_msgs::TimeReference::ConstPtr& msg) {
  // The stamp is the system (ROS) time at which the reference clock read time_ref.
  const int64_t offset_ns = static_cast<int64_t>(msg->time_ref.toNSec()) -
                            static_cast<int64_t>(msg->header.stamp.toNSec());
  driver_.set_clock_offset_ms(offset_ns / 1000000);
}

}  // namespace k40t::driver
