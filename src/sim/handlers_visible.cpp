// Visible camera requests (section 3.2.3).
#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

p::VisibleSettingsAck read_all(RequestContext& ctx, const p::VisibleReadSettingsRequest&) {
  const VisibleSettings& v = ctx.pod.camera().visible();
  p::VisibleSettingsAck ack;
  ack.photo_resolution = same_code<p::PhotoResolution>(v.photo_resolution);
  ack.video_resolution = same_code<p::VideoResolution>(v.video_resolution);
  ack.video_bitrate_code = v.video_bitrate;
  ack.white_balance = same_code<p::WhiteBalance>(v.white_balance);
  ack.ev = same_code<p::ExposureValue>(v.ev);
  ack.iso = same_code<p::Iso>(v.iso);
  ack.shutter = same_code<p::Shutter>(v.shutter);
  ack.zoom_fine_tune = v.zoom_fine_tune;
  ack.backlight_on = v.backlight_on;
  ack.backlight_value = v.backlight;
  ack.strong_light_on = v.strong_light_on;
  ack.strong_light_value = v.strong_light;
  ack.ae_lock_on = v.ae_lock;
  ack.watermark_on = ctx.pod.camera().settings().watermark;
  ack.anti_flicker = same_code<p::AntiFlicker>(v.anti_flicker);
  ack.metering = same_code<p::MeteringMode>(v.metering);
  return ack;
}

VisibleSettings& visible_settings(PodModel& pod) {
  return pod.camera().visible();
}

template <class Req, class Field, class Value>
HandlerEntry visible_setting(Field VisibleSettings::*field, Value Req::*value) {
  return stored_setting<Req>(visible_settings, field, value);
}

}  // namespace

void add_visible_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(with_data<p::VisibleReadSettingsRequest>(read_all));
  out.push_back(visible_setting(&VisibleSettings::video_resolution,
                                &p::VisibleVideoResolutionRequest::video_resolution));
  out.push_back(visible_setting(&VisibleSettings::photo_resolution,
                                &p::VisiblePhotoResolutionRequest::photo_resolution));
  out.push_back(visible_setting(&VisibleSettings::iso, &p::VisibleIsoRequest::iso));
  out.push_back(visible_setting(&VisibleSettings::shutter, &p::VisibleShutterRequest::shutter));
  out.push_back(visible_setting(&VisibleSettings::ev, &p::VisibleEvRequest::ev));
  out.push_back(visible_setting(&VisibleSettings::white_balance,
                                &p::VisibleWhiteBalanceRequest::white_balance));
  out.push_back(
      visible_setting(&VisibleSettings::anti_flicker, &p::VisibleAntiFlickerRequest::anti_flicker));
  out.push_back(plain<p::VisibleStrongLightRequest>(
      [](PodModel& pod, const p::VisibleStrongLightRequest& req) {
        return pod.camera().set_strong_light(req.strong_light_on, req.strong_light_value);
      }));
  out.push_back(
      plain<p::VisibleBacklightRequest>([](PodModel& pod, const p::VisibleBacklightRequest& req) {
        return pod.camera().set_backlight(req.backlight_on, req.backlight_value);
      }));
  out.push_back(visible_setting(&VisibleSettings::ae_lock, &p::VisibleAeLockRequest::ae_lock_on));
  out.push_back(visible_setting(&VisibleSettings::metering, &p::VisibleMeteringRequest::metering));
}

}  // namespace k40t::sim
