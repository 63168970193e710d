// Common camera requests (section 3.2.4) and the flight controller's target request 0x000320.
#include <arpa/inet.h>

#include <cstdio>

#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/camera.h"

namespace k40t::sim {

namespace handlers {
Ipv4 parse_ipv4(const std::string& text) {
  in_addr addr{};
  Ipv4 out{};
  if (::inet_pton(AF_INET, text.c_str(), &addr) != 1) return out;
  const uint32_t host = ntohl(addr.s_addr);
  for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(host >> (24 - 8 * i));
  return out;
}

std::string format_ipv4(const Ipv4& a) {
  char text[16];
  std::snprintf(text, sizeof text, "%u.%u.%u.%u", a[0], a[1], a[2], a[3]);
  return text;
}
}  // namespace handlers

namespace {

using namespace handlers;
namespace p = protocol;

Outcome take_photo(PodModel& pod, const p::TakePhotoRequest& req) {
  if (req.action == p::PhotoAction::kStop) return pod.camera().stop_photo();
  return pod.camera().take_photo(same_code<uint8_t>(req.lens), req.folder, req.name);
}

Outcome record(PodModel& pod, const p::RecordRequest& req) {
  if (req.action == p::RecordAction::kStop) return pod.camera().stop_recording();
  return pod.camera().start_recording(same_code<uint8_t>(req.lens), req.folder, req.name);
}

Outcome precise_reshoot(PodModel& pod, const p::PreciseReshootRequest& req) {
  const Outcome shot = pod.camera().precise_reshoot(
      same_code<uint8_t>(req.lens), same_code<uint8_t>(req.resolution), req.folder, req.name);
  if (shot != Outcome::kOk) return shot;
  pod.camera().settings().precise_focal_length_raw = req.focal_length_raw;
  // The re-shoot waits for the zoom to reach the magnification asked for.
  return pod.zoom().set_zoom(req.zoom_x);
}

Outcome set_ip(PodModel& pod, const p::SetIpRequest& req) {
  NetworkSettings network;
  network.dynamic = req.mode == p::IpMode::kDhcp;
  network.address = parse_ipv4(req.address);
  network.netmask = parse_ipv4(req.netmask);
  network.gateway = parse_ipv4(req.gateway);
  return pod.set_network(network);
}

p::GetIpAck get_ip(RequestContext& ctx, const p::GetIpRequest&) {
  p::GetIpAck ack;
  ack.address = format_ipv4(ctx.pod.network().address);
  ack.netmask = format_ipv4(ctx.pod.network().netmask);
  ack.gateway = format_ipv4(ctx.pod.network().gateway);
  return ack;
}

p::CameraVersionAck camera_version(RequestContext& ctx, const p::CameraVersionRequest&) {
  p::CameraVersionAck ack;
  ack.major = ctx.pod.versions().camera.major;
  ack.minor = ctx.pod.versions().camera.minor;
  ack.patch = ctx.pod.versions().camera.patch;
  return ack;
}

p::TargetGpsAck target_position(RequestContext& ctx, const p::TargetGpsRequest& req) {
  ctx.pod.ground_truth().flight_data_received({0, req.ground_speed_m_s, req.climb_rate_m_s,
                                               req.heading_deg, req.airspeed_m_s,
                                               req.throttle_percent});
  const GeoPoint host{req.latitude_deg, req.longitude_deg, req.relative_height_m, req.altitude_m};
  const auto target =
      ctx.pod.locate_target(host, YawPitchRoll{req.yaw_deg, req.pitch_deg, req.roll_deg});
  p::TargetGpsAck ack;
  ack.utc_time_ms = req.utc_time_ms;
  if (!target) {
    // No laser return: zeros with code OK, or a refusal from a pod whose zeros would be a
    // position (laser_target_zeros, docs/protocol/decisions.md#conventions).
    if (ctx.codec.conventions.laser_target_zeros == p::LaserTargetZeros::kPosition)
      ack.code = p::ResponseCode::kFailure;
    return ack;
  }
  ack.latitude_deg = target->latitude_deg;
  ack.longitude_deg = target->longitude_deg;
  ack.relative_height_m = target->relative_height_m;
  ack.altitude_m = target->altitude_m;
  return ack;
}

ContinuousZoom zoom_command(p::ZoomCommand command) {
  return same_code<ContinuousZoom>(command);
}

// 0x000313: codes 1 "+" and 2 "-" of manual focus go nearer or farther as the pod's reading says
// (focus_plus, docs/protocol/decisions.md#conventions).
HandlerEntry focus_entry() {
  return {p::FocusRequest::kId, [](RequestContext& ctx, const p::FrameView& frame) {
            const Decoded<p::FocusRequest> d = decode<p::FocusRequest>(frame, ctx.codec);
            if (!d.request) return code_ack(d.refusal, ctx.codec);
            const p::FocusRequest& req = *d.request;
            FocusArea area;
            area.left = req.area_left_px;
            area.top = req.area_top_px;
            area.right = req.area_right_px;
            area.bottom = req.area_bottom_px;
            FocusCommand command = same_code<FocusCommand>(req.command);
            if (command == FocusCommand::kManualNear || command == FocusCommand::kManualFar) {
              const bool nearer =
                  p::manual_focus_is_nearer(req.command, ctx.codec.conventions.focus_plus);
              command = nearer ? FocusCommand::kManualNear : FocusCommand::kManualFar;
            }
            return outcome_ack(ctx.pod.zoom().focus(command, area), ctx.codec);
          }};
}

}  // namespace

void add_camera_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(plain<p::CaptureModeRequest>([](PodModel& pod, const p::CaptureModeRequest& req) {
    return pod.camera().set_capture_mode(same_code<CaptureMode>(req.mode));
  }));
  out.push_back(
      plain<p::PhotoSettingsRequest>([](PodModel& pod, const p::PhotoSettingsRequest& req) {
        return pod.camera().set_photo_mode(same_code<PhotoMode>(req.photo_mode),
                                           req.time_lapse_interval_s, req.burst_count);
      }));
  out.push_back(plain<p::TakePhotoRequest>(take_photo));
  out.push_back(plain<p::RecordRequest>(record));
  out.push_back(plain<p::ZoomRatioRequest>([](PodModel& pod, const p::ZoomRatioRequest& req) {
    return pod.zoom().set_zoom(req.zoom_x);
  }));
  out.push_back(
      plain<p::ContinuousZoomRequest>([](PodModel& pod, const p::ContinuousZoomRequest& req) {
        return pod.zoom().zoom_control(zoom_command(req.command));
      }));
  out.push_back(plain<p::PreciseReshootRequest>(precise_reshoot));
  out.push_back(
      store<p::StreamBitrateRequest>([](PodModel& pod, const p::StreamBitrateRequest& req) {
        pod.camera().settings().stream_bitrate = same_code<uint8_t>(req.bitrate);
      }));
  out.push_back(
      store<p::StreamResolutionRequest>([](PodModel& pod, const p::StreamResolutionRequest& req) {
        // The request codes 1 = 1080P30, 2 = 720P30; the report 0 and 1 (docs/protocol/camera.md).
        pod.camera().settings().stream_resolution =
            static_cast<uint8_t>(same_code<uint8_t>(req.resolution) - 1);
      }));
  out.push_back(
      store<p::StreamEncodingRequest>([](PodModel& pod, const p::StreamEncodingRequest& req) {
        pod.camera().settings().stream_encoding = same_code<uint8_t>(req.encoding);
      }));
  out.push_back(plain<p::TfCardUpgradeRequest>([](PodModel& pod, const p::TfCardUpgradeRequest&) {
    return pod.camera().start_tf_upgrade();
  }));
  out.push_back(plain<p::FormatSdRequest>(
      [](PodModel& pod, const p::FormatSdRequest&) { return pod.camera().format_sd(); }));
  out.push_back(store<p::TimeSyncRequest>([](PodModel& pod, const p::TimeSyncRequest& req) {
    pod.camera().clock().sync(req.unix_time_ms, req.tz_minutes_west, req.tz_dst_type);
  }));
  out.push_back(plain<p::FactoryResetRequest>(
      [](PodModel& pod, const p::FactoryResetRequest&) { return pod.factory_reset(); }));
  out.push_back(plain<p::SetIpRequest>(set_ip));
  out.push_back(with_data<p::GetIpRequest>(get_ip));
  out.push_back(focus_entry());
  out.push_back(store<p::OsdWatermarkRequest>([](PodModel& pod, const p::OsdWatermarkRequest& req) {
    pod.camera().settings().watermark = req.enabled;
  }));
  out.push_back(plain<p::ShutdownRequest>(
      [](PodModel& pod, const p::ShutdownRequest&) { return pod.shutdown(); }));
  out.push_back(with_data<p::CameraVersionRequest>(camera_version));
  out.push_back(store<p::ImageModeRequest>([](PodModel& pod, const p::ImageModeRequest& req) {
    pod.camera().settings().image_mode = same_code<uint8_t>(req.mode);
  }));
  out.push_back(
      plain<p::AiRecognitionRequest>([](PodModel& pod, const p::AiRecognitionRequest& req) {
        return pod.set_ai(req.recognition == p::FeatureSwitch::kOn, req.model, req.classes);
      }));
  out.push_back(with_data<p::TargetGpsRequest>(target_position));
  out.push_back(plain<p::BoxTrackingRequest>([](PodModel& pod, const p::BoxTrackingRequest& req) {
    return pod.set_tracking(req.tracking == p::FeatureSwitch::kOn,
                            TrackingBox{req.x_px, req.y_px, req.width_px, req.height_px});
  }));
}

}  // namespace k40t::sim
