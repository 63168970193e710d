// The simulated pod's answers to the common camera requests (section 3.2.4) and the resulting
// state as its reports and status frames show it. Requests are typed structs encoded by the
// protocol library; what is checked is the simulator's behaviour.
#include <gtest/gtest.h>

#include "k40t_driver/protocol/messages/camera.h"
#include "message_text.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // PodHarness, SimPodTest, request_with, ResponseCode
using k40t::testing::fields_are;
using k40t::testing::message_from_text;
using SimCameraRequests = SimPodTest;

p::TakePhotoRequest photo(p::PhotoAction action = p::PhotoAction::kStart) {
  p::TakePhotoRequest request;
  request.lens = p::PhotoLensMode::kVisible;
  request.action = action;
  return request;
}

p::RecordRequest record(p::RecordAction action) {
  p::RecordRequest request;
  request.lens = p::RecordLensMode::kVisible;
  request.action = action;
  return request;
}

p::CaptureModeRequest mode(p::CaptureMode m) {
  p::CaptureModeRequest request;
  request.mode = m;
  return request;
}

TEST_F(SimCameraRequests, ModesAndPhotoSettingsShowInTheSystemStatus) {
  EXPECT_EQ(h.send(mode(p::CaptureMode::kVideo)), ResponseCode::kOk);
  p::PhotoSettingsRequest settings;
  settings.photo_mode = p::PhotoMode::kTimeLapse;
  settings.time_lapse_interval_s = 30;
  settings.burst_count = 5;
  EXPECT_EQ(h.send(settings), ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::StreamBitrateRequest::bitrate, p::StreamBitrate::k12Mbps)),
            ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::StreamEncodingRequest::encoding, p::VideoEncoding::kH265)),
            ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::ImageModeRequest::mode, p::ImageMode::kSplit)),
            ResponseCode::kOk);

  const auto status = h.report<p::CameraSystemStatus>();
  EXPECT_EQ(status.capture_mode, p::CaptureMode::kVideo);
  EXPECT_EQ(status.photo_mode, p::PhotoMode::kTimeLapse);
  EXPECT_EQ(status.time_lapse_interval_s, 30);
  EXPECT_EQ(status.burst_count, 5);
  EXPECT_EQ(status.bitrate, p::StreamBitrate::k12Mbps);
  EXPECT_EQ(status.encoding, p::VideoEncoding::kH265);
  EXPECT_EQ(status.image_mode, p::ImageMode::kSplit);
  EXPECT_EQ(status.sd_state, p::SdCardState::kNormal);
  EXPECT_DOUBLE_EQ(status.sd_total_mb, 65530);  // 64 GB in the wire's 10 MB steps
}

// Section 3.2.4.1 note: in photo mode the pod does not answer a record request, in video mode a
// photo request (0x000302, and the precise re-shoot 0x000307): no ACK at all (kTimeout here).
TEST_F(SimCameraRequests, TheOtherCaptureModesRequestsGetNoAnswer) {
  EXPECT_EQ(h.send(record(p::RecordAction::kStart)), ResponseCode::kTimeout);  // photo mode
  EXPECT_EQ(h.send(record(p::RecordAction::kStop)), ResponseCode::kTimeout);
  EXPECT_EQ(h.send(mode(p::CaptureMode::kVideo)), ResponseCode::kOk);
  EXPECT_EQ(h.send(photo()), ResponseCode::kTimeout);  // video mode
  p::PreciseReshootRequest reshoot;
  EXPECT_EQ(h.send(reshoot), ResponseCode::kTimeout);
  EXPECT_TRUE(h.pod.camera().photos().empty());
  EXPECT_FALSE(h.pod.camera().shooting());
  EXPECT_EQ(h.send(mode(p::CaptureMode::kPhoto)), ResponseCode::kOk);
  EXPECT_EQ(h.send(reshoot), ResponseCode::kOk);  // the same request, in photo mode
}

