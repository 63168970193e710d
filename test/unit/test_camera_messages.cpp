// Round trips, validation and decode edge cases of the common camera family (document sections
// 3.2.1.1, 3.2.1.4, 3.2.4). The byte-exact checks against the document are in
// test_camera_golden.cpp; here every struct is encoded and decoded with values other than its
// defaults, every validated field is pushed out of its range, and the text fields are tried at
// their exact width and one byte over.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "k40t_driver/protocol/messages/camera.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

// ---- samples: every field away from its default ------------------------------------------------
template <class T>
T sample();

template <>
CameraSystemStatus sample() {
  CameraSystemStatus m;
  m.capture_mode = CaptureMode::kVideo;
  m.stream_resolution = ReportedStreamResolution::k720p30;
  m.encoding = VideoEncoding::kH265;
  m.image_mode = ImageMode::kVisibleAlt;
  m.bitrate = StreamBitrate::k12Mbps;
  m.photo_mode = PhotoMode::kBurst;
  m.time_lapse_interval_s = 60;
  m.burst_count = 5;
  m.sd_state = SdCardState::kFull;
  m.sd_total_mb = 655350;
  m.sd_free_mb = 10;
  m.sd_used_mb = 655340;
  return m;
}
template <>
CameraUpgradeStatus sample() {
  return {CameraUpgradeState::kRepairing, 100};
}
template <>
CaptureModeRequest sample() {
  return {CaptureMode::kVideo};
}
template <>
PhotoSettingsRequest sample() {
  return {PhotoMode::kTimeLapse, 60, 5};
}
template <>
TakePhotoRequest sample() {
  TakePhotoRequest m;
  m.lens = PhotoLensMode::kInfraredAndVisible;
  m.action = PhotoAction::kStop;
  m.folder = "a";
  m.name = "b c";
  return m;
}
template <>
RecordRequest sample() {
  RecordRequest m;
  m.lens = RecordLensMode::kInfrared;
  m.action = RecordAction::kStop;
  m.folder = "rec";
  m.name = "clip-01";
  return m;
}
template <>
ZoomRatioRequest sample() {
  return {160.0};
}
template <>
ContinuousZoomRequest sample() {
  return {ZoomCommand::kStepOut};
}
template <>
PreciseReshootRequest sample() {
  return {PhotoLensMode::kInfrared, ReshootResolution::k5664x4248, 1.1, 65535, "f", "n"};
}
template <>
StreamBitrateRequest sample() {
  return {StreamBitrate::k1_5Mbps};
}
template <>
StreamResolutionRequest sample() {
  return {StreamResolution::k1080p30};
}
template <>
StreamEncodingRequest sample() {
  return {VideoEncoding::kH265};
}
template <>
TfCardUpgradeRequest sample() {
  return {};
}
template <>
FormatSdRequest sample() {
  return {};
}
template <>
TimeSyncRequest sample() {
  return {4102444800000, 720, 1};  // 2100-01-01, UTC-12
}
template <>
FactoryResetRequest sample() {
  return {};
}
template <>
SetIpRequest sample() {
  return {IpMode::kDhcp, "10.0.0.255", "255.255.255.252", "10.0.0.1"};
}
template <>
GetIpRequest sample() {
  return {};
}
template <>
GetIpAck sample() {
  return {ResponseCode::kFailure, "172.16.1.2", "255.240.0.0", "0.0.0.0"};
}
template <>
FocusRequest sample() {
  return {FocusCommand::kArea, 0, 0, 1920, 1080};
}
template <>
OsdWatermarkRequest sample() {
  return {true};
}
template <>
ShutdownRequest sample() {
  return {};
}
template <>
CameraVersionRequest sample() {
  return {};
}
template <>
CameraVersionAck sample() {
  return {ResponseCode::kBusy, 255, 0, 9};
}
template <>
ImageModeRequest sample() {
  return {ImageMode::kSplit};
}
template <>
AiRecognitionRequest sample() {
  return {FeatureSwitch::kOff, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 255}};
}
template <>
BoxTrackingRequest sample() {
  return {FeatureSwitch::kOff, 1720, 980, 200, 100};
}
template <>
PhotoStatus sample() {
  return {PhotoLensMode::kInfrared, PhotoState::kSdFormatError, 65535};
}
template <>
RecordStatus sample() {
  return {RecordLensMode::kVisible, RecordState::kSdFormatError, 3600};
}
template <>
ZoomStatus sample() {
  return {ZoomProgress::kZooming};
}
template <>
PreciseReshootStatus sample() {
  return {PhotoLensMode::kInfraredAndVisible, ReshootState::kReshooting};
}
template <>
TfCardUpgradeStatus sample() {
  return {TfUpgradeState::kFailed};
}
template <>
SdFormatStatus sample() {
  return {SdFormatState::kUnavailable};
}
template <>
CameraGpsRequest sample() {
  return {false, 23, 59, 59, 999};
}
template <>
CameraGpsAck sample() {
  return {ResponseCode::kOk, 23,      59,     59,    999,    -179.9999999,
          -89.9999999,       -3276.8, 3276.7, 180.0, -180.0, 90.0};
}
template <>
TargetGpsRequest sample() {
  return {0xFF,
          GpsFixStatus::kPpp,
          18446744073709551615ull,
          180.0,
          90.0,
          -2147483.647,
          2147483.647,
          -180.0,
          180.0,
          -90.0,
          655.35,
          0.0,
          360.0,
          100.0,
          -327.68};
}
template <>
TargetGpsAck sample() {
  return {ResponseCode::kNoSdCard, 0x1F, 1, -0.0000001, 0.0000001, -1.001, 8848.86};
}

