// The open readings' effect on message values (protocol/convention_readings.h). Payload bytes are
// written by hand from the document's tables (section cited per test), never from the encoder.
#include <gtest/gtest.h>

#include <vector>

#include "byte_checks.h"
#include "k40t_driver/protocol/convention_readings.h"

namespace k40t::protocol {
namespace {

using k40t::testing::same_bytes;

// 3.1.1.2: nine int16 deg x100, low byte first (joint yaw, roll, pitch; attitude yaw, roll, pitch;
// rates yaw, pitch, roll), then 2 reserved bytes.
std::vector<uint8_t> attitude_bytes(uint16_t joint_yaw, uint16_t joint_pitch, uint16_t yaw) {
  return {static_cast<uint8_t>(joint_yaw), static_cast<uint8_t>(joint_yaw >> 8), 0, 0,
          static_cast<uint8_t>(joint_pitch), static_cast<uint8_t>(joint_pitch >> 8),
          static_cast<uint8_t>(yaw), static_cast<uint8_t>(yaw >> 8), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
          0, 0};
}

GimbalAttitude decoded_attitude(const std::vector<uint8_t>& bytes) {
  Result<GimbalAttitude> m = decode_payload<GimbalAttitude>(bytes.data(), bytes.size());
  EXPECT_TRUE(m.is_ok()) << m.error();
  return m.is_ok() ? *m : GimbalAttitude{};
}

TEST(ConventionReadings, AttitudeHeadingAbove327DegreesReadsBackAsMinus10) {
  // A 0..360 heading of 350.00 deg: 35000 = 0x88B8; joint yaw 200.00 deg = 20000 = 0x4E20.
  GimbalAttitude m = decoded_attitude(attitude_bytes(0x4E20, 0, 0x88B8));
  EXPECT_NEAR(m.yaw_deg, -305.36, 1e-9);  // what int16 makes of it
  EXPECT_EQ(yaw_range_evidence(m), YawRange::kHeading);
  attitude_from_wire(m, Conventions{}, YawRange::kHeading);
  EXPECT_NEAR(m.yaw_deg, -10.0, 1e-9);
  EXPECT_NEAR(m.joint_yaw_deg, -160.0, 1e-9);
}

TEST(ConventionReadings, YawRangeEvidence) {
  // -20.00 deg signed = 0xF830: no heading is 635.36 deg, so the pod is signed.
  EXPECT_EQ(yaw_range_evidence(decoded_attitude(attitude_bytes(0, 0, 0xF830))), YawRange::kSigned);
  // 20.00 deg = 0x07D0 reads the same both ways: nothing learnt.
  EXPECT_EQ(yaw_range_evidence(decoded_attitude(attitude_bytes(0x07D0, 0, 0x07D0))),
            YawRange::kAuto);
  // 181.00 deg = 18100 = 0x46B4 cannot be a signed +-180 yaw.
  EXPECT_EQ(yaw_range_evidence(decoded_attitude(attitude_bytes(0x46B4, 0, 0))), YawRange::kHeading);
}

TEST(ConventionReadings, SignsTurnThePodsCountingIntoRightUpPositive) {
  // Joint yaw 10.00 deg = 0x03E8, joint pitch 30.00 deg = 0x0BB8, on a pod counting yaw to the
  // left and pitch down: 10 deg left and 30 deg down.
  GimbalAttitude m = decoded_attitude(attitude_bytes(0x03E8, 0x0BB8, 0x03E8));
  Conventions c;
  c.yaw_sign = YawSign::kLeft;
  c.pitch_sign = PitchSign::kDown;
  attitude_from_wire(m, c, YawRange::kSigned);
  EXPECT_DOUBLE_EQ(m.joint_yaw_deg, -10.0);
  EXPECT_DOUBLE_EQ(m.yaw_deg, -10.0);
  EXPECT_DOUBLE_EQ(m.joint_pitch_deg, -30.0);
}

TEST(ConventionReadings, AttitudeToWireUnderEveryReadingReadsBackTheTruth) {
  for (YawSign ys : {YawSign::kRight, YawSign::kLeft})
    for (PitchSign ps : {PitchSign::kUp, PitchSign::kDown})
      for (RollSign rs : {RollSign::kRightDown, RollSign::kLeftDown})
        for (YawRange range : {YawRange::kSigned, YawRange::kHeading}) {
          Conventions c;
          c.yaw_sign = ys;
          c.pitch_sign = ps;
          c.roll_sign = rs;
          c.yaw_range = range;
          GimbalAttitude truth;
          truth.joint_yaw_deg = -170.5;
          truth.yaw_deg = 20.25;
          truth.joint_pitch_deg = -80;
          truth.roll_deg = 3;
          truth.yaw_rate_deg_s = 12;
          GimbalAttitude m = truth;
          attitude_to_wire(m, c);
          Result<Payload> bytes = encode_payload(m);
          ASSERT_TRUE(bytes.is_ok()) << bytes.error();
          GimbalAttitude back = *decode_payload<GimbalAttitude>(bytes->data(), bytes->size);
          attitude_from_wire(back, c, range);
          EXPECT_NEAR(back.joint_yaw_deg, truth.joint_yaw_deg, 0.006);
          EXPECT_NEAR(back.yaw_deg, truth.yaw_deg, 0.006);
          EXPECT_NEAR(back.joint_pitch_deg, truth.joint_pitch_deg, 0.006);
          EXPECT_NEAR(back.roll_deg, truth.roll_deg, 0.006);
          EXPECT_NEAR(back.yaw_rate_deg_s, truth.yaw_rate_deg_s, 0.006);
        }
}

TEST(ConventionReadings, SdCapacitiesOfATenthMb) {
  // 3.2.1.1: bytes 10-11 total, 12-13 free, 14-15 used, low byte first. 30000 = 0x7530 counts,
  // 10000 = 0x2710, 20000 = 0x4E20.
  std::vector<uint8_t> bytes = {0, 0, 0, 0, 0, 0, 5, 3, 0, 0x30, 0x75, 0x10, 0x27, 0x20, 0x4E, 0};
  Result<CameraSystemStatus> m = decode_payload<CameraSystemStatus>(bytes.data(), bytes.size());
  ASSERT_TRUE(m.is_ok()) << m.error();
  CameraSystemStatus ten_mb = *m;
  sd_capacities_from_wire(ten_mb, Conventions{});
  EXPECT_DOUBLE_EQ(ten_mb.sd_total_mb, 300000);
  Conventions tenth;
  tenth.sd_capacity_unit = SdCapacityUnit::kTenthMb;
  CameraSystemStatus tenths = *m;
  sd_capacities_from_wire(tenths, tenth);
  EXPECT_NEAR(tenths.sd_total_mb, 3000, 1e-9);
  EXPECT_NEAR(tenths.sd_free_mb, 1000, 1e-9);
  EXPECT_NEAR(tenths.sd_used_mb, 2000, 1e-9);
  // The simulator's side: 3000.05 MB is 30000 counts of 0.1 MB, 300 of 10 MB.
  EXPECT_DOUBLE_EQ(sd_capacity_to_wire(3000.05, tenth), 300000);
  EXPECT_DOUBLE_EQ(sd_capacity_to_wire(3009, Conventions{}), 3000);
}

TEST(ConventionReadings, ShutterReadings) {
  // 1/4 s = 250000 us = 0x3D090: saturated 0xFFFF, wrapped 0xD090 = 53392, 100 us counts 2500.
  EXPECT_EQ(shutter_to_wire(250000, ShutterField::kMicroseconds), 0xFFFF);
  EXPECT_EQ(shutter_to_wire(250000, ShutterField::kMicrosecondsWrapped), 0xD090);
  EXPECT_EQ(shutter_to_wire(250000, ShutterField::kHundredMicroseconds), 2500);
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(0xD090, ShutterField::kMicrosecondsWrapped), 250000);
  // 1/8 s = 125000 = 0x1E848 -> 0xE848; 1/15 s = 66667 = 0x1046B -> 0x046B.
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(0xE848, ShutterField::kMicrosecondsWrapped), 125000);
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(0x046B, ShutterField::kMicrosecondsWrapped), 66667);
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(33333, ShutterField::kMicrosecondsWrapped), 33333);
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(2500, ShutterField::kHundredMicroseconds), 250000);
  EXPECT_DOUBLE_EQ(shutter_us_from_wire(0xFFFF, ShutterField::kMicroseconds), 65535);
}

