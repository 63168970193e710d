// Gimbal messages (document section 3.1, system 0x03 per docs/protocol/decisions.md#a3): the
// periodic reports 0x000001 and 0x000002, the requests 0x000010..0x000033 and the data-carrying ACK
// 0x010018. The other requests are acknowledged with the bare response code (PlainAck).
//
// Sign conventions of the host-side structs (the wire uses direction bytes instead of signs):
//   pitch: positive = up (the document's 0 "up"), negative = down;
//   yaw:   positive = right (the document's 1 "right", clockwise seen from above, like a compass
//          heading and the gimbal conventions of drone SDKs), negative = LEFT.
// docs/protocol/gimbal_laser_sbus.md explains this and the other decisions.
//
// Every message is a declarative layout (codec/layout.h): 0x000012's direction bytes and option
// scale are wire::directed, 0x00002C's lens-dependent zoom range a wire::ruled check.
#pragma once

#include <cstdint>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/simple_requests.h"

namespace k40t::protocol {

// ---- 0x000001 gimbal status, section 3.1.1.1, 2 Hz ------------------------------------------

// Byte 1: the low nibble is the gimbal's link, the high nibble the camera's.
enum class GimbalLinkState : uint8_t { kNormal = 0, kAbnormal = 1 };
const char* to_string(GimbalLinkState state);

// Byte 2.
enum class GimbalUpgradeState : uint8_t {
  kNormal = 0x00,
  kKernelUpgradeIncomplete = 0x01,
  kFirmwareUpgradeIncomplete = 0x02,
};
const char* to_string(GimbalUpgradeState state);

// Byte 4: electronic image stabilisation.
enum class GimbalStabilisationState : uint8_t {
  kOff = 0,
  kStabilising = 1,
  kFailed = 2,
  kFeatureLost = 3,
};
const char* to_string(GimbalStabilisationState state);

struct GimbalStatus {
  // kMinSize: bytes 5..7 are reserved: optional on receive
  K40T_POD_REPORT(0x000001, "gimbal_status", "3.1.1.1", 7, 4);

  GimbalLinkState gimbal_link = GimbalLinkState::kNormal;
  GimbalLinkState camera_link = GimbalLinkState::kNormal;
  GimbalUpgradeState upgrade = GimbalUpgradeState::kNormal;
  // Byte 3, self-test: bit 0 IR core, bit 1 telephoto, bit 2 wide-angle, bit 3 laser (1 = ok).
  bool ir_ok = true;
  bool tele_ok = true;
  bool wide_ok = true;
  bool laser_ok = true;
  GimbalStabilisationState stabilisation = GimbalStabilisationState::kOff;

  K40T_LAYOUT(s, v) {
    v("links",
      wire::bit_group(wire::in_bits("gimbal_link", s.gimbal_link, wire::bits(0, 4)),
                      wire::in_bits("camera_link", s.camera_link, wire::bits(4, 4))),
      wire::packed8);
    v("upgrade", s.upgrade, wire::u8);
    v("self_test",
      wire::bit_group(wire::in_bits("ir_ok", s.ir_ok, wire::bit(0)),
                      wire::in_bits("tele_ok", s.tele_ok, wire::bit(1)),
                      wire::in_bits("wide_ok", s.wide_ok, wire::bit(2)),
                      wire::in_bits("laser_ok", s.laser_ok, wire::bit(3))),
      wire::packed8);
    v("stabilisation", s.stabilisation, wire::u8);
    v("reserved", wire::gap, wire::reserved(3));
  }
};

// ---- 0x000002 gimbal attitude, section 3.1.1.2, 10 Hz ---------------------------------------

// All angles int16 degrees x100, low byte first. Note the rate order on the wire: yaw, pitch, roll.
struct GimbalAttitude {
  // kMinSize: the 2 reserved bytes are optional on receive
  K40T_POD_REPORT(0x000002, "gimbal_attitude", "3.1.1.2", 20, 18);
  static constexpr double kCentiDegMin = -327.68;  // what int16 x0.01 deg can carry
  static constexpr double kCentiDegMax = 327.67;