// ---- round trips --------------------------------------------------------------------------------
template <class T>
void expect_round_trip(const CodecOptions& options) {
  testing::expect_round_trip(sample<T>(), options);
}

// Every struct of the family's list (camera.h): a new struct without a sample does not compile.
void round_trip_every_struct(const CodecOptions& options) {
  for_each_message(CameraMessages{}, [&](auto* type) {
    expect_round_trip<std::remove_pointer_t<decltype(type)>>(options);
  });
}

TEST(CameraMessages, EveryStructRoundTripsWithBigEndianAcks) {
  round_trip_every_struct({});
}

TEST(CameraMessages, EveryStructRoundTripsWithLittleEndianAcks) {
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  round_trip_every_struct(little);
}

// ---- range errors: each validated field, out of range, is refused by name ---------------------
// Each case starts from sample<T>(), which the round trips above show to be valid, so the error
// must come from the one field changed; the test checks that the error names it.
struct RangeCase {
  const char* field;
  std::function<Result<Payload>()> encode;
};

template <class T>
std::function<Result<Payload>()> with(std::function<void(T&)> mutate) {
  return [mutate] {
    T m = sample<T>();
    mutate(m);
    return encode_payload(m);
  };
}

std::vector<RangeCase> range_cases() {
  const std::string text21(21, 'x');
  const std::string text33(33, 'x');
  const double nan = std::nan("");
  return {
      // 0x000003 and 0x000008
      {"capture_mode", with<CameraSystemStatus>([](auto& m) { m.capture_mode = CaptureMode{2}; })},
      {"stream_resolution", with<CameraSystemStatus>([](auto& m) {
         m.stream_resolution = ReportedStreamResolution{2};
       })},
      {"encoding", with<CameraSystemStatus>([](auto& m) { m.encoding = VideoEncoding{2}; })},
      {"image_mode", with<CameraSystemStatus>([](auto& m) { m.image_mode = ImageMode{1}; })},
      {"bitrate", with<CameraSystemStatus>([](auto& m) { m.bitrate = StreamBitrate{0}; })},
      {"photo_mode", with<CameraSystemStatus>([](auto& m) { m.photo_mode = PhotoMode{3}; })},
      {"time_lapse_interval_s",
       with<CameraSystemStatus>([](auto& m) { m.time_lapse_interval_s = 6; })},
      {"burst_count", with<CameraSystemStatus>([](auto& m) { m.burst_count = 4; })},
      {"sd_state", with<CameraSystemStatus>([](auto& m) { m.sd_state = SdCardState{6}; })},
      {"sd_total_mb", with<CameraSystemStatus>([](auto& m) { m.sd_total_mb = 655360; })},
      {"sd_free_mb", with<CameraSystemStatus>([](auto& m) { m.sd_free_mb = -10; })},
      {"sd_used_mb", with<CameraSystemStatus>([nan](auto& m) { m.sd_used_mb = nan; })},
      {"state", with<CameraUpgradeStatus>([](auto& m) { m.state = CameraUpgradeState{4}; })},
      {"progress_percent", with<CameraUpgradeStatus>([](auto& m) { m.progress_percent = 101; })},
      // capture requests
      {"mode", with<CaptureModeRequest>([](auto& m) { m.mode = CaptureMode{2}; })},
      {"photo_mode", with<PhotoSettingsRequest>([](auto& m) { m.photo_mode = PhotoMode{3}; })},
      {"time_lapse_interval_s",
       with<PhotoSettingsRequest>([](auto& m) { m.time_lapse_interval_s = 0; })},
      {"burst_count", with<PhotoSettingsRequest>([](auto& m) { m.burst_count = 1; })},
      {"lens", with<TakePhotoRequest>([](auto& m) { m.lens = PhotoLensMode{4}; })},
      {"action", with<TakePhotoRequest>([](auto& m) { m.action = PhotoAction{2}; })},
      {"folder", with<TakePhotoRequest>([text21](auto& m) { m.folder = text21; })},
      {"name", with<TakePhotoRequest>([text33](auto& m) { m.name = text33; })},
      {"lens", with<RecordRequest>([](auto& m) { m.lens = RecordLensMode{5}; })},
      {"action", with<RecordRequest>([](auto& m) { m.action = RecordAction{0}; })},
      {"folder", with<RecordRequest>([text21](auto& m) { m.folder = text21; })},
      {"name", with<RecordRequest>([text33](auto& m) { m.name = text33; })},
      {"zoom_x", with<ZoomRatioRequest>([](auto& m) { m.zoom_x = 0.9; })},
      {"zoom_x", with<ZoomRatioRequest>([](auto& m) { m.zoom_x = 160.1; })},
      {"zoom_x", with<ZoomRatioRequest>([nan](auto& m) { m.zoom_x = nan; })},
      {"command", with<ContinuousZoomRequest>([](auto& m) { m.command = ZoomCommand{5}; })},
      {"lens", with<PreciseReshootRequest>([](auto& m) { m.lens = PhotoLensMode{4}; })},
      {"resolution",
       with<PreciseReshootRequest>([](auto& m) { m.resolution = ReshootResolution{0x18}; })},
      {"zoom_x", with<PreciseReshootRequest>([](auto& m) { m.zoom_x = 200; })},
      {"folder", with<PreciseReshootRequest>([text21](auto& m) { m.folder = text21; })},
      {"name", with<PreciseReshootRequest>([text33](auto& m) { m.name = text33; })},
      // stream and image requests
      {"bitrate", with<StreamBitrateRequest>([](auto& m) { m.bitrate = StreamBitrate{7}; })},
      {"resolution",
       with<StreamResolutionRequest>([](auto& m) { m.resolution = StreamResolution{0}; })},
      {"resolution",
       with<StreamResolutionRequest>([](auto& m) { m.resolution = StreamResolution::k720p30; })},
      {"encoding", with<StreamEncodingRequest>([](auto& m) { m.encoding = VideoEncoding{2}; })},
      {"command", with<FocusRequest>([](auto& m) { m.command = FocusCommand{8}; })},
      {"area_left_px", with<FocusRequest>([](auto& m) { m.area_left_px = 1921; })},
      {"area_top_px", with<FocusRequest>([](auto& m) { m.area_top_px = 1081; })},
      {"area_right_px",
       with<FocusRequest>([](auto& m) { m.area_left_px = m.area_right_px = 900; })},
      {"area_bottom_px", with<FocusRequest>([](auto& m) { m.area_bottom_px = 1081; })},
      {"mode", with<ImageModeRequest>([](auto& m) { m.mode = ImageMode{4}; })},
      {"recognition",
       with<AiRecognitionRequest>([](auto& m) { m.recognition = FeatureSwitch{0}; })},
      {"tracking", with<BoxTrackingRequest>([](auto& m) { m.tracking = FeatureSwitch{3}; })},
      {"x_px", with<BoxTrackingRequest>([](auto& m) { m.x_px = 1921; })},
      {"y_px", with<BoxTrackingRequest>([](auto& m) { m.y_px = 1081; })},
      {"width_px",
       with<BoxTrackingRequest>([](auto& m) { m.width_px = 201; })},  // 1720 + 201 > 1920
      {"height_px",
       with<BoxTrackingRequest>([](auto& m) { m.height_px = 101; })},  // 980 + 101 > 1080
      // system requests and the IP ACK
      {"unix_time_ms", with<TimeSyncRequest>([](auto& m) { m.unix_time_ms = -1; })},
      {"tz_minutes_west", with<TimeSyncRequest>([](auto& m) { m.tz_minutes_west = -841; })},
      {"tz_minutes_west", with<TimeSyncRequest>([](auto& m) { m.tz_minutes_west = 721; })},
      {"mode", with<SetIpRequest>([](auto& m) { m.mode = IpMode{2}; })},
      {"address", with<SetIpRequest>([](auto& m) { m.address = "192.168.1"; })},
      {"address", with<SetIpRequest>([](auto& m) { m.address = "192.168.1.256"; })},
      {"address", with<SetIpRequest>([](auto& m) {
         m.mode = IpMode::kStatic;
         m.address = "0.0.0.0";
       })},
      {"netmask", with<SetIpRequest>([](auto& m) { m.netmask = "255.0.255.0"; })},
      {"gateway", with<SetIpRequest>([](auto& m) { m.gateway = "gateway"; })},
      {"address", with<GetIpAck>([](auto& m) { m.address = ""; })},
      {"netmask", with<GetIpAck>([](auto& m) { m.netmask = "1.2.3.4.5"; })},
      {"gateway", with<GetIpAck>([](auto& m) { m.gateway = std::string("1.2.3.4\0", 8); })},
      // status frames
      {"lens", with<PhotoStatus>([](auto& m) { m.lens = PhotoLensMode{4}; })},
      {"state", with<PhotoStatus>([](auto& m) { m.state = PhotoState{12}; })},
      {"lens", with<RecordStatus>([](auto& m) { m.lens = RecordLensMode{5}; })},
      {"state", with<RecordStatus>([](auto& m) { m.state = RecordState{9}; })},
      {"progress", with<ZoomStatus>([](auto& m) { m.progress = ZoomProgress{2}; })},
      {"lens", with<PreciseReshootStatus>([](auto& m) { m.lens = PhotoLensMode{4}; })},
      {"state", with<PreciseReshootStatus>([](auto& m) { m.state = ReshootState{13}; })},
      {"state", with<TfCardUpgradeStatus>([](auto& m) { m.state = TfUpgradeState{3}; })},
      {"state", with<SdFormatStatus>([](auto& m) { m.state = SdFormatState{4}; })},
      // flight controller
      {"hour", with<CameraGpsRequest>([](auto& m) { m.hour = 24; })},
      {"minute", with<CameraGpsRequest>([](auto& m) { m.minute = 60; })},
      {"second", with<CameraGpsRequest>([](auto& m) { m.second = 60; })},
      {"millisecond", with<CameraGpsRequest>([](auto& m) { m.millisecond = 1000; })},
      {"hour", with<CameraGpsAck>([](auto& m) { m.hour = 24; })},
      {"minute", with<CameraGpsAck>([](auto& m) { m.minute = 60; })},
      {"second", with<CameraGpsAck>([](auto& m) { m.second = 60; })},
      {"millisecond", with<CameraGpsAck>([](auto& m) { m.millisecond = 1000; })},
      {"longitude_deg", with<CameraGpsAck>([](auto& m) { m.longitude_deg = 180.1; })},
      {"latitude_deg", with<CameraGpsAck>([](auto& m) { m.latitude_deg = -90.1; })},
      {"relative_height_m", with<CameraGpsAck>([](auto& m) { m.relative_height_m = 3276.8; })},
      {"altitude_m", with<CameraGpsAck>([](auto& m) { m.altitude_m = -3276.9; })},
      {"yaw_deg", with<CameraGpsAck>([](auto& m) { m.yaw_deg = 180.5; })},
      {"roll_deg", with<CameraGpsAck>([](auto& m) { m.roll_deg = -180.5; })},
      {"pitch_deg", with<CameraGpsAck>([](auto& m) { m.pitch_deg = 90.5; })},
      {"mount_mask", with<TargetGpsRequest>([](auto& m) { m.mount_mask = 0; })},
      {"fix", with<TargetGpsRequest>([](auto& m) { m.fix = GpsFixStatus{9}; })},
      {"longitude_deg", with<TargetGpsRequest>([](auto& m) { m.longitude_deg = -180.1; })},
      {"latitude_deg", with<TargetGpsRequest>([](auto& m) { m.latitude_deg = 90.1; })},
      {"relative_height_m", with<TargetGpsRequest>([](auto& m) { m.relative_height_m = 2147484; })},
      {"altitude_m", with<TargetGpsRequest>([](auto& m) { m.altitude_m = -2147484; })},
      {"yaw_deg", with<TargetGpsRequest>([](auto& m) { m.yaw_deg = 270; })},
      {"roll_deg", with<TargetGpsRequest>([](auto& m) { m.roll_deg = 181; })},
      {"pitch_deg", with<TargetGpsRequest>([](auto& m) { m.pitch_deg = -91; })},
      {"airspeed_m_s", with<TargetGpsRequest>([](auto& m) { m.airspeed_m_s = -0.1; })},
      {"ground_speed_m_s", with<TargetGpsRequest>([](auto& m) { m.ground_speed_m_s = 655.36; })},
      {"heading_deg", with<TargetGpsRequest>([](auto& m) { m.heading_deg = 360.01; })},
      {"throttle_percent", with<TargetGpsRequest>([](auto& m) { m.throttle_percent = 100.5; })},
      {"climb_rate_m_s", with<TargetGpsRequest>([](auto& m) { m.climb_rate_m_s = 327.7; })},
      {"longitude_deg", with<TargetGpsAck>([](auto& m) { m.longitude_deg = 181; })},
      {"latitude_deg", with<TargetGpsAck>([](auto& m) { m.latitude_deg = -91; })},
      {"relative_height_m", with<TargetGpsAck>([](auto& m) { m.relative_height_m = 2147484; })},
      {"altitude_m", with<TargetGpsAck>([](auto& m) { m.altitude_m = -2147484; })},
  };
}