ThermalSettingsAck with_enhancement_byte(uint8_t byte) {
  ThermalSettingsAck m;
  m.enhancement_on = (byte & 0x80) != 0;
  m.enhancement_level = byte & 0x7F;
  return m;
}

TEST(ConventionReadings, EnhancementLevelWithItsSwitchClearIsOn) {
  // 3.2.2.1 byte 10 = 0x05: level 5, bit 7 clear. Decision T7: on at level 5.
  const Enhancement bit7 =
      enhancement_from_wire(with_enhancement_byte(0x05), EnhancementSwitch::kBit7);
  EXPECT_TRUE(bit7.on);
  EXPECT_EQ(bit7.level, 5);
  const Enhancement level =
      enhancement_from_wire(with_enhancement_byte(0x05), EnhancementSwitch::kLevel);
  EXPECT_TRUE(level.on);
  EXPECT_EQ(level.level, 5);
  // 0x0B = level 5 in bits 7..1, switch bit 0 set.
  const Enhancement bit0 =
      enhancement_from_wire(with_enhancement_byte(0x0B), EnhancementSwitch::kBit0);
  EXPECT_TRUE(bit0.on);
  EXPECT_EQ(bit0.level, 5);
  EXPECT_FALSE(enhancement_fits(with_enhancement_byte(0x0B), EnhancementSwitch::kBit7));  // 11
  EXPECT_FALSE(enhancement_fits(with_enhancement_byte(0x85), EnhancementSwitch::kLevel));  // 133
  EXPECT_TRUE(enhancement_fits(with_enhancement_byte(0x85), EnhancementSwitch::kBit7));
  const Enhancement off =
      enhancement_from_wire(with_enhancement_byte(0x00), EnhancementSwitch::kBit7);
  EXPECT_FALSE(off.on);
  for (EnhancementSwitch r :
       {EnhancementSwitch::kBit7, EnhancementSwitch::kBit0, EnhancementSwitch::kLevel}) {
    ThermalSettingsAck m;
    enhancement_to_wire(m, 7, r);
    EXPECT_EQ(enhancement_from_wire(m, r).level, 7);
    EXPECT_TRUE(enhancement_from_wire(m, r).on);
  }
}

