// Gimbal messages (document section 3.1). Golden frames: test/data/golden/gimbal_laser_sbus.txt,
// written by hand from the document (each entry cites its section and explains every byte).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "message_checks.h"
#include "message_text.h"

namespace k40t::protocol {
namespace {

using namespace testing;  // the checks of golden_checks.h, message_checks.h, message_text.h

const char kGolden[] = "gimbal_laser_sbus.txt";

// Every request names its ACK type; the data-carrying one is its own struct.
static_assert(acked_plainly<GimbalControlRequest, GimbalAngleRequest, GimbalDriftCalibrationRequest,
                            GimbalDialSpeedRequest, GimbalPointAtRequest, GimbalServoOffRequest,
                            GimbalLinearCalibrationRequest, GimbalRestartRequest,
                            GimbalUseFlightControllerAttitudeRequest,
                            GimbalAccelerationCalibrationRequest, GimbalStabilisationRequest>);
static_assert(std::is_same_v<GimbalVersionRequest::Ack, GimbalVersionAck>);

// ---- golden: 3.1.1.1 status -----------------------------------------------------------------
TEST(GimbalGolden, StatusNibblesBitsAndStates) {
  const GimbalStatus m = decode_golden<GimbalStatus>(golden(kGolden, "gimbal_status"));
  EXPECT_EQ(m.gimbal_link, GimbalLinkState::kNormal);    // low nibble of 0x10
  EXPECT_EQ(m.camera_link, GimbalLinkState::kAbnormal);  // high nibble of 0x10
  EXPECT_EQ(m.upgrade, GimbalUpgradeState::kFirmwareUpgradeIncomplete);
  EXPECT_TRUE(m.ir_ok);
  EXPECT_TRUE(m.tele_ok);
  EXPECT_FALSE(m.wide_ok);  // bit 2 of 0x0B is clear
  EXPECT_TRUE(m.laser_ok);
  EXPECT_EQ(m.stabilisation, GimbalStabilisationState::kStabilising);
  // The simulator sends it: encoding gives the document's bytes back.
  expect_encodes_to(m, golden(kGolden, "gimbal_status"));
}

TEST(GimbalGolden, StatusAcceptsTheFourMeaningfulBytesAlone) {
  auto m = decode_bytes<GimbalStatus>({0x01, 0x00, 0x0F, 0x03});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->gimbal_link, GimbalLinkState::kAbnormal);
  EXPECT_EQ(m->camera_link, GimbalLinkState::kNormal);
  EXPECT_TRUE(m->wide_ok);
  EXPECT_EQ(m->stabilisation, GimbalStabilisationState::kFeatureLost);
  expect_decode_error<GimbalStatus>({0x01, 0x00, 0x0F}, "too short");
}

TEST(GimbalGolden, StatusReportsUndefinedCodesWithoutALabel) {
  auto m = decode_bytes<GimbalStatus>({0x52, 0x07, 0x00, 0x09, 0, 0, 0});
  ASSERT_TRUE(m);
  EXPECT_EQ(static_cast<int>(m->gimbal_link), 2);
  EXPECT_EQ(static_cast<int>(m->camera_link), 5);
  EXPECT_EQ(to_string(m->gimbal_link), nullptr);
  EXPECT_EQ(to_string(m->upgrade), nullptr);
  EXPECT_EQ(to_string(m->stabilisation), nullptr);
  EXPECT_FALSE(m->ir_ok || m->tele_ok || m->wide_ok || m->laser_ok);
}

// ---- golden: 3.1.1.2 attitude ---------------------------------------------------------------
TEST(GimbalGolden, AttitudeCentidegreesAndRateOrder) {
  const GimbalAttitude m = decode_golden<GimbalAttitude>(golden(kGolden, "gimbal_attitude"));
  EXPECT_DOUBLE_EQ(m.joint_yaw_deg, 12.34);
  EXPECT_DOUBLE_EQ(m.joint_roll_deg, -1.5);
  EXPECT_DOUBLE_EQ(m.joint_pitch_deg, -45.0);
  EXPECT_DOUBLE_EQ(m.yaw_deg, 90.0);
  EXPECT_DOUBLE_EQ(m.roll_deg, 0.01);
  EXPECT_DOUBLE_EQ(m.pitch_deg, -90.0);
  EXPECT_DOUBLE_EQ(m.yaw_rate_deg_s, 10.5);    // bytes 13-14
  EXPECT_DOUBLE_EQ(m.pitch_rate_deg_s, -2.0);  // bytes 15-16: pitch before roll
  EXPECT_DOUBLE_EQ(m.roll_rate_deg_s, 0.0);
  expect_encodes_to(m, golden(kGolden, "gimbal_attitude"));
}

// ---- golden: 3.1.2.1 control ----------------------------------------------------------------
TEST(GimbalGolden, ControlModeInTheUpperNibble) {
  GimbalControlRequest centre;
  centre.mode = GimbalMode::kCentre;
  centre.yaw = GimbalYawDirection::kRight;
  centre.pitch = GimbalPitchDirection::kStop;
  expect_encodes_to(centre, golden(kGolden, "gimbal_control", 0));

  GimbalControlRequest look_down;
  look_down.mode = GimbalMode::kLookDown;
  look_down.yaw = GimbalYawDirection::kLeft;
  look_down.pitch = GimbalPitchDirection::kDown;
  expect_encodes_to(look_down, golden(kGolden, "gimbal_control", 1));

  const auto decoded = decode_golden<GimbalControlRequest>(golden(kGolden, "gimbal_control", 1));
  EXPECT_EQ(decoded.mode, GimbalMode::kLookDown);
  EXPECT_EQ(decoded.yaw, GimbalYawDirection::kLeft);
  EXPECT_EQ(decoded.pitch, GimbalPitchDirection::kDown);
}

TEST(GimbalGolden, ControlAckIsTheBareResponseCode) {
  const PlainAck ack = decode_golden<PlainAck>(golden(kGolden, "gimbal_control_ack"));
  EXPECT_EQ(ack.code, ResponseCode::kOk);
}

// ---- golden: 3.1.2.2 angle ------------------------------------------------------------------
TEST(GimbalGolden, AngleDownAndLeftAreNegative) {
  GimbalAngleRequest m;
  m.pitch_deg = -45.5;  // direction 1 (down), 4550
  m.yaw_deg = -120.25;  // direction 0 (left), 12025
  expect_encodes_to(m, golden(kGolden, "gimbal_angle", 0));
  const auto d = decode_golden<GimbalAngleRequest>(golden(kGolden, "gimbal_angle", 0));
  EXPECT_TRUE(d.pitch_move);
  EXPECT_DOUBLE_EQ(d.pitch_deg, -45.5);
  EXPECT_TRUE(d.yaw_move);
  EXPECT_DOUBLE_EQ(d.yaw_deg, -120.25);
}

TEST(GimbalGolden, AngleUpLimitAndNoYawMovement) {
  GimbalAngleRequest m;
  m.pitch_deg = 30;
  m.yaw_move = false;
  m.yaw_deg = 77;  // ignored when not moving: sent as 0
  expect_encodes_to(m, golden(kGolden, "gimbal_angle", 1));
  const auto d = decode_golden<GimbalAngleRequest>(golden(kGolden, "gimbal_angle", 1));
  EXPECT_DOUBLE_EQ(d.pitch_deg, 30);
  EXPECT_FALSE(d.yaw_move);
  EXPECT_EQ(d.yaw_deg, 0);
}

TEST(GimbalGolden, AngleRightLimitAndNoPitchMovement) {
  GimbalAngleRequest m;
  m.pitch_move = false;
  m.yaw_deg = 180;  // direction 1 (right)
  expect_encodes_to(m, golden(kGolden, "gimbal_angle", 2));
  const auto d = decode_golden<GimbalAngleRequest>(golden(kGolden, "gimbal_angle", 2));
  EXPECT_FALSE(d.pitch_move);
  EXPECT_DOUBLE_EQ(d.yaw_deg, 180);
}

TEST(GimbalGolden, AngleNackIsBigEndianBusy) {
  EXPECT_EQ(decode_golden<PlainAck>(golden(kGolden, "gimbal_angle_ack")).code, ResponseCode::kBusy);
}

TEST(GimbalAngle, ScaleComesFromTheCodecOptions) {
  CodecOptions tenths;
  tenths.angle_command_scale = 10;  // docs/protocol/decisions.md#a4 alternative: degrees x10
  GimbalAngleRequest m;
  m.pitch_deg = -45.5;
  m.yaw_deg = 90;
  auto p = encode_payload(m, tenths);
  ASSERT_TRUE(p);
  // 455 = 0x01C7, 900 = 0x0384, low byte first.
  const std::vector<uint8_t> expected = {0x01, 0xC7, 0x01, 0x01, 0x84, 0x03, 0x00};
  EXPECT_EQ(std::vector<uint8_t>(p->data(), p->data() + p->size), expected);
  auto back = decode_bytes<GimbalAngleRequest>(expected, tenths);
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->pitch_deg, -45.5);
  EXPECT_DOUBLE_EQ(back->yaw_deg, 90);
}