TEST(CameraMessages, EveryValidatedFieldIsRefusedOutOfRangeByName) {
  for (const RangeCase& c : range_cases()) {
    const Result<Payload> result = c.encode();
    ASSERT_FALSE(result) << "accepted an out-of-range '" << c.field << "'";
    EXPECT_NE(result.error().find(std::string("'") + c.field + "'"), std::string::npos)
        << "error does not name '" << c.field << "': " << result.error();
  }
}

TEST(CameraMessages, RangeErrorsSayTheAllowedValues) {
  PhotoSettingsRequest photo = sample<PhotoSettingsRequest>();
  photo.burst_count = 4;
  EXPECT_EQ(encode_payload(photo).error(),
            "photo_settings: field 'burst_count' must be one of 3, 5, got 4");

  ImageModeRequest image;
  image.mode = ImageMode{1};
  EXPECT_EQ(encode_payload(image).error(),
            "image_mode: field 'mode' has no code 1; allowed: 0 (infrared), 5 (visible), "
            "6 (visible (code 6)), 7 (split screen)");

  BoxTrackingRequest box = sample<BoxTrackingRequest>();
  box.width_px = 201;
  EXPECT_NE(encode_payload(box).error().find("x_px + width_px <= 1920"), std::string::npos);

  StreamResolutionRequest resolution{StreamResolution::k720p30};
  EXPECT_NE(encode_payload(resolution).error().find("not supported"), std::string::npos);
}

