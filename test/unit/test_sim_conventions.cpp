// The simulator playing the document's open readings (docs/protocol/decisions.md#conventions)
// where its model, not only its encoding, changes: shutters beyond 16 bits of microseconds,
// photo mode 2 as a self-timer, and the attitude's Euler order with a roll held. The bytes of each
// reading are test_convention_readings.cpp's.
#include <gtest/gtest.h>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/sim/sim_options.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // PodHarness, request_with, ResponseCode

// 1/4 s = 250 000 us = 0x3D090. Before the fix the simulator cast it to uint16 and sent 0xD090
// (53 392 us, "0.053 s") under every reading.
TEST(SimConventions, ASlowShutterIsSentAsEachShutterReadingSays) {
  for (const auto& [field, raw] : {std::pair{p::ShutterField::kMicroseconds, 0xFFFF},
                                   std::pair{p::ShutterField::kMicrosecondsWrapped, 0xD090},
                                   std::pair{p::ShutterField::kHundredMicroseconds, 2500}}) {
    p::CodecOptions codec;
    codec.conventions.shutter_field = field;
    PodHarness h({}, codec);
    ASSERT_EQ(h.send(request_with(&p::VisibleShutterRequest::shutter, p::Shutter::k1_4)),
              ResponseCode::kOk);
    EXPECT_EQ(h.report<p::VisibleStatus>().shutter_us, raw);
  }
}

p::TakePhotoRequest photo(p::PhotoAction action = p::PhotoAction::kStart) {
  p::TakePhotoRequest request;
  request.lens = p::PhotoLensMode::kVisible;
  request.action = action;
  return request;
}

// Photo mode 2 (3.2.4.2): a self-timer takes one photo the interval after the request, and
// "stop" is for burst mode only (3.2.4.3); a time-lapse repeats until stopped.
TEST(SimConventions, PhotoMode2AsASelfTimer) {
  PodConfig config;
  config.camera.self_timer = true;
  PodHarness h(config);
  p::PhotoSettingsRequest settings;
  settings.photo_mode = p::PhotoMode::kTimeLapse;
  settings.time_lapse_interval_s = 5;
  settings.burst_count = 3;
  ASSERT_EQ(h.send(settings), ResponseCode::kOk);
  ASSERT_EQ(h.send(photo()), ResponseCode::kOk);
  h.run(4.5);
  EXPECT_EQ(h.pod.camera().photos().size(), 0u);
  EXPECT_EQ(h.send(photo(p::PhotoAction::kStop)), ResponseCode::kFailure);
  h.run(16.0);
  EXPECT_EQ(h.pod.camera().photos().size(), 1u);
  EXPECT_EQ(h.send(photo()), ResponseCode::kOk);  // the camera is free again

  PodHarness lapse;  // the default reading
  ASSERT_EQ(lapse.send(settings), ResponseCode::kOk);
  ASSERT_EQ(lapse.send(photo()), ResponseCode::kOk);
  lapse.run(11.0);
  EXPECT_GE(lapse.pod.camera().photos().size(), 2u);
  EXPECT_EQ(lapse.send(photo(p::PhotoAction::kStop)), ResponseCode::kOk);
}

// attitude_order with the roll joint at 10 deg and the gimbal down 45: the joint chain's rotation
// R = Rx(10 deg) Ry(45 deg) (REP 103: roll right-down and pitch down positive). zxy reports the
// chain's own angles; zyx the Z-Y-X angles of R, worked out from its matrix: yaw = atan2(R10, R00)
// = -9.851 deg REP 103, pitch = asin(-R20) = 44.136, roll = atan2(R21, R22) = 14.002, so in the
// pod's terms left 9.85, down 44.14, right-down 14.00.
TEST(SimConventions, TheAttitudeIsReportedInThePodsEulerOrder) {
  PodConfig config;
  config.gimbal.roll_deg = 10;
  for (const p::AttitudeOrder order : {p::AttitudeOrder::kZxy, p::AttitudeOrder::kZyx}) {
    p::CodecOptions codec;
    codec.conventions.attitude_order = order;
    PodHarness h(config, codec);
    p::GimbalAngleRequest down45;
    down45.pitch_deg = -45;
    down45.yaw_move = false;
    ASSERT_EQ(h.send(down45), ResponseCode::kOk);
    h.run(3.0);  // 45 deg at 20 deg/s
    const p::GimbalAttitude a = h.report<p::GimbalAttitude>();
    EXPECT_NEAR(a.joint_roll_deg, 10, 0.01);
    EXPECT_NEAR(a.joint_pitch_deg, -45, 0.01);
    const bool zxy = order == p::AttitudeOrder::kZxy;
    EXPECT_NEAR(a.yaw_deg, zxy ? 0 : -9.85, 0.01);
    EXPECT_NEAR(a.pitch_deg, zxy ? -45 : -44.14, 0.01);
    EXPECT_NEAR(a.roll_deg, zxy ? 10 : 14.00, 0.01);
  }
}

TEST(SimConventions, TheRollIsAnOption) {
  const auto options = parse_sim_options({"--gimbal-roll", "-12.5"});
  ASSERT_TRUE(options) << options.error();
  EXPECT_EQ(options->pod.gimbal.roll_deg, -12.5);
  EXPECT_FALSE(parse_sim_options({"--gimbal-roll", "60"}));  // -45..45
}

}  // namespace
}  // namespace k40t::sim