  double joint_yaw_deg = 0;
  double joint_roll_deg = 0;
  double joint_pitch_deg = 0;
  double yaw_deg = 0;  // stabilised attitude
  double roll_deg = 0;
  double pitch_deg = 0;
  double yaw_rate_deg_s = 0;
  double pitch_rate_deg_s = 0;
  double roll_rate_deg_s = 0;

  K40T_LAYOUT(s, v) {
    constexpr auto deg = wire::scaled<int16_t>(100).range(kCentiDegMin, kCentiDegMax, "deg");
    constexpr auto deg_s = wire::scaled<int16_t>(100).range(kCentiDegMin, kCentiDegMax, "deg/s");
    v("joint_yaw_deg", s.joint_yaw_deg, deg);
    v("joint_roll_deg", s.joint_roll_deg, deg);
    v("joint_pitch_deg", s.joint_pitch_deg, deg);
    v("yaw_deg", s.yaw_deg, deg);
    v("roll_deg", s.roll_deg, deg);
    v("pitch_deg", s.pitch_deg, deg);
    v("yaw_rate_deg_s", s.yaw_rate_deg_s, deg_s);
    v("pitch_rate_deg_s", s.pitch_rate_deg_s, deg_s);
    v("roll_rate_deg_s", s.roll_rate_deg_s, deg_s);
    v("reserved", wire::gap, wire::reserved(2));
  }
};

// ---- 0x000010 gimbal control, section 3.1.2.1 -----------------------------------------------

// Byte 1, upper nibble (the lower nibble is reserved, sent as zero).
enum class GimbalMode : uint8_t { kNone = 0, kCentre = 1, kLookDown = 2 };
const char* to_string(GimbalMode mode);
// Byte 2: keep turning until told to stop.
enum class GimbalYawDirection : uint8_t { kLeft = 0, kRight = 1, kStop = 2 };
const char* to_string(GimbalYawDirection direction);
// Byte 3.
enum class GimbalPitchDirection : uint8_t { kUp = 0, kDown = 1, kStop = 2 };
const char* to_string(GimbalPitchDirection direction);

struct GimbalControlRequest {
  K40T_POD_REQUEST(0x000010, "gimbal_control", "3.1.2.1", 4, 3);

  GimbalMode mode = GimbalMode::kNone;
  GimbalYawDirection yaw = GimbalYawDirection::kStop;
  GimbalPitchDirection pitch = GimbalPitchDirection::kStop;

