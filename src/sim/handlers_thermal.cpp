// Thermal camera requests (section 3.2.2).
#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

std::optional<double> alarm_limit(bool on, double degC) {
  return on ? std::optional<double>(degC) : std::nullopt;
}

// The read-all ACK is what the model keeps (thermal_model.h): every handler below writes it. The
// enhancement byte and the zoom code go out as the pod's readings say
// (docs/protocol/decisions.md#conventions: enhancement_switch, thermal_zoom_code).
HandlerEntry read_all() {
  using Req = p::ThermalReadSettingsRequest;
  return {Req::kId, [](RequestContext& ctx, const p::FrameView& frame) {
            const Decoded<Req> d = decode<Req>(frame, ctx.codec);
            if (!d.request) return code_ack(d.refusal, ctx.codec);
            const p::ThermalSettingsAck& truth = ctx.pod.thermal().settings().reported;
            const p::Conventions& c = ctx.codec.conventions;
            p::ThermalSettingsAck played = truth;
            p::enhancement_to_wire(played, truth.enhancement_on ? truth.enhancement_level : 0,
                                   c.enhancement_switch);
            played.zoom_x = p::thermal_zoom_to_wire(truth.zoom_x, c.thermal_zoom_code);
            return played_ack(truth, played, ctx.codec);
          }};
}

p::ThermalSettingsAck& reported(PodModel& pod) {
  return pod.thermal().settings().reported;
}

// A setting the pod stores as it is and reports in 0x010100: ack.*field = request.*value.
template <class Req, class Field, class Value>
HandlerEntry thermal_setting(Field p::ThermalSettingsAck::*field, Value Req::*value) {
  return stored_setting<Req>(reported, field, value);
}

}  // namespace

void add_thermal_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(read_all());
  out.push_back(plain<p::ThermalZoomRequest>([](PodModel& pod, const p::ThermalZoomRequest& req) {
    return pod.thermal().set_digital_zoom(req.zoom_x);
  }));
  out.push_back(
      thermal_setting(&p::ThermalSettingsAck::palette, &p::ThermalPaletteRequest::palette));
  out.push_back(thermal_setting(&p::ThermalSettingsAck::measurement_on,
                                &p::ThermalMeasurementRequest::measurement_on));
  out.push_back(
      thermal_setting(&p::ThermalSettingsAck::sharpness, &p::ThermalSharpnessRequest::sharpness));
  out.push_back(thermal_setting(&p::ThermalSettingsAck::brightness,
                                &p::ThermalBrightnessRequest::brightness));
  out.push_back(
      thermal_setting(&p::ThermalSettingsAck::contrast, &p::ThermalContrastRequest::contrast));
  out.push_back(
      store<p::ThermalDenoiseRequest>([](PodModel& pod, const p::ThermalDenoiseRequest& req) {
        reported(pod).denoise_on = req.denoise_on;
        reported(pod).denoise_level = req.denoise_level;
      }));
  // 0x00010E has the level only (0 = off); the ACK has a switch bit too.
  out.push_back(store<p::ThermalEnhancementRequest>(
      [](PodModel& pod, const p::ThermalEnhancementRequest& req) {
        reported(pod).enhancement_on = req.enhancement_level > 0;
        reported(pod).enhancement_level = req.enhancement_level;
      }));
  out.push_back(plain<p::ThermalSpotRequest>([](PodModel& pod, const p::ThermalSpotRequest& req) {
    return pod.thermal().set_spot(req.x_px, req.y_px);
  }));
  out.push_back(plain<p::ThermalAreaRequest>([](PodModel& pod, const p::ThermalAreaRequest& req) {
    return pod.thermal().set_area(req.width_px, req.height_px, req.center_x_px, req.center_y_px);
  }));
  out.push_back(
      thermal_setting(&p::ThermalSettingsAck::gain_mode, &p::ThermalGainModeRequest::gain_mode));
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
