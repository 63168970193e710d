#include "k40t_driver/protocol/messages/gimbal.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

namespace {
constexpr double kCentiDegMax = 327.67;  // int16 / 100
constexpr double kCentiDegMin = -327.68;
}  // namespace

// ---- 0x000002 ------------------------------------------------------------------------------
Status GimbalAttitude::validate() const {
  return first_failure(check_range("joint_yaw_deg", joint_yaw_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("joint_roll_deg", joint_roll_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("joint_pitch_deg", joint_pitch_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("yaw_deg", yaw_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("roll_deg", roll_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("pitch_deg", pitch_deg, kCentiDegMin, kCentiDegMax, "deg"),
                       check_range("yaw_rate_deg_s", yaw_rate_deg_s, kCentiDegMin, kCentiDegMax, "deg/s"),
                       check_range("pitch_rate_deg_s", pitch_rate_deg_s, kCentiDegMin, kCentiDegMax, "deg/s"),
                       check_range("roll_rate_deg_s", roll_rate_deg_s, kCentiDegMin, kCentiDegMax, "deg/s"));
}

void GimbalAttitude::encode(ByteWriter& w, const CodecOptions&) const {
  for (double v : {joint_yaw_deg, joint_roll_deg, joint_pitch_deg, yaw_deg, roll_deg, pitch_deg,
                   yaw_rate_deg_s, pitch_rate_deg_s, roll_rate_deg_s}) {
    w.i16(to_wire<int16_t>(v, 100));
  }
  w.zeros(2);
}

Status GimbalAttitude::decode(ByteReader& r, const CodecOptions&) {
  for (double* v : {&joint_yaw_deg, &joint_roll_deg, &joint_pitch_deg, &yaw_deg, &roll_deg,
                    &pitch_deg, &yaw_rate_deg_s, &pitch_rate_deg_s, &roll_rate_deg_s}) {
    *v = r.i16() / 100.0;
  }
  return Status::ok();
}

void add_gimbal_messages(std::vector<MessageInfo>& out) { out.push_back(info_of<GimbalAttitude>()); }

}  // namespace k40t::protocol
