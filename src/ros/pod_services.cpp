#include "k40t_driver/ros/pod_services.h"

#include <cmath>
#include <limits>
#include <optional>

#include <std_srvs/Trigger.h>

#include "k40t_driver/Calibrate.h"
#include "k40t_driver/Focus.h"
#include "k40t_driver/GetIp.h"
#include "k40t_driver/GetSbus.h"
#include "k40t_driver/GetVersions.h"
#include "k40t_driver/MeasureRange.h"
#include "k40t_driver/PointAt.h"
#include "k40t_driver/Record.h"
#include "k40t_driver/Send.h"
#include "k40t_driver/SetAiRecognition.h"
#include "k40t_driver/SetAngle.h"
#include "k40t_driver/SetArea.h"
#include "k40t_driver/SetIp.h"
#include "k40t_driver/SetSbus.h"
#include "k40t_driver/SetSpot.h"
#include "k40t_driver/SetZoom.h"
#include "k40t_driver/TakePhoto.h"
#include "k40t_driver/Track.h"
#include "k40t_driver/Zoom.h"
#include "k40t_driver/driver/pod_queries.h"
#include "k40t_driver/driver/sbus_write.h"
#include "k40t_driver/operations/ai_request.h"
#include "k40t_driver/operations/gimbal_operations.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/ros/service_support.h"

