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
#include "sim_link_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using p::ResponseCode;
using testing::SimLink;
using namespace std::chrono_literals;

bool near(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance;
}

// Short calibrations and reboots keep the tests quick; the behaviour is the same.
SimOptions quick_pod() {
  SimOptions options;
  options.pod.gimbal.drift_calibration_s = 1;
  options.pod.gimbal.linear_calibration_s = 1;
  options.pod.gimbal.accelerometer_calibration_s = 1;
  options.pod.gimbal.restart_s = 1.2;  // two 2 Hz gimbal status reports see it
  options.pod.camera_boot_s = 1;
  return options;
}

p::GimbalAngleRequest angles(double pitch_deg, double yaw_deg) {
  p::GimbalAngleRequest request;
  request.pitch_deg = pitch_deg;
  request.yaw_deg = yaw_deg;
  return request;
}

// Turns the gimbal at full speed and waits until the attitude report shows it there.
void aim(SimLink& link, double pitch_deg, double yaw_deg) {
  p::GimbalDialSpeedRequest speed;
  speed.pitch_speed_deg_s = 30;
  speed.yaw_speed_deg_s = 30;
  ASSERT_EQ(link.send(speed), ResponseCode::kOk);
  ASSERT_EQ(link.send(angles(pitch_deg, yaw_deg)), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<p::GimbalAttitude>(
      [&](const p::GimbalAttitude& a) {
        return near(a.joint_pitch_deg, pitch_deg, 0.011) && near(a.joint_yaw_deg, yaw_deg, 0.011);
      },
      15s));
}

// ---- gimbal (3.1) ---------------------------------------------------------------------------

TEST(SimConformance, GimbalMovesAsCommandedAtTheDialSpeed) {
  SimLink link(quick_pod());
  p::GimbalDialSpeedRequest speed;
  speed.pitch_speed_deg_s = 10;
  speed.yaw_speed_deg_s = 20;
  EXPECT_EQ(link.send(speed), ResponseCode::kOk);
  EXPECT_EQ(link.send(angles(-10, 40)), ResponseCode::kOk);
  // Moving: the reported rates are the dial speeds.
  const auto moving = link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_yaw_deg > 5 && a.joint_yaw_deg < 15; });
  ASSERT_TRUE(moving);
  EXPECT_NEAR(moving->yaw_rate_deg_s, 20, 0.01);
  EXPECT_NEAR(moving->pitch_rate_deg_s, -10, 0.01);
  const auto there = link.wait_report<p::GimbalAttitude>([](const p::GimbalAttitude& a) {
    return near(a.joint_yaw_deg, 40, 0.001) && near(a.joint_pitch_deg, -10, 0.001);
  });
  ASSERT_TRUE(there);
  EXPECT_NEAR(there->yaw_deg, 40, 0.001);  // attitude: level vehicle heading north
  EXPECT_NEAR(there->pitch_deg, -10, 0.001);

  p::GimbalControlRequest right;
  right.yaw = p::GimbalYawDirection::kRight;
  EXPECT_EQ(link.send(right), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_yaw_deg > 45; }));
  EXPECT_EQ(link.send(p::GimbalControlRequest{}), ResponseCode::kOk);  // stop, stop
  ASSERT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.yaw_rate_deg_s == 0; }));

  speed.pitch_speed_deg_s = 30;
  speed.yaw_speed_deg_s = 30;
  EXPECT_EQ(link.send(speed), ResponseCode::kOk);
  p::GimbalControlRequest look_down;
  look_down.mode = p::GimbalMode::kLookDown;
  EXPECT_EQ(link.send(look_down), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_pitch_deg == -90 && a.joint_yaw_deg == 0; },
      15s));
  p::GimbalControlRequest centre;
  centre.mode = p::GimbalMode::kCentre;
  EXPECT_EQ(link.send(centre), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_pitch_deg == 0 && a.joint_yaw_deg == 0; },
      15s));
}

