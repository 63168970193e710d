// Conformance of the simulated pod's thermal (3.2.2) and visible (3.2.3) cameras, seen from a
// client built only on the core library (see test_sim_conformance.cpp): settings are stored and
// read back, and show in the status reports; zoom and focus.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "message_text.h"
#include "sim_conformance_support.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // SimConformance, SimLink, quick_pod, near, aim, ResponseCode, 1s
using k40t::testing::fields_are;

// ---- thermal camera (3.2.2) -----------------------------------------------------------------

TEST_F(SimConformance, ThermalSettingsAreStoredAndReadBack) {
  auto defaults = link.ask(p::ThermalReadSettingsRequest{});
  EXPECT_EQ(defaults.code, ResponseCode::kOk);
  EXPECT_EQ(defaults.palette, p::Palette::kWhiteHot);
  EXPECT_TRUE(defaults.measurement_on);
  EXPECT_FALSE(defaults.high_alarm_on);

  p::ThermalPaletteRequest palette;
  palette.palette = p::Palette::kIronRed;
  p::ThermalDenoiseRequest denoise;
  denoise.denoise_on = true;
  denoise.denoise_level = 30;
  p::ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = true;
  alarms.high_alarm_degC = 80;
  alarms.low_alarm_on = true;
  alarms.low_alarm_degC = 5;
  p::ThermalThresholdAlarmRequest threshold;
  threshold.threshold_alarm_on = true;
  threshold.threshold_reference_degC = 20;
  threshold.threshold_float_degC = 10;
  p::ThermalAreaRequest area;
  area.width_px = 400;
  area.height_px = 300;
  area.center_x_px = 800;
  area.center_y_px = 528;
  for (ResponseCode code :
       {link.send(palette), link.send(request_with(&p::ThermalZoomRequest::zoom_x, 2)),
        link.send(request_with(&p::ThermalSharpnessRequest::sharpness, 40)),
        link.send(request_with(&p::ThermalBrightnessRequest::brightness, 60)),
        link.send(request_with(&p::ThermalContrastRequest::contrast, 70)), link.send(denoise),
        link.send(request_with(&p::ThermalEnhancementRequest::enhancement_level, 4)),
        link.send(request_with(&p::ThermalGainModeRequest::gain_mode, p::ThermalGainMode::kLow)),
        link.send(request_with(&p::ThermalOverlayRequest::overlay_on, true)), link.send(alarms),
        link.send(threshold), link.send(area)}) {
    EXPECT_EQ(code, ResponseCode::kOk);
  }
  const auto s = link.ask(p::ThermalReadSettingsRequest{});
  EXPECT_EQ(s.palette, p::Palette::kIronRed);
  EXPECT_EQ(s.zoom_x, 2);
  EXPECT_EQ(s.sharpness, 40);
  EXPECT_EQ(s.brightness, 60);
  EXPECT_EQ(s.contrast, 70);
  EXPECT_TRUE(s.denoise_on);
  EXPECT_EQ(s.denoise_level, 30);
  EXPECT_EQ(s.enhancement_level, 4);
  EXPECT_EQ(s.gain_mode, p::ThermalGainMode::kLow);
  EXPECT_EQ(s.measurement_type, p::ThermalMeasurementType::kArea);
  EXPECT_TRUE(s.high_alarm_on);
  EXPECT_DOUBLE_EQ(s.high_alarm_degC, 80);
  EXPECT_DOUBLE_EQ(s.low_alarm_degC, 5);
  EXPECT_FALSE(s.difference_alarm_on);
  EXPECT_TRUE(s.threshold_alarm_on);
  EXPECT_DOUBLE_EQ(s.threshold_float_degC, 10);

  p::ThermalSpotRequest spot;
  spot.x_px = 900;
  spot.y_px = 600;
  EXPECT_EQ(link.send(spot), ResponseCode::kOk);
  EXPECT_EQ(link.ask(p::ThermalReadSettingsRequest{}).measurement_type,
            p::ThermalMeasurementType::kPoint);
  EXPECT_TRUE(link.wait_report<p::ThermalStatus>(
      [](const p::ThermalStatus& t) { return t.point_x_px == 900 && t.point_y_px == 600; }));
  spot.x_px = 100;  // on the black border
  EXPECT_EQ(link.send(spot), ResponseCode::kFailure);
  EXPECT_EQ(link.send_raw(0x000106, {21, 0}), ResponseCode::kFailure);  // palette 21
}

