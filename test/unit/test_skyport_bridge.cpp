// SkyportBridge (ROS-free) against the simulated SKYPORT adapter over an in-memory link, with a
// fake pod behind the PodPort: what the adapter's commands do to the pod, the return codes, the
// signs, and the power-off order (the pod's recording stops before the ACK says ready).

#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;
using namespace bridge_testing;

TEST(SkyportBridge, IdentityAndPayloadStatePass) {
  Rig rig;
  const psdk::sim::IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.passed) << r.detail;
  const psdk::sim::CheckReport report = rig.adapter->check_payload_state();
  EXPECT_TRUE(report.passed()) << report.summary();
}

TEST(SkyportBridge, IdentityFailsWithAnotherKey) {
  Credentials other = kCredentials;
  other.app_key = "ffffffffffffffffffffffffffffffff";
  Rig rig(other);
  const psdk::sim::IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.answered);
  EXPECT_FALSE(r.passed);
}

TEST(SkyportBridge, ShootPhotoDrivesThePodAndReportsItsRefusal) {
  Rig rig;
  ShootPhoto photo;
  AckResult raw;
  ASSERT_TRUE(rig.ask(photo, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "photo"));
  rig.pod.refuse(true);
  ASSERT_TRUE(rig.ask(photo, &raw));
  EXPECT_EQ(raw.code(), 0x01);  // never a made-up success
}

// PhotoStatus STATE_* (msg/PhotoStatus.msg).
constexpr uint8_t kPhotoTaken = 0, kSingleInProgress = 5;

bool single_shooting(Rig& rig) {
  const Result<ShootPhotoStateAck> state = rig.ask(GetShootPhotoState{});
  EXPECT_TRUE(state && state->code == AckCode::kOk);
  return state && state->state.shooting_single;
}

TEST(SkyportBridge, PhotoStateIsIdleUntilAPhotoIsTaken) {
  Rig rig;
  EXPECT_FALSE(single_shooting(rig));
}

TEST(SkyportBridge, PhotoStateFollowsThePodsPhotoStatus) {
  Rig rig(kCredentials, 60.0);        // the bound never ends it here: the pod's status does
  rig.pod.report_photo(kPhotoTaken);  // an earlier photo's status does not end this one
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.report_photo(kSingleInProgress);
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.report_photo(kPhotoTaken);
  EXPECT_FALSE(single_shooting(rig));
}

TEST(SkyportBridge, PhotoStateIsShootingWhileThePodRefusesForThePhoto) {
  Rig rig(kCredentials, 60.0);
  rig.pod.store_photos_for(std::chrono::hours(1));
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  RecordVideo record;
  AckResult raw;
  ASSERT_TRUE(rig.ask(record, &raw));
  EXPECT_EQ(raw.code(), 0x01);  // refused: still storing
  EXPECT_TRUE(has_call(rig.pod, "record start (refused: taking photo)"));
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.photo_stored();
  ASSERT_TRUE(rig.ask(record, &raw));
  EXPECT_EQ(raw.code(), 0x00);         // accepted: the pod stores nothing any more...
  EXPECT_FALSE(single_shooting(rig));  // ...so nothing is in progress
}

TEST(SkyportBridge, PhotoStateEndsAfterTheStoringBoundWithoutStatus) {
  Rig rig(kCredentials, 0.2);
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  EXPECT_TRUE(eventually([&] { return !single_shooting(rig); }));
}

// The adapter's own camera check, against a pod that refuses capture commands while it stores a
// photo (shorter than the bridge's bound): every step passes, as DJI Pilot would see it.
TEST(SkyportBridge, CameraCheckPassesAgainstAPodStoringItsPhoto) {
  Rig rig(kCredentials, 1.0);
  rig.pod.store_photos_for(std::chrono::milliseconds(300));
  const psdk::sim::CheckReport report = rig.adapter->check_camera();
  EXPECT_TRUE(report.passed()) << report.summary();
  EXPECT_NE(report.summary().find("shooting: single"), std::string::npos) << report.summary();
}