// ---- text fields: exactly the width, and one byte over
// -------------------------------------------
template <class T>
void expect_text_widths() {
  SCOPED_TRACE(T::kName);
  T m = sample<T>();
  m.folder = std::string(kCameraFolderBytes, 'F');
  m.name = std::string(kCameraFileNameBytes, 'N');
  Result<Payload> full = encode_payload(m);
  ASSERT_TRUE(full) << full.error();
  ASSERT_EQ(full->size, T::kSize);
  // Both texts fill their fields completely: no terminator, the name ends the payload.
  const size_t folder_at = T::kSize - kCameraFileNameBytes - kCameraFolderBytes;
  EXPECT_EQ(std::string(full->bytes.begin() + folder_at, full->bytes.begin() + folder_at + 20),
            m.folder);
  EXPECT_EQ(std::string(full->bytes.begin() + folder_at + 20, full->bytes.begin() + T::kSize),
            m.name);
  Result<T> back = decode_payload<T>(full->data(), full->size);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->folder, m.folder);
  EXPECT_EQ(back->name, m.name);

  T long_folder = m;
  long_folder.folder += 'F';
  EXPECT_EQ(encode_payload(long_folder).error(),
            std::string(T::kName) + ": field 'folder' must be at most 20 bytes, got 21");
  T long_name = m;
  long_name.name += 'N';
  EXPECT_EQ(encode_payload(long_name).error(),
            std::string(T::kName) + ": field 'name' must be at most 32 bytes, got 33");
  T with_nul = m;
  with_nul.name = std::string("a\0b", 3);
  EXPECT_NE(encode_payload(with_nul).error().find("'name' must not contain NUL"),
            std::string::npos);
}