// docs/protocol/decisions.md#a4: the magnitudes are uint16, at most 65535. At scale 364 the yaw
// limit 180 deg is 65520 = 0xFFF0 (low byte first: F0 FF); at 1000 90 deg would be 90000 and
// used to go out saturated as 65535 (65.5 deg). Such a request is refused, nothing is encoded.
TEST(GimbalAngle, AnAngleTheScaleCannotCarryIsRefused) {
  CodecOptions most;
  most.angle_command_scale = 364;
  GimbalAngleRequest m;
  m.pitch_move = false;
  m.yaw_deg = -180;  // direction 0 (left)
  auto p = encode_payload(m, most);
  ASSERT_TRUE(p) << p.error();
  const std::vector<uint8_t> expected = {0x02, 0x00, 0x00, 0x00, 0xF0, 0xFF, 0x00};
  EXPECT_EQ(std::vector<uint8_t>(p->data(), p->data() + p->size), expected);

  CodecOptions large;
  large.angle_command_scale = 1000;
  m.yaw_deg = 90;
  auto refused = encode_payload(m, large);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("field 'yaw_deg' 90 x angle_command_scale 1000 = 90000 does not "
                                 "fit the 16-bit magnitude"),
            std::string::npos)
      << refused.error();
  EXPECT_NE(refused.error().find("angle_command_scale must be 1..364"), std::string::npos)
      << refused.error();
  m.yaw_deg = 65;  // 65000 fits
  EXPECT_TRUE(encode_payload(m, large));
  m.yaw_move = false;  // no movement: sent as 0 whatever the angle
  m.yaw_deg = 90;
  EXPECT_TRUE(encode_payload(m, large));
  EXPECT_TRUE(m.validate());  // the document's ranges alone still hold
}