TEST(SimConformance, GimbalPointAtUsesTheLensFieldOfView) {
  SimLink link(quick_pod());
  p::GimbalDialSpeedRequest speed;
  speed.pitch_speed_deg_s = 30;
  speed.yaw_speed_deg_s = 30;
  ASSERT_EQ(link.send(speed), ResponseCode::kOk);
  p::GimbalPointAtRequest point;
  point.lens = p::GimbalAimLens::kThermal;
  point.zoom_x = 1;
  point.x_px = 1920;  // right edge: half the thermal field of view
  point.y_px = 540;
  EXPECT_EQ(link.send(point), ResponseCode::kOk);
  const double half_fov = field_of_view(Lens::kThermal, 1).horizontal_deg / 2;
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>([&](const p::GimbalAttitude& a) {
    return near(a.joint_yaw_deg, half_fov, 0.02) && a.yaw_rate_deg_s == 0;
  }));
}

TEST(SimConformance, GimbalServoStabilisationVersionAndRestart) {
  SimLink link(quick_pod());
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kStabilising && s.ir_ok && s.laser_ok &&
           s.gimbal_link == p::GimbalLinkState::kNormal &&
           s.camera_link == p::GimbalLinkState::kNormal;
  }));
  EXPECT_EQ(link.send(p::GimbalServoOffRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kOff;
  }));
  p::GimbalControlRequest centre;
  centre.mode = p::GimbalMode::kCentre;
  EXPECT_EQ(link.send(centre), ResponseCode::kOk);  // the servo comes back on
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kStabilising;
  }));
  p::GimbalStabilisationRequest stabilisation;
  stabilisation.enable = false;
  EXPECT_EQ(link.send(stabilisation), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kOff;
  }));

  const auto version = link.ask(p::GimbalVersionRequest{});
  EXPECT_EQ(version.code, ResponseCode::kOk);
  EXPECT_EQ(version.hardware_major, 1);
  EXPECT_EQ(version.hardware_minor, 2);
  EXPECT_EQ(version.software_major, 3);
  EXPECT_EQ(version.software_patch, 1);
  EXPECT_EQ(link.send(p::GimbalUseFlightControllerAttitudeRequest{}), ResponseCode::kOk);

  EXPECT_EQ(link.send(p::GimbalRestartRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.gimbal_link == p::GimbalLinkState::kAbnormal; }));
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.gimbal_link == p::GimbalLinkState::kNormal; }));
}

TEST(SimConformance, GimbalCalibrationsReportProgress) {
  SimLink link(quick_pod());
  EXPECT_EQ(link.send(p::GimbalDriftCalibrationRequest{}), ResponseCode::kOk);
  EXPECT_EQ(link.send(p::GimbalLinearCalibrationRequest{}), ResponseCode::kBusy);
  EXPECT_EQ(link.send(angles(0, 10)), ResponseCode::kBusy);
  ASSERT_TRUE(link.wait_report<p::CameraUpgradeStatus>([](const p::CameraUpgradeStatus& s) {
    return s.state == p::CameraUpgradeState::kSucceeded;
  }));
  const auto progress = link.all<p::CameraUpgradeStatus>();
  ASSERT_GE(progress.size(), 2u);
  EXPECT_EQ(progress.front().state, p::CameraUpgradeState::kRepairing);
  EXPECT_EQ(progress.back().progress_percent, 100);
  EXPECT_EQ(link.send(p::GimbalLinearCalibrationRequest{}), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_for([&] {
    const auto now = link.all<p::CameraUpgradeStatus>();
    return now.size() > progress.size() && now.back().state == p::CameraUpgradeState::kSucceeded;
  }));
  EXPECT_EQ(link.send(p::GimbalAccelerationCalibrationRequest{}), ResponseCode::kOk);
}

