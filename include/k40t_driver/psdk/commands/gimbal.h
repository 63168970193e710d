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
K40T_PSDK_FLAGS(GimbalStateFlags, upward_mounted, yaw_at_limit, roll_at_limit, pitch_at_limit);

// Three angles in 0.1 degree on the wire, as int16 (the document does not say signed for 3.5.1
// and says Uint16 for 3.5.6, but angles below zero exist; docs/psdk.md).
struct GimbalAngles {
  K40T_PSDK_FIELDS((double, pitch_deg, wire::scaled<int16_t>(10)),
                   (double, roll_deg, wire::scaled<int16_t>(10)),
                   (double, yaw_deg, wire::scaled<int16_t>(10)));
};

// 3.5.1 ACK.
struct GimbalStateValue {
  GimbalStateMode mode = GimbalStateMode::kFree;
  GimbalStateFlags flags;
  GimbalAngles angles;
  K40T_PSDK_LAYOUT(s, v) {
    v("mode", s.mode, wire::u8);
    v("flags", s.flags, wire::packed8);
    GimbalAngles::layout(s.angles, v);
  }
};

// 3.5.1: GetGimbalState, GimbalStateAck.
K40T_PSDK_GET(GimbalState, gimbal_state, GimbalStateValue, kGimbal, 0x01, "3.5.1");

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
  K40T_PSDK_FIELDS((double, pitch_rate_deg_s, wire::scaled<int16_t>(10)),
                   (double, roll_rate_deg_s, wire::scaled<int16_t>(10)),
                   (double, yaw_rate_deg_s, wire::scaled<int16_t>(10)),
                   (GimbalControlAction, action, wire::u8, GimbalControlAction::kControl));
  Status validate() const;
};

// 3.5.5: attitude angles in degrees (no range given).
struct ControlGimbalAngle : Command<CommandSet::kGimbal, 0x05, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("control_gimbal_angle", "3.5.5");
  K40T_PSDK_FIELDS((float, pitch_deg, wire::f32), (float, roll_deg, wire::f32),
                   (float, yaw_deg, wire::f32));
};

// 3.5.6: joint angles.
struct ControlGimbalJointAngle : Command<CommandSet::kGimbal, 0x06, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("control_gimbal_joint_angle", "3.5.6");
  GimbalAngles angles;
  K40T_PSDK_LAYOUT(s, v) { GimbalAngles::layout(s.angles, v); }
};

// 3.5.7.
K40T_PSDK_NO_DATA(CalibrateGimbal, kGimbal, 0x07, PlainAck, "calibrate_gimbal", "3.5.7");

// 3.5.8 ACK.
struct CalibrationProgressValue {
  K40T_PSDK_FIELDS((uint8_t, progress_percent, wire::u8),
                   (CalibrationStatus, status, wire::u8, CalibrationStatus::kComplete));
  Status validate() const { return check_int("progress_percent", progress_percent, 0, 100, "%"); }
};

// 3.5.8: GetCalibrationProgress, CalibrationProgressAck.
K40T_PSDK_GET(CalibrationProgress, calibration_progress, CalibrationProgressValue, kGimbal, 0x08,
              "3.5.8");

// 3.5.9 ACK: body-frame rotation speeds, floats in 0.1 deg/s on the wire.
struct GimbalAdditionalStatusValue {
  K40T_PSDK_FIELDS((double, pitch_rate_deg_s, wire::f32_scaled(10)),
                   (double, roll_rate_deg_s, wire::f32_scaled(10)),
                   (double, yaw_rate_deg_s, wire::f32_scaled(10)));
};

// 3.5.9: GetGimbalAdditionalStatus, GimbalAdditionalStatusAck.
K40T_PSDK_GET(GimbalAdditionalStatus, gimbal_additional_status, GimbalAdditionalStatusValue,
              kGimbal, 0x09, "3.5.9");

// 3.5.10 ACK.
struct GimbalCapabilityValue {
  K40T_PSDK_FIELDS((bool, supported, wire::u8));
};

// 3.5.10: GetGimbalCapability, GimbalCapabilityAck.
K40T_PSDK_GET(GimbalCapability, gimbal_capability, GimbalCapabilityValue, kGimbal, 0xFF, "3.5.10");

}  // namespace k40t::psdk
