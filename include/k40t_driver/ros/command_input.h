// What the driver subscribes to:
//   gimbal/cmd_angle  geometry_msgs/Vector3Stamped  joint angles, rad, REP 103 (y = pitch,
//                     positive down; z = yaw, positive left; x = roll is ignored: the pod takes no
//                     roll command) -> 0x000012
//   gimbal/cmd_rate   geometry_msgs/Twist  angular.y pitch rate, angular.z yaw rate, rad/s, REP 103
//                     -> 0x000010 + 0x000017 through RateCommander; 0.5 s without one stops the
//                     gimbal
//   fix               sensor_msgs/NavSatFix  the vehicle's position }  answers to the pod's GPS
//   attitude          sensor_msgs/Imu        its orientation (ENU)  }  requests, laser-target
//   velocity          geometry_msgs/TwistStamped  its velocity, linear in ENU (optional) }
//   velocity_odom     nav_msgs/Odometry  the same from odometry (optional): twist in the body
//                     (child_frame_id, REP 105), turned into ENU by the message's own
//                     orientation (its header.frame_id taken as ENU)                  }
//                     requests; each also goes into the history the GPS answers are
//                     interpolated in (stamps: header.stamp; 0 = time of arrival)
//   time_reference    sensor_msgs/TimeReference  a better clock (time_ref at header.stamp): the
//                     pod's clock is set from it (0x00030E) instead of from the system clock
#pragma once

#include <cmath>
#include <mutex>

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/TimeReference.h>

#include "k40t_driver/driver/pod_driver.h"

namespace k40t::driver {

class CommandInput {
 public:
  CommandInput(ros::NodeHandle nh, PodDriver& driver);

 private:
  void on_cmd_angle(const geometry_msgs::Vector3Stamped::ConstPtr& msg);
  void on_cmd_rate(const geometry_msgs::Twist::ConstPtr& msg);
  void on_fix(const sensor_msgs::NavSatFix::ConstPtr& msg);
  void on_attitude(const sensor_msgs::Imu::ConstPtr& msg);
  void on_time_reference(const sensor_msgs::TimeReference::ConstPtr& msg);
  void on_velocity(const geometry_msgs::TwistStamped::ConstPtr& msg);
  void on_velocity_odom(const nav_msgs::Odometry::ConstPtr& msg);

  PodDriver& driver_;
  std::mutex mutex_;
  double reference_altitude_m_ = std::nan("");
  ros::Subscriber cmd_angle_, cmd_rate_, fix_, attitude_, time_reference_, velocity_,
      velocity_odom_;
};

}  // namespace k40t::driver
