// 3.5.5's angles in the frame of 3.5.1 (docs/psdk.md P28): with `gimbal_angle_layout:
// dji_headers` the state reports the pod's attitude (NED), so an angle command names an attitude
// too. The pod only takes joint angles (gimbal/set_angle): the bridge turns the NED target into
// the joint target with the pod's current attitude-minus-joint offset (on the yaw, the aircraft's
// heading; on the pitch, what the stabilisation adds), so that the state reads back what was set.
#pragma once

#include <cmath>
#include <optional>

#include "k40t_driver/skyport/pod_port.h"

namespace k40t::driver::skyport {

// Degrees in DJI signs (pitch up, yaw right positive), like 3.5.5's floats.
struct GimbalTargetDeg {
  double pitch_deg = 0;
  double yaw_deg = 0;
};

// An angle in degrees brought into [-180, 180).
inline double wrap_deg_180(double deg) {
  const double wrapped = std::fmod(deg + 180.0, 360.0);
  return (wrapped < 0 ? wrapped + 360.0 : wrapped) - 180.0;
}

// The joint target that puts the pod at the NED attitude `ned` (DJI signs), from the snapshot's
// attitude and joints (REP 103 radians, pod_port.h): joint = ned - (attitude - joint), per axis,
// the yaw wrapped to +-180. Nothing without both the attitude and the joints (the offset is
// unknown: better refuse than drive to a guess).
inline std::optional<GimbalTargetDeg> joint_target_from_ned(const GimbalTargetDeg& ned,
                                                            const PodSnapshot& s) {
  if (!s.have_attitude || !s.have_joints) return std::nullopt;
  constexpr double kDegPerRad = 180.0 / M_PI;
  // REP 103 -> DJI: pitch and yaw change sign; differences of two such angles too.
  const double pitch_offset_deg = -(s.attitude_pitch_rad - s.pitch_rad) * kDegPerRad;
  const double yaw_offset_deg = -(s.attitude_yaw_rad - s.yaw_rad) * kDegPerRad;
  GimbalTargetDeg joint;
  joint.pitch_deg = ned.pitch_deg - pitch_offset_deg;
  joint.yaw_deg = wrap_deg_180(ned.yaw_deg - yaw_offset_deg);
  return joint;
}

}  // namespace k40t::driver::skyport
