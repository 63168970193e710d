// The velocity of a nav_msgs/Odometry in the local east-north-up frame. Odometry's twist is in
// its child_frame_id, the body (REP 105: "the twist in this message should be specified in the
// coordinate frame given by the child_frame_id"), while its pose.orientation turns the body into
// header.frame_id. The driver takes that frame as east-north-up (REP 103/105 world frames: x
// east, y north, z up, as MAVROS's local_position/odom and robot_localization's navsat-aligned
// odometry give it), so the ENU velocity is the body velocity turned by that orientation.
// ROS-free: the glue passes the message's numbers.
#pragma once

#include "k40t_driver/geo/state_history.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::geo {

struct Orientation {  // a quaternion, body -> ENU, as geometry_msgs/Quaternion (need not be unit)
  double x = 0;
  double y = 0;
  double z = 0;
  double w = 1;
};

// Fails (and the sample must be dropped) when a number is not finite or the orientation is not a
// rotation (a zero quaternion: many sources publish one when the orientation is unknown).
Result<VelocitySample> enu_velocity_from_body(const Orientation& body_to_enu, double forward,
                                              double left, double up);

}  // namespace k40t::geo
