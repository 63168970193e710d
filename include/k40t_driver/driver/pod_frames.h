// The pod's frames and angles in ROS terms (REP 103), ROS-free: the frame and joint names, the
// gimbal chain's geometry, the laser's range limits and the pod's angles in REP 103 signs.
// ros/conversions.h turns them into JointState, TF and Range messages.
#pragma once

#include <array>
#include <string>

#include "k40t_driver/protocol/convention_values.h"

namespace k40t::driver {

// Gimbal angles or rates in REP 103 convention, radians (per second).
struct Rep103Angles {
  double yaw = 0;
  double roll = 0;
  double pitch = 0;
};
// The pod's degrees (yaw right-positive, pitch up-positive) in REP 103 radians (yaw
// left-positive, pitch down-positive); roll keeps its sign.
Rep103Angles rep103_from_pod(double yaw_deg, double roll_deg, double pitch_deg);

// A rotation as a unit quaternion (x, y, z, w).
struct Quaternion {
  double x = 0;
  double y = 0;
  double z = 0;
  double w = 1;
};
// The rotation of 0x000002's attitude angles (in REP 103 terms) composed in the order the pod
// means (attitude_order, docs/protocol/decisions.md#conventions): zyx = Rz(yaw) Ry(pitch)
// Rx(roll), the aerospace order; zxy = Rz(yaw) Rx(roll) Ry(pitch), the joint chain's order.
Quaternion attitude_rotation(const Rep103Angles& angles, protocol::AttitudeOrder order);

// The inverse, for commands (gimbal/cmd_angle, gimbal/cmd_rate): REP 103 radians (per second) ->
// the pod's degrees (per second).
struct PodAngles {
  double yaw_deg = 0;
  double roll_deg = 0;
  double pitch_deg = 0;
};
PodAngles pod_from_rep103(const Rep103Angles& angles);

// Every frame id the driver uses, from ~frame_prefix; the joint names from ~joint_prefix.
struct FrameIds {
  explicit FrameIds(const std::string& frame_prefix = "k40t_",
                    const std::string& joint_prefix = "k40t_");
  std::string base, yaw, roll, pitch;      // the gimbal chain
  std::string tele, wide, thermal, laser;  // sensors (optical frames, laser x along the beam)
  std::string level;                       // gravity-aligned frame of gimbal/attitude
  std::string yaw_joint, roll_joint, pitch_joint;
};

// Translations of the gimbal chain (metres, parent frame), the same as urdf/k40t.urdf.
struct GimbalGeometry {
  std::array<double, 3> yaw_joint{0, 0, -0.02};    // base -> yaw link
  std::array<double, 3> roll_joint{0, 0, -0.04};   // yaw -> roll link
  std::array<double, 3> pitch_joint{0, 0, -0.06};  // roll -> pitch link
  // Sensor positions in the pitch link (parameters *_offset).
  std::array<double, 3> tele{0.05, 0.02, 0.015};
  std::array<double, 3> wide{0.05, -0.02, 0.015};
  std::array<double, 3> thermal{0.05, 0.02, -0.015};
  std::array<double, 3> laser{0.05, -0.02, -0.015};
};

// Limits written into every laser/range message.
struct RangeLimits {
  float min_range = 5.0f;
  float max_range = 1500.0f;
  float field_of_view = 0.003f;
};

}  // namespace k40t::driver
