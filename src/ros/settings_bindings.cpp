// Each dynamic_reconfigure parameter of cfg/K40t.cfg bound to the request that sets it, and the
// pod's reports read back into the parameters.
#include <cmath>
#include <type_traits>

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/ros/settings_sync.h"

namespace k40t::driver {

namespace p = protocol;

namespace {

// `next` is `current` moved into the cfg range [lo, hi] by dynamic_reconfigure's clamp: current
// was outside it and next is the nearest bound.
template <class T>
bool clamped_from(const T& next, const T& current, const T& lo, const T& hi) {
  if (next == current) return true;
  if (current < lo) return next == lo;
  if (hi < current) return next == hi;
  return false;
}

// A binding for the parameters `members`, sent together as the request build(config) returns.
template <class Build, class... Members>
SettingBinding bind(std::string name, Build build, Members... members) {
  SettingBinding b;
  b.name = std::move(name);
  b.differs = [=](const Config& a, const Config& c) { return ((a.*members != c.*members) || ...); };
  b.copy = [=](Config& to, const Config& from) { ((to.*members = from.*members), ...); };
  b.apply = [build](PodDriver& driver, const Config& c) { return driver.request(build(c)); };
  b.only_clamped = [=](const Config& next, const Config& current) {
    const Config& lo = Config::__getMin__();
    const Config& hi = Config::__getMax__();
    return (clamped_from(next.*members, current.*members, lo.*members, hi.*members) && ...);
  };
  return b;
}

// For one of two settings the pod will not have on at once (3.2.3.9/3.2.3.10 note).
template <class Member>
std::function<bool(const Config&, const Config&)> turned_off(Member member) {
  return [member](const Config& next, const Config& current) {
    return current.*member && !(next.*member);
  };
}

// The common case: one parameter, one request field (enums, switches and levels alike).
template <class Req, class ReqField, class ConfigField>
SettingBinding bind_field(std::string name, ReqField field, ConfigField Config::*member) {
  return bind(
      std::move(name),
      [field, member](const Config& c) {
        Req r;
        r.*field = static_cast<std::decay_t<decltype(r.*field)>>(c.*member);
        return r;
      },
      member);
}

template <class E>
int value(E code) {
  return static_cast<int>(code);
}

std::vector<SettingBinding> make_bindings() {
  using C = Config;
  std::vector<SettingBinding> b;
  // general
  b.push_back(
      bind_field<p::ImageModeRequest>("image_mode", &p::ImageModeRequest::mode, &C::image_mode));
  b.push_back(bind_field<p::CaptureModeRequest>("camera_mode", &p::CaptureModeRequest::mode,
                                                &C::camera_mode));
  b.push_back(bind_field<p::OsdWatermarkRequest>("osd_watermark", &p::OsdWatermarkRequest::enabled,
                                                 &C::osd_watermark));
  b.push_back(bind_field<p::LaserPeriodicRangeRequest>(
      "periodic_ranging", &p::LaserPeriodicRangeRequest::enable, &C::periodic_ranging));
  // photo
  b.push_back(bind(
      "photo_mode",
      [](const C& c) {
        p::PhotoSettingsRequest r;
        r.photo_mode = static_cast<p::PhotoMode>(c.photo_mode);
        r.time_lapse_interval_s = static_cast<uint8_t>(c.timelapse_interval);
        r.burst_count = static_cast<uint8_t>(c.burst_count);
        return r;
      },
      &C::photo_mode, &C::timelapse_interval, &C::burst_count));
  // gimbal
  b.push_back(bind_field<p::GimbalStabilisationRequest>(
      "stabilisation", &p::GimbalStabilisationRequest::enable, &C::stabilisation));
  b.push_back(bind(
      "dial_speed",
      [](const C& c) {
        p::GimbalDialSpeedRequest r;  // the parameters are in wire units (deg/s x5)
        r.pitch_speed_deg_s = c.pitch_dial_speed / p::GimbalDialSpeedRequest::kWirePerDegS;
        r.yaw_speed_deg_s = c.yaw_dial_speed / p::GimbalDialSpeedRequest::kWirePerDegS;
        return r;
      },
      &C::pitch_dial_speed, &C::yaw_dial_speed));
  // thermal
  b.push_back(bind_field<p::ThermalPaletteRequest>("palette", &p::ThermalPaletteRequest::palette,
                                                   &C::palette));
  b.push_back(bind_field<p::ThermalZoomRequest>("thermal_zoom", &p::ThermalZoomRequest::zoom_x,
                                                &C::thermal_zoom));
  b.push_back(bind_field<p::ThermalMeasurementRequest>(
      "thermal_measurement", &p::ThermalMeasurementRequest::measurement_on,
      &C::thermal_measurement));
  b.push_back(bind_field<p::ThermalGainModeRequest>(
      "thermal_gain", &p::ThermalGainModeRequest::gain_mode, &C::thermal_gain));
  b.push_back(bind_field<p::ThermalSharpnessRequest>(
      "thermal_sharpness", &p::ThermalSharpnessRequest::sharpness, &C::thermal_sharpness));
  b.push_back(bind_field<p::ThermalBrightnessRequest>(
      "thermal_brightness", &p::ThermalBrightnessRequest::brightness, &C::thermal_brightness));
  b.push_back(bind_field<p::ThermalContrastRequest>(
      "thermal_contrast", &p::ThermalContrastRequest::contrast, &C::thermal_contrast));
  b.push_back(bind(
      "thermal_denoise",
      [](const C& c) {
        p::ThermalDenoiseRequest r;
        r.denoise_on = c.thermal_denoise;
        r.denoise_level = static_cast<uint8_t>(c.thermal_denoise_level);
        return r;
      },
      &C::thermal_denoise, &C::thermal_denoise_level));
  b.push_back(bind_field<p::ThermalEnhancementRequest>(
      "thermal_enhancement", &p::ThermalEnhancementRequest::enhancement_level,
      &C::thermal_enhancement));
  b.push_back(bind_field<p::ThermalOverlayRequest>(
      "thermal_overlay", &p::ThermalOverlayRequest::overlay_on, &C::thermal_overlay));
  b.push_back(bind(
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
      &C::high_alarm, &C::high_alarm_degC, &C::low_alarm, &C::low_alarm_degC, &C::difference_alarm,
      &C::difference_alarm_degC));
  b.push_back(bind(
      "threshold_alarm",
      [](const C& c) {
        p::ThermalThresholdAlarmRequest r;
        r.threshold_alarm_on = c.threshold_alarm;
        r.threshold_reference_degC = c.threshold_reference_degC;
        r.threshold_float_degC = c.threshold_float_degC;
        return r;
      },
      &C::threshold_alarm, &C::threshold_reference_degC, &C::threshold_float_degC));
  // visible
  b.push_back(bind_field<p::VisibleVideoResolutionRequest>(
      "video_resolution", &p::VisibleVideoResolutionRequest::video_resolution,
      &C::video_resolution));
  b.push_back(bind_field<p::VisiblePhotoResolutionRequest>(
      "photo_resolution", &p::VisiblePhotoResolutionRequest::photo_resolution,
      &C::photo_resolution));
  b.push_back(bind_field<p::VisibleIsoRequest>("iso", &p::VisibleIsoRequest::iso, &C::iso));
  b.push_back(bind_field<p::VisibleShutterRequest>("shutter", &p::VisibleShutterRequest::shutter,
                                                   &C::shutter));
  b.push_back(bind_field<p::VisibleEvRequest>("ev", &p::VisibleEvRequest::ev, &C::ev));
  b.push_back(bind_field<p::VisibleWhiteBalanceRequest>(
      "white_balance", &p::VisibleWhiteBalanceRequest::white_balance, &C::white_balance));
  b.push_back(bind_field<p::VisibleAntiFlickerRequest>(
      "anti_flicker", &p::VisibleAntiFlickerRequest::anti_flicker, &C::anti_flicker));
  b.push_back(bind(
      "strong_light_suppression",
      [](const C& c) {
        p::VisibleStrongLightRequest r;
        r.strong_light_on = c.strong_light_suppression;
        r.strong_light_value = static_cast<uint8_t>(c.strong_light_level);
        return r;
      },
      &C::strong_light_suppression, &C::strong_light_level));
  b.back().switches_off = turned_off(&C::strong_light_suppression);
  b.push_back(bind(
      "backlight_compensation",
      [](const C& c) {
        p::VisibleBacklightRequest r;
        r.backlight_on = c.backlight_compensation;
        r.backlight_value = static_cast<uint8_t>(c.backlight_level);
        return r;
      },
      &C::backlight_compensation, &C::backlight_level));
  b.back().switches_off = turned_off(&C::backlight_compensation);
  b.push_back(bind_field<p::VisibleAeLockRequest>("ae_lock", &p::VisibleAeLockRequest::ae_lock_on,
                                                  &C::ae_lock));
  b.push_back(bind_field<p::VisibleMeteringRequest>(
      "metering", &p::VisibleMeteringRequest::metering, &C::metering));
  // stream
  b.push_back(bind_field<p::StreamBitrateRequest>(
      "stream_bitrate", &p::StreamBitrateRequest::bitrate, &C::stream_bitrate));
  b.push_back(bind_field<p::StreamResolutionRequest>(
      "stream_resolution", &p::StreamResolutionRequest::resolution, &C::stream_resolution));
  b.push_back(bind_field<p::StreamEncodingRequest>(
      "stream_encoding", &p::StreamEncodingRequest::encoding, &C::stream_encoding));
  return b;
}

}  // namespace

const std::vector<SettingBinding>& setting_bindings() {
  static const std::vector<SettingBinding> bindings = [] {
    std::vector<SettingBinding> b = make_bindings();
    // What no report (0x000001, 0x000003, 0x000100, 0x000200) carries.
    for (SettingBinding& binding : b) {
      for (const char* write_only : {"dial_speed", "periodic_ranging", "thermal_overlay"}) {
        if (binding.name == write_only) binding.readable = false;
      }
    }
    return b;
  }();
  return bindings;
}

const SettingBinding* find_binding(const std::string& name) {
  for (const SettingBinding& binding : setting_bindings()) {
    if (binding.name == name) return &binding;
  }
  return nullptr;
}

void absorb(Config& c, const p::ThermalSettingsAck& t) {
  c.palette = value(t.palette);
  c.thermal_zoom = t.zoom_x;
  c.thermal_measurement = t.measurement_on;
  c.thermal_gain = value(t.gain_mode);
  c.thermal_sharpness = t.sharpness;
  c.thermal_brightness = t.brightness;
  c.thermal_contrast = t.contrast;
  c.thermal_denoise = t.denoise_on;
  c.thermal_denoise_level = t.denoise_level;
  c.thermal_enhancement = t.enhancement_on ? t.enhancement_level : 0;
  // A switched-off alarm carries no threshold (-273.2 degC on the wire): keep the parameter's.
  c.high_alarm = t.high_alarm_on;
  if (t.high_alarm_on) c.high_alarm_degC = t.high_alarm_degC;
  c.low_alarm = t.low_alarm_on;
  if (t.low_alarm_on) c.low_alarm_degC = t.low_alarm_degC;
  c.difference_alarm = t.difference_alarm_on;
  if (t.difference_alarm_on) c.difference_alarm_degC = t.difference_alarm_degC;
  c.threshold_alarm = t.threshold_alarm_on;
  c.threshold_reference_degC = t.threshold_reference_degC;
  c.threshold_float_degC = t.threshold_float_degC;
}

void absorb(Config& c, const p::VisibleSettingsAck& v) {
  c.photo_resolution = value(v.photo_resolution);
  c.video_resolution = value(v.video_resolution);
  c.white_balance = value(v.white_balance);
  c.ev = value(v.ev);
  c.iso = value(v.iso);
  c.shutter = value(v.shutter);
  c.backlight_compensation = v.backlight_on;
  c.backlight_level = v.backlight_value;
  c.strong_light_suppression = v.strong_light_on;
  c.strong_light_level = v.strong_light_value;
  c.ae_lock = v.ae_lock_on;
  c.osd_watermark = v.watermark_on;
  c.anti_flicker = value(v.anti_flicker);
  c.metering = value(v.metering);
}

void absorb(Config& c, const p::CameraSystemStatus& s) {
  c.camera_mode = value(s.capture_mode);
  // The report codes the resolution 0/1, the setting request 1/2 (sections 3.2.1.1, 3.2.4.9).
  c.stream_resolution = s.stream_resolution == p::ReportedStreamResolution::k720p30 ? 2 : 1;
  c.stream_encoding = value(s.encoding);
  c.image_mode = value(s.image_mode);
  c.stream_bitrate = value(s.bitrate);
  c.photo_mode = value(s.photo_mode);
  c.timelapse_interval = s.time_lapse_interval_s;
  c.burst_count = s.burst_count;
}

void absorb(Config& c, const p::GimbalStatus& g) {
  c.stabilisation = g.stabilisation != p::GimbalStabilisationState::kOff;
}

}  // namespace k40t::driver
