// Conformance of the simulated pod, seen from a client built only on the core library (a Session
// over the serial transport on the simulator's pty): every request of the catalogue gets its ACK,
// and the state it sets shows in the pod's reports, status frames and read-all answers.
#include <gtest/gtest.h>

#include <cmath>

#include "geo_test_support.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "sim_conformance_support.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // SimConformance, SimLink, quick_pod, near, aim, ResponseCode, 1s

// ---- common camera part (3.2.4) -------------------------------------------------------------

TEST_F(SimConformance, PhotosAskForGpsAndRecordTheAnswer) {
  p::TimeSyncRequest sync;
  sync.unix_time_ms = 1741064767089;  // 2025-03-04T05:06:07.089Z
  EXPECT_EQ(link.send(sync), ResponseCode::kOk);
  p::TakePhotoRequest photo;
  photo.lens = p::PhotoLensMode::kVisible;
  photo.folder = "survey";
  EXPECT_EQ(link.send(photo), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_for([&] { return link.gps_answers() == 1; }));
  std::optional<PhotoRecord> taken;
  ASSERT_TRUE(link.wait_for([&] {
    link.server().with_model([&](PodModel& pod) {
      if (!pod.camera().photos().empty() && pod.camera().photos()[0].gps)
        taken = pod.camera().photos()[0];
    });
    return taken.has_value();
  }));
  EXPECT_NEAR(taken->gps->position.latitude_deg, testing::kHostLatitudeDeg, 1e-7);
  EXPECT_NEAR(taken->gps->position.longitude_deg, testing::kHostLongitudeDeg, 1e-7);
  EXPECT_NEAR(taken->gps->position.altitude_m, testing::kHostAltitudeM, 0.1);
  EXPECT_EQ(taken->path.rfind("survey/IMG_20250304_0506", 0), 0u) << taken->path;
  EXPECT_TRUE(link.all<p::PhotoStatus>().empty());  // no status frame for a single shot
}

TEST_F(SimConformance, BurstRecordingAndModeRules) {
  p::PhotoSettingsRequest burst;
  burst.photo_mode = p::PhotoMode::kBurst;
  burst.burst_count = 3;
  EXPECT_EQ(link.send(burst), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>([](const p::CameraSystemStatus& s) {
    return s.photo_mode == p::PhotoMode::kBurst && s.burst_count == 3;
  }));
  p::TakePhotoRequest photo;
  photo.lens = p::PhotoLensMode::kInfrared;
  const SimLink::Mark before_burst = link.mark();
  EXPECT_EQ(link.send(photo), ResponseCode::kOk);
  EXPECT_EQ(link.send(photo), ResponseCode::kPhotoInProgress);
  ASSERT_TRUE(link.wait_report<p::PhotoStatus>(
      before_burst, [](const p::PhotoStatus& s) { return s.state == p::PhotoState::kDone; }));
  const auto statuses = link.all<p::PhotoStatus>();
  ASSERT_EQ(statuses.size(), 4u);
  EXPECT_EQ(statuses[0].state, p::PhotoState::kBurst);
  EXPECT_EQ(statuses[2].burst_count, 3);
  EXPECT_EQ(statuses[3].lens, p::PhotoLensMode::kInfrared);
  EXPECT_TRUE(link.wait_for([&] { return link.gps_answers() == 3; }));

  p::RecordRequest record;
  record.lens = p::RecordLensMode::kVisible;
  record.action = p::RecordAction::kStart;
  EXPECT_EQ(link.send(record), ResponseCode::kTimeout);  // photo mode: no answer (3.2.4.1)
  EXPECT_EQ(link.send(request_with(&p::CaptureModeRequest::mode, p::CaptureMode::kVideo)),
            ResponseCode::kOk);
  const SimLink::Mark before_record = link.mark();
  EXPECT_EQ(link.send(record), ResponseCode::kOk);
  EXPECT_EQ(link.send(photo), ResponseCode::kTimeout);  // video mode: no answer
  EXPECT_TRUE(link.wait_report<p::RecordStatus>(
      before_record, [](const p::RecordStatus& r) { return r.recording_time_s == 2; }));
  record.action = p::RecordAction::kStop;
  const SimLink::Mark before_stop = link.mark();
  EXPECT_EQ(link.send(record), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::RecordStatus>(
      before_stop, [](const p::RecordStatus& r) { return r.state == p::RecordState::kStopped; }));
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.capture_mode == p::CaptureMode::kVideo; }));
  link.server().with_model([](PodModel& pod) {
    ASSERT_EQ(pod.camera().videos().size(), 1u);
    EXPECT_GE(pod.camera().videos()[0].seconds, 2.0);
    EXPECT_GT(pod.camera().videos()[0].size_mb, 2.0);  // 1080p at 8 Mbit/s
    EXPECT_EQ(pod.camera().photos().size(), 3u);
  });
}

