// The simulated pod's answers to the thermal (3.2.2) and visible (3.2.3) camera requests, and the
// state they set as the read-all ACKs (0x010100, 0x010200) and the reports 0x000004/0x000005
// show it.
#include <gtest/gtest.h>

#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // PodHarness, SimPodTest, request_with, ResponseCode
using SimThermalRequests = SimPodTest;
using SimVisibleRequests = SimPodTest;

TEST_F(SimThermalRequests, SettingsAreStoredAndReadBack) {
  const auto defaults = h.ask(p::ThermalReadSettingsRequest{});
  EXPECT_EQ(defaults.code, ResponseCode::kOk);
  EXPECT_EQ(defaults.palette, p::Palette::kWhiteHot);
  EXPECT_TRUE(defaults.measurement_on);
  EXPECT_EQ(defaults.core_type, p::ThermalCoreType::kRadiometric);

  EXPECT_EQ(h.send(request_with(&p::ThermalPaletteRequest::palette, p::Palette::kRainbow)),
            ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::ThermalZoomRequest::zoom_x, 4)), ResponseCode::kOk);
  p::ThermalDenoiseRequest denoise;
  denoise.denoise_on = true;
  denoise.denoise_level = 66;
  EXPECT_EQ(h.send(denoise), ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::ThermalEnhancementRequest::enhancement_level, 7)),
            ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::ThermalGainModeRequest::gain_mode, p::ThermalGainMode::kAuto)),
            ResponseCode::kOk);
  p::ThermalAlarmsRequest alarms;
  alarms.difference_alarm_on = true;
  alarms.difference_alarm_degC = 25.5;
  EXPECT_EQ(h.send(alarms), ResponseCode::kOk);

  const auto s = h.ask(p::ThermalReadSettingsRequest{});
  EXPECT_EQ(s.palette, p::Palette::kRainbow);
  EXPECT_EQ(s.zoom_x, 4);
  EXPECT_TRUE(s.denoise_on);
  EXPECT_EQ(s.denoise_level, 66);
  EXPECT_TRUE(s.enhancement_on);
  EXPECT_EQ(s.enhancement_level, 7);
  EXPECT_EQ(s.gain_mode, p::ThermalGainMode::kAuto);
  EXPECT_FALSE(s.high_alarm_on);
  EXPECT_TRUE(s.difference_alarm_on);
  EXPECT_DOUBLE_EQ(s.difference_alarm_degC, 25.5);
}

TEST_F(SimThermalRequests, SpotAndAreaMustLieOnTheImage) {
  p::ThermalSpotRequest spot;
  spot.x_px = 1000;
  spot.y_px = 700;
  EXPECT_EQ(h.send(spot), ResponseCode::kOk);
  const auto status = h.report<p::ThermalStatus>();
  EXPECT_EQ(status.point_x_px, 1000);
  EXPECT_EQ(status.point_y_px, 700);
  spot.x_px = 1500;  // inside the 1920 frame, outside the thermal picture
  EXPECT_EQ(h.send(spot), ResponseCode::kFailure);
  // 200 x 200 around (1250, 500) sticks out on the right (raw: the struct refuses to encode it).
  const auto outside =
      h.raw(p::ThermalAreaRequest::kId, {200, 0, 200, 0, 0xE2, 0x04, 0xF4, 0x01, 0});
  ASSERT_TRUE(outside);
  EXPECT_EQ(p::ack_response_code(outside->data(), outside->size, h.codec), ResponseCode::kFailure);
  p::ThermalAreaRequest area;
  area.width_px = 200;
  area.height_px = 200;
  area.center_x_px = 1100;
  area.center_y_px = 500;
  EXPECT_EQ(h.send(area), ResponseCode::kOk);
  const auto in_area = h.report<p::ThermalStatus>();
  EXPECT_GE(in_area.max_x_px, 998);
  EXPECT_LE(in_area.max_x_px, 1202);  // the edge pixel's frame coordinate
  EXPECT_NEAR(in_area.center_x_px, 1100, 2);
}

TEST_F(SimThermalRequests, MeasurementOffStopsTheReport) {
  const auto active = [&] {
    for (const PeriodicReport& r : periodic_reports()) {
      if (r.id == p::ThermalStatus::kId) return r.active(h.pod);
    }
    return false;
  };
  EXPECT_TRUE(active());
  EXPECT_EQ(h.send(request_with(&p::ThermalMeasurementRequest::measurement_on, false)),
            ResponseCode::kOk);
  EXPECT_FALSE(active());
  EXPECT_FALSE(h.ask(p::ThermalReadSettingsRequest{}).measurement_on);
}