  K40T_LAYOUT(s, v) {
    // The low nibble of byte 1 is reserved: sent as zero, ignored on receive.
    v("mode_byte", wire::bit_group(wire::in_bits("mode", s.mode, wire::bits(4, 4))), wire::packed8);
    v("yaw", s.yaw, wire::u8);
    v("pitch", s.pitch, wire::u8);
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x000012 gimbal angle, section 3.1.2.2 -------------------------------------------------

// Absolute angles. On the wire each axis is a direction byte (pitch 0 up / 1 down, yaw 0 left /
// 1 right, 2 = no movement) and a uint16 magnitude in degrees x CodecOptions::angle_command_scale
// (docs/protocol/decisions.md#a4, default 100). Here: signed degrees (see the sign conventions at
// the top of this file) and, per axis, `*_move = false` for the document's "no movement" (the angle
// is then ignored and sent as 0).
struct GimbalAngleRequest {
  K40T_POD_REQUEST(0x000012, "gimbal_angle", "3.1.2.2", 7, 6);
  static constexpr double kPitchMinDeg = -90;  // "down 90 degrees"
  static constexpr double kPitchMaxDeg = 30;   // "up 30 degrees"
  static constexpr double kYawLimitDeg = 180;  // "180 degrees left, 180 degrees right"
  static constexpr uint8_t kNoMovement = 2;    // either axis's direction byte

  bool pitch_move = true;
  double pitch_deg = 0;  // up positive
  bool yaw_move = true;
  double yaw_deg = 0;  // right positive, left negative

  K40T_LAYOUT(s, v) {
    constexpr auto scale = &CodecOptions::angle_command_scale;
    constexpr const char* kScaleName = "angle_command_scale";
    v("pitch", wire::switchable("pitch_move", s.pitch_move, "pitch_deg", s.pitch_deg),
      wire::directed({0, "up"}, {1, "down"}, kNoMovement, scale, kScaleName)
          .range(kPitchMinDeg, kPitchMaxDeg, "deg (up positive)"));
    v("yaw", wire::switchable("yaw_move", s.yaw_move, "yaw_deg", s.yaw_deg),
      wire::directed({1, "right"}, {0, "left"}, kNoMovement, scale, kScaleName)
          .range(-kYawLimitDeg, kYawLimitDeg, "deg (right positive)"));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x000013 one-key gyro drift calibration, section 3.1.2.3: byte 1 = 0x01 ----------------
struct GimbalDriftCalibrationRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x000013, "gimbal_drift_calibration", "3.1.2.3");
};

// ---- 0x000017 dial (thumb-wheel) speed, section 3.1.2.4 -------------------------------------

// Maximum speed the gimbal turns at when steered with the dial: wire 5..150 = deg/s x5, i.e.
// 1..30 deg/s. Byte 1 pitch, byte 2 yaw, byte 3 reserved.
struct GimbalDialSpeedRequest {
  K40T_POD_REQUEST(0x000017, "gimbal_dial_speed", "3.1.2.4", 3, 2);

  static constexpr double kMinDegS = 1;
  static constexpr double kMaxDegS = 30;
  static constexpr double kWirePerDegS = 5;

  // The document gives no default; the project's one (docs/protocol/gimbal_laser_sbus.md, 0x000017
  // row), shared by this struct, cfg/K40t.cfg (wire units: 100) and the simulated pod.
  static constexpr double kDefaultDegS = 20;

  double pitch_speed_deg_s = kDefaultDegS;
  double yaw_speed_deg_s = kDefaultDegS;

  K40T_LAYOUT(s, v) {
    constexpr auto speed = wire::scaled<uint8_t>(kWirePerDegS).range(kMinDegS, kMaxDegS, "deg/s");
    v("pitch_speed_deg_s", s.pitch_speed_deg_s, speed);
    v("yaw_speed_deg_s", s.yaw_speed_deg_s, speed);
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x000018 version, section 3.1.2.5 ------------------------------------------------------

// ACK 0x010018: response code (docs/protocol/decisions.md#a2 byte order), hardware
// major.minor.patch, software major.minor.patch, 1 reserved byte.
struct GimbalVersionAck {
  K40T_POD_DATA_ACK(0x010018, "gimbal_version_ack", "3.1.2.5", kPodToHost, 9);

  K40T_FIELDS((ResponseCode, code, wire::response_code, ResponseCode::kOk),
              (uint8_t, hardware_major, wire::u8), (uint8_t, hardware_minor, wire::u8),
              (uint8_t, hardware_patch, wire::u8), (uint8_t, software_major, wire::u8),
              (uint8_t, software_minor, wire::u8), (uint8_t, software_patch, wire::u8),
              (reserved, wire::reserved(1)));
  // The code alone (a refusal), or the code and all six version numbers.
  Status finish_decode(size_t payload_size) const;
};

// Byte 1 = 0x01 "get the gimbal version".
struct GimbalVersionRequest : CommandRequest<0x01, GimbalVersionAck> {
  K40T_POD_MESSAGE(0x000018, "gimbal_version", "3.1.2.5");
};

// ---- 0x00002C point-to-aim, section 3.1.2.6 -------------------------------------------------

// Byte 1: which lens the pixel coordinates and zoom ratio refer to.
enum class GimbalAimLens : uint8_t { kTele = 0x00, kWide = 0x01, kThermal = 0x02 };
const char* to_string(GimbalAimLens lens);
// Telephoto 3.5..160, wide and thermal 1..8 whole multiples; ok for a lens the document does not
// define (the lens field's own check reports that).
Status check_aim_zoom(const char* field, GimbalAimLens lens, double zoom_x);

// Turn the gimbal so that pixel (x, y) of the given lens's 1920x1080 picture, seen at the given
// zoom, comes to the centre. Zoom: uint16 x0.1; telephoto 3.5..160 (3.5..11 optical, beyond that
// digital), wide and thermal 1..8 whole multiples (digital only). x 1..1920, y 1..1080 (centre
// 960, 540).
struct GimbalPointAtRequest {
  K40T_POD_REQUEST(0x00002C, "gimbal_point_at", "3.1.2.6", 7, 7);

  GimbalAimLens lens = GimbalAimLens::kTele;
  double zoom_x = 3.5;
  uint16_t x_px = 960;
  uint16_t y_px = 540;

  K40T_LAYOUT(s, v) {
    const auto zoom_for_lens = [&s](const char* name, double zoom_x) {
      return check_aim_zoom(name, s.lens, zoom_x);
    };
    v("lens", s.lens, wire::u8);
    v("zoom_x", s.zoom_x, wire::ruled(wire::scaled<uint16_t>(10), zoom_for_lens));  // x0.1
    v("x_px", s.x_px, wire::u16.range(1, 1920, "px"));
    v("y_px", s.y_px, wire::u16.range(1, 1080, "px"));
  }
};

// ---- 0x00002D..0x000031: one fixed command byte each ----------------------------------------

// 3.1.2.7: byte 1 = 0x00 "turn off the servo".
struct GimbalServoOffRequest : CommandRequest<0x00> {
  K40T_POD_MESSAGE(0x00002D, "gimbal_servo_off", "3.1.2.7");
};

// 3.1.2.8: byte 1 = 0x01 "linear calibration".
struct GimbalLinearCalibrationRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x00002E, "gimbal_linear_calibration", "3.1.2.8");
};

// 3.1.2.9: byte 1 = 0x01 "soft restart".
struct GimbalRestartRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x00002F, "gimbal_restart", "3.1.2.9");
};

// 3.1.2.10: byte 1 = 0x01 "use the flight controller's (fake) attitude".
struct GimbalUseFlightControllerAttitudeRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x000030, "gimbal_use_flight_controller_attitude", "3.1.2.10");
};