TEST(SimConformance, GimbalRefusesWhatTheDocumentDoesNotAllow) {
  SimLink link(quick_pod());
  EXPECT_EQ(link.send_raw(0x000017, {200, 10, 0}), ResponseCode::kFailure);  // dial speed 40 deg/s
  EXPECT_EQ(link.send_raw(0x000012, {0x00, 0x10, 0x27}),
            ResponseCode::kLengthMismatch);  // 3 of 6 bytes
  EXPECT_EQ(link.send_raw(0x000012, {0x00, 0xB9, 0x0B, 0x02, 0, 0, 0}),
            ResponseCode::kFailure);  // up 30.01 deg
  EXPECT_EQ(link.send_raw(0x000010, {0x30, 0x02, 0x02, 0x00}), ResponseCode::kFailure);  // mode 3
}

// ---- thermal camera (3.2.2) -----------------------------------------------------------------

TEST(SimConformance, ThermalSettingsAreStoredAndReadBack) {
  SimLink link(quick_pod());
  auto defaults = link.ask(p::ThermalReadSettingsRequest{});
  EXPECT_EQ(defaults.code, ResponseCode::kOk);
  EXPECT_EQ(defaults.palette, p::Palette::kWhiteHot);
  EXPECT_TRUE(defaults.measurement_on);
  EXPECT_FALSE(defaults.high_alarm_on);

  p::ThermalPaletteRequest palette;
  palette.palette = p::Palette::kIronRed;
  p::ThermalZoomRequest zoom;
  zoom.zoom_x = 2;
  p::ThermalSharpnessRequest sharpness;
  sharpness.sharpness = 40;
  p::ThermalBrightnessRequest brightness;
  brightness.brightness = 60;
  p::ThermalContrastRequest contrast;
  contrast.contrast = 70;
  p::ThermalDenoiseRequest denoise;
  denoise.denoise_on = true;
  denoise.denoise_level = 30;
  p::ThermalEnhancementRequest enhancement;
  enhancement.enhancement_level = 4;
  p::ThermalGainModeRequest gain;
  gain.gain_mode = p::ThermalGainMode::kLow;
  p::ThermalOverlayRequest overlay;
  overlay.overlay_on = true;
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
       {link.send(palette), link.send(zoom), link.send(sharpness), link.send(brightness),
        link.send(contrast), link.send(denoise), link.send(enhancement), link.send(gain),
        link.send(overlay), link.send(alarms), link.send(threshold), link.send(area)}) {
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

TEST(SimConformance, ThermalMeasurementSwitchStartsAndStopsTheReport) {
  SimLink link(quick_pod());
  ASSERT_TRUE(link.wait_for([&] { return link.count(p::ThermalStatus::kId) > 0; }));
  p::ThermalMeasurementRequest off;
  off.measurement_on = false;
  EXPECT_EQ(link.send(off), ResponseCode::kOk);
  std::this_thread::sleep_for(300ms);  // frames already on their way
  const size_t after_off = link.count(p::ThermalStatus::kId);
  // Other reports go on meanwhile; thermal ones do not.
  const size_t visible_before = link.count(p::VisibleStatus::kId);
  ASSERT_TRUE(
      link.wait_for([&] { return link.count(p::VisibleStatus::kId) >= visible_before + 5; }));
  EXPECT_EQ(link.count(p::ThermalStatus::kId), after_off);
  p::ThermalMeasurementRequest on;
  on.measurement_on = true;
  EXPECT_EQ(link.send(on), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_for([&] { return link.count(p::ThermalStatus::kId) > after_off; }));
}

TEST(SimConformance, ThermalStatsFollowTheSceneAndTripAlarms) {
  SimLink link(quick_pod());
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

TEST(SimConformance, VisibleSettingsAreStoredReadBackAndReported) {
  SimLink link(quick_pod());
  p::VisibleVideoResolutionRequest video;
  video.video_resolution = p::VideoResolution::k3840x2160;
  p::VisiblePhotoResolutionRequest photo;
  photo.photo_resolution = p::PhotoResolution::k8000x6000;
  p::VisibleIsoRequest iso;
  iso.iso = p::Iso::k400;
  p::VisibleShutterRequest shutter;
  shutter.shutter = p::Shutter::k1_1000;
  p::VisibleEvRequest ev;
  ev.ev = p::ExposureValue::kPlus1;
  p::VisibleWhiteBalanceRequest white;
  white.white_balance = p::WhiteBalance::kDaylight;
  p::VisibleAntiFlickerRequest flicker;
  flicker.anti_flicker = p::AntiFlicker::k50Hz;
  p::VisibleStrongLightRequest strong;
  strong.strong_light_on = true;
  strong.strong_light_value = 40;
  p::VisibleAeLockRequest ae;
  ae.ae_lock_on = true;
  p::VisibleMeteringRequest metering;
  metering.metering = p::MeteringMode::kAverage;
  for (ResponseCode code : {link.send(video), link.send(photo), link.send(iso), link.send(shutter),
                            link.send(ev), link.send(white), link.send(flicker), link.send(strong),
                            link.send(ae), link.send(metering)}) {
    EXPECT_EQ(code, ResponseCode::kOk);
  }
  p::VisibleBacklightRequest backlight;
  backlight.backlight_on = true;
  backlight.backlight_value = 20;
  EXPECT_EQ(link.send(backlight), ResponseCode::kFailure);  // not with strong-light suppression

  const auto s = link.ask(p::VisibleReadSettingsRequest{});
  EXPECT_EQ(s.code, ResponseCode::kOk);
  EXPECT_EQ(s.video_resolution, p::VideoResolution::k3840x2160);
  EXPECT_EQ(s.photo_resolution, p::PhotoResolution::k8000x6000);
  EXPECT_EQ(s.iso, p::Iso::k400);
  EXPECT_EQ(s.shutter, p::Shutter::k1_1000);
  EXPECT_EQ(s.ev, p::ExposureValue::kPlus1);
  EXPECT_EQ(s.white_balance, p::WhiteBalance::kDaylight);
  EXPECT_EQ(s.anti_flicker, p::AntiFlicker::k50Hz);
  EXPECT_TRUE(s.strong_light_on);
  EXPECT_EQ(s.strong_light_value, 40);
  EXPECT_FALSE(s.backlight_on);
  EXPECT_TRUE(s.ae_lock_on);
  EXPECT_EQ(s.metering, p::MeteringMode::kAverage);

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

TEST(SimConformance, ZoomAndFocusShowInTheVisibleStatus) {
  SimLink link(quick_pod());
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

// ---- common camera part (3.2.4) -------------------------------------------------------------

TEST(SimConformance, PhotosAskForGpsAndRecordTheAnswer) {
  SimLink link(quick_pod());
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
  EXPECT_NEAR(taken->gps->latitude_deg, testing::kHostLatitudeDeg, 1e-7);
  EXPECT_NEAR(taken->gps->longitude_deg, testing::kHostLongitudeDeg, 1e-7);
  EXPECT_NEAR(taken->gps->altitude_m, testing::kHostAltitudeM, 0.1);
  EXPECT_EQ(taken->path.rfind("survey/IMG_20250304_0506", 0), 0u) << taken->path;
  EXPECT_TRUE(link.all<p::PhotoStatus>().empty());  // no status frame for a single shot
}

TEST(SimConformance, BurstRecordingAndModeRules) {
  SimLink link(quick_pod());
  p::PhotoSettingsRequest burst;
  burst.photo_mode = p::PhotoMode::kBurst;
  burst.burst_count = 3;
  EXPECT_EQ(link.send(burst), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>([](const p::CameraSystemStatus& s) {
    return s.photo_mode == p::PhotoMode::kBurst && s.burst_count == 3;
  }));
  p::TakePhotoRequest photo;
  photo.lens = p::PhotoLensMode::kInfrared;
  EXPECT_EQ(link.send(photo), ResponseCode::kOk);
  EXPECT_EQ(link.send(photo), ResponseCode::kPhotoInProgress);
  ASSERT_TRUE(link.wait_report<p::PhotoStatus>(
      [](const p::PhotoStatus& s) { return s.state == p::PhotoState::kDone; }));
  const auto statuses = link.all<p::PhotoStatus>();
  ASSERT_EQ(statuses.size(), 4u);
  EXPECT_EQ(statuses[0].state, p::PhotoState::kBurst);
  EXPECT_EQ(statuses[2].burst_count, 3);
  EXPECT_EQ(statuses[3].lens, p::PhotoLensMode::kInfrared);
  EXPECT_TRUE(link.wait_for([&] { return link.gps_answers() == 3; }));

  p::RecordRequest record;
  record.lens = p::RecordLensMode::kVisible;
  record.action = p::RecordAction::kStart;
  EXPECT_EQ(link.send(record), ResponseCode::kFailure);  // photo mode
  p::CaptureModeRequest video;
  video.mode = p::CaptureMode::kVideo;
  EXPECT_EQ(link.send(video), ResponseCode::kOk);
  EXPECT_EQ(link.send(record), ResponseCode::kOk);
  EXPECT_EQ(link.send(photo), ResponseCode::kRecording);
  EXPECT_TRUE(link.wait_report<p::RecordStatus>(
      [](const p::RecordStatus& r) { return r.recording_time_s == 2; }));
  record.action = p::RecordAction::kStop;
  EXPECT_EQ(link.send(record), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::RecordStatus>(
      [](const p::RecordStatus& r) { return r.state == p::RecordState::kStopped; }));
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.capture_mode == p::CaptureMode::kVideo; }));
  link.server().with_model([](PodModel& pod) {
    ASSERT_EQ(pod.camera().videos().size(), 1u);
    EXPECT_GE(pod.camera().videos()[0].seconds, 2.0);
    EXPECT_GT(pod.camera().videos()[0].size_mb, 2.0);  // 1080p at 8 Mbit/s
    EXPECT_EQ(pod.camera().photos().size(), 3u);
  });
}

TEST(SimConformance, StreamNetworkAiAndSystemRequests) {
  SimLink link(quick_pod());
  p::StreamBitrateRequest bitrate;
  bitrate.bitrate = p::StreamBitrate::k2Mbps;
  p::StreamResolutionRequest resolution;
  resolution.resolution = p::StreamResolution::k1080p30;
  p::StreamEncodingRequest encoding;
  encoding.encoding = p::VideoEncoding::kH265;
  p::ImageModeRequest image;
  image.mode = p::ImageMode::kInfrared;
  p::OsdWatermarkRequest osd;
  osd.enabled = true;
  for (ResponseCode code : {link.send(bitrate), link.send(resolution), link.send(encoding),
                            link.send(image), link.send(osd)}) {
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
  p::AiRecognitionRequest ai;
  ai.recognition = p::FeatureSwitch::kOn;
  EXPECT_EQ(link.send(ai), ResponseCode::kOk);
  EXPECT_EQ(link.send(track), ResponseCode::kOk);

  p::PreciseReshootRequest reshoot;
  reshoot.lens = p::PhotoLensMode::kVisible;
  reshoot.zoom_x = 2;
  reshoot.focal_length_raw = 940;
  EXPECT_EQ(link.send(reshoot), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::PreciseReshootStatus>(
      [](const p::PreciseReshootStatus& s) { return s.state == p::ReshootState::kDone; }));
  EXPECT_TRUE(link.wait_report<p::VisibleStatus>(
      [](const p::VisibleStatus& v) { return near(v.precise_shot_focal_length_mm, 9.40, 0.001); }));
}

TEST(SimConformance, SdCardFormatAndUpgrade) {
  SimLink link(quick_pod());
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kOk);
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kBusy);
  EXPECT_TRUE(link.wait_report<p::SdFormatStatus>(
      [](const p::SdFormatStatus& s) { return s.state == p::SdFormatState::kDone; }));
  EXPECT_GE(link.all<p::SdFormatStatus>().size(), 5u);  // 2 s at 5 Hz
  EXPECT_EQ(link.send(p::TfCardUpgradeRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::TfCardUpgradeStatus>(
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

TEST(SimConformance, NoSdCardRefusesPhotos) {
  SimOptions options = quick_pod();
  options.sd_condition = "absent";
  SimLink link(options);
  EXPECT_EQ(link.send(p::TakePhotoRequest{}), ResponseCode::kNoSdCard);
  EXPECT_EQ(link.send(p::FormatSdRequest{}), ResponseCode::kNoSdCard);
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>([](const p::CameraSystemStatus& s) {
    return s.sd_state == p::SdCardState::kMissing && s.sd_total_mb == 0;
  }));
}

TEST(SimConformance, ShutdownAndFactoryReset) {
  SimLink link(quick_pod());
  p::CaptureModeRequest video;
  video.mode = p::CaptureMode::kVideo;
  EXPECT_EQ(link.send(video), ResponseCode::kOk);
  EXPECT_EQ(link.send(p::FactoryResetRequest{}), ResponseCode::kOk);
  // The camera restarts: its link drops in 0x000001, then it comes back with factory settings.
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.camera_link == p::GimbalLinkState::kAbnormal; }));
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.capture_mode == p::CaptureMode::kPhoto; }));

  EXPECT_EQ(link.send(p::ShutdownRequest{}), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.camera_link == p::GimbalLinkState::kAbnormal; }));
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), ResponseCode::kTimeout);  // nobody answers
  EXPECT_EQ(link.ask(p::GimbalVersionRequest{}).code, ResponseCode::kOk);   // the gimbal does
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.camera_link == p::GimbalLinkState::kNormal; }));
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), ResponseCode::kOk);
}

