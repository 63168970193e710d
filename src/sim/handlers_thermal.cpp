// Thermal camera requests (section 3.2.2).
#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

std::optional<double> alarm_limit(bool on, double degC) {
  return on ? std::optional<double>(degC) : std::nullopt;
}

p::ThermalSettingsAck read_all(RequestContext& ctx, const p::ThermalReadSettingsRequest&) {
  const ThermalSettings& s = ctx.pod.thermal().settings();
  p::ThermalSettingsAck ack;
  ack.palette = same_code<p::Palette>(s.palette);
  ack.measurement_on = s.measurement_on;
  ack.measurement_type = same_code<p::ThermalMeasurementType>(s.measurement_type);
  ack.core_type = s.radiometric ? p::ThermalCoreType::kRadiometric : p::ThermalCoreType::kSighting;
  ack.zoom_x = s.digital_zoom;
  ack.sharpness = s.sharpness;
  ack.gain_mode = same_code<p::ThermalGainMode>(s.gain);
  ack.brightness = s.brightness;
  ack.contrast = s.contrast;
  ack.denoise_on = s.denoise_on;
  ack.denoise_level = s.denoise_level;
  ack.enhancement_on = s.enhancement > 0;
  ack.enhancement_level = s.enhancement;
  ack.high_alarm_on = s.high_alarm_degC.has_value();
  ack.high_alarm_degC = s.high_alarm_degC.value_or(0);
  ack.low_alarm_on = s.low_alarm_degC.has_value();
  ack.low_alarm_degC = s.low_alarm_degC.value_or(0);
  ack.difference_alarm_on = s.difference_alarm_degC.has_value();
  ack.difference_alarm_degC = s.difference_alarm_degC.value_or(0);
  ack.threshold_alarm_on = s.threshold_alarm_on;
  ack.threshold_reference_degC = s.threshold_reference_degC;
  ack.threshold_float_degC = s.threshold_float_degC;
  return ack;
}

ThermalSettings& thermal_settings(PodModel& pod) {
  return pod.thermal().settings();
}

template <class Req, class Field, class Value>
HandlerEntry thermal_setting(Field ThermalSettings::*field, Value Req::*value) {
  return stored_setting<Req>(thermal_settings, field, value);
}

}  // namespace

void add_thermal_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(with_data<p::ThermalReadSettingsRequest>(read_all));
  out.push_back(plain<p::ThermalZoomRequest>([](PodModel& pod, const p::ThermalZoomRequest& req) {
    return pod.thermal().set_digital_zoom(req.zoom_x);
  }));
  out.push_back(thermal_setting(&ThermalSettings::palette, &p::ThermalPaletteRequest::palette));
  out.push_back(store<p::ThermalMeasurementRequest>(
      [](PodModel& pod, const p::ThermalMeasurementRequest& req) {
        pod.thermal().settings().measurement_on = req.measurement_on;
      }));
  out.push_back(
      thermal_setting(&ThermalSettings::sharpness, &p::ThermalSharpnessRequest::sharpness));
  out.push_back(
      thermal_setting(&ThermalSettings::brightness, &p::ThermalBrightnessRequest::brightness));
  out.push_back(thermal_setting(&ThermalSettings::contrast, &p::ThermalContrastRequest::contrast));
  out.push_back(
      store<p::ThermalDenoiseRequest>([](PodModel& pod, const p::ThermalDenoiseRequest& req) {
        pod.thermal().settings().denoise_on = req.denoise_on;
        pod.thermal().settings().denoise_level = req.denoise_level;
      }));
  out.push_back(thermal_setting(&ThermalSettings::enhancement,
                                &p::ThermalEnhancementRequest::enhancement_level));
  out.push_back(plain<p::ThermalSpotRequest>([](PodModel& pod, const p::ThermalSpotRequest& req) {
    return pod.thermal().set_spot(req.x_px, req.y_px);
  }));
  out.push_back(plain<p::ThermalAreaRequest>([](PodModel& pod, const p::ThermalAreaRequest& req) {
    return pod.thermal().set_area(req.width_px, req.height_px, req.center_x_px, req.center_y_px);
  }));
  out.push_back(thermal_setting(&ThermalSettings::gain, &p::ThermalGainModeRequest::gain_mode));
  out.push_back(
      plain<p::ThermalAlarmsRequest>([](PodModel& pod, const p::ThermalAlarmsRequest& req) {
        return pod.thermal().set_alarms(
            alarm_limit(req.high_alarm_on, req.high_alarm_degC),
            alarm_limit(req.low_alarm_on, req.low_alarm_degC),
            alarm_limit(req.difference_alarm_on, req.difference_alarm_degC));
      }));
  out.push_back(
      store<p::ThermalOverlayRequest>([](PodModel& pod, const p::ThermalOverlayRequest& req) {
        pod.thermal().settings().overlay = req.overlay_on;
      }));
  out.push_back(plain<p::ThermalThresholdAlarmRequest>(
      [](PodModel& pod, const p::ThermalThresholdAlarmRequest& req) {
        return pod.thermal().set_threshold_alarm(
            req.threshold_alarm_on, req.threshold_reference_degC, req.threshold_float_degC);
      }));
}

}  // namespace k40t::sim