TEST(GimbalAngle, RejectsUndefinedDirectionsAndAZeroScale) {
  expect_decode_error<GimbalAngleRequest>({0x03, 0, 0, 0x00, 0, 0, 0}, "pitch direction byte");
  expect_decode_error<GimbalAngleRequest>({0x00, 0, 0, 0x07, 0, 0, 0}, "yaw direction byte");
  CodecOptions zero;
  zero.angle_command_scale = 0;
  auto d = decode_bytes<GimbalAngleRequest>({0, 0, 0, 0, 0, 0, 0}, zero);
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().find("angle_command_scale"), std::string::npos) << d.error();
}

// ---- golden: one-byte commands 3.1.2.3, 3.1.2.5, 3.1.2.7..3.1.2.11 --------------------------
TEST(GimbalGolden, FixedCommandRequests) {
  expect_encodes_to(GimbalDriftCalibrationRequest{}, golden(kGolden, "gimbal_drift_calibration"));
  expect_encodes_to(GimbalVersionRequest{}, golden(kGolden, "gimbal_version"));
  expect_encodes_to(GimbalServoOffRequest{}, golden(kGolden, "gimbal_servo_off"));  // command 0x00
  expect_encodes_to(GimbalLinearCalibrationRequest{}, golden(kGolden, "gimbal_linear_calibration"));
  expect_encodes_to(GimbalRestartRequest{}, golden(kGolden, "gimbal_restart"));
  expect_encodes_to(GimbalUseFlightControllerAttitudeRequest{},
                    golden(kGolden, "gimbal_use_flight_controller_attitude"));
  expect_encodes_to(GimbalAccelerationCalibrationRequest{},
                    golden(kGolden, "gimbal_acceleration_calibration"));
  decode_golden<GimbalRestartRequest>(golden(kGolden, "gimbal_restart"));
  decode_golden<GimbalServoOffRequest>(golden(kGolden, "gimbal_servo_off"));
}