TEST(SimConformance, TargetPositionFromTheLaser) {
  SimLink link(quick_pod());
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

TEST(SimConformance, LaserRangesTheWorld) {
  SimLink link(quick_pod());
  aim(link, -30, 60);  // clear of both objects: flat ground 30 m below
  const auto single = link.ask(p::LaserRangeRequest{});
  EXPECT_EQ(single.code, ResponseCode::kOk);
  EXPECT_NEAR(single.distance_m, 60.0, 0.05);  // 30 / sin(30 deg)
  p::LaserPeriodicRangeRequest periodic;
  periodic.enable = true;
  EXPECT_EQ(link.send(periodic), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_for([&] { return link.count(p::LaserPeriodicRangeStatus::kId) >= 2; }, 4s));
  EXPECT_NEAR(link.latest<p::LaserPeriodicRangeStatus>()->distance_m, 60.0, 0.05);
  aim(link, 10, 60);  // above the horizon: no return
  EXPECT_TRUE(link.wait_report<p::LaserPeriodicRangeStatus>(
      [](const p::LaserPeriodicRangeStatus& s) { return s.distance_m == 0; }, 4s));
  EXPECT_EQ(link.ask(p::LaserRangeRequest{}).distance_m, 0);
  periodic.enable = false;
  EXPECT_EQ(link.send(periodic), ResponseCode::kOk);
}

TEST(SimConformance, SbusConfigurationIsStoredAndReadBack) {
  SimLink link(quick_pod());
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

TEST(SimConformance, UnknownIdsAreIgnored) {
  session::SessionOptions client;
  client.ack_timeout = 200ms;
  client.retries = 0;
  SimLink link(quick_pod(), client);
  EXPECT_EQ(link.send_raw(0x0003F0, {0x01, 0x00}), ResponseCode::kTimeout);
  EXPECT_EQ(link.send_raw(0x000017, {50, 50, 0}), ResponseCode::kOk);  // still talking
}

TEST(SimConformance, WholeFrameCoverageIsDetectedByAnAutoClient) {
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

TEST(SimConformance, LittleEndianAcks) {
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
  p::CaptureModeRequest video;
  video.mode = p::CaptureMode::kVideo;
  EXPECT_EQ(link.send(video), ResponseCode::kPhotoInProgress);  // 0x0203, read little-endian
}

}  // namespace
}  // namespace k40t::sim