TEST(CameraMessages, TextFieldsTakeExactly20And32BytesAndNoMore) {
  expect_text_widths<TakePhotoRequest>();
  expect_text_widths<RecordRequest>();
  expect_text_widths<PreciseReshootRequest>();
}

TEST(CameraMessages, ShortTextsArePaddedWithZeros) {
  TakePhotoRequest m;
  m.folder = "ab";
  Result<Payload> p = encode_payload(m);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->bytes[2], 'a');
  EXPECT_EQ(p->bytes[3], 'b');
  for (size_t i = 4; i < TakePhotoRequest::kSize; ++i) EXPECT_EQ(p->bytes[i], 0) << i;
}

// ---- decoding ----------------------------------------------------------------------------------
TEST(CameraMessages, ShortPayloadsAreRefusedWithTheSizes) {
  const std::vector<uint8_t> bytes(53, 0);
  EXPECT_EQ(decode_payload<TakePhotoRequest>(bytes.data(), bytes.size()).error(),
            "take_photo (0x000302): payload of 53 bytes is too short, need 54");
  EXPECT_FALSE(decode_payload<CameraSystemStatus>(bytes.data(), 14));
  EXPECT_FALSE(decode_payload<TargetGpsRequest>(bytes.data(), 41));
  // A data ACK that is longer than the code but shorter than its data is truncated, not a refusal.
  EXPECT_FALSE(decode_payload<GetIpAck>(bytes.data(), 7));
  EXPECT_FALSE(decode_payload<CameraGpsAck>(bytes.data(), 24));
}

