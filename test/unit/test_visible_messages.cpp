// Visible-light camera messages (document sections 3.2.1.3 and 3.2.3; 3.2.3.6 and 3.2.3.7 from
// the Chinese original). The values below are the ones the comments of
// test/data/golden/thermal_visible.txt spell out for each hand-written frame.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "golden_checks.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "message_checks.h"
#include "message_text.h"
#include "request_with.h"

namespace k40t::protocol {
namespace {

using namespace testing;  // the test helpers included above

const char kGolden[] = "thermal_visible.txt";

// ---- golden frames ------------------------------------------------------------------------

TEST(VisibleGolden, StatusReport) {  // 3.2.1.3
  VisibleStatus m = message_from_text<VisibleStatus>(
      "zooming=true focal_length_mm=24.5 zoom_x=12.5 iso_db=12.0 shutter_us=1000 "
      "ae_lock_on=false focusing=false precise_shot_focal_length_mm=24.5");
  m.ev = ExposureValue::kPlus1;  // by hand: the labels "+1" and "-1" are both "1" as text
  expect_matches_golden(m, kGolden);
}

VisibleSettingsAck golden_settings() {  // 3.2.3.1, the comment of the golden frame
  return message_from_text<VisibleSettingsAck>(
      "photo_resolution=8000x6000 video_resolution=3840x2160 video_bitrate_code=2 "
      "white_balance=daylight ev=0 iso=iso_400 shutter=1/6000 zoom_fine_tune=50 "
      "backlight_on=true backlight_value=40 strong_light_on=false strong_light_value=0 "
      "ae_lock_on=true watermark_on=true anti_flicker=50hz metering=average");
}

TEST(VisibleGolden, ReadSettingsRequestAndAck) {  // 3.2.3.1
  expect_matches_golden(VisibleReadSettingsRequest{}, kGolden);
  expect_matches_golden(golden_settings(), kGolden);
}

TEST(VisibleGolden, SettingRequests) {  // 3.2.3.2 .. 3.2.3.12
  expect_matches_golden(
      request_with(&VisibleVideoResolutionRequest::video_resolution, VideoResolution::k4000x3000),
      kGolden);
  expect_matches_golden(
      request_with(&VisiblePhotoResolutionRequest::photo_resolution, PhotoResolution::k4000x3000),
      kGolden);
  expect_matches_golden(request_with(&VisibleIsoRequest::iso, Iso::k6400), kGolden);
  expect_matches_golden(request_with(&VisibleShutterRequest::shutter, Shutter::k1_8000), kGolden);
  expect_matches_golden(request_with(&VisibleEvRequest::ev, ExposureValue::kMinus2), kGolden);
  expect_matches_golden(
      request_with(&VisibleWhiteBalanceRequest::white_balance, WhiteBalance::kCloudy), kGolden);
  expect_matches_golden(request_with(&VisibleAntiFlickerRequest::anti_flicker, AntiFlicker::k60Hz),
                        kGolden);

  VisibleStrongLightRequest strong_light;
  strong_light.strong_light_on = true;
  strong_light.strong_light_value = 70;
  expect_matches_golden(strong_light, kGolden);

  VisibleBacklightRequest backlight;
  backlight.backlight_on = false;
  backlight.backlight_value = 0;
  expect_matches_golden(backlight, kGolden);
  expect_matches_golden(request_with(&VisibleAeLockRequest::ae_lock_on, true), kGolden);
  expect_matches_golden(
      request_with(&VisibleMeteringRequest::metering, MeteringMode::kCenterWeighted), kGolden);
}

// ---- wire details -------------------------------------------------------------------------

TEST(VisibleRequests, EverySettingStartsWithTheStartSettingByte) {
  expect_decode_error<VisibleIsoRequest>({0x01, 0x03},
                                         "byte 1 must be 0x00 (start setting), got 0x01");
  expect_decode_error<VisibleWhiteBalanceRequest>({0x05, 0x01, 0, 0}, "start setting");
  expect_decode_error<VisibleStrongLightRequest>({0x01, 0x01, 0x10}, "start setting");
  expect_decode_error<VisibleAeLockRequest>({0xFF, 0x01}, "start setting");
  expect_decode_error<VisibleReadSettingsRequest>({0x00, 0x00}, "byte 1 must be 0x01");
}

TEST(VisibleRequests, OnOffSwitchesAreOneAndTwo) {  // 3.2.3.9 .. 3.2.3.11
  expect_decode_error<VisibleAeLockRequest>({0x00, 0x00},
                                            "'ae_lock_on' must be 0x01 (on) or 0x02 (off)");
  expect_decode_error<VisibleBacklightRequest>({0x00, 0x03, 0x10}, "'backlight_on'");
  expect_decode_error<VisibleStrongLightRequest>({0x00, 0x00, 0x10}, "'strong_light_on'");
}

TEST(VisibleRequests, WhiteBalanceReservedBitsAreIgnoredOnReceive) {  // 3.2.3.7 bits 7..4
  const std::vector<uint8_t> payload = {0x00, 0xF3, 0x00, 0x00};
  auto decoded = decode_payload<VisibleWhiteBalanceRequest>(payload.data(), payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(decoded->white_balance, WhiteBalance::kFluorescent);
}

TEST(VisibleSettingsAck, BareRefusalAndTruncatedSettings) {
  auto refusal = decode_payload<VisibleSettingsAck>(std::vector<uint8_t>{0x02, 0x04}.data(), 2);
  ASSERT_TRUE(refusal) << refusal.error();
  EXPECT_EQ(refusal->code, ResponseCode::kNoSdCard);
  expect_decode_error<VisibleSettingsAck>({0x00, 0x00}, "need 15 bytes, got 0");
  expect_decode_error<VisibleSettingsAck>({0x00, 0x00, 0x14, 0x26}, "need 15 bytes, got 2");
}

TEST(VisibleSettingsAck, ResponseCodeFollowsTheAckByteOrder) {  // docs/protocol/decisions.md#a2
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  VisibleSettingsAck ack = golden_settings();
  ack.code = ResponseCode::kRecording;  // 0x0201: the two byte orders differ
  auto payload = encode_payload(ack, little);
  ASSERT_TRUE(payload);
  EXPECT_EQ(payload->bytes[0], 0x01);
  EXPECT_EQ(payload->bytes[1], 0x02);
  auto big = encode_payload(ack);
  ASSERT_TRUE(big);
  EXPECT_EQ(big->bytes[0], 0x02);
  EXPECT_EQ(big->bytes[1], 0x01);
}

TEST(VisibleSettingsAck, UnpacksTheSwitchBitsAndNibbles) {  // 3.2.3.1 bytes 13, 14, 16
  std::vector<uint8_t> payload = {0x00, 0x00, 0x15, 0x08, 0x00, 0xA1, 0x00, 0x00, 0x00,
                                  0x00, 0x00, 0x64, 0x64, 0xE4, 0x02, 0x40, 0x02};
  auto decoded = decode_payload<VisibleSettingsAck>(payload.data(), payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(decoded->white_balance, WhiteBalance::kAuto) << "bits 7..4 of byte 6 are reserved";
  EXPECT_FALSE(decoded->backlight_on);
  EXPECT_EQ(decoded->backlight_value, 100);
  EXPECT_TRUE(decoded->strong_light_on);
  EXPECT_EQ(decoded->strong_light_value, 100);
  EXPECT_FALSE(decoded->ae_lock_on);
  EXPECT_FALSE(decoded->watermark_on);
  EXPECT_EQ(decoded->anti_flicker, AntiFlicker::kAuto);
  EXPECT_EQ(decoded->metering, MeteringMode::kArea);
}

TEST(VisibleStatus, ReservedByteIsOptionalOnReceive) {
  std::vector<uint8_t> payload(14, 0);
  payload[10] = 0x01;  // AE lock on
  auto decoded = decode_payload<VisibleStatus>(payload.data(), payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_TRUE(decoded->ae_lock_on);
  expect_decode_error<VisibleStatus>(std::vector<uint8_t>(13, 0), "need 14");
}

// A report is read as the pod sends it: an AE-lock byte other than 0x01 (on) reads as off, where
// a request with such a switch byte is refused (OnOffSwitchesAreOneAndTwo).
TEST(VisibleStatus, AeLockOtherThanOneReadsAsOff) {  // 3.2.1.3 byte 11
  for (const uint8_t code : {uint8_t{0x00}, uint8_t{0x02}, uint8_t{0x03}}) {
    std::vector<uint8_t> payload(15, 0);
    payload[10] = code;
    auto decoded = decode_payload<VisibleStatus>(payload.data(), payload.size());
    ASSERT_TRUE(decoded) << decoded.error();
    EXPECT_FALSE(decoded->ae_lock_on) << int{code};
  }
}

TEST(VisibleBitrate, TableOfSection3231Byte5) {
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(0, VideoResolution::k1920x1080, false), 6);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(3, VideoResolution::k1920x1080, true), 6);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(1, VideoResolution::k3840x2160, false), 40);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(2, VideoResolution::k3840x2160, true), 25);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(3, VideoResolution::k4000x3000, false), 80);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(2, VideoResolution::k4000x3000, true), 35);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(4, VideoResolution::k1920x1080, true), 0);
  EXPECT_DOUBLE_EQ(video_bitrate_mbps(0, static_cast<VideoResolution>(0x09), true), 0);
}

