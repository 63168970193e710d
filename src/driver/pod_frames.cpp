#include "k40t_driver/driver/pod_frames.h"

#include <cmath>

namespace k40t::driver {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

Rep103Angles rep103_from_pod(double yaw_deg, double roll_deg, double pitch_deg) {
  return Rep103Angles{-yaw_deg * kDegToRad, roll_deg * kDegToRad, -pitch_deg * kDegToRad};
}

PodAngles pod_from_rep103(const Rep103Angles& a) {
  return PodAngles{-a.yaw / kDegToRad, a.roll / kDegToRad, -a.pitch / kDegToRad};
}

FrameIds::FrameIds(const std::string& frame_prefix, const std::string& joint_prefix)
    : base(frame_prefix + "base_link"),
      yaw(frame_prefix + "yaw_link"),
      roll(frame_prefix + "roll_link"),
      pitch(frame_prefix + "pitch_link"),
      tele(frame_prefix + "tele_optical_frame"),
      wide(frame_prefix + "wide_optical_frame"),
      thermal(frame_prefix + "thermal_optical_frame"),
      laser(frame_prefix + "laser_frame"),
      level(frame_prefix + "level"),
      yaw_joint(joint_prefix + "yaw_joint"),
      roll_joint(joint_prefix + "roll_joint"),
      pitch_joint(joint_prefix + "pitch_joint") {}

}  // namespace k40t::driver