TEST_F(SimConformance, ThermalMeasurementSwitchStartsAndStopsTheReport) {
  ASSERT_TRUE(link.wait_for([&] { return link.count(p::ThermalStatus::kId) > 0; }));
  EXPECT_EQ(link.send(request_with(&p::ThermalMeasurementRequest::measurement_on, false)),
            ResponseCode::kOk);
  // Other reports go on meanwhile; thermal ones do not. Frames arrive in the order they are sent,
  // so once a second of 5 Hz visible reports has come after the ACK, any thermal report that was
  // already on its way has arrived too (however late the client gets to read them).
  const auto visible_reports_after = [&](size_t from) {
    return link.wait_for([&] { return link.count(p::VisibleStatus::kId) >= from + 5; });
  };
  ASSERT_TRUE(visible_reports_after(link.count(p::VisibleStatus::kId)));
  const size_t after_off = link.count(p::ThermalStatus::kId);
  ASSERT_TRUE(visible_reports_after(link.count(p::VisibleStatus::kId)));
  EXPECT_EQ(link.count(p::ThermalStatus::kId), after_off);
  EXPECT_EQ(link.send(request_with(&p::ThermalMeasurementRequest::measurement_on, true)),
            ResponseCode::kOk);
  EXPECT_TRUE(link.wait_for([&] { return link.count(p::ThermalStatus::kId) > after_off; }));
}

TEST_F(SimConformance, ThermalStatsFollowTheSceneAndTripAlarms) {
  const World world;
  const Vec3 hot = world.hot_object_centre();
  const double yaw = std::round(yaw_of(hot) * 100) / 100;
  const double pitch = std::round(pitch_of(hot) * 100) / 100;
  aim(link, pitch, yaw);
  const auto on_target =
      link.wait_report<p::ThermalStatus>([](const p::ThermalStatus&) { return true; });
  ASSERT_TRUE(on_target);
  EXPECT_NEAR(on_target->max_degC, 85, 1);
  EXPECT_NEAR(on_target->max_x_px, 800, 4);
  EXPECT_NEAR(on_target->max_y_px, 528, 4);
  EXPECT_FALSE(on_target->high_alarm);

  aim(link, pitch, yaw + 5);  // the hot spot moves left in the image
  const auto turned =
      link.wait_report<p::ThermalStatus>([](const p::ThermalStatus&) { return true; });
  ASSERT_TRUE(turned);
  EXPECT_LT(turned->max_x_px, on_target->max_x_px - 100);
  EXPECT_NEAR(turned->max_degC, 85, 1);

  p::ThermalAlarmsRequest alarms;
  alarms.high_alarm_on = true;
  alarms.high_alarm_degC = 80;
  EXPECT_EQ(link.send(alarms), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::ThermalStatus>([](const p::ThermalStatus& t) { return t.high_alarm; }));
  alarms.high_alarm_degC = 90;
  EXPECT_EQ(link.send(alarms), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::ThermalStatus>([](const p::ThermalStatus& t) { return !t.high_alarm; }));
}

// ---- visible camera (3.2.3) -----------------------------------------------------------------