// ---- ranges ---------------------------------------------------------------------------------

TEST(VisibleRanges, EveryValidatedFieldIsNamedInItsError) {
  const auto status = golden_message<VisibleStatus>(kGolden);
  expect_range_error(status, "focal_length_mm", [](auto& m) { m.focal_length_mm = 655.36; });
  expect_range_error(status, "zoom_x", [](auto& m) { m.zoom_x = -0.1; });
  expect_range_error(status, "ev", [](auto& m) { m.ev = static_cast<ExposureValue>(0x11); });
  expect_range_error(status, "iso_db", [](auto& m) { m.iso_db = 6553.6; });
  expect_range_error(status, "precise_shot_focal_length_mm",
                     [](auto& m) { m.precise_shot_focal_length_mm = -1; });

  const VisibleSettingsAck ack = golden_settings();
  expect_range_error(ack, "photo_resolution",
                     [](auto& m) { m.photo_resolution = static_cast<PhotoResolution>(0x17); });
  expect_range_error(ack, "video_resolution",
                     [](auto& m) { m.video_resolution = static_cast<VideoResolution>(0x00); });
  expect_range_error(ack, "video_bitrate_code", [](auto& m) { m.video_bitrate_code = 4; });
  expect_range_error(ack, "white_balance",
                     [](auto& m) { m.white_balance = static_cast<WhiteBalance>(0); });
  expect_range_error(ack, "ev", [](auto& m) { m.ev = static_cast<ExposureValue>(0x01); });
  expect_range_error(ack, "iso", [](auto& m) { m.iso = static_cast<Iso>(8); });
  expect_range_error(ack, "shutter", [](auto& m) { m.shutter = static_cast<Shutter>(0x0F); });
  expect_range_error(ack, "zoom_fine_tune", [](auto& m) { m.zoom_fine_tune = 101; });
  expect_range_error(ack, "backlight_value", [](auto& m) { m.backlight_value = 101; });
  expect_range_error(ack, "strong_light_value", [](auto& m) { m.strong_light_value = 127; });
  expect_range_error(ack, "anti_flicker",
                     [](auto& m) { m.anti_flicker = static_cast<AntiFlicker>(5); });
  expect_range_error(ack, "metering", [](auto& m) { m.metering = static_cast<MeteringMode>(0); });

  expect_range_error(VisibleVideoResolutionRequest{}, "video_resolution",
                     [](auto& m) { m.video_resolution = static_cast<VideoResolution>(0x27); });
  expect_range_error(VisiblePhotoResolutionRequest{}, "photo_resolution",
                     [](auto& m) { m.photo_resolution = static_cast<PhotoResolution>(0x13); });
  expect_range_error(VisibleIsoRequest{}, "iso", [](auto& m) { m.iso = static_cast<Iso>(8); });
  expect_range_error(VisibleShutterRequest{}, "shutter",
                     [](auto& m) { m.shutter = static_cast<Shutter>(0x0F); });
  expect_range_error(VisibleEvRequest{}, "ev",
                     [](auto& m) { m.ev = static_cast<ExposureValue>(0x16 + 1); });
  expect_range_error(VisibleWhiteBalanceRequest{}, "white_balance",
                     [](auto& m) { m.white_balance = static_cast<WhiteBalance>(9); });
  expect_range_error(VisibleAntiFlickerRequest{}, "anti_flicker",
                     [](auto& m) { m.anti_flicker = static_cast<AntiFlicker>(0); });
  expect_range_error(VisibleStrongLightRequest{}, "strong_light_value",
                     [](auto& m) { m.strong_light_value = 101; });
  expect_range_error(VisibleBacklightRequest{}, "backlight_value",
                     [](auto& m) { m.backlight_value = 101; });
  expect_range_error(VisibleMeteringRequest{}, "metering",
                     [](auto& m) { m.metering = static_cast<MeteringMode>(4); });
}

