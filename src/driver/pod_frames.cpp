#include "k40t_driver/driver/pod_frames.h"

#include <cmath>

namespace k40t::driver {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

Rep103Angles rep103_from_pod(double yaw_deg, double roll_deg, double pitch_deg) {
  return Rep103Angles{-yaw_deg * kDegToRad, roll_deg * kDegToRad, -pitch_deg * kDegToRad};
}

namespace {
Quaternion about(double x, double y, double z, double angle) {
  const double s = std::sin(angle / 2);
  return {x * s, y * s, z * s, std::cos(angle / 2)};
}
Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
      a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
}  // namespace

Quaternion attitude_rotation(const Rep103Angles& a, protocol::AttitudeOrder order) {
  const Quaternion yaw = about(0, 0, 1, a.yaw);
  const Quaternion pitch = about(0, 1, 0, a.pitch);
  const Quaternion roll = about(1, 0, 0, a.roll);
  return order == protocol::AttitudeOrder::kZyx ? yaw * pitch * roll : yaw * roll * pitch;
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