TEST(ConventionReadings, ThermalZoomCodes) {
  EXPECT_EQ(thermal_zoom_from_wire(0, ThermalZoomCode::kZeroBased), 1);
  EXPECT_EQ(thermal_zoom_from_wire(2, ThermalZoomCode::kRatio), 2);
  EXPECT_FALSE(thermal_zoom_fits(0, ThermalZoomCode::kRatio));
  EXPECT_FALSE(thermal_zoom_fits(8, ThermalZoomCode::kZeroBased));
  EXPECT_EQ(thermal_zoom_to_wire(4, ThermalZoomCode::kZeroBased), 3);
}

TEST(ConventionReadings, GpsRequestInLocalTime) {
  // 10:00:00.000 local in UTC+2 (tz_minuteswest -120) is 08:00 UTC = 28 800 000 ms.
  CameraGpsRequest r;
  r.hour = 10;
  EXPECT_EQ(gps_request_utc_ms_of_day(r, GpsRequestTime::kLocal, -120), 28800000);
  EXPECT_EQ(gps_request_utc_ms_of_day(r, GpsRequestTime::kUtc, -120), 36000000);
  // 01:00 local in UTC+2 is 23:00 UTC the day before.
  r.hour = 1;
  EXPECT_EQ(gps_request_utc_ms_of_day(r, GpsRequestTime::kLocal, -120), 23 * 3600000);
  CameraGpsRequest back;
  gps_request_time_to_wire(back, 23 * 3600000 + 1500, GpsRequestTime::kLocal, -120);
  EXPECT_EQ(back.hour, 1);
  EXPECT_EQ(back.second, 1);
  EXPECT_EQ(back.millisecond, 500);
}

TEST(ConventionReadings, GpsAnswerDataInItsOwnByteOrder) {
  // 3.2.4.15 ACK: code (2), hour, minute, second, millisecond (2), ... Code OK, 00:00:00.500:
  // 500 = 0x01F4.
  CameraGpsAck a;
  a.millisecond = 500;
  CodecOptions o;  // ack_byte_order big
  Result<Payload> like_ack = encode_gps_answer(a, o);
  ASSERT_TRUE(like_ack.is_ok());
  EXPECT_TRUE(same_bytes({like_ack->bytes.begin(), like_ack->bytes.begin() + 7},
                         {0x00, 0x00, 0, 0, 0, 0x01, 0xF4}));
  o.conventions.gps_answer_byte_order = GpsAnswerByteOrder::kLittle;
  a.code = ResponseCode::kFailure;  // 0x0001, still big
  Result<Payload> little = encode_gps_answer(a, o);
  ASSERT_TRUE(little.is_ok());
  EXPECT_TRUE(same_bytes({little->bytes.begin(), little->bytes.begin() + 7},
                         {0x00, 0x01, 0, 0, 0, 0xF4, 0x01}));
  Result<CameraGpsAck> back = decode_gps_answer(little->data(), little->size, o);
  ASSERT_TRUE(back.is_ok()) << back.error();
  EXPECT_EQ(back->code, ResponseCode::kFailure);
  EXPECT_EQ(back->millisecond, 500);
}

TEST(ConventionReadings, LaserTargetZerosAndFocus) {
  TargetGpsAck zeros;
  EXPECT_TRUE(laser_target_no_return(zeros, LaserTargetZeros::kNoReturn));
  EXPECT_FALSE(laser_target_no_return(zeros, LaserTargetZeros::kPosition));
  zeros.latitude_deg = 1e-7;
  EXPECT_FALSE(laser_target_no_return(zeros, LaserTargetZeros::kNoReturn));
  EXPECT_EQ(manual_focus_command(true, FocusPlus::kNear), FocusCommand::kFinePlus);
  EXPECT_EQ(manual_focus_command(true, FocusPlus::kFar), FocusCommand::kFineMinus);
  EXPECT_EQ(manual_focus_command(false, FocusPlus::kFar), FocusCommand::kFinePlus);
  EXPECT_TRUE(manual_focus_is_nearer(FocusCommand::kFineMinus, FocusPlus::kFar));
}

}  // namespace
}  // namespace k40t::protocol
