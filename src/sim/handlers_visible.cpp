// Visible camera requests (section 3.2.3).
#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

// The read-all ACK is what the model keeps (camera_settings.h): every handler below writes it.
p::VisibleSettingsAck read_all(RequestContext& ctx, const p::VisibleReadSettingsRequest&) {
  p::VisibleSettingsAck ack = ctx.pod.camera().visible();
  ack.watermark_on = ctx.pod.camera().settings().watermark;  // set by 0x000314
  return ack;
}

VisibleSettings& visible_settings(PodModel& pod) {
  return pod.camera().visible();
}

// A setting the pod stores as it is and reports in 0x010200: ack.*field = request.*value.
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
  out.push_back(
      visible_setting(&VisibleSettings::ae_lock_on, &p::VisibleAeLockRequest::ae_lock_on));
  out.push_back(visible_setting(&VisibleSettings::metering, &p::VisibleMeteringRequest::metering));
}

}  // namespace k40t::sim
