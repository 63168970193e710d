// One sample of each struct of the common camera family (sections 3.2.1.1, 3.2.1.4, 3.2.4) with
// every field away from its default: the values the round-trip, range and byte-order tests of
// test_camera_message*.cpp start from.
#pragma once

#include <cmath>

#include "k40t_driver/protocol/messages/camera.h"
#include "message_text.h"

namespace k40t::protocol::camera_samples {

template <class T>
T sample();

template <>
inline CameraSystemStatus sample() {
  return testing::message_from_text<CameraSystemStatus>(
      "capture_mode=video stream_resolution=720p30 encoding=h265 image_mode=visible_alt "
      "bitrate=12_Mbit/s photo_mode=burst time_lapse_interval_s=60 burst_count=5 "
      "sd_state=sd_card_full "
      "sd_total_mb=655350 sd_free_mb=10 sd_used_mb=655340");
}
template <>
inline CameraUpgradeStatus sample() {
  return {CameraUpgradeState::kRepairing, 100};
}
template <>
inline CaptureModeRequest sample() {
  return {{}, CaptureMode::kVideo};
}
template <>
inline PhotoSettingsRequest sample() {
  return {{PhotoMode::kTimeLapse, 60, 5}};
}
template <>
inline TakePhotoRequest sample() {
  auto m = testing::message_from_text<TakePhotoRequest>(
      "lens=infrared_visible action=stop_burst_only folder=a");
  m.name = "b c";  // by hand: message_text.h splits at spaces
  return m;
}
template <>
inline RecordRequest sample() {
  return testing::message_from_text<RecordRequest>(
      "lens=infrared action=stop_recording folder=rec name=clip-01");
}
template <>
inline ZoomRatioRequest sample() {
  return {160.0};
}
template <>
inline ContinuousZoomRequest sample() {
  return {{}, ZoomCommand::kStepOut};
}
template <>
inline PreciseReshootRequest sample() {
  return {{"f", "n"}, PhotoLensMode::kInfrared, ReshootResolution::k5664x4248, 1.1, 65535};
}
template <>
inline StreamBitrateRequest sample() {
  return {{}, StreamBitrate::k1_5Mbps};
}
template <>
inline StreamResolutionRequest sample() {
  return {{}, StreamResolution::k1080p30};
}
template <>
inline StreamEncodingRequest sample() {
  return {{}, VideoEncoding::kH265};
}
template <>
inline TfCardUpgradeRequest sample() {
  return {};
}
template <>
inline FormatSdRequest sample() {
  return {};
}
template <>
inline TimeSyncRequest sample() {
  return {4102444800000, 720, 1};  // 2100-01-01, UTC-12
}
template <>
inline FactoryResetRequest sample() {
  return {};
}
template <>
inline SetIpRequest sample() {
  return {IpMode::kDhcp, "10.0.0.255", "255.255.255.252", "10.0.0.1"};
}
template <>
inline GetIpRequest sample() {
  return {};
}
template <>
inline GetIpAck sample() {
  return {ResponseCode::kFailure, "172.16.1.2", "255.240.0.0", "0.0.0.0"};
}
template <>
inline FocusRequest sample() {
  return {FocusCommand::kArea, 0, 0, 1920, 1080};
}
template <>
inline OsdWatermarkRequest sample() {
  return {{}, true};
}
template <>
inline ShutdownRequest sample() {
  return {};
}
template <>
inline CameraVersionRequest sample() {
  return {};
}
template <>
inline CameraVersionAck sample() {
  return {ResponseCode::kBusy, 255, 0, 9};
}
template <>
inline ImageModeRequest sample() {
  return {{}, ImageMode::kSplit};
}
template <>
inline AiRecognitionRequest sample() {
  return {FeatureSwitch::kOff, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 255}};
}
template <>
inline BoxTrackingRequest sample() {
  return {FeatureSwitch::kOff, 1720, 980, 200, 100};
}
template <>
inline PhotoStatus sample() {
  return testing::message_from_text<PhotoStatus>(
      "lens=infrared state=sd_card_format_error burst_count=65535");
}
template <>
inline RecordStatus sample() {
  return testing::message_from_text<RecordStatus>(
      "lens=visible state=sd_card_format_error recording_time_s=3600");
}
template <>
inline ZoomStatus sample() {
  return {{}, ZoomProgress::kZooming};
}
template <>
inline PreciseReshootStatus sample() {
  return {{PhotoLensMode::kInfraredAndVisible, ReshootState::kReshooting}};
}
template <>
inline TfCardUpgradeStatus sample() {
  return {{}, TfUpgradeState::kFailed};
}
template <>
inline SdFormatStatus sample() {
  return {{}, SdFormatState::kUnavailable};
}
template <>
inline CameraGpsRequest sample() {
  return {false, 23, 59, 59, 999};
}
template <>
inline CameraGpsAck sample() {
  return {ResponseCode::kOk, 23,      59,     59,    999,    -179.9999999,
          -89.9999999,       -3276.8, 3276.7, 180.0, -180.0, 90.0};
}
template <>
inline TargetGpsRequest sample() {
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
inline TargetGpsAck sample() {
  return {ResponseCode::kNoSdCard, 0x1F, 1, -0.0000001, 0.0000001, -1.001, 8848.86};
}

}  // namespace k40t::protocol::camera_samples