TEST_F(SimCameraRequests, PhotoAndRecordingRefusalsCarryTheirCodes) {
  EXPECT_EQ(h.send(mode(p::CaptureMode::kVideo)), ResponseCode::kOk);
  EXPECT_EQ(h.send(record(p::RecordAction::kStart)), ResponseCode::kOk);
  EXPECT_EQ(h.send(mode(p::CaptureMode::kPhoto)), ResponseCode::kRecording);
  EXPECT_EQ(h.send(p::FormatSdRequest{}), ResponseCode::kRecording);
  EXPECT_EQ(h.send(record(p::RecordAction::kStart)), ResponseCode::kBusy);
  h.run(2.05);
  EXPECT_EQ(h.send(record(p::RecordAction::kStop)), ResponseCode::kOk);
  h.run(0.05);
  const auto frames = h.status_frames<p::RecordStatus>();
  ASSERT_EQ(frames.size(), 4u);  // 0 s, 1 s, 2 s, stopped
  EXPECT_EQ(frames[2].recording_time_s, 2);
  EXPECT_EQ(frames.back().state, p::RecordState::kStopped);
  EXPECT_EQ(frames.back().lens, p::RecordLensMode::kVisible);

  EXPECT_EQ(h.send(mode(p::CaptureMode::kPhoto)), ResponseCode::kOk);
  p::PhotoSettingsRequest burst;
  burst.photo_mode = p::PhotoMode::kBurst;
  burst.burst_count = 5;
  EXPECT_EQ(h.send(burst), ResponseCode::kOk);
  EXPECT_EQ(h.send(photo()), ResponseCode::kOk);
  EXPECT_EQ(h.send(photo()), ResponseCode::kPhotoInProgress);
  EXPECT_EQ(h.send(record(p::RecordAction::kStart)), ResponseCode::kTimeout);  // photo mode
  h.run(2.0);
  const auto photos = h.status_frames<p::PhotoStatus>();
  ASSERT_EQ(photos.size(), 6u);
  EXPECT_EQ(photos[4].state, p::PhotoState::kBurst);
  EXPECT_EQ(photos[4].burst_count, 5);
  EXPECT_EQ(photos[5].state, p::PhotoState::kDone);
}

TEST_F(SimCameraRequests, SdCardConditionsRefuseAndShowInTheStatus) {
  h.pod.camera().sd().remove();
  EXPECT_EQ(h.send(photo()), ResponseCode::kNoSdCard);
  EXPECT_EQ(h.send(p::FormatSdRequest{}), ResponseCode::kNoSdCard);
  EXPECT_EQ(h.send(p::TfCardUpgradeRequest{}), ResponseCode::kNoSdCard);
  EXPECT_EQ(h.report<p::CameraSystemStatus>().sd_state, p::SdCardState::kMissing);
  EXPECT_DOUBLE_EQ(h.report<p::CameraSystemStatus>().sd_total_mb, 0);
  h.pod.camera().sd().insert();
  h.pod.camera().sd().fill();
  EXPECT_EQ(h.send(photo()), ResponseCode::kNoSpace);
  EXPECT_EQ(h.report<p::CameraSystemStatus>().sd_state, p::SdCardState::kFull);
  EXPECT_EQ(h.send(p::FormatSdRequest{}), ResponseCode::kOk);
  EXPECT_EQ(h.send(p::FormatSdRequest{}), ResponseCode::kBusy);
  h.run(2.5);
  const auto format = h.status_frames<p::SdFormatStatus>();
  ASSERT_FALSE(format.empty());
  EXPECT_EQ(format.front().state, p::SdFormatState::kFormatting);
  EXPECT_EQ(format.back().state, p::SdFormatState::kDone);
  const auto status = h.report<p::CameraSystemStatus>();
  EXPECT_EQ(status.sd_state, p::SdCardState::kNormal);
  EXPECT_DOUBLE_EQ(status.sd_used_mb, 0);
}

