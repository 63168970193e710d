// Range errors of the common camera family (sections 3.2.1.1, 3.2.1.4, 3.2.4): each validated
// field, out of range, is refused by name, and the error says the allowed values.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "camera_message_samples.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

using camera_samples::sample;

// ---- range errors: each validated field, out of range, is refused by name ---------------------
// Each case starts from sample<T>(), which the round trips of test_camera_messages.cpp show to be
// valid, so the error must come from the one field changed; the test checks that the error names
// it.
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
            "image_mode: field 'mode' has no code 1; allowed: 0 (thermal), 5 (visible), "
            "6 (visible_alt), 7 (split)");

  BoxTrackingRequest box = sample<BoxTrackingRequest>();
  box.width_px = 201;
  EXPECT_NE(encode_payload(box).error().find("x_px + width_px <= 1920"), std::string::npos);

  StreamResolutionRequest resolution;
  resolution.resolution = StreamResolution::k720p30;
  EXPECT_NE(encode_payload(resolution).error().find("not supported"), std::string::npos);
}

}  // namespace
}  // namespace k40t::protocol