TEST(GimbalCommands, RejectOtherCommandBytes) {
  expect_decode_error<GimbalRestartRequest>({0x02, 0x00}, "command code 1, got 2");
  expect_decode_error<GimbalServoOffRequest>({0x01, 0x00}, "command code 0, got 1");
  expect_decode_error<GimbalRestartRequest>({}, "too short");
}

// ---- golden: 3.1.2.4 dial speed -------------------------------------------------------------
TEST(GimbalGolden, DialSpeedIsDegreesPerSecondTimesFive) {
  GimbalDialSpeedRequest m;
  m.pitch_speed_deg_s = 20;  // 100
  m.yaw_speed_deg_s = 1;     // 5, the document's minimum
  expect_encodes_to(m, golden(kGolden, "gimbal_dial_speed"));
  const auto d = decode_golden<GimbalDialSpeedRequest>(golden(kGolden, "gimbal_dial_speed"));
  EXPECT_DOUBLE_EQ(d.pitch_speed_deg_s, 20);
  EXPECT_DOUBLE_EQ(d.yaw_speed_deg_s, 1);
}

// ---- golden: 3.1.2.5 version ACK ------------------------------------------------------------
TEST(GimbalGolden, VersionAck) {
  const auto v = decode_golden<GimbalVersionAck>(golden(kGolden, "gimbal_version_ack", 0));
  EXPECT_EQ(v.code, ResponseCode::kOk);
  EXPECT_TRUE(fields_are(v,
                         "hardware_major=1 hardware_minor=2 hardware_patch=3 "
                         "software_major=2 software_minor=10 software_patch=7"));
  expect_encodes_to(v, golden(kGolden, "gimbal_version_ack", 0));
}

TEST(GimbalGolden, VersionRefusalCarriesTheCodeAlone) {
  const auto v = decode_golden<GimbalVersionAck>(golden(kGolden, "gimbal_version_ack", 1));
  EXPECT_EQ(v.code, ResponseCode::kFailure);  // 00 01, big-endian
  EXPECT_EQ(v.software_major, 0);
}

TEST(GimbalVersionAck, ByteOrderOfTheCodeFollowsTheOption) {
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  auto v = decode_bytes<GimbalVersionAck>({0x01, 0x02, 1, 2, 3, 4, 5, 6, 0}, little);
  ASSERT_TRUE(v);
  EXPECT_EQ(static_cast<uint16_t>(v->code), 0x0201);  // "recording", read low byte first
  EXPECT_EQ(v->software_patch, 6);
  // Some but not all of the version bytes: an error, not silent zeros.
  expect_decode_error<GimbalVersionAck>({0x00, 0x00, 1, 2, 3}, "too short");
}

// ---- golden: 3.1.2.6 point at ---------------------------------------------------------------
TEST(GimbalGolden, PointAtBothFrames) {
  const GimbalPointAtRequest frames[] = {
      {GimbalAimLens::kWide, 4, 1600, 300},   // frame 0: the wide lens
      {GimbalAimLens::kTele, 35.5, 1920, 1},  // frame 1: the telephoto at the corner
  };
  for (size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE("gimbal_point_at #" + std::to_string(i));
    const GimbalPointAtRequest& m = frames[i];
    expect_encodes_to(m, golden(kGolden, "gimbal_point_at", i));
    const auto d = decode_golden<GimbalPointAtRequest>(golden(kGolden, "gimbal_point_at", i));
    EXPECT_EQ(d.lens, m.lens);
    EXPECT_DOUBLE_EQ(d.zoom_x, m.zoom_x);
    EXPECT_EQ(d.x_px, m.x_px);
    EXPECT_EQ(d.y_px, m.y_px);
  }
}

// ---- golden: 3.1.2.12 stabilisation ---------------------------------------------------------
TEST(GimbalGolden, StabilisationOnAndOff) {
  GimbalStabilisationRequest on;
  on.enable = true;
  expect_encodes_to(on, golden(kGolden, "gimbal_stabilisation", 0));
  GimbalStabilisationRequest off;
  off.enable = false;
  expect_encodes_to(off, golden(kGolden, "gimbal_stabilisation", 1));
  EXPECT_FALSE(
      decode_golden<GimbalStabilisationRequest>(golden(kGolden, "gimbal_stabilisation", 1)).enable);
  expect_decode_error<GimbalStabilisationRequest>({0x02, 0x00}, "0 (off) or 1 (on), got 2");
}

}  // namespace
}  // namespace k40t::protocol
