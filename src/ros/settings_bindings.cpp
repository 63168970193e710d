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
      fields<p::PhotoSettingsRequest>(
          "photo_mode", from(&p::PhotoSettingsRequest::photo_mode, &C::photo_mode),
          from(&p::PhotoSettingsRequest::time_lapse_interval_s, &C::timelapse_interval),
          from(&p::PhotoSettingsRequest::burst_count, &C::burst_count))
          .reads<Camera>(&Camera::photo_mode, &Camera::time_lapse_interval_s, &Camera::burst_count)
          .service("set_photo_mode"),
      one_field<p::GimbalStabilisationRequest>(
          "stabilisation", &p::GimbalStabilisationRequest::enable, &C::stabilisation)
          // Only "stabilising" is on: 2 (failed) and 3 (feature lost) are not stabilising
          // (0x000001 byte 4, section 3.1.1.1); switching it on again retries. Why it is not is
          // the diagnostics' "stabilisation" check.
          .reads_with<Gimbal>([](C& c, const Gimbal& g) {
            c.stabilisation = g.stabilisation == p::GimbalStabilisationState::kStabilising;
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
      fields<p::ThermalDenoiseRequest>(
          "thermal_denoise", from(&p::ThermalDenoiseRequest::denoise_on, &C::thermal_denoise),
          from(&p::ThermalDenoiseRequest::denoise_level, &C::thermal_denoise_level))
          .reads(&Thermal::denoise_on, &Thermal::denoise_level),
      one_field<p::ThermalEnhancementRequest>("thermal_enhancement",
                                              &p::ThermalEnhancementRequest::enhancement_level,
                                              &C::thermal_enhancement)
          .reads_with<Thermal>([](C& c, const Thermal& t) {
            c.thermal_enhancement = t.enhancement_on ? t.enhancement_level : 0;
          }),
      one_field<p::ThermalOverlayRequest>("thermal_overlay", &p::ThermalOverlayRequest::overlay_on,
                                          &C::thermal_overlay)
          .write_only(),
      fields<p::ThermalAlarmsRequest>(
          "temperature_alarms", from(&p::ThermalAlarmsRequest::high_alarm_on, &C::high_alarm),
          from(&p::ThermalAlarmsRequest::high_alarm_degC, &C::high_alarm_degC),
          from(&p::ThermalAlarmsRequest::low_alarm_on, &C::low_alarm),
          from(&p::ThermalAlarmsRequest::low_alarm_degC, &C::low_alarm_degC),
          from(&p::ThermalAlarmsRequest::difference_alarm_on, &C::difference_alarm),
          from(&p::ThermalAlarmsRequest::difference_alarm_degC, &C::difference_alarm_degC))
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
      fields<p::ThermalThresholdAlarmRequest>(
          "threshold_alarm",
          from(&p::ThermalThresholdAlarmRequest::threshold_alarm_on, &C::threshold_alarm),
          from(&p::ThermalThresholdAlarmRequest::threshold_reference_degC,
               &C::threshold_reference_degC),
          from(&p::ThermalThresholdAlarmRequest::threshold_float_degC, &C::threshold_float_degC))
          .reads(&Thermal::threshold_alarm_on, &Thermal::threshold_reference_degC,
                 &Thermal::threshold_float_degC),
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
      fields<p::VisibleStrongLightRequest>(
          "strong_light_suppression",
          from(&p::VisibleStrongLightRequest::strong_light_on, &C::strong_light_suppression),
          from(&p::VisibleStrongLightRequest::strong_light_value, &C::strong_light_level))
          .reads(&Visible::strong_light_on, &Visible::strong_light_value)
          .sent_first_when_off(&C::strong_light_suppression),
      fields<p::VisibleBacklightRequest>(
          "backlight_compensation",
          from(&p::VisibleBacklightRequest::backlight_on, &C::backlight_compensation),
          from(&p::VisibleBacklightRequest::backlight_value, &C::backlight_level))
          .reads(&Visible::backlight_on, &Visible::backlight_value)
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