TEST_F(SimThermalRequests, ReportFollowsTheGimbalAndTripsAlarms) {
  const Vec3 hot = h.pod.world().hot_object_centre();
  ASSERT_EQ(h.pod.gimbal().set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(h.pod.gimbal().command_angles(pitch_of(hot), yaw_of(hot)), Outcome::kOk);
  h.run(2.0);
  const auto on_target = h.report<p::ThermalStatus>();
  EXPECT_NEAR(on_target.max_degC, 85, 1);
  EXPECT_NEAR(on_target.max_x_px, 800, 3);
  EXPECT_NEAR(on_target.center_degC, on_target.max_degC, 1);
  p::ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = true;
  alarms.high_alarm_degC = 84;
  alarms.low_alarm_on = true;
  alarms.low_alarm_degC = -100;
  EXPECT_EQ(h.send(alarms), ResponseCode::kOk);
  const auto alarmed = h.report<p::ThermalStatus>();
  EXPECT_TRUE(alarmed.high_alarm);
  EXPECT_FALSE(alarmed.low_alarm);
  EXPECT_EQ(h.send(request_with(&p::ThermalZoomRequest::zoom_x, 2)), ResponseCode::kOk);
  ASSERT_EQ(h.pod.gimbal().command_angles(pitch_of(hot), yaw_of(hot) - 2), Outcome::kOk);
  h.run(1.0);
  const auto zoomed = h.report<p::ThermalStatus>();
  EXPECT_GT(zoomed.max_x_px, 900);  // 2 deg right of centre, magnified twice
}

TEST_F(SimVisibleRequests, SettingsAreStoredAndReadBack) {
  EXPECT_EQ(h.send(request_with(&p::VisibleVideoResolutionRequest::video_resolution,
                                p::VideoResolution::k4000x3000)),
            ResponseCode::kOk);
  EXPECT_EQ(
      h.send(request_with(&p::VisibleWhiteBalanceRequest::white_balance, p::WhiteBalance::kCloudy)),
      ResponseCode::kOk);
  EXPECT_EQ(
      h.send(request_with(&p::VisibleMeteringRequest::metering, p::MeteringMode::kCenterWeighted)),
      ResponseCode::kOk);
  p::VisibleBacklightRequest backlight;
  backlight.backlight_on = true;
  backlight.backlight_value = 35;
  EXPECT_EQ(h.send(backlight), ResponseCode::kOk);
  p::VisibleStrongLightRequest strong;
  strong.strong_light_on = true;
  strong.strong_light_value = 50;
  EXPECT_EQ(h.send(strong), ResponseCode::kFailure);  // not together (3.2.3.9 note)
  const auto s = h.ask(p::VisibleReadSettingsRequest{});
  EXPECT_EQ(s.video_resolution, p::VideoResolution::k4000x3000);
  EXPECT_EQ(s.white_balance, p::WhiteBalance::kCloudy);
  EXPECT_EQ(s.metering, p::MeteringMode::kCenterWeighted);
  EXPECT_TRUE(s.backlight_on);
  EXPECT_EQ(s.backlight_value, 35);
  EXPECT_FALSE(s.strong_light_on);
}

TEST_F(SimVisibleRequests, ExposureAndZoomShowInTheStatus) {
  auto status = h.report<p::VisibleStatus>();
  EXPECT_EQ(status.ev, p::ExposureValue::kAuto);
  EXPECT_EQ(status.shutter_us, 500);  // auto, looking at the horizon: sky above the centre line
  EXPECT_EQ(h.send(request_with(&p::VisibleShutterRequest::shutter, p::Shutter::k1_6000)),
            ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::VisibleIsoRequest::iso, p::Iso::k6400)), ResponseCode::kOk);
  EXPECT_EQ(h.send(request_with(&p::VisibleAeLockRequest::ae_lock_on, true)), ResponseCode::kOk);
  status = h.report<p::VisibleStatus>();
  EXPECT_EQ(status.shutter_us, 167);  // docs/protocol/decisions.md#a7: 0x0D = 1/6000
  EXPECT_NEAR(status.iso_db, 36.1, 0.05);
  EXPECT_TRUE(status.ae_lock_on);

  ASSERT_EQ(h.pod.zoom().set_zoom(20), Outcome::kOk);
  h.run(0.5);
  status = h.report<p::VisibleStatus>();
  EXPECT_TRUE(status.zooming);
  h.run(3.0);
  status = h.report<p::VisibleStatus>();
  EXPECT_FALSE(status.zooming);
  EXPECT_NEAR(status.zoom_x, 20, 0.05);
  EXPECT_NEAR(status.focal_length_mm, 51.7, 0.01);
}

}  // namespace
}  // namespace k40t::sim