TEST_F(SimConformance, StreamNetworkAiAndSystemRequests) {
  for (ResponseCode code :
       {link.send(request_with(&p::StreamBitrateRequest::bitrate, p::StreamBitrate::k2Mbps)),
        link.send(
            request_with(&p::StreamResolutionRequest::resolution, p::StreamResolution::k1080p30)),
        link.send(request_with(&p::StreamEncodingRequest::encoding, p::VideoEncoding::kH265)),
        link.send(request_with(&p::ImageModeRequest::mode, p::ImageMode::kInfrared)),
        link.send(request_with(&p::OsdWatermarkRequest::enabled, true))}) {
    EXPECT_EQ(code, ResponseCode::kOk);
  }
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>([](const p::CameraSystemStatus& s) {
    return s.bitrate == p::StreamBitrate::k2Mbps && s.encoding == p::VideoEncoding::kH265 &&
           s.image_mode == p::ImageMode::kInfrared &&
           s.stream_resolution == p::ReportedStreamResolution::k1080p30;
  }));
  EXPECT_TRUE(link.ask(p::VisibleReadSettingsRequest{}).watermark_on);

  p::SetIpRequest ip;
  ip.address = "192.168.144.70";
  ip.gateway = "192.168.144.1";
  EXPECT_EQ(link.send(ip), ResponseCode::kOk);
  const auto got = link.ask(p::GetIpRequest{});
  EXPECT_EQ(got.address, "192.168.144.70");
  EXPECT_EQ(got.netmask, "255.255.255.0");
  EXPECT_EQ(link.ask(p::CameraVersionRequest{}).version_text(), "2.1.7");

  p::BoxTrackingRequest track;
  track.x_px = 800;
  track.y_px = 400;
  track.width_px = 100;
  track.height_px = 100;
  EXPECT_EQ(link.send(track), ResponseCode::kFailure);  // AI recognition is off
  EXPECT_EQ(link.send(request_with(&p::AiRecognitionRequest::recognition, p::FeatureSwitch::kOn)),
            ResponseCode::kOk);
  EXPECT_EQ(link.send(track), ResponseCode::kOk);

  p::PreciseReshootRequest reshoot;
  reshoot.lens = p::PhotoLensMode::kVisible;
  reshoot.zoom_x = 2;
  reshoot.focal_length_raw = 940;
  const SimLink::Mark before_reshoot = link.mark();
  EXPECT_EQ(link.send(reshoot), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::PreciseReshootStatus>(
      before_reshoot,
      [](const p::PreciseReshootStatus& s) { return s.state == p::ReshootState::kDone; }));
  EXPECT_TRUE(link.wait_report<p::VisibleStatus>(
      [](const p::VisibleStatus& v) { return near(v.precise_shot_focal_length_mm, 9.40, 0.001); }));
}