// 3.1.2.11: byte 1 = 0x01 "calibrate the motion acceleration bias".
struct GimbalAccelerationCalibrationRequest : CommandRequest<0x01> {
  K40T_POD_MESSAGE(0x000031, "gimbal_acceleration_calibration", "3.1.2.11");
};

// ---- 0x000033 image stabilisation, section 3.1.2.12: byte 1 = 1 on, 0 off -------------------
struct GimbalStabilisationRequest : SwitchRequest<> {
  K40T_POD_MESSAGE(0x000033, "gimbal_stabilisation", "3.1.2.12");
};

// Every message struct of the gimbal family: the catalogue, the catalogue tests and the fuzz target
// take their entries from this list (message_list.h).
using GimbalMessages =
    MessageList<GimbalStatus, GimbalAttitude, GimbalControlRequest, GimbalAngleRequest,
                GimbalDriftCalibrationRequest, GimbalDialSpeedRequest, GimbalVersionRequest,
                GimbalVersionAck, GimbalPointAtRequest, GimbalServoOffRequest,
                GimbalLinearCalibrationRequest, GimbalRestartRequest,
                GimbalUseFlightControllerAttitudeRequest, GimbalAccelerationCalibrationRequest,
                GimbalStabilisationRequest>;

}  // namespace k40t::protocol
