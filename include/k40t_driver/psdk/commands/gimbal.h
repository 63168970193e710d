// Gimbal command set 0x05 (protocol document section 3.5): DJI Pilot reads and drives the
// payload's gimbal.
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

// 3.5.1 (state report): 0 free, 1 following, 2 FPV.
enum class GimbalStateMode : uint8_t { kFree = 0, kFollowing = 1, kFpv = 2 };
const char* to_string(GimbalStateMode mode);

// 3.5.2 (set): 0 free, 1 FPV, 2 following. The document numbers the modes differently in 3.5.1
// and 3.5.2; each is kept as written (docs/psdk.md), to_state_mode() maps one to the other.
enum class GimbalMode : uint8_t { kFree = 0, kFpv = 1, kFollowing = 2 };
const char* to_string(GimbalMode mode);
GimbalStateMode to_state_mode(GimbalMode mode);

enum class GimbalControlAction : uint8_t { kStop = 0, kControl = 1 };
const char* to_string(GimbalControlAction action);

enum class CalibrationStatus : uint8_t { kComplete = 0, kInProgress = 1, kFailed = 2 };
const char* to_string(CalibrationStatus status);

constexpr double kMaxGimbalRateDegS = 180.0;  // 3.5.4: -1800..1800 x 0.1 deg/s

// 3.5.1 byte 3.
struct GimbalStateFlags {
  bool upward_mounted = false;
  bool yaw_at_limit = false;
  bool roll_at_limit = false;
  bool pitch_at_limit = false;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("upward_mounted", s.upward_mounted, wire::bit(0));
    v("yaw_at_limit", s.yaw_at_limit, wire::bit(1));
    v("roll_at_limit", s.roll_at_limit, wire::bit(2));
    v("pitch_at_limit", s.pitch_at_limit, wire::bit(3));
  }
};

// Three angles in 0.1 degree on the wire, as int16 (the document does not say signed for 3.5.1
// and says Uint16 for 3.5.6, but angles below zero exist; docs/psdk.md).
struct GimbalAngles {
  double pitch_deg = 0;
  double roll_deg = 0;
  double yaw_deg = 0;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("pitch_deg", s.pitch_deg, wire::scaled<int16_t>(10));
    v("roll_deg", s.roll_deg, wire::scaled<int16_t>(10));
    v("yaw_deg", s.yaw_deg, wire::scaled<int16_t>(10));
  }
};

// 3.5.1 ACK.
struct GimbalStateAck : Reply<CommandSet::kGimbal, 0x01, Sender::kPayload> {
  K40T_PSDK_NAMED("get_gimbal_state_ack", "3.5.1");
  GimbalStateMode mode = GimbalStateMode::kFree;
  GimbalStateFlags flags;
  GimbalAngles angles;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("mode", s.mode, wire::u8);
    v("flags", s.flags, wire::packed8);
    GimbalAngles::layout(s.angles, v);
  }
};

// 3.5.1.
K40T_PSDK_NO_DATA(GetGimbalState, kGimbal, 0x01, GimbalStateAck, "get_gimbal_state", "3.5.1");

// 3.5.2.
struct SetGimbalMode : Command<CommandSet::kGimbal, 0x02, Sender::kAdapter, PlainAck>,
                       ModeValue<GimbalMode, GimbalMode::kFree> {
  K40T_PSDK_NAMED("set_gimbal_mode", "3.5.2");
};

// 3.5.3: back to the centre ("return head").
K40T_PSDK_NO_DATA(GimbalReturnHead, kGimbal, 0x03, PlainAck, "gimbal_return_head", "3.5.3");

// 3.5.4.
struct ControlGimbalSpeed : Command<CommandSet::kGimbal, 0x04, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("control_gimbal_speed", "3.5.4");
  double pitch_rate_deg_s = 0;
  double roll_rate_deg_s = 0;
  double yaw_rate_deg_s = 0;
  GimbalControlAction action = GimbalControlAction::kControl;
  Status validate() const;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("pitch_rate_deg_s", s.pitch_rate_deg_s, wire::scaled<int16_t>(10));
    v("roll_rate_deg_s", s.roll_rate_deg_s, wire::scaled<int16_t>(10));
    v("yaw_rate_deg_s", s.yaw_rate_deg_s, wire::scaled<int16_t>(10));
    v("action", s.action, wire::u8);
  }
};

// 3.5.5: attitude angles in degrees (no range given).
struct ControlGimbalAngle : Command<CommandSet::kGimbal, 0x05, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("control_gimbal_angle", "3.5.5");
  float pitch_deg = 0;
  float roll_deg = 0;
  float yaw_deg = 0;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("pitch_deg", s.pitch_deg, wire::f32);
    v("roll_deg", s.roll_deg, wire::f32);
    v("yaw_deg", s.yaw_deg, wire::f32);
  }
};

// 3.5.6: joint angles.
struct ControlGimbalJointAngle : Command<CommandSet::kGimbal, 0x06, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("control_gimbal_joint_angle", "3.5.6");
  GimbalAngles angles;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    GimbalAngles::layout(s.angles, v);
  }
};

// 3.5.7.
K40T_PSDK_NO_DATA(CalibrateGimbal, kGimbal, 0x07, PlainAck, "calibrate_gimbal", "3.5.7");

// 3.5.8 ACK.
struct CalibrationProgressAck : Reply<CommandSet::kGimbal, 0x08, Sender::kPayload> {
  K40T_PSDK_NAMED("get_calibration_progress_ack", "3.5.8");
  uint8_t progress_percent = 0;
  CalibrationStatus status = CalibrationStatus::kComplete;
  Status validate() const { return check_int("progress_percent", progress_percent, 0, 100, "%"); }
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("progress_percent", s.progress_percent, wire::u8);
    v("status", s.status, wire::u8);
  }
};

// 3.5.8.
K40T_PSDK_NO_DATA(GetCalibrationProgress, kGimbal, 0x08, CalibrationProgressAck,
                  "get_calibration_progress", "3.5.8");

// 3.5.9 ACK: body-frame rotation speeds, floats in 0.1 deg/s on the wire.
struct GimbalAdditionalStatusAck : Reply<CommandSet::kGimbal, 0x09, Sender::kPayload> {
  K40T_PSDK_NAMED("get_gimbal_additional_status_ack", "3.5.9");
  double pitch_rate_deg_s = 0;
  double roll_rate_deg_s = 0;
  double yaw_rate_deg_s = 0;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("pitch_rate_deg_s", s.pitch_rate_deg_s, wire::f32_scaled(10));
    v("roll_rate_deg_s", s.roll_rate_deg_s, wire::f32_scaled(10));
    v("yaw_rate_deg_s", s.yaw_rate_deg_s, wire::f32_scaled(10));
  }
};

// 3.5.9.
K40T_PSDK_NO_DATA(GetGimbalAdditionalStatus, kGimbal, 0x09, GimbalAdditionalStatusAck,
                  "get_gimbal_additional_status", "3.5.9");

// 3.5.10 ACK.
struct GimbalCapabilityAck : Reply<CommandSet::kGimbal, 0xFF, Sender::kPayload> {
  K40T_PSDK_NAMED("get_gimbal_capability_ack", "3.5.10");
  bool supported = false;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("supported", s.supported, wire::u8);
  }
};

// 3.5.10.
K40T_PSDK_NO_DATA(GetGimbalCapability, kGimbal, 0xFF, GimbalCapabilityAck, "get_gimbal_capability",
                  "3.5.10");

}  // namespace k40t::psdk