TEST_F(SimConformance, SdCardFormatAndUpgrade) {
  // Each state is reported once, possibly before send() returns: wait from before the request.
  const SimLink::Mark before_format = link.mark();
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kOk);
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kBusy);
  EXPECT_TRUE(link.wait_report<p::SdFormatStatus>(before_format, [](const p::SdFormatStatus& s) {
    return s.state == p::SdFormatState::kDone;
  }));
  EXPECT_GE(link.all<p::SdFormatStatus>().size(), 5u);  // 2 s at 5 Hz
  const SimLink::Mark before_upgrade = link.mark();
  EXPECT_EQ(link.send(p::TfCardUpgradeRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::TfCardUpgradeStatus>(
      before_upgrade,
      [](const p::TfCardUpgradeStatus& s) { return s.state == p::TfUpgradeState::kUpgrading; }));
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.upgrade == p::GimbalUpgradeState::kFirmwareUpgradeIncomplete;
  }));
  EXPECT_TRUE(link.wait_report<p::CameraUpgradeStatus>([](const p::CameraUpgradeStatus& s) {
    return s.state == p::CameraUpgradeState::kUpgrading && s.progress_percent > 0;
  }));

  link.server().with_model([](PodModel& pod) { pod.camera().sd().remove(); });
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.sd_state == p::SdCardState::kMissing; }));
  p::TakePhotoRequest photo;
  EXPECT_EQ(link.send(photo), ResponseCode::kBusy);  // the upgrade is still running
}

TEST(SimConformanceOptions, NoSdCardRefusesPhotos) {
  SimOptions options = quick_pod();
  options.sd_condition = "absent";
  SimLink link(options);
  EXPECT_EQ(link.send(p::TakePhotoRequest{}), ResponseCode::kNoSdCard);
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kNoSdCard);
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>([](const p::CameraSystemStatus& s) {
    return s.sd_state == p::SdCardState::kMissing && s.sd_total_mb == 0;
  }));
}

TEST(SimConformanceOptions, ShutdownAndFactoryReset) {
  SimOptions options = quick_pod();
  // The camera stays down long enough for all three attempts of a request (3 x 300 ms) to go
  // unanswered after the 2 Hz status has shown the drop, however late the test gets to them.
  options.pod.camera_boot_s = 3;
  SimLink link(options);
  EXPECT_EQ(link.send(request_with(&p::CaptureModeRequest::mode, p::CaptureMode::kVideo)),
            ResponseCode::kOk);
  // The camera restarts: its link drops in 0x000001, then it comes back with factory settings.
  // The drop lasts camera_boot_s only: look for it from before the request.
  const SimLink::Mark before_reset = link.mark();
  EXPECT_EQ(link.send(p::FactoryResetRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(before_reset, [](const p::GimbalStatus& s) {
    return s.camera_link == p::GimbalLinkState::kAbnormal;
  }));
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.capture_mode == p::CaptureMode::kPhoto; }));

  const SimLink::Mark before_shutdown = link.mark();
  EXPECT_EQ(link.send(p::ShutdownRequest{}), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<p::GimbalStatus>(before_shutdown, [](const p::GimbalStatus& s) {
    return s.camera_link == p::GimbalLinkState::kAbnormal;
  }));
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), ResponseCode::kTimeout);  // nobody answers
  EXPECT_EQ(link.ask(p::GimbalVersionRequest{}).code, ResponseCode::kOk);   // the gimbal does
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.camera_link == p::GimbalLinkState::kNormal; }));
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), ResponseCode::kOk);
}

TEST_F(SimConformance, TargetPositionFromTheLaser) {
  aim(link, -45, 90);
  p::TargetGpsRequest request;
  request.latitude_deg = 47.0;
  request.longitude_deg = 8.0;
  request.relative_height_m = 30;
  request.altitude_m = 530;
  const auto target = link.ask(request);
  EXPECT_EQ(target.code, ResponseCode::kOk);
  EXPECT_NEAR(target.latitude_deg, 47.0, 1e-7);
  const double east_m = test::metres_east(47.0, 8.0, target.longitude_deg, 530);
  EXPECT_NEAR(east_m, 30, 0.05);  // 45 deg down from 30 m: 30 m out
  EXPECT_NEAR(target.altitude_m, 500, 0.01);
}

// ---- laser (3.2.5) and SBUS (3.2.6) ---------------------------------------------------------

