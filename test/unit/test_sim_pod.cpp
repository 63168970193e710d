// The whole simulated pod: what spans several models (boresight in the world, exposure, power,
// factory reset, target geolocation).
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/sim/pod_model.h"
#include "sim_test_util.h"

namespace k40t::sim {
namespace {

void run(PodModel& pod, double seconds) {
  const int steps = static_cast<int>(std::lround(seconds / testing::kStepS));
  for (int i = 0; i < steps; ++i) pod.step(testing::kStepS);
}

TEST(SimPod, ThermalAndLaserFollowTheGimbal) {
  PodModel pod;
  const Vec3 hot = pod.world().hot_object_centre();
  ASSERT_EQ(pod.gimbal().set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(pod.gimbal().command_angles(pitch_of(hot), yaw_of(hot)), Outcome::kOk);
  run(pod, 2.0);
  EXPECT_NEAR(pod.thermal_stats().max_degC, pod.world().config().hot.temperature_degC, 0.5);
  ASSERT_TRUE(pod.laser_range());
  EXPECT_NEAR(*pod.laser_range(), norm(hot) - pod.world().config().hot.radius_m, 1e-6);
}

TEST(SimPod, VehicleHeadingTurnsTheWorldAndTheReportedAttitude) {
  PodModel pod;
  ASSERT_TRUE(pod.locate_target(GeoPoint{47, 8, 30, 500}, YawPitchRoll{90, 0, 0}) == std::nullopt);
  EXPECT_DOUBLE_EQ(pod.attitude_yaw_deg(), 90);
  ASSERT_EQ(pod.gimbal().command_angles(-45.0, std::nullopt), Outcome::kOk);
  run(pod, 3.0);
  const auto target = pod.locate_target(GeoPoint{47, 8, 30, 500}, YawPitchRoll{90, 0, 0});
  ASSERT_TRUE(target);
  EXPECT_GT(target->longitude_deg, 8.0);  // looking east, 30 m out
  // On the ground, which 30 m out is d^2 / 2R = 0.07 mm below the pod's tangent plane.
  EXPECT_NEAR(target->relative_height_m, 0, 1e-3);
}

TEST(SimPod, AutoExposureIsFasterOnTheSkyAndAeLockHoldsIt) {
  PodModel pod;
  ASSERT_EQ(pod.gimbal().set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(pod.gimbal().command_angles(20.0, std::nullopt), Outcome::kOk);
  run(pod, 1.0);
  EXPECT_DOUBLE_EQ(pod.exposure().shutter_us, 500);
  pod.camera().visible().ae_lock_on = true;
  ASSERT_EQ(pod.gimbal().command_angles(-60.0, std::nullopt), Outcome::kOk);
  run(pod, 3.0);
  EXPECT_DOUBLE_EQ(pod.exposure().shutter_us, 500);
  pod.camera().visible().ae_lock_on = false;
  run(pod, 0.1);
  EXPECT_DOUBLE_EQ(pod.exposure().shutter_us, 2000);
  pod.camera().visible().ev = protocol::ExposureValue::kPlus1;  // 0x10: twice as long
  run(pod, 0.1);
  EXPECT_DOUBLE_EQ(pod.exposure().shutter_us, 4000);
  pod.camera().visible().shutter = protocol::Shutter::k1_1000;  // 0x09, manual
  pod.camera().visible().iso = protocol::Iso::k400;             // 0x03: 12 dB
  EXPECT_DOUBLE_EQ(pod.exposure().shutter_us, 1000);
  EXPECT_NEAR(pod.exposure().iso_db, 12.04, 0.01);
}

TEST(SimPod, ShutdownTakesTheCameraDownAndItBootsAgain) {
  PodConfig config;
  config.camera_boot_s = 3;
  PodModel pod(config);
  ASSERT_EQ(pod.shutdown(), Outcome::kOk);
  EXPECT_TRUE(pod.camera_available());  // the ACK goes out first
  run(pod, 0.5);
  EXPECT_FALSE(pod.camera_available());
  EXPECT_FALSE(pod.camera_link_ok());
  run(pod, 3.0);
  EXPECT_TRUE(pod.camera_available());
}

TEST(SimPod, FactoryResetRestoresDefaultsAfterASecond) {
  PodModel pod;
  pod.thermal().settings().reported.palette = protocol::Palette::kSky;
  ASSERT_EQ(pod.set_sbus_range(1500, 300), Outcome::kOk);
  ASSERT_EQ(pod.factory_reset(), Outcome::kOk);
  run(pod, 0.5);
  EXPECT_EQ(pod.thermal().settings().reported.palette, protocol::Palette::kSky);
  run(pod, 0.6);
  EXPECT_EQ(pod.thermal().settings().reported.palette, protocol::Palette::kWhiteHot);
  EXPECT_EQ(pod.sbus().max_value, SbusSettings{}.max_value);
  EXPECT_FALSE(pod.camera_available());  // rebooting
}

TEST(SimPod, SystemSettingsAreCheckedAndStored) {
  PodModel pod;
  EXPECT_EQ(pod.set_sbus_range(100, 200), Outcome::kFailure);
  EXPECT_EQ(pod.set_sbus_range(2048, 200), Outcome::kFailure);
  EXPECT_EQ(pod.set_sbus_channels({0, 1, 2, 3, 4, 5, 16}), Outcome::kFailure);
  ASSERT_EQ(pod.set_sbus_channels({6, 5, 4, 3, 2, 1, 0}), Outcome::kOk);
  EXPECT_EQ(pod.sbus().channels[0], 6);
  EXPECT_EQ(pod.set_tracking(true, TrackingBox{100, 100, 50, 50}), Outcome::kFailure);  // AI off
  ASSERT_EQ(pod.set_ai(true, 0, {1, 2}), Outcome::kOk);
  EXPECT_EQ(pod.set_tracking(true, TrackingBox{1900, 100, 50, 50}), Outcome::kFailure);
  EXPECT_EQ(pod.set_tracking(true, TrackingBox{100, 100, 50, 50}), Outcome::kOk);
  EXPECT_TRUE(pod.ai().tracking);
  EXPECT_TRUE(pod.gimbal().tracking());
  EXPECT_LT(pod.gimbal().yaw_target_deg(), 0);    // the box is left of centre
  EXPECT_GT(pod.gimbal().pitch_target_deg(), 0);  // and above it
  EXPECT_EQ(pod.gimbal().centre(), Outcome::kBusy);
  ASSERT_EQ(pod.set_tracking(false, TrackingBox{}), Outcome::kOk);
  EXPECT_EQ(pod.gimbal().centre(), Outcome::kOk);
  NetworkSettings network;
  network.address = {10, 0, 0, 7};
  ASSERT_EQ(pod.set_network(network), Outcome::kOk);
  EXPECT_EQ(pod.network().address[3], 7);
  network.address = {0, 0, 0, 0};
  EXPECT_EQ(pod.set_network(network), Outcome::kFailure);
}

TEST(SimPod, EventsAreDrainedOnce) {
  PodModel pod;
  ASSERT_EQ(pod.zoom().set_zoom(2.0), Outcome::kOk);
  run(pod, 1.0);
  EXPECT_FALSE(pod.take_events().empty());
  EXPECT_TRUE(pod.take_events().empty());
}

}  // namespace
}  // namespace k40t::sim