TEST_F(SimConformance, VisibleSettingsAreStoredReadBackAndReported) {
  p::VisibleEvRequest ev;
  ev.ev = p::ExposureValue::kPlus1;
  p::VisibleStrongLightRequest strong;
  strong.strong_light_on = true;
  strong.strong_light_value = 40;
  for (ResponseCode code :
       {link.send(request_with(&p::VisibleVideoResolutionRequest::video_resolution,
                               p::VideoResolution::k3840x2160)),
        link.send(request_with(&p::VisiblePhotoResolutionRequest::photo_resolution,
                               p::PhotoResolution::k8000x6000)),
        link.send(request_with(&p::VisibleIsoRequest::iso, p::Iso::k400)),
        link.send(request_with(&p::VisibleShutterRequest::shutter, p::Shutter::k1_1000)),
        link.send(ev),
        link.send(request_with(&p::VisibleWhiteBalanceRequest::white_balance,
                               p::WhiteBalance::kDaylight)),
        link.send(request_with(&p::VisibleAntiFlickerRequest::anti_flicker, p::AntiFlicker::k50Hz)),
        link.send(strong), link.send(request_with(&p::VisibleAeLockRequest::ae_lock_on, true)),
        link.send(request_with(&p::VisibleMeteringRequest::metering, p::MeteringMode::kAverage))}) {
    EXPECT_EQ(code, ResponseCode::kOk);
  }
  p::VisibleBacklightRequest backlight;
  backlight.backlight_on = true;
  backlight.backlight_value = 20;
  EXPECT_EQ(link.send(backlight), ResponseCode::kFailure);  // not with strong-light suppression

  const auto s = link.ask(p::VisibleReadSettingsRequest{});
  EXPECT_EQ(s.code, ResponseCode::kOk);
  EXPECT_TRUE(fields_are(s,
                         "video_resolution=3840x2160 photo_resolution=8000x6000 "
                         "iso=iso_400 shutter=1/1000 white_balance=daylight anti_flicker=50hz "
                         "strong_light_on=true strong_light_value=40 backlight_on=false "
                         "ae_lock_on=true metering=average"));
  EXPECT_EQ(s.ev, p::ExposureValue::kPlus1);  // not as text: "+1" and "-1" both read "1"

  const auto status =
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus&) { return true; });
  ASSERT_TRUE(status);
  EXPECT_EQ(status->shutter_us, 1000);
  EXPECT_NEAR(status->iso_db, 12.0, 0.05);
  EXPECT_EQ(status->ev, p::ExposureValue::kPlus1);
  EXPECT_TRUE(status->ae_lock_on);
  EXPECT_EQ(link.send_raw(0x000203, {0x00, 0x08}), ResponseCode::kFailure);  // ISO code 8
  EXPECT_EQ(link.send_raw(0x000203, {0x01, 0x03}), ResponseCode::kFailure);  // not "start setting"
}

TEST_F(SimConformance, ZoomAndFocusShowInTheVisibleStatus) {
  p::ZoomRatioRequest zoom;
  zoom.zoom_x = 4;
  EXPECT_EQ(link.send(zoom), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus& v) { return v.zooming; }));
  const auto done = link.wait_report<p::VisibleStatus>(
      [](const p::VisibleStatus& v) { return !v.zooming && near(v.zoom_x, 4, 0.01); });
  ASSERT_TRUE(done);
  EXPECT_NEAR(done->focal_length_mm, lens_spec(Lens::kTele).focal_length_mm * 4, 0.01);
  const auto frames = link.all<p::ZoomStatus>();
  ASSERT_GE(frames.size(), 2u);
  EXPECT_EQ(frames.front().progress, p::ZoomProgress::kZooming);
  EXPECT_EQ(frames.back().progress, p::ZoomProgress::kDone);

  zoom.zoom_x = 40;  // beyond the optical 11x: the focal length stops at 11x
  EXPECT_EQ(link.send(zoom), ResponseCode::kOk);
  const auto digital = link.wait_report<p::VisibleStatus>(
      [](const p::VisibleStatus& v) { return !v.zooming && near(v.zoom_x, 40, 0.01); });
  ASSERT_TRUE(digital);
  EXPECT_NEAR(digital->focal_length_mm, lens_spec(Lens::kTele).focal_length_mm * 11, 0.01);

  p::ContinuousZoomRequest out;
  out.command = p::ZoomCommand::kZoomOut;
  EXPECT_EQ(link.send(out), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus& v) { return v.zoom_x < 20; }));
  out.command = p::ZoomCommand::kStop;
  EXPECT_EQ(link.send(out), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus& v) { return !v.zooming; }));

  p::FocusRequest focus;
  focus.command = p::FocusCommand::kFinePlus;
  EXPECT_EQ(link.send(focus), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus& v) { return v.focusing; }));
  focus.command = p::FocusCommand::kFineStop;
  EXPECT_EQ(link.send(focus), ResponseCode::kOk);
  EXPECT_TRUE(
      link.wait_report<p::VisibleStatus>([](const p::VisibleStatus& v) { return !v.focusing; }));
}

}  // namespace
}  // namespace k40t::sim