TEST(CameraMessages, TrailingReservedBytesAreOptionalOnReceive) {
  const uint8_t report[15] = {0, 0, 0, 0, 1, 0, 5, 3,
                              0, 1, 0, 1, 0, 0, 0};  // 0x000003 without byte 16
  Result<CameraSystemStatus> status = decode_payload<CameraSystemStatus>(report, sizeof(report));
  ASSERT_TRUE(status) << status.error();
  EXPECT_DOUBLE_EQ(status->sd_total_mb, 10.0);
  const uint8_t photo[4] = {1, 2, 0x10, 0x00};  // 0x020302 without its 3 reserved bytes
  Result<PhotoStatus> frame = decode_payload<PhotoStatus>(photo, sizeof(photo));
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(frame->burst_count, 16);
}

TEST(CameraMessages, UndefinedCodesFromThePodAreReportedNotRefused) {
  const uint8_t payload[7] = {9, 99, 0, 0, 0, 0, 0};
  Result<PhotoStatus> status = decode_payload<PhotoStatus>(payload, sizeof(payload));
  ASSERT_TRUE(status) << status.error();
  EXPECT_EQ(static_cast<int>(status->lens), 9);
  EXPECT_EQ(to_string(status->state), nullptr);
  EXPECT_FALSE(status->validate());  // but the struct would not be sent as it is
}

