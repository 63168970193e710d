// Gimbal messages (document section 3.1) beyond the golden frames of test_messages_gimbal.cpp:
// every struct round-trips with unusual codec options, every validated field is refused out of its
// range by name, and the catalogue registers each message with its ACK.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "message_checks.h"
#include "message_text.h"

namespace k40t::protocol {
namespace {

using namespace testing;  // the checks of golden_checks.h, message_checks.h, message_text.h

// ---- round trips ----------------------------------------------------------------------------
CodecOptions unusual_options() {
  CodecOptions o;
  o.ack_byte_order = ByteOrder::kLittle;
  o.angle_command_scale = 10;
  return o;
}

TEST(GimbalRoundTrip, EveryStruct) {
  GimbalStatus status;
  status.gimbal_link = GimbalLinkState::kAbnormal;
  status.upgrade = GimbalUpgradeState::kKernelUpgradeIncomplete;
  status.ir_ok = false;
  status.laser_ok = false;
  status.stabilisation = GimbalStabilisationState::kFailed;

  GimbalAttitude attitude;
  attitude.joint_yaw_deg = -179.99;
  attitude.joint_roll_deg = 3.21;
  attitude.joint_pitch_deg = 25;
  attitude.yaw_deg = 327.67;
  attitude.roll_deg = -327.68;
  attitude.pitch_deg = -0.01;
  attitude.yaw_rate_deg_s = 100.5;
  attitude.pitch_rate_deg_s = -60;
  attitude.roll_rate_deg_s = 1.25;

  GimbalControlRequest control;
  control.mode = GimbalMode::kNone;
  control.yaw = GimbalYawDirection::kLeft;
  control.pitch = GimbalPitchDirection::kUp;

  GimbalAngleRequest angle;
  angle.pitch_deg = -90;
  angle.yaw_deg = 12.5;

  GimbalDialSpeedRequest dial;
  dial.pitch_speed_deg_s = 30;
  dial.yaw_speed_deg_s = 7.4;  // 37 on the wire

  GimbalVersionAck version;
  version.code = ResponseCode::kBusy;
  version.hardware_major = 255;
  version.software_patch = 9;

  GimbalPointAtRequest point;
  point.lens = GimbalAimLens::kThermal;
  point.zoom_x = 8;
  point.x_px = 1;
  point.y_px = 1080;

  GimbalStabilisationRequest stabilisation;
  stabilisation.enable = false;

  for (const CodecOptions& o : {CodecOptions{}, unusual_options()})
    expect_round_trips(o, status, attitude, control, angle, dial, GimbalDriftCalibrationRequest{},
                       GimbalVersionRequest{}, version, point, GimbalServoOffRequest{},
                       GimbalLinearCalibrationRequest{}, GimbalRestartRequest{},
                       GimbalUseFlightControllerAttitudeRequest{},
                       GimbalAccelerationCalibrationRequest{}, stabilisation);
}

TEST(GimbalRoundTrip, AngleWithoutMovementOnEitherAxis) {
  GimbalAngleRequest m;
  m.pitch_move = false;
  m.yaw_move = false;
  expect_round_trip(m);
}

// ---- range errors: every validated field ----------------------------------------------------
TEST(GimbalRanges, Status) {
  const GimbalStatus valid;
  expect_range_error(valid, "gimbal_link",
                     [](auto& m) { m.gimbal_link = static_cast<GimbalLinkState>(2); });
  expect_range_error(valid, "camera_link",
                     [](auto& m) { m.camera_link = static_cast<GimbalLinkState>(16); });
  expect_range_error(valid, "upgrade",
                     [](auto& m) { m.upgrade = static_cast<GimbalUpgradeState>(3); });
  expect_range_error(valid, "stabilisation",
                     [](auto& m) { m.stabilisation = static_cast<GimbalStabilisationState>(4); });
}

TEST(GimbalRanges, Attitude) {  // every angle and rate: int16 x100 ends at -327.68 and 327.67
  for_each_field_set_to<GimbalAttitude>(
      {"327.68", "-327.69"},
      [](const std::string& name, const GimbalAttitude& m) { expect_range_error(m, name); });
}

TEST(GimbalRanges, Control) {
  const GimbalControlRequest valid;
  expect_range_error(valid, "mode", [](auto& m) { m.mode = static_cast<GimbalMode>(3); });
  expect_range_error(valid, "yaw", [](auto& m) { m.yaw = static_cast<GimbalYawDirection>(3); });
  expect_range_error(valid, "pitch",
                     [](auto& m) { m.pitch = static_cast<GimbalPitchDirection>(9); });
}

TEST(GimbalRanges, Angle) {
  for (double bad : {30.01, -90.01, std::nan("")}) {
    GimbalAngleRequest m;
    m.pitch_deg = bad;
    expect_range_error(m, "pitch_deg");
  }
  for (double bad : {180.01, -180.01, std::numeric_limits<double>::infinity()}) {
    GimbalAngleRequest m;
    m.yaw_deg = bad;
    expect_range_error(m, "yaw_deg");
  }
  GimbalAngleRequest m;
  m.pitch_deg = 31;
  auto p = encode_payload(m);
  ASSERT_FALSE(p);
  EXPECT_NE(p.error().find("-90..30"), std::string::npos)
      << "the message gives the range: " << p.error();
}

TEST(GimbalRanges, DialSpeed) {
  for (double bad : {0.9, 30.1, 0.0}) {
    GimbalDialSpeedRequest m;
    m.pitch_speed_deg_s = bad;
    expect_range_error(m, "pitch_speed_deg_s");
    m = {};
    m.yaw_speed_deg_s = bad;
    expect_range_error(m, "yaw_speed_deg_s");
  }
}

TEST(GimbalRanges, PointAt) {
  GimbalPointAtRequest m;
  m.lens = static_cast<GimbalAimLens>(3);
  expect_range_error(m, "lens");

  for (double bad : {3.4, 160.1}) {
    m = {};
    m.lens = GimbalAimLens::kTele;
    m.zoom_x = bad;
    expect_range_error(m, "zoom_x");
  }
  for (GimbalAimLens lens : {GimbalAimLens::kWide, GimbalAimLens::kThermal}) {
    for (double bad : {0.0, 9.0, 2.5}) {  // 1..8, whole multiples only
      m = {};
      m.lens = lens;
      m.zoom_x = bad;
      expect_range_error(m, "zoom_x");
    }
  }
  for (int bad : {0, 1921})
    expect_range_error(GimbalPointAtRequest{}, "x_px", [&](auto& r) { r.x_px = bad; });
  for (int bad : {0, 1081})
    expect_range_error(GimbalPointAtRequest{}, "y_px", [&](auto& r) { r.y_px = bad; });
}

// ---- catalogue ------------------------------------------------------------------------------
TEST(GimbalCatalogue, EveryMessageIsRegisteredWithItsAck) {
  struct Expected {
    MessageId id;
    const char* name;
  };
  const Expected expected[] = {
      {0x000001, "gimbal_status"},
      {0x000002, "gimbal_attitude"},
      {0x000010, "gimbal_control"},
      {0x010010, "gimbal_control_ack"},
      {0x000012, "gimbal_angle"},
      {0x010012, "gimbal_angle_ack"},
      {0x000013, "gimbal_drift_calibration"},
      {0x010013, "gimbal_drift_calibration_ack"},
      {0x000017, "gimbal_dial_speed"},
      {0x010017, "gimbal_dial_speed_ack"},
      {0x000018, "gimbal_version"},
      {0x010018, "gimbal_version_ack"},
      {0x00002C, "gimbal_point_at"},
      {0x01002C, "gimbal_point_at_ack"},
      {0x00002D, "gimbal_servo_off"},
      {0x01002D, "gimbal_servo_off_ack"},
      {0x00002E, "gimbal_linear_calibration"},
      {0x01002E, "gimbal_linear_calibration_ack"},
      {0x00002F, "gimbal_restart"},
      {0x01002F, "gimbal_restart_ack"},
      {0x000030, "gimbal_use_flight_controller_attitude"},
      {0x010030, "gimbal_use_flight_controller_attitude_ack"},
      {0x000031, "gimbal_acceleration_calibration"},
      {0x010031, "gimbal_acceleration_calibration_ack"},
      {0x000033, "gimbal_stabilisation"},
      {0x010033, "gimbal_stabilisation_ack"},
  };
  for (const Expected& e : expected) {
    const MessageInfo* info = find_message(e.id);
    ASSERT_NE(info, nullptr) << e.name;
    EXPECT_STREQ(info->name, e.name);
    EXPECT_EQ(find_message(e.name), info);
  }
  // Periodic reports get no ACK entry.
  EXPECT_EQ(find_message(0x010001), nullptr);
  EXPECT_EQ(find_message(0x010002), nullptr);
  EXPECT_EQ(find_message(0x000010)->direction, Direction::kHostToPod);
  EXPECT_EQ(find_message(0x010010)->direction, Direction::kPodToHost);
}

}  // namespace
}  // namespace k40t::protocol