TEST_F(SimCameraRequests, BadPayloadsAreRefusedAndUnknownIdsIgnored) {
  // 0x000302 needs 54 bytes.
  const auto short_ack = h.raw(0x000302, {0x02, 0x00});
  ASSERT_TRUE(short_ack);
  EXPECT_EQ(p::ack_response_code(short_ack->data(), short_ack->size, h.codec),
            ResponseCode::kLengthMismatch);
  // Lens mode 9 does not exist.
  std::vector<uint8_t> bad_lens(54, 0);
  bad_lens[0] = 9;
  const auto bad_ack = h.raw(0x000302, bad_lens);
  ASSERT_TRUE(bad_ack);
  EXPECT_EQ(p::ack_response_code(bad_ack->data(), bad_ack->size, h.codec), ResponseCode::kFailure);
  // 0x00030A 2 = 720P30 "not supported".
  const auto unsupported = h.raw(0x00030A, {0x02, 0x00});
  EXPECT_EQ(p::ack_response_code(unsupported->data(), unsupported->size, h.codec),
            ResponseCode::kFailure);
  // Zoom 0.5x is below 1x.
  const auto low_zoom = h.raw(0x000304, {0x00, 0x05, 0x00});
  EXPECT_EQ(p::ack_response_code(low_zoom->data(), low_zoom->size, h.codec),
            ResponseCode::kFailure);
  EXPECT_FALSE(h.raw(0x0003F0, {0x01, 0x00}));
  EXPECT_FALSE(h.raw(0x000310, {1, 2, 3, 4, 5, 0}));  // the pod's own request, not answered by it
}

TEST_F(SimCameraRequests, ZoomMovesAndReportsItsStatus) {
  EXPECT_EQ(h.send(request_with(&p::ZoomRatioRequest::zoom_x, 4.0)), ResponseCode::kOk);
  h.run(1.2);
  const auto frames = h.status_frames<p::ZoomStatus>();
  ASSERT_GE(frames.size(), 2u);
  EXPECT_EQ(frames.front().progress, p::ZoomProgress::kZooming);
  EXPECT_EQ(frames.back().progress, p::ZoomProgress::kDone);
  EXPECT_DOUBLE_EQ(h.pod.zoom().zoom(), 4.0);
  EXPECT_EQ(h.send(request_with(&p::ContinuousZoomRequest::command, p::ZoomCommand::kStepOut)),
            ResponseCode::kOk);
  h.run(1.0);
  EXPECT_NEAR(h.pod.zoom().zoom(), 4.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(h.send(request_with(&p::FocusRequest::command, p::FocusCommand::kOneShot)),
            ResponseCode::kOk);
  EXPECT_TRUE(h.pod.zoom().focusing());
}

TEST_F(SimCameraRequests, PreciseReshootZoomsThenShootsWithItsOwnStatus) {
  p::PreciseReshootRequest request;
  request.lens = p::PhotoLensMode::kVisible;
  request.zoom_x = 8.0;
  request.focal_length_raw = 3760;
  request.name = "pole_17";
  EXPECT_EQ(h.send(request), ResponseCode::kOk);
  h.run(3.0);
  const auto frames = h.status_frames<p::PreciseReshootStatus>();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].state, p::ReshootState::kReshooting);
  EXPECT_EQ(frames[1].state, p::ReshootState::kDone);
  ASSERT_EQ(h.pod.camera().photos().size(), 1u);
  EXPECT_EQ(h.pod.camera().photos()[0].path, "pole_17.jpg");
  EXPECT_DOUBLE_EQ(h.pod.zoom().zoom(), 8.0);
  EXPECT_EQ(h.pod.camera().settings().precise_focal_length_raw, 3760);
}

TEST_F(SimCameraRequests, SystemRequestsAnswerWithData) {
  const auto version = h.ask(p::CameraVersionRequest{});
  EXPECT_EQ(version.code, ResponseCode::kOk);
  EXPECT_EQ(version.version_text(), "2.1.7");

  EXPECT_EQ(h.ask(p::GetIpRequest{}).address, "192.168.144.64");
  const char ip[] = "address=10.1.2.3 netmask=255.255.0.0 gateway=10.1.0.1";
  EXPECT_EQ(h.send(message_from_text<p::SetIpRequest>(ip)), ResponseCode::kOk);
  EXPECT_TRUE(fields_are(h.ask(p::GetIpRequest{}), ip));

  p::TimeSyncRequest sync;
  sync.unix_time_ms = 1741064767089;  // 2025-03-04T05:06:07.089Z
  sync.tz_minutes_west = -480;        // UTC+8
  EXPECT_EQ(h.send(sync), ResponseCode::kOk);
  EXPECT_EQ(h.send(photo()), ResponseCode::kOk);
  h.run(0.01);
  ASSERT_EQ(h.pod.camera().photos().size(), 1u);
  EXPECT_EQ(h.pod.camera().photos()[0].path, "IMG_20250304_130607_099.jpg");

  EXPECT_EQ(h.send(request_with(&p::OsdWatermarkRequest::enabled, true)), ResponseCode::kOk);
  EXPECT_TRUE(h.pod.camera().settings().watermark);
}