TEST(CameraMessages, FixedCommandBytesMustBeTheDocumentedCode) {
  const uint8_t zero[2] = {0x00, 0x00};
  Result<FormatSdRequest> format = decode_payload<FormatSdRequest>(zero, 2);
  ASSERT_FALSE(format);
  EXPECT_EQ(format.error(), "format_sd: byte 1 must be 0x01 (the command code), got 0x00");
  const uint8_t start_not_zero[3] = {0x01, 0x7D, 0x00};
  EXPECT_NE(decode_payload<ZoomRatioRequest>(start_not_zero, 3).error().find("start setting"),
            std::string::npos);
  const uint8_t flag_two[3] = {0x02, 0x00, 0x00};
  EXPECT_NE(decode_payload<OsdWatermarkRequest>(flag_two, 3).error().find("'enabled'"),
            std::string::npos);
}

TEST(CameraMessages, GpsRequestReadsAnyNonZeroLensByteAsEnabled) {
  const uint8_t payload[6] = {0x02, 1, 2, 3, 0xE7, 0x03};
  Result<CameraGpsRequest> request = decode_payload<CameraGpsRequest>(payload, 6);
  ASSERT_TRUE(request);
  EXPECT_TRUE(request->lens_enabled);
  EXPECT_EQ(request->millisecond, 999);
}