TEST(VisibleRanges, PhotoResolution5160x3870IsReportedButNotSettable) {  // 3.2.3.1 vs 3.2.3.3
  VisiblePhotoResolutionRequest photo;
  photo.photo_resolution = PhotoResolution::k5160x3870;
  const auto refused = encode_payload(photo);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("'photo_resolution'"), std::string::npos) << refused.error();
  EXPECT_NE(refused.error().find("20 (8000x6000), 21 (4000x3000)"), std::string::npos)
      << refused.error();
  VisibleSettingsAck ack = golden_settings();
  ack.photo_resolution = PhotoResolution::k5160x3870;
  EXPECT_TRUE(ack.validate()) << ack.validate().message();
}

// ---- enums ----------------------------------------------------------------------------------

TEST(VisibleEnums, DefineExactlyTheDocumentsCodes) {
  EXPECT_EQ(defined_codes<VideoResolution>(), (std::set<int>{0x08, 0x26, 0x36}));
  EXPECT_EQ(defined_codes<PhotoResolution>(), (std::set<int>{0x14, 0x15, 0x16}));
  EXPECT_EQ(defined_codes<Iso>(), (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  std::set<int> shutter_codes;
  for (int code = 0; code <= 0x0E; ++code) shutter_codes.insert(code);
  EXPECT_EQ(defined_codes<Shutter>(), shutter_codes);
  EXPECT_EQ(defined_codes<ExposureValue>(), (std::set<int>{0x00, 0x0A, 0x10, 0x16, 0x1C, 0x23}));
  EXPECT_EQ(defined_codes<WhiteBalance>(), (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(defined_codes<AntiFlicker>(), (std::set<int>{1, 2, 3, 4}));
  EXPECT_EQ(defined_codes<MeteringMode>(), (std::set<int>{1, 2, 3}));
}

TEST(VisibleEnums, NamesOfTheDocument) {
  EXPECT_STREQ(to_string(Shutter::k1_5000), "1/5000");  // docs/protocol/decisions.md#a7
  EXPECT_STREQ(to_string(Shutter::k1_6000), "1/6000");
  EXPECT_STREQ(to_string(Shutter::k1_8000), "1/8000");
  EXPECT_STREQ(to_string(Shutter::kAuto), "auto");
  EXPECT_STREQ(to_string(ExposureValue::kPlus2), "+2");
  EXPECT_STREQ(to_string(ExposureValue::kZero), "0");
  EXPECT_STREQ(to_string(ExposureValue::kMinus2), "-2");
  EXPECT_STREQ(to_string(Iso::k6400), "ISO 6400");
  EXPECT_STREQ(to_string(WhiteBalance::kWarmFluorescent), "warm_fluorescent");
  EXPECT_STREQ(to_string(WhiteBalance::kDark), "dark");
  EXPECT_STREQ(to_string(AntiFlicker::k50Hz), "50hz");
  EXPECT_STREQ(to_string(MeteringMode::kCenterWeighted), "center");
  EXPECT_STREQ(to_string(VideoResolution::k3840x2160), "3840x2160");
  EXPECT_STREQ(to_string(PhotoResolution::k5160x3870), "5160x3870");
}

}  // namespace
}  // namespace k40t::protocol