TEST_F(SimCameraRequests, TargetPositionFollowsTheLaser) {
  const auto request = message_from_text<p::TargetGpsRequest>(
      "latitude_deg=47.0 longitude_deg=8.0 relative_height_m=30 altitude_m=530 "
      "utc_time_ms=1741064767089");
  // Gimbal level: the laser sees the horizon, no return: zeros with code OK (laser_target_zeros:
  // no_return, the default), or a refusal from a pod whose zeros would be a position.
  const auto none = h.ask(request);
  EXPECT_EQ(none.code, ResponseCode::kOk);
  EXPECT_EQ(none.latitude_deg, 0.0);
  EXPECT_EQ(none.longitude_deg, 0.0);
  h.codec.conventions.laser_target_zeros = p::LaserTargetZeros::kPosition;
  EXPECT_EQ(h.ask(request).code, ResponseCode::kFailure);
  h.codec.conventions.laser_target_zeros = p::LaserTargetZeros::kNoReturn;
  ASSERT_EQ(h.pod.gimbal().command_angles(-90.0, std::nullopt), Outcome::kOk);
  h.run(5.0);
  const auto target = h.ask(request);
  EXPECT_EQ(target.code, ResponseCode::kOk);
  EXPECT_NEAR(target.latitude_deg, 47.0, 1e-6);  // straight down
  EXPECT_NEAR(target.longitude_deg, 8.0, 1e-6);
  EXPECT_NEAR(target.altitude_m, 500, 0.01);
  EXPECT_EQ(target.utc_time_ms, request.utc_time_ms);
}

TEST_F(SimCameraRequests, AiAndTrackingRules) {
  const auto track =
      message_from_text<p::BoxTrackingRequest>("x_px=900 y_px=500 width_px=100 height_px=80");
  EXPECT_EQ(h.send(track), ResponseCode::kFailure);  // AI off
  p::AiRecognitionRequest ai;
  ai.recognition = p::FeatureSwitch::kOn;
  ai.classes = {0, 2, 7};
  EXPECT_EQ(h.send(ai), ResponseCode::kOk);
  EXPECT_EQ(h.send(track), ResponseCode::kOk);
  EXPECT_TRUE(h.pod.ai().tracking);
  EXPECT_EQ(h.pod.ai().classes[2], 7);
}

TEST(SimCameraRequestsConfigured, ShutdownSilencesTheCameraUntilItBoots) {
  PodConfig config;
  config.camera_boot_s = 2;
  PodHarness h(config);
  EXPECT_EQ(h.send(p::ShutdownRequest{}), ResponseCode::kOk);
  h.run(0.5);
  EXPECT_EQ(h.send(p::CameraVersionRequest{}), ResponseCode::kTimeout);  // no answer at all
  h.run(2.0);
  EXPECT_EQ(h.send(p::CameraVersionRequest{}), ResponseCode::kOk);
}

TEST_F(SimCameraRequests, FactoryResetRestoresSettings) {
  EXPECT_EQ(h.send(mode(p::CaptureMode::kVideo)), ResponseCode::kOk);
  EXPECT_EQ(h.send(p::FactoryResetRequest{}), ResponseCode::kOk);
  EXPECT_EQ(h.send(p::FactoryResetRequest{}), ResponseCode::kBusy);
  h.run(1.2);  // the reset happens one second after the ACK
  EXPECT_EQ(h.report<p::CameraSystemStatus>().capture_mode, p::CaptureMode::kPhoto);
}

TEST(SimCameraRequestsConfigured, AckByteOrderFollowsTheOption) {
  p::CodecOptions little;
  little.ack_byte_order = p::ByteOrder::kLittle;
  PodHarness h({}, little);
  h.pod.camera().sd().remove();
  const auto ack = h.ack_of(photo());
  ASSERT_TRUE(ack);
  ASSERT_EQ(ack->size, 2u);
  EXPECT_EQ(ack->bytes[0], 0x04);  // 0x0204 low byte first
  EXPECT_EQ(ack->bytes[1], 0x02);
}

}  // namespace
}  // namespace k40t::sim