TEST(CameraMessages, DataAcksMayCarryTheCodeOnly) {
  const uint8_t refusal[2] = {0x02, 0x04};  // 0x0204 no SD card, big-endian
  Result<GetIpAck> ip = decode_payload<GetIpAck>(refusal, 2);
  ASSERT_TRUE(ip);
  EXPECT_EQ(ip->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(ip->address, "0.0.0.0");
  EXPECT_EQ(decode_payload<CameraVersionAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(decode_payload<CameraGpsAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(decode_payload<TargetGpsAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
}

// ---- byte order (docs/protocol/decisions.md#a2, section 2.1)
// ---------------------------------------------------------
CodecOptions little_acks() {
  CodecOptions o;
  o.ack_byte_order = ByteOrder::kLittle;
  return o;
}

TEST(CameraMessages, IpAckOctetsAreBytesWhateverTheAckByteOrder) {
  // Section 3.2.4.17: Byte1-2 response code, then each octet a byte of its own, first octet
  // first. ack_byte_order orders the code only: 192.168.144.64 is C0 A8 90 40 either way.
  const GetIpAck ack{ResponseCode::kFailure, "192.168.144.64", "255.255.255.0", "192.168.144.1"};
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  const std::vector<uint8_t> big_bytes(big->bytes.begin(), big->bytes.begin() + 6);
  const std::vector<uint8_t> little_bytes(little->bytes.begin(), little->bytes.begin() + 6);
  EXPECT_EQ(big_bytes, (std::vector<uint8_t>{0x00, 0x01, 0xC0, 0xA8, 0x90, 0x40}));
  EXPECT_EQ(little_bytes, (std::vector<uint8_t>{0x01, 0x00, 0xC0, 0xA8, 0x90, 0x40}));
  // And read back from a little-endian pod: 00 00 OK, 0A 00 00 07 = 10.0.0.7, not 7.0.0.10.
  const uint8_t wire[14] = {0x00, 0x00, 0x0A, 0x00, 0x00, 0x07, 0xFF,
                            0xFF, 0x00, 0x00, 0x0A, 0x00, 0x00, 0x01};
  Result<GetIpAck> read = decode_payload<GetIpAck>(wire, sizeof(wire), little_acks());
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->address, "10.0.0.7");
  EXPECT_EQ(read->netmask, "255.255.0.0");
  EXPECT_EQ(read->gateway, "10.0.0.1");
}

TEST(CameraMessages, TargetGpsAckDataIsLowByteFirstWhateverTheAckByteOrder) {
  TargetGpsAck ack = sample<TargetGpsAck>();
  ack.code = ResponseCode::kFailure;
  ack.utc_time_ms = 0x0102030405060708ull;
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  EXPECT_EQ(big->bytes[0], 0x00);  // the code follows ack_byte_order
  EXPECT_EQ(big->bytes[1], 0x01);
  EXPECT_EQ(little->bytes[0], 0x01);
  EXPECT_EQ(little->bytes[1], 0x00);
  EXPECT_EQ(big->bytes[3], 0x08);  // UTC ms low byte first in both
  EXPECT_EQ(big->bytes[10], 0x01);
  EXPECT_TRUE(
      std::equal(big->bytes.begin() + 2, big->bytes.begin() + 27, little->bytes.begin() + 2));
}

TEST(CameraMessages, StatusFramesAreLowByteFirstWhateverTheAckByteOrder) {
  const RecordStatus status{RecordLensMode::kDefault, RecordState::kRecording, 0x0102};
  for (const CodecOptions& o : {CodecOptions{}, little_acks()}) {
    Result<Payload> p = encode_payload(status, o);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->bytes[2], 0x02);
    EXPECT_EQ(p->bytes[3], 0x01);
  }
}

TEST(CameraMessages, GpsAckIsAnAckInEveryField) {
  CameraGpsAck ack = sample<CameraGpsAck>();
  ack.millisecond = 0x0102;
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  EXPECT_EQ(big->bytes[5], 0x01);  // millisecond, after code and h/m/s
  EXPECT_EQ(little->bytes[5], 0x02);
}

// ---- code tables -------------------------------------------------------------------------------
template <class E>
int defined_codes() {
  return static_cast<int>(testing::defined_codes<E>().size());
}

TEST(CameraEnums, EachTableHasExactlyTheDocumentsCodes) {
  EXPECT_EQ(defined_codes<CaptureMode>(), 2);
  EXPECT_EQ(defined_codes<ReportedStreamResolution>(), 2);
  EXPECT_EQ(defined_codes<StreamResolution>(), 2);
  EXPECT_EQ(defined_codes<VideoEncoding>(), 2);
  EXPECT_EQ(defined_codes<ImageMode>(), 4);
  EXPECT_EQ(defined_codes<StreamBitrate>(), 6);
  EXPECT_EQ(defined_codes<PhotoMode>(), 3);
  EXPECT_EQ(defined_codes<SdCardState>(), 6);
  EXPECT_EQ(defined_codes<CameraUpgradeState>(), 4);
  EXPECT_EQ(defined_codes<PhotoLensMode>(), 4);
  EXPECT_EQ(defined_codes<RecordLensMode>(), 5);
  EXPECT_EQ(defined_codes<PhotoAction>(), 2);
  EXPECT_EQ(defined_codes<RecordAction>(), 2);
  EXPECT_EQ(defined_codes<ZoomCommand>(), 5);
  EXPECT_EQ(defined_codes<ReshootResolution>(), 4);
  EXPECT_EQ(defined_codes<IpMode>(), 2);
  EXPECT_EQ(defined_codes<FocusCommand>(), 8);
  EXPECT_EQ(defined_codes<FeatureSwitch>(), 2);
  EXPECT_EQ(defined_codes<PhotoState>(), 12);
  EXPECT_EQ(defined_codes<ReshootState>(), 13);
  EXPECT_EQ(defined_codes<RecordState>(), 9);
  EXPECT_EQ(defined_codes<ZoomProgress>(), 2);
  EXPECT_EQ(defined_codes<TfUpgradeState>(), 3);
  EXPECT_EQ(defined_codes<SdFormatState>(), 4);
  EXPECT_EQ(defined_codes<GpsFixStatus>(), 9);
}

TEST(CameraEnums, CodesWhereTheDocumentLeavesGaps) {
  EXPECT_EQ(to_string(ImageMode{4}), nullptr);
  EXPECT_STREQ(to_string(ImageMode{5}), "visible");
  EXPECT_EQ(to_string(StreamResolution{0}), nullptr);               // the request counts from 1 ...
  EXPECT_STREQ(to_string(ReportedStreamResolution{0}), "1080P30");  // ... the report from 0
  EXPECT_EQ(to_string(RecordAction{0}), nullptr);
  EXPECT_EQ(to_string(FeatureSwitch{0}), nullptr);
  EXPECT_EQ(to_string(ReshootResolution{0x13}), nullptr);
  EXPECT_STREQ(to_string(ReshootResolution{0x14}), "8000x6000");
  EXPECT_EQ(to_string(StreamBitrate{0}), nullptr);
}

TEST(CameraEnums, BitrateCodesInMegabitsPerSecond) {
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k1Mbps), 1.0);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k1_5Mbps), 1.5);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k12Mbps), 12.0);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate{7}), 0.0);
}

TEST(CameraMessages, VersionText) {
  EXPECT_EQ((CameraVersionAck{ResponseCode::kOk, 2, 10, 7}).version_text(), "2.10.7");
}

}  // namespace
}  // namespace k40t::protocol
