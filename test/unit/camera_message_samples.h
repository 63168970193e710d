// One sample of each struct of the common camera family (sections 3.2.1.1, 3.2.1.4, 3.2.4) with
// every field away from its default: the values the round-trip, range and byte-order tests of
// test_camera_message*.cpp start from.
#pragma once

#include <cmath>

#include "k40t_driver/protocol/messages/camera.h"

namespace k40t::protocol::camera_samples {

template <class T>
T sample();

template <>
inline CameraSystemStatus sample() {
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
  TakePhotoRequest m;
  m.lens = PhotoLensMode::kInfraredAndVisible;
  m.action = PhotoAction::kStop;
  m.folder = "a";
  m.name = "b c";
  return m;
}
template <>
inline RecordRequest sample() {
  RecordRequest m;
  m.lens = RecordLensMode::kInfrared;
  m.action = RecordAction::kStop;
  m.folder = "rec";
  m.name = "clip-01";
  return m;
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
  PhotoStatus m;
  m.lens = PhotoLensMode::kInfrared;
  m.state = PhotoState::kSdFormatError;
  m.burst_count = 65535;
  return m;
}
template <>
inline RecordStatus sample() {
  RecordStatus m;
  m.lens = RecordLensMode::kVisible;
  m.state = RecordState::kSdFormatError;
  m.recording_time_s = 3600;
  return m;
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
