// Thermal camera messages (document sections 3.2.1.2 and 3.2.2). The values below are the ones
// the comments of test/data/golden/thermal_visible.txt spell out for each hand-written frame.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "golden_checks.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "message_checks.h"
#include "message_text.h"
#include "request_with.h"

namespace k40t::protocol {
namespace {

using namespace testing;  // the test helpers included above

const char kGolden[] = "thermal_visible.txt";

// ---- golden frames ------------------------------------------------------------------------

TEST(ThermalGolden, StatusReport) {  // 3.2.1.2
  expect_matches_golden(
      message_from_text<ThermalStatus>(
          "max_degC=52.3 min_degC=-12.5 center_degC=20.0 point_degC=36.6 average_degC=18.4 "
          "max_x_px=400 max_y_px=300 min_x_px=1200 min_y_px=1000 center_x_px=800 "
          "center_y_px=528 point_x_px=960 point_y_px=544 high_alarm=true threshold_alarm=true"),
      kGolden);
}

ThermalSettingsAck golden_settings() {  // 3.2.2.1, the comment of the golden frame
  return message_from_text<ThermalSettingsAck>(
      "palette=iron_red measurement_on=true measurement_type=area core_type=radiometric "
      "zoom_x=2 sharpness=50 gain_mode=auto brightness=60 contrast=70 denoise_on=true "
      "denoise_level=30 enhancement_on=true enhancement_level=3 high_alarm_on=true "
      "high_alarm_degC=120.0 difference_alarm_on=true difference_alarm_degC=15.5 "
      "threshold_alarm_on=true threshold_reference_degC=-20.0 threshold_float_degC=5.0");
}

TEST(ThermalGolden, ReadSettingsRequestAndAck) {  // 3.2.2.1
  expect_matches_golden(ThermalReadSettingsRequest{}, kGolden);
  expect_matches_golden(golden_settings(), kGolden);
}

TEST(ThermalGolden, BareRefusalAckKeepsDefaults) {  // 3.2.2.1 + 3.3: code only
  ThermalSettingsAck refusal;
  refusal.code = ResponseCode::kBusy;
  expect_matches_golden(refusal, kGolden, 1);
}

TEST(ThermalGolden, SettingRequests) {  // 3.2.2.2 .. 3.2.2.15
  expect_matches_golden(request_with(&ThermalZoomRequest::zoom_x, 4), kGolden);
  expect_matches_golden(request_with(&ThermalPaletteRequest::palette, Palette::kCyanRed), kGolden);
  expect_matches_golden(request_with(&ThermalMeasurementRequest::measurement_on, false), kGolden);
  expect_matches_golden(request_with(&ThermalSharpnessRequest::sharpness, 75), kGolden);
  expect_matches_golden(request_with(&ThermalBrightnessRequest::brightness, 100), kGolden);
  expect_matches_golden(request_with(&ThermalContrastRequest::contrast, 40), kGolden);

  ThermalDenoiseRequest denoise;
  denoise.denoise_on = true;
  denoise.denoise_level = 80;
  expect_matches_golden(denoise, kGolden);
  expect_matches_golden(request_with(&ThermalEnhancementRequest::enhancement_level, 10), kGolden);

  ThermalSpotRequest spot;
  spot.x_px = 960;
  spot.y_px = 544;
  expect_matches_golden(spot, kGolden);

  ThermalAreaRequest area;
  area.width_px = 200;
  area.height_px = 100;
  area.center_x_px = 800;
  area.center_y_px = 500;
  expect_matches_golden(area, kGolden);
  expect_matches_golden(request_with(&ThermalGainModeRequest::gain_mode, ThermalGainMode::kLow),
                        kGolden);

  ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = true;
  alarms.high_alarm_degC = 80.0;
  alarms.low_alarm_on = true;
  alarms.low_alarm_degC = -10.5;
  alarms.difference_alarm_on = false;
  expect_matches_golden(alarms, kGolden);
  expect_matches_golden(request_with(&ThermalOverlayRequest::overlay_on, true), kGolden);

  ThermalThresholdAlarmRequest threshold;
  threshold.threshold_alarm_on = true;
  threshold.threshold_reference_degC = 25.0;
  threshold.threshold_float_degC = 3.5;
  expect_matches_golden(threshold, kGolden);
}

// ---- wire details -------------------------------------------------------------------------

TEST(ThermalSettingsAck,
     LittleEndianOptionReadsTheSameBytesSwapped) {  // docs/protocol/decisions.md#a2
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  auto payload = encode_payload(golden_settings(), little);
  ASSERT_TRUE(payload);
  // code 00 00; high alarm 1200 = 0x04B0 low byte first at bytes 11-12
  EXPECT_EQ(payload->bytes[10], 0xB0);
  EXPECT_EQ(payload->bytes[11], 0x04);
  auto decoded = decode_payload<ThermalSettingsAck>(payload->data(), payload->size, little);
  ASSERT_TRUE(decoded);
  EXPECT_DOUBLE_EQ(decoded->high_alarm_degC, 120.0);
  auto crossed = decode_payload<ThermalSettingsAck>(payload->data(), payload->size);  // big
  ASSERT_TRUE(crossed);
  EXPECT_DOUBLE_EQ(crossed->high_alarm_degC, static_cast<int16_t>(0xB004) / 10.0);
}

TEST(ThermalSettingsAck, AcceptsSettingsWithoutTheTrailingReservedBytes) {
  auto payload = encode_payload(golden_settings());
  ASSERT_TRUE(payload);
  auto decoded = decode_payload<ThermalSettingsAck>(payload->data(), payload->size - 2);
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_DOUBLE_EQ(decoded->threshold_float_degC, 5.0);
}

TEST(ThermalSettingsAck, OkWithTruncatedSettingsIsAnError) {
  expect_decode_error<ThermalSettingsAck>({0x00, 0x00}, "need 19 bytes, got 0");
  expect_decode_error<ThermalSettingsAck>({0x00, 0x01, 0x05, 0x16}, "need 19 bytes, got 2");
  expect_decode_error<ThermalSettingsAck>({0x00}, "too short");
}

TEST(ThermalSettingsAck, UnpacksEveryBitOfByte4) {  // 3.2.2.1 byte 4
  std::vector<uint8_t> payload(23, 0);
  payload[2] = 0x01;
  payload[3] = 0x41;  // 0b01000001: measurement off, point, sighting core, zoom 8
  auto decoded = decode_payload<ThermalSettingsAck>(payload.data(), payload.size());
  ASSERT_TRUE(decoded);
  EXPECT_FALSE(decoded->measurement_on);
  EXPECT_EQ(decoded->measurement_type, ThermalMeasurementType::kPoint);
  EXPECT_EQ(decoded->core_type, ThermalCoreType::kSighting);
  EXPECT_EQ(decoded->zoom_x, 8);
  // alarm limit bytes 00 00 are 0.0 degC and on: only -2732 means off
  EXPECT_TRUE(decoded->high_alarm_on);
  EXPECT_DOUBLE_EQ(decoded->high_alarm_degC, 0.0);
}

TEST(ThermalAlarmsRequest, AcceptsSevenBytesOnReceive) {  // docs/protocol/decisions.md#a9
  const std::vector<uint8_t> seven = {0x54, 0xF5, 0x54, 0xF5, 0x64, 0x00, 0x00};
  auto decoded = decode_payload<ThermalAlarmsRequest>(seven.data(), seven.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_FALSE(decoded->high_alarm_on);
  EXPECT_FALSE(decoded->low_alarm_on);
  EXPECT_TRUE(decoded->difference_alarm_on);
  EXPECT_DOUBLE_EQ(decoded->difference_alarm_degC, 10.0);
  expect_decode_error<ThermalAlarmsRequest>({0x54, 0xF5, 0x54, 0xF5, 0x64, 0x00}, "need 7");
}

TEST(ThermalAlarmsRequest, OffSendsMinus2732WhateverTheValue) {  // 3.2.2.13
  ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = false;
  alarms.high_alarm_degC = 9999;  // ignored while off, not validated
  auto payload = encode_payload(alarms);
  ASSERT_TRUE(payload) << payload.error();
  const std::vector<uint8_t> off = {0x54, 0xF5, 0x54, 0xF5, 0x54, 0xF5, 0x00, 0x00};
  EXPECT_EQ(std::vector<uint8_t>(payload->data(), payload->data() + payload->size), off);
}

TEST(ThermalRequests, DecodeRefusesBytesTheStructCannotHold) {
  expect_decode_error<ThermalReadSettingsRequest>({0x02, 0x00}, "byte 1 must be 0x01");
  expect_decode_error<ThermalMeasurementRequest>({0x02, 0x00}, "'measurement_on'");
  expect_decode_error<ThermalOverlayRequest>({0x07, 0x00}, "'overlay_on'");
  expect_decode_error<ThermalDenoiseRequest>({0x02, 0x10, 0x00}, "'denoise_on'");
  expect_decode_error<ThermalThresholdAlarmRequest>({0x05, 0, 0, 0, 0, 0}, "'threshold_alarm_on'");
}

TEST(ThermalRequests, DecodeReportsOutOfRangeValuesForValidateToRefuse) {
  // What arrives is reported as it is; the simulator validates and answers with a NACK.
  auto zoom = decode_payload<ThermalZoomRequest>(std::vector<uint8_t>{0x09, 0x00}.data(), 2);
  ASSERT_TRUE(zoom);
  EXPECT_EQ(zoom->zoom_x, 9);
  EXPECT_FALSE(zoom->validate());
}

TEST(ThermalStatus, AnyNonZeroFlagIsAnAlarmAndReservedBytesAreOptional) {
  std::vector<uint8_t> payload(30, 0);
  payload[26] = 0x02;
  auto decoded = decode_payload<ThermalStatus>(payload.data(), payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_TRUE(decoded->high_alarm);
  EXPECT_FALSE(decoded->low_alarm);
  expect_decode_error<ThermalStatus>(std::vector<uint8_t>(29, 0), "need 30");
}

// ---- ranges ---------------------------------------------------------------------------------

TEST(ThermalRanges, EveryValidatedFieldIsNamedInItsError) {
  const auto status = golden_message<ThermalStatus>(kGolden);
  expect_range_error(status, "max_degC", [](auto& m) { m.max_degC = 3276.8; });
  expect_range_error(status, "min_degC", [](auto& m) { m.min_degC = -3276.9; });
  expect_range_error(status, "center_degC", [](auto& m) { m.center_degC = 4000; });
  expect_range_error(status, "point_degC", [](auto& m) { m.point_degC = -4000; });
  expect_range_error(status, "average_degC", [](auto& m) { m.average_degC = NAN; });

  const ThermalSettingsAck ack = golden_settings();
  expect_range_error(ack, "palette", [](auto& m) { m.palette = static_cast<Palette>(21); });
  expect_range_error(ack, "measurement_type",
                     [](auto& m) { m.measurement_type = static_cast<ThermalMeasurementType>(2); });
  expect_range_error(ack, "core_type",
                     [](auto& m) { m.core_type = static_cast<ThermalCoreType>(2); });
  expect_range_error(ack, "zoom_x", [](auto& m) { m.zoom_x = 0; });
  expect_range_error(ack, "sharpness", [](auto& m) { m.sharpness = 101; });
  expect_range_error(ack, "gain_mode",
                     [](auto& m) { m.gain_mode = static_cast<ThermalGainMode>(3); });
  expect_range_error(ack, "brightness", [](auto& m) { m.brightness = 101; });
  expect_range_error(ack, "contrast", [](auto& m) { m.contrast = 101; });
  expect_range_error(ack, "denoise_level", [](auto& m) { m.denoise_level = 101; });
  expect_range_error(ack, "enhancement_level", [](auto& m) { m.enhancement_level = 11; });
  expect_range_error(ack, "high_alarm_degC", [](auto& m) { m.high_alarm_degC = 500.1; });
  expect_range_error(ack, "low_alarm_degC", [](auto& m) {
    m.low_alarm_on = true;
    m.low_alarm_degC = -100.1;
  });
  expect_range_error(ack, "difference_alarm_degC", [](auto& m) { m.difference_alarm_degC = 0.0; });
  expect_range_error(ack, "threshold_reference_degC",
                     [](auto& m) { m.threshold_reference_degC = 50.1; });
  expect_range_error(ack, "threshold_float_degC", [](auto& m) { m.threshold_float_degC = -0.1; });

  expect_range_error(ThermalZoomRequest{}, "zoom_x", [](auto& m) { m.zoom_x = 9; });
  expect_range_error(ThermalZoomRequest{}, "zoom_x", [](auto& m) { m.zoom_x = 0; });
  expect_range_error(ThermalPaletteRequest{}, "palette",
                     [](auto& m) { m.palette = static_cast<Palette>(0); });
  expect_range_error(ThermalPaletteRequest{}, "palette",
                     [](auto& m) { m.palette = static_cast<Palette>(21); });
  expect_range_error(ThermalSharpnessRequest{}, "sharpness", [](auto& m) { m.sharpness = 101; });
  expect_range_error(ThermalBrightnessRequest{}, "brightness", [](auto& m) { m.brightness = 101; });
  expect_range_error(ThermalContrastRequest{}, "contrast", [](auto& m) { m.contrast = 255; });
  expect_range_error(ThermalDenoiseRequest{}, "denoise_level",
                     [](auto& m) { m.denoise_level = 101; });
  expect_range_error(ThermalEnhancementRequest{}, "enhancement_level",
                     [](auto& m) { m.enhancement_level = 11; });
  expect_range_error(ThermalSpotRequest{}, "x_px", [](auto& m) { m.x_px = 1921; });
  expect_range_error(ThermalSpotRequest{}, "y_px", [](auto& m) { m.y_px = 1089; });
  expect_range_error(ThermalGainModeRequest{}, "gain_mode",
                     [](auto& m) { m.gain_mode = static_cast<ThermalGainMode>(3); });

  const ThermalAlarmsRequest alarms{};
  expect_range_error(alarms, "high_alarm_degC", [](auto& m) {
    m.high_alarm_on = true;
    m.high_alarm_degC = -100.1;
  });
  expect_range_error(alarms, "low_alarm_degC", [](auto& m) {
    m.low_alarm_on = true;
    m.low_alarm_degC = 500.1;
  });
  expect_range_error(alarms, "difference_alarm_degC", [](auto& m) {
    m.difference_alarm_on = true;
    m.difference_alarm_degC = 600.1;
  });

  const ThermalThresholdAlarmRequest threshold{};
  expect_range_error(threshold, "threshold_reference_degC",
                     [](auto& m) { m.threshold_reference_degC = -30.1; });
  expect_range_error(threshold, "threshold_float_degC",
                     [](auto& m) { m.threshold_float_degC = 80.1; });
}

TEST(ThermalRanges, BoundsThemselvesAreAccepted) {
  ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = alarms.low_alarm_on = alarms.difference_alarm_on = true;
  alarms.high_alarm_degC = 500.0;
  alarms.low_alarm_degC = -100.0;
  alarms.difference_alarm_degC = 0.1;
  EXPECT_TRUE(alarms.validate()) << alarms.validate().message();
  alarms.difference_alarm_degC = 600.0;
  EXPECT_TRUE(alarms.validate()) << alarms.validate().message();

  ThermalSpotRequest spot;
  spot.x_px = kThermalPictureWidth;
  spot.y_px = kThermalPictureHeight;
  EXPECT_TRUE(spot.validate());

  ThermalThresholdAlarmRequest threshold;
  threshold.threshold_reference_degC = -30.0;
  threshold.threshold_float_degC = 80.0;
  EXPECT_TRUE(threshold.validate());
  ThermalZoomRequest zoom;
  zoom.zoom_x = 8;
  EXPECT_TRUE(zoom.validate());
}

}  // namespace
}  // namespace k40t::protocol
