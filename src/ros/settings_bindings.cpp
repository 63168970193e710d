// The settings table: each dynamic_reconfigure parameter group of cfg/K40t.cfg, the request that
// sets it, the report that reads it back (or write_only()) and the service that also writes it,
// in one entry. Everything else about settings is derived from it (setting_binding.h).
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "setting_builder.h"

namespace k40t::driver {

namespace p = protocol;
using namespace setting_table;  // NOLINT: the table's vocabulary

namespace {

using C = Config;
using Thermal = p::ThermalSettingsAck;  // 0x010100
using Visible = p::VisibleSettingsAck;  // 0x010200
using Camera = p::CameraSystemStatus;   // 0x000003
using Gimbal = p::GimbalStatus;         // 0x000001

std::vector<SettingBinding> general_and_gimbal() {
  return {
      one_field<p::ImageModeRequest>("image_mode", &p::ImageModeRequest::mode, &C::image_mode)
          .reads(&Camera::image_mode),
      one_field<p::CaptureModeRequest>("camera_mode", &p::CaptureModeRequest::mode, &C::camera_mode)
          .reads(&Camera::capture_mode),
      one_field<p::OsdWatermarkRequest>("osd_watermark", &p::OsdWatermarkRequest::enabled,
                                        &C::osd_watermark)
          .reads(&Visible::watermark_on),
      one_field<p::LaserPeriodicRangeRequest>(
          "periodic_ranging", &p::LaserPeriodicRangeRequest::enable, &C::periodic_ranging)
          .write_only(),
      group(
          "photo_mode",
          [](const C& c) {
            p::PhotoSettingsRequest r;
            r.photo_mode = static_cast<p::PhotoMode>(c.photo_mode);
            r.time_lapse_interval_s = static_cast<uint8_t>(c.timelapse_interval);
            r.burst_count = static_cast<uint8_t>(c.burst_count);
            return r;
          },
          &C::photo_mode, &C::timelapse_interval, &C::burst_count)
          .reads_with<Camera>([](C& c, const Camera& s) {
            c.photo_mode = static_cast<int>(s.photo_mode);
            c.timelapse_interval = s.time_lapse_interval_s;
            c.burst_count = s.burst_count;
          })
          .service("set_photo_mode"),
      one_field<p::GimbalStabilisationRequest>(
          "stabilisation", &p::GimbalStabilisationRequest::enable, &C::stabilisation)
          .reads_with<Gimbal>([](C& c, const Gimbal& g) {
            c.stabilisation = g.stabilisation != p::GimbalStabilisationState::kOff;
          }),
      group(
          "dial_speed",
          [](const C& c) {
            p::GimbalDialSpeedRequest r;  // the parameters are in wire units (deg/s x5)
            r.pitch_speed_deg_s = c.pitch_dial_speed / p::GimbalDialSpeedRequest::kWirePerDegS;
            r.yaw_speed_deg_s = c.yaw_dial_speed / p::GimbalDialSpeedRequest::kWirePerDegS;
            return r;
          },
          &C::pitch_dial_speed, &C::yaw_dial_speed)
          .write_only(),
  };
}

std::vector<SettingBinding> thermal() {
  return {
      one_field<p::ThermalPaletteRequest>("palette", &p::ThermalPaletteRequest::palette,
                                          &C::palette)
          .reads(&Thermal::palette)
          .service("set_palette"),
      one_field<p::ThermalZoomRequest>("thermal_zoom", &p::ThermalZoomRequest::zoom_x,
                                       &C::thermal_zoom)
          .reads(&Thermal::zoom_x),
      one_field<p::ThermalMeasurementRequest>("thermal_measurement",
                                              &p::ThermalMeasurementRequest::measurement_on,
                                              &C::thermal_measurement)
          .reads(&Thermal::measurement_on),
      one_field<p::ThermalGainModeRequest>("thermal_gain", &p::ThermalGainModeRequest::gain_mode,
                                           &C::thermal_gain)
          .reads(&Thermal::gain_mode),
      one_field<p::ThermalSharpnessRequest>(
          "thermal_sharpness", &p::ThermalSharpnessRequest::sharpness, &C::thermal_sharpness)
          .reads(&Thermal::sharpness),
      one_field<p::ThermalBrightnessRequest>(
          "thermal_brightness", &p::ThermalBrightnessRequest::brightness, &C::thermal_brightness)
          .reads(&Thermal::brightness),
      one_field<p::ThermalContrastRequest>("thermal_contrast", &p::ThermalContrastRequest::contrast,
                                           &C::thermal_contrast)
          .reads(&Thermal::contrast),
      group(
          "thermal_denoise",
          [](const C& c) {
            p::ThermalDenoiseRequest r;
            r.denoise_on = c.thermal_denoise;
            r.denoise_level = static_cast<uint8_t>(c.thermal_denoise_level);
            return r;
          },
          &C::thermal_denoise, &C::thermal_denoise_level)
          .reads_with<Thermal>([](C& c, const Thermal& t) {
            c.thermal_denoise = t.denoise_on;
            c.thermal_denoise_level = t.denoise_level;
          }),
      one_field<p::ThermalEnhancementRequest>("thermal_enhancement",
                                              &p::ThermalEnhancementRequest::enhancement_level,
                                              &C::thermal_enhancement)
          .reads_with<Thermal>([](C& c, const Thermal& t) {
            c.thermal_enhancement = t.enhancement_on ? t.enhancement_level : 0;
          }),
      one_field<p::ThermalOverlayRequest>("thermal_overlay", &p::ThermalOverlayRequest::overlay_on,
                                          &C::thermal_overlay)
          .write_only(),
      group(
          "temperature_alarms",
          [](const C& c) {
            p::ThermalAlarmsRequest r;
            r.high_alarm_on = c.high_alarm;
            r.high_alarm_degC = c.high_alarm_degC;
            r.low_alarm_on = c.low_alarm;
            r.low_alarm_degC = c.low_alarm_degC;
            r.difference_alarm_on = c.difference_alarm;
            r.difference_alarm_degC = c.difference_alarm_degC;
            return r;
          },
          &C::high_alarm, &C::high_alarm_degC, &C::low_alarm, &C::low_alarm_degC,
          &C::difference_alarm, &C::difference_alarm_degC)
          .reads_with<Thermal>([](C& c, const Thermal& t) {
            // A switched-off alarm carries no threshold (-273.2 degC on the wire): keep the
            // parameter's.
            c.high_alarm = t.high_alarm_on;
            if (t.high_alarm_on) c.high_alarm_degC = t.high_alarm_degC;
            c.low_alarm = t.low_alarm_on;
            if (t.low_alarm_on) c.low_alarm_degC = t.low_alarm_degC;
            c.difference_alarm = t.difference_alarm_on;
            if (t.difference_alarm_on) c.difference_alarm_degC = t.difference_alarm_degC;
          }),
      group(
          "threshold_alarm",
          [](const C& c) {
            p::ThermalThresholdAlarmRequest r;
            r.threshold_alarm_on = c.threshold_alarm;
            r.threshold_reference_degC = c.threshold_reference_degC;
            r.threshold_float_degC = c.threshold_float_degC;
            return r;
          },
          &C::threshold_alarm, &C::threshold_reference_degC, &C::threshold_float_degC)
          .reads_with<Thermal>([](C& c, const Thermal& t) {
            c.threshold_alarm = t.threshold_alarm_on;
            c.threshold_reference_degC = t.threshold_reference_degC;
            c.threshold_float_degC = t.threshold_float_degC;
          }),
  };
}

std::vector<SettingBinding> visible() {
  return {
      one_field<p::VisibleVideoResolutionRequest>(
          "video_resolution", &p::VisibleVideoResolutionRequest::video_resolution,
          &C::video_resolution)
          .reads(&Visible::video_resolution),
      one_field<p::VisiblePhotoResolutionRequest>(
          "photo_resolution", &p::VisiblePhotoResolutionRequest::photo_resolution,
          &C::photo_resolution)
          .reads(&Visible::photo_resolution),
      one_field<p::VisibleIsoRequest>("iso", &p::VisibleIsoRequest::iso, &C::iso)
          .reads(&Visible::iso),
      one_field<p::VisibleShutterRequest>("shutter", &p::VisibleShutterRequest::shutter,
                                          &C::shutter)
          .reads(&Visible::shutter),
      one_field<p::VisibleEvRequest>("ev", &p::VisibleEvRequest::ev, &C::ev).reads(&Visible::ev),
      one_field<p::VisibleWhiteBalanceRequest>(
          "white_balance", &p::VisibleWhiteBalanceRequest::white_balance, &C::white_balance)
          .reads(&Visible::white_balance),
      one_field<p::VisibleAntiFlickerRequest>(
          "anti_flicker", &p::VisibleAntiFlickerRequest::anti_flicker, &C::anti_flicker)
          .reads(&Visible::anti_flicker),
      group(
          "strong_light_suppression",
          [](const C& c) {
            p::VisibleStrongLightRequest r;
            r.strong_light_on = c.strong_light_suppression;
            r.strong_light_value = static_cast<uint8_t>(c.strong_light_level);
            return r;
          },
          &C::strong_light_suppression, &C::strong_light_level)
          .reads_with<Visible>([](C& c, const Visible& v) {
            c.strong_light_suppression = v.strong_light_on;
            c.strong_light_level = v.strong_light_value;
          })
          .sent_first_when_off(&C::strong_light_suppression),
      group(
          "backlight_compensation",
          [](const C& c) {
            p::VisibleBacklightRequest r;
            r.backlight_on = c.backlight_compensation;
            r.backlight_value = static_cast<uint8_t>(c.backlight_level);
            return r;
          },
          &C::backlight_compensation, &C::backlight_level)
          .reads_with<Visible>([](C& c, const Visible& v) {
            c.backlight_compensation = v.backlight_on;
            c.backlight_level = v.backlight_value;
          })
          .sent_first_when_off(&C::backlight_compensation),
      one_field<p::VisibleAeLockRequest>("ae_lock", &p::VisibleAeLockRequest::ae_lock_on,
                                         &C::ae_lock)
          .reads(&Visible::ae_lock_on),
      one_field<p::VisibleMeteringRequest>("metering", &p::VisibleMeteringRequest::metering,
                                           &C::metering)
          .reads(&Visible::metering),
  };
}

std::vector<SettingBinding> stream() {
  return {
      one_field<p::StreamBitrateRequest>("stream_bitrate", &p::StreamBitrateRequest::bitrate,
                                         &C::stream_bitrate)
          .reads(&Camera::bitrate),
      one_field<p::StreamResolutionRequest>(
          "stream_resolution", &p::StreamResolutionRequest::resolution, &C::stream_resolution)
          .reads_with<Camera>([](C& c, const Camera& s) {
            // The report codes the resolution 0/1, the setting request 1/2 (3.2.1.1, 3.2.4.9).
            c.stream_resolution =
                s.stream_resolution == p::ReportedStreamResolution::k720p30 ? 2 : 1;
          }),
      one_field<p::StreamEncodingRequest>("stream_encoding", &p::StreamEncodingRequest::encoding,
                                          &C::stream_encoding)
          .reads(&Camera::encoding),
  };
}

}  // namespace

const std::vector<SettingBinding>& setting_bindings() {
  static const std::vector<SettingBinding> table = [] {
    std::vector<SettingBinding> all;
    for (auto part : {general_and_gimbal, thermal, visible, stream}) {
      for (SettingBinding& binding : part()) all.push_back(std::move(binding));
    }
    return all;
  }();
  return table;
}

}  // namespace k40t::driver
