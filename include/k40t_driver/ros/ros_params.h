// Reads the driver's private parameters (config/k40t.yaml documents each) into DriverOptions and
// the ROS-side settings, checking every value: a bad one fails with a message naming the
// parameter, what it got and what it accepts.
#pragma once

#include <ros/node_handle.h>

#include "k40t_driver/driver/driver_options.h"
#include "k40t_driver/driver/look_at_controller.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/ros/conversions.h"
#include "k40t_driver/ros/param_reader.h"

namespace k40t::driver {

struct RosPodConfig {
  DriverOptions driver;
  FrameIds ids;
  GimbalGeometry geometry;
  RangeLimits range;
  bool publish_tf = true;
  double rate_tolerance = 0.5;  // accepted deviation of each report's rate (fraction)
  // gimbal/look_at and gimbal/look_at_point (docs/ros_interface.md "Looking at a place").
  struct LookAt {
    LookAtConfig control;          // look_at_drive, look_at_lead, gimbal_yaw_continuous
    double rate_hz = 20;           // look_at_rate: control steps per second
    double point_timeout_s = 1.0;  // look_at_point_timeout: the points' dead-man
  } look_at;
};

Result<RosPodConfig> read_params(const ros::NodeHandle& private_nh);
// The same from any ParamReader (offline: a YAML file's values, see `k40t bag`).
Result<RosPodConfig> read_params(ParamReader& reader);

}  // namespace k40t::driver