TEST(SkyportBridge, GimbalAnglesAreConvertedToRep103) {
  // Joint angles (`document`): 3.5.5 drives the joints as given (NED: gimbal_frame tests).
  Rig rig(kCredentials, BridgeOptions{}.photo_storing_s,
          [](BridgeOptions& o) { o.gimbal_angle_layout = PsdkLayout::kDocument; });
  ControlGimbalAngle angle;  // DJI: pitch -30 = down, yaw +20 = right
  angle.pitch_deg = -30;
  angle.yaw_deg = 20;
  AckResult raw;
  ASSERT_TRUE(rig.ask(angle, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "angle 0.5236 -0.3491"));
  angle.roll_deg = 10;  // the pod takes no roll command
  ASSERT_TRUE(rig.ask(angle, &raw));
  EXPECT_EQ(raw.code(), 0x01);
  // And back: the pod's pose in DJI signs.
  const Result<GimbalStateAck> state = rig.ask(GetGimbalState{});
  ASSERT_TRUE(state) << state.error();
  EXPECT_NEAR(state->angles.pitch_deg, -30, 0.1);
  EXPECT_NEAR(state->angles.yaw_deg, 20, 0.1);
  // "Following" as DJI's headers number the state (one enum with 3.5.2: 2), the default (P28).
  EXPECT_EQ(static_cast<uint8_t>(state->mode), 2);
}

TEST(SkyportBridge, OpticalTimesDigitalZoomIsThePodsHybridZoom) {
  Rig rig;
  SetOpticalZoomFocalLength focal;
  focal.focal_length_mm = 9.4;  // 2x of the 4.7 mm telephoto
  AckResult raw;
  ASSERT_TRUE(rig.ask(focal, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  SetDigitalZoomFactor digital;
  digital.factor_x = 3;
  ASSERT_TRUE(rig.ask(digital, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "zoom 6.00"));
  focal.focal_length_mm = 100;  // beyond 11x optical
  ASSERT_TRUE(rig.ask(focal, &raw));
  EXPECT_EQ(raw.code(), 0x01);
}

TEST(SkyportBridge, WhatThePodCannotDoIsUnsupported) {
  Rig rig;
  EXPECT_EQ(rig.code_of(SetFocusRing::key(), {0x10, 0x00}), 0x02);
  EXPECT_EQ(rig.code_of(SetGimbalMode::key(), {0x00}), 0x02);  // free mode
  EXPECT_EQ(rig.code_of(SetGimbalMode::key(), {0x02}), 0x00);  // following
  EXPECT_EQ(rig.code_of(CommandKey{0x04, 0x50}), 0x02);        // not in the document
  EXPECT_TRUE(rig.pod.calls().empty());
}

TEST(SkyportBridge, PowerOffStopsRecordingBeforeAckingReady) {
  Rig rig;
  rig.pod.set_recording(true);
  rig.adapter->announce_power_off();
  ASSERT_TRUE(eventually([&] { return rig.adapter->stats().last_power_off_ready; }));
  EXPECT_TRUE(has_call(rig.pod, "record stop"));
  EXPECT_TRUE(rig.bridge->stats().power_off_ready);
}

TEST(SkyportBridge, PowerOffIsNotReadyWhileThePodKeepsRecording) {
  Rig rig;
  rig.pod.set_recording(true);
  rig.pod.refuse(true);
  rig.adapter->announce_power_off();
  const uint64_t acks = rig.adapter->stats().battery_acks;
  ASSERT_TRUE(eventually([&] { return rig.adapter->stats().battery_acks >= acks + 2; }));
  EXPECT_FALSE(rig.adapter->stats().last_power_off_ready);
  EXPECT_TRUE(has_call(rig.pod, "record stop"));
}

TEST(SkyportBridge, WidgetsDriveThePod) {
  Rig rig;
  const Result<WidgetListLengthAck> length = rig.ask(GetWidgetListLength{});
  ASSERT_TRUE(length);
  EXPECT_EQ(length->count, 4);
  GetWidgetListData which;
  which.index = 0;
  const Result<WidgetListDataAck> palette = rig.ask(which);
  ASSERT_TRUE(palette);
  EXPECT_EQ(palette->type, WidgetType::kChooseList);
  EXPECT_EQ(palette->name, "Palette");
  SetWidgetValue set;
  set.widget = {WidgetType::kChooseList, 0, 4};  // iron red, the pod's palette 5
  AckResult raw;
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "palette 5"));
  set.widget = {WidgetType::kButton, 2, 1};  // laser ranging: the result in the floating window
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(eventually([&] {
    for (const auto& m : rig.adapter->floating_window_messages())
      if (m.find("123.4 m") != std::string::npos) return true;
    return false;
  }));
  GetWidgetGroupData group;
  const Result<WidgetGroupDataAck> values = rig.ask(group);
  ASSERT_TRUE(values);
  EXPECT_EQ(values->count, 4);
  EXPECT_EQ(values->widgets[0].value, 4);
}

}  // namespace
}  // namespace k40t::driver::skyport
