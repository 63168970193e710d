// Gimbal messages (document section 3.1, system 0x03 per NOTES A3): the periodic reports
// 0x000001 and 0x000002, the requests 0x000010..0x000033 and their ACKs.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {

// 0x000002, section 3.1.1.2, 10 Hz. All angles int16 degrees x100, low byte first. Note the
// rate order on the wire: yaw, pitch, roll.
struct GimbalAttitude {
  static constexpr MessageId kId = 0x000002;
  static constexpr const char* kName = "gimbal_attitude";
  static constexpr const char* kSection = "3.1.1.2";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 20;
  static constexpr size_t kMinSize = 18;  // the 2 reserved bytes are optional on receive

  double joint_yaw_deg = 0;
  double joint_roll_deg = 0;
  double joint_pitch_deg = 0;
  double yaw_deg = 0;  // stabilised attitude
  double roll_deg = 0;
  double pitch_deg = 0;
  double yaw_rate_deg_s = 0;
  double pitch_rate_deg_s = 0;
  double roll_rate_deg_s = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("joint_yaw_deg", self.joint_yaw_deg);
    v("joint_roll_deg", self.joint_roll_deg);
    v("joint_pitch_deg", self.joint_pitch_deg);
    v("yaw_deg", self.yaw_deg);
    v("roll_deg", self.roll_deg);
    v("pitch_deg", self.pitch_deg);
    v("yaw_rate_deg_s", self.yaw_rate_deg_s);
    v("pitch_rate_deg_s", self.pitch_rate_deg_s);
    v("roll_rate_deg_s", self.roll_rate_deg_s);
  }
};

}  // namespace k40t::protocol