namespace k40t::driver {

namespace p = protocol;
using session::AckResult;

namespace {

// take_photo and record: a lens mode, an action and the file's folder and name.
template <class Req, class SrvReq, class Action>
Req file_capture(const SrvReq& req, Action action) {
  Req r;
  r.lens = static_cast<decltype(r.lens)>(req.lens);
  r.action = action;
  r.folder = req.folder;
  r.name = req.name;
  return r;
}

// The typed ACK of `request`; `res` gets the exchange's success and message. None when the pod
// refused or did not answer, or (said in `res`) when its answer cannot be read.
template <class Req, class Res>
std::optional<typename Req::Ack> typed_ack(PodDriver& driver, const Req& request, Res& res) {
  AckResult raw;
  Result<typename Req::Ack> ack = driver.request_typed(request, &raw);
  fill(res, raw);
  if (ack) return ack.value();
  if (raw.ok()) fail(res, ack.error());  // an OK code but an unreadable answer
  return std::nullopt;
}

// sbus/get's response and sbus/set's request carry the fields of the SBUS range and channel
// messages (0x000500, 0x000501) under their names: one list, copied either way by
// `copy(pod_field, ros_field)`.
template <class Range, class Channels, class Ros, class Copy>
void for_each_sbus_field(Range& range, Channels& channels, Ros& ros, Copy copy) {
  copy(range.max_value, ros.max_value);
  copy(range.min_value, ros.min_value);
  copy(channels.stream_channel, ros.stream_channel);
  copy(channels.zoom_channel, ros.zoom_channel);
  copy(channels.photo_channel, ros.photo_channel);
  copy(channels.record_channel, ros.record_channel);
  copy(channels.pitch_channel, ros.pitch_channel);
  copy(channels.yaw_channel, ros.yaw_channel);
  copy(channels.centre_channel, ros.centre_channel);
}

}  // namespace

template <class Srv, class Handler>
void PodServices::serve(const std::string& name, Handler handler) {
  advertise_service<Srv>(nh_, servers_, name, std::move(handler));
}

template <class Srv, class Req, class Build>
void PodServices::serve_request(const std::string& name, Build build) {
  serve<Srv>(name, [this, build](auto& req, auto& res) {
    Req r;
    build(req, r);
    fill(res, driver_.request(r));
  });
}

template <class Srv, class Req, class Answer>
void PodServices::serve_answer(const std::string& name, Answer answer) {
  serve<Srv>(name, [this, answer](auto&, auto& res) {
    if (const std::optional<typename Req::Ack> ack = typed_ack(driver_, Req{}, res)) {
      answer(*ack, res);
    }
  });
}

template <class Req>
void PodServices::serve_trigger(const std::string& name, Req request) {
  serve<std_srvs::Trigger>(
      name, [this, request](std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
        fill(res, driver_.request(request));
      });
}

PodServices::PodServices(ros::NodeHandle nh, PodDriver& driver) : nh_(nh), driver_(driver) {
  advertise_camera();
  advertise_gimbal();
  advertise_thermal_and_laser();
  advertise_system();
}

void PodServices::advertise_camera() {
  serve_request<k40t_driver::SetZoom, p::ZoomRatioRequest>(
      "set_zoom", [](auto& req, auto& r) { r.zoom_x = req.ratio; });
  serve_request<k40t_driver::Zoom, p::ContinuousZoomRequest>(
      "zoom", [](auto& req, auto& r) { r.command = static_cast<p::ZoomCommand>(req.action); });
  // MANUAL_NEAR/FAR go out as "+" or "-" as the pod reads them (focus_plus,
  // docs/protocol/decisions.md#conventions).
  const p::FocusPlus plus = driver_.codec().conventions.focus_plus;
  serve_request<k40t_driver::Focus, p::FocusRequest>("focus", [plus](auto& req, auto& r) {
    r.command = static_cast<p::FocusCommand>(req.mode);
    if (req.mode == k40t_driver::Focus::Request::MANUAL_NEAR ||
        req.mode == k40t_driver::Focus::Request::MANUAL_FAR)
      r.command =
          p::manual_focus_command(req.mode == k40t_driver::Focus::Request::MANUAL_NEAR, plus);
    r.area_left_px = req.x1;
    r.area_top_px = req.y1;
    r.area_right_px = req.x2;
    r.area_bottom_px = req.y2;
  });
  // The pod does not answer either in the other capture mode: refused before sending, with why.
  driver_.on_tx_frame(
      [this](const p::FrameView& frame, StampNs) { mode_.frame_sent(frame, driver_.codec()); });
  driver_.on_rx_frame(
      [this](const p::FrameView& frame, StampNs) { mode_.frame_received(frame, driver_.codec()); });
  serve<k40t_driver::TakePhoto>("take_photo", [this](auto& req, auto& res) {
    const p::PhotoAction action = req.stop ? p::PhotoAction::kStop : p::PhotoAction::kStart;
    if (req.stop) {
      const Status stop = mode_.allows_stop(driver_.codec().conventions.photo_mode_2);
      if (!stop) return fail(res, stop.message());
    }
    fill(res, in_mode(p::CaptureMode::kPhoto, "photo requests",
                      file_capture<p::TakePhotoRequest>(req, action)));
  });
  serve<k40t_driver::Record>("record", [this](auto& req, auto& res) {
    const p::RecordAction action = req.start ? p::RecordAction::kStart : p::RecordAction::kStop;
    fill(res, in_mode(p::CaptureMode::kVideo, "record requests",
                      file_capture<p::RecordRequest>(req, action)));
  });
  serve<k40t_driver::SetAiRecognition>("ai/recognition", [this](auto& req, auto& res) {
    // Unused class slots repeat the last class (operations/ai_request.h), never class 0.
    Result<p::AiRecognitionRequest> r =
        operations::ai_recognition_request(req.enable, req.model, req.classes);
    if (!r) return fail(res, r.error());
    fill(res, driver_.request(r.value()));
  });
  serve_request<k40t_driver::Track, p::BoxTrackingRequest>("ai/track", [](auto& req, auto& r) {
    r.tracking = req.enable ? p::FeatureSwitch::kOn : p::FeatureSwitch::kOff;
    r.x_px = req.x;
    r.y_px = req.y;
    r.width_px = req.width;
    r.height_px = req.height;
  });
}

template <class Req>
AckResult PodServices::in_mode(p::CaptureMode mode, const char* what, const Req& request) {
  // The arguments first: a bad one is the caller's error in any mode.
  if (const Status valid = request.validate(); !valid)
    return AckResult::not_sent(std::string(Req::kName) + ": " + valid.message());
  if (const Status allowed = mode_.allows(mode, what); !allowed)
    return AckResult::not_sent(allowed.message());
  AckResult result = driver_.request(request);
  if (result.sent && !result.received)
    result.message = operations::CaptureModeGuard::unanswered(mode, what, result.message);
  return result;
}

void PodServices::advertise_gimbal() {
  serve<k40t_driver::SetAngle>("gimbal/set_angle", [this](auto& req, auto& res) {
    // Checked in the caller's units (REP 103 signs, radians), so the message speaks them.
    Result<p::GimbalAngleRequest> r = operations::angle_request_from_rep103(req.pitch, req.yaw);
    if (!r) return fail(res, r.error());
    fill(res, driver_.request(r.value()));
  });
  p::GimbalControlRequest centre;
  centre.mode = p::GimbalMode::kCentre;
  serve_trigger("gimbal/center", centre);
  p::GimbalControlRequest look_down;
  look_down.mode = p::GimbalMode::kLookDown;
  serve_trigger("gimbal/look_down", look_down);
  serve_trigger("gimbal/restart", p::GimbalRestartRequest{});
  serve_trigger("gimbal/servo_off", p::GimbalServoOffRequest{});
  serve_trigger("gimbal/use_flight_controller_attitude",
                p::GimbalUseFlightControllerAttitudeRequest{});
  serve_request<k40t_driver::PointAt, p::GimbalPointAtRequest>(
      "gimbal/point_at", [](auto& req, auto& r) {
        r.lens = static_cast<p::GimbalAimLens>(req.lens);
        r.zoom_x = req.zoom;
        r.x_px = req.x;
        r.y_px = req.y;
      });
  serve<k40t_driver::Calibrate>("gimbal/calibrate", [this](auto& req, auto& res) {
    Result<operations::CalibrationKind> kind = operations::calibration_kind(req.kind);
    if (!kind) return fail(res, kind.error());
    switch (kind.value()) {
      case operations::CalibrationKind::kDrift:
        return fill(res, driver_.request(p::GimbalDriftCalibrationRequest{}));
      case operations::CalibrationKind::kLinear:
        return fill(res, driver_.request(p::GimbalLinearCalibrationRequest{}));
      case operations::CalibrationKind::kAccelerometer:
        return fill(res, driver_.request(p::GimbalAccelerationCalibrationRequest{}));
    }
  });
}

void PodServices::advertise_thermal_and_laser() {
  serve_request<k40t_driver::SetSpot, p::ThermalSpotRequest>("thermal/set_spot",
                                                             [](auto& req, auto& r) {
                                                               r.x_px = req.x;
                                                               r.y_px = req.y;
                                                             });
  serve_request<k40t_driver::SetArea, p::ThermalAreaRequest>("thermal/set_area",
                                                             [](auto& req, auto& r) {
                                                               r.width_px = req.width;
                                                               r.height_px = req.height;
                                                               r.center_x_px = req.center_x;
                                                               r.center_y_px = req.center_y;
                                                             });
  serve<k40t_driver::MeasureRange>("laser/measure", [this](auto&, auto& res) {
    const std::optional<p::LaserRangeAck> ack = typed_ack(driver_, p::LaserRangeRequest{}, res);
    if (!ack) {
      res.range = std::numeric_limits<float>::quiet_NaN();
      return;
    }
    res.range = ack->distance_m > 0 ? static_cast<float>(ack->distance_m)
                                    : std::numeric_limits<float>::infinity();
  });
}

void PodServices::advertise_system() {
  serve<k40t_driver::GetVersions>("get_versions", [this](auto&, auto& res) {
    const PodVersions v = read_versions(driver_);
    res.success = v.ok;
    res.message = v.message;
    res.gimbal_hardware = v.gimbal_hardware;
    res.gimbal_software = v.gimbal_software;
    res.camera = v.camera;
  });
  serve_answer<k40t_driver::GetIp, p::GetIpRequest>("get_ip", [](const auto& ack, auto& res) {
    res.address = ack.address;
    res.netmask = ack.netmask;
    res.gateway = ack.gateway;
  });
  serve_request<k40t_driver::SetIp, p::SetIpRequest>("set_ip", [](auto& req, auto& r) {
    r.mode = req.dhcp ? p::IpMode::kDhcp : p::IpMode::kStatic;
    r.address = req.address.empty() ? "0.0.0.0" : req.address;
    r.netmask = req.netmask.empty() ? "0.0.0.0" : req.netmask;
    r.gateway = req.gateway.empty() ? "0.0.0.0" : req.gateway;
  });
  serve_trigger("format_sd", p::FormatSdRequest{});
  serve_trigger("factory_reset", p::FactoryResetRequest{});
  serve_trigger("shutdown", p::ShutdownRequest{});
  serve_answer<k40t_driver::GetSbus, p::SbusConfigRequest>(
      "sbus/get", [](const auto& ack, auto& res) {
        for_each_sbus_field(ack.range, ack.channels, res,
                            [](const auto& pod, auto& ros) { ros = pod; });
      });
  serve<k40t_driver::SetSbus>("sbus/set", [this](auto& req, auto& res) {
    p::SbusRangeRequest range;
    p::SbusChannelsRequest channels;
    for_each_sbus_field(range, channels, req, [](auto& pod, const auto& ros) { pod = ros; });
    const SbusWriteOutcome outcome = write_sbus(driver_, range, channels);
    res.success = outcome.success;
    res.message = outcome.message;
    res.range_applied = outcome.range_applied;
    res.channels_applied = outcome.channels_applied;
    res.power_cycle_needed = outcome.power_cycle_needed;
  });
  serve<k40t_driver::Send>("send", [this](auto& req, auto& res) {
    if (req.id == 0 || req.id > 0x00FFFF) {
      return fail(
          res, "field 'id' must be a request id 0x000001..0x00FFFF, got " + std::to_string(req.id));
    }
    if (req.payload.size() > p::kMaxPayloadSize) {
      return fail(res, "field 'payload' must be at most 243 bytes, got " +
                           std::to_string(req.payload.size()));
    }
    const AckResult result = driver_.request_raw(req.id, req.payload.data(), req.payload.size());
    fill(res, result);
    res.code = static_cast<uint16_t>(result.code);
    res.ack = result.payload;
  });
}

}  // namespace k40t::driver