TEST_F(SimConformance, LaserRangesTheWorld) {
  aim(link, -30, 60);  // clear of both objects: flat ground 30 m below
  const auto single = link.ask(p::LaserRangeRequest{});
  EXPECT_EQ(single.code, ResponseCode::kOk);
  EXPECT_NEAR(single.distance_m, 60.0, 0.05);  // 30 / sin(30 deg)
  p::LaserPeriodicRangeRequest periodic;
  periodic.enable = true;
  EXPECT_EQ(link.send(periodic), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_for([&] { return link.count(p::LaserPeriodicRangeStatus::kId) >= 2; }));
  EXPECT_NEAR(link.latest<p::LaserPeriodicRangeStatus>()->distance_m, 60.0, 0.05);
  aim(link, 10, 60);  // above the horizon: no return
  EXPECT_TRUE(link.wait_report<p::LaserPeriodicRangeStatus>(
      [](const p::LaserPeriodicRangeStatus& s) { return s.distance_m == 0; }));
  EXPECT_EQ(link.ask(p::LaserRangeRequest{}).distance_m, 0);
  periodic.enable = false;
  EXPECT_EQ(link.send(periodic), ResponseCode::kOk);
}

TEST_F(SimConformance, SbusConfigurationIsStoredAndReadBack) {
  p::SbusRangeRequest range;
  range.max_value = 1900;
  range.min_value = 100;
  EXPECT_EQ(link.send(range), ResponseCode::kOk);
  p::SbusChannelsRequest channels;
  channels.stream_channel = 9;
  channels.centre_channel = 16;
  EXPECT_EQ(link.send(channels), ResponseCode::kOk);
  const auto config = link.ask(p::SbusConfigRequest{});
  EXPECT_EQ(config.range.max_value, 1900);
  EXPECT_EQ(config.range.min_value, 100);
  EXPECT_EQ(config.channels.stream_channel, 9);
  EXPECT_EQ(config.channels.zoom_channel, 2);
  EXPECT_EQ(config.channels.centre_channel, 16);
  EXPECT_EQ(link.send_raw(0x000500, {0x64, 0x00, 0xC8, 0x00, 0x00}),
            ResponseCode::kFailure);  // min > max
}

// ---- what every request shares --------------------------------------------------------------

TEST(SimConformanceOptions, UnknownIdsAreIgnored) {
  // The client's usual patience (three 300 ms attempts): a single short attempt would save time
  // on the unknown id but could miss the known id's ACK on a loaded machine.
  SimLink link(quick_pod());
  EXPECT_EQ(link.send_raw(0x0003F0, {0x01, 0x00}), ResponseCode::kTimeout);
  EXPECT_EQ(link.send_raw(0x000017, {50, 50, 0}), ResponseCode::kOk);  // still talking
}

TEST(SimConformanceOptions, WholeFrameCoverageIsDetectedByAnAutoClient) {
  SimOptions options = quick_pod();
  options.crc_coverage = p::CrcCoverage::kWholeFrame;
  session::SessionOptions client;
  client.crc_coverage = p::CrcCoverage::kWholeFrame;
  SimLink link(options, client);
  EXPECT_EQ(link.ask(p::GimbalVersionRequest{}).code, ResponseCode::kOk);
  EXPECT_EQ(link.client().stats().parser.checksum_errors, 0u);

  // An auto-detecting client locks onto it from the reports.
  session::SessionOptions auto_client;
  auto_client.crc_coverage = p::CrcCoverage::kAuto;
  SimLink detecting(options, auto_client);
  EXPECT_TRUE(SimLink::wait_for([&] {
    return detecting.client().dispatcher().locked_coverage() == p::CrcCoverage::kWholeFrame;
  }));
}

TEST(SimConformanceOptions, LittleEndianAcks) {
  SimOptions options = quick_pod();
  options.codec.ack_byte_order = p::ByteOrder::kLittle;
  session::SessionOptions client;
  client.codec.ack_byte_order = p::ByteOrder::kLittle;
  SimLink link(options, client);
  aim(link, -90, 0);
  const auto range = link.ask(p::LaserRangeRequest{});
  EXPECT_EQ(range.code, ResponseCode::kOk);
  EXPECT_NEAR(range.distance_m, 30.0, 0.05);
  EXPECT_EQ(link.send(p::TakePhotoRequest{}), ResponseCode::kOk);
  EXPECT_EQ(link.send(request_with(&p::CaptureModeRequest::mode, p::CaptureMode::kVideo)),
            ResponseCode::kPhotoInProgress);  // 0x0203, read little-endian
}

}  // namespace
}  // namespace k40t::sim
