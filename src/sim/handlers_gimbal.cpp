// Gimbal requests (section 3.1.2, system 0x03 per docs/protocol/decisions.md#a3).
#include "code_mapping.h"
#include "handler_support.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

Outcome control(PodModel& pod, const p::GimbalControlRequest& req) {
  // The working mode wins over the direction bytes when both are given.
  switch (req.mode) {
    case p::GimbalMode::kCentre:
      return pod.gimbal().centre();
    case p::GimbalMode::kLookDown:
      return pod.gimbal().look_down();
    case p::GimbalMode::kNone:
      break;
  }
  return pod.gimbal().move(same_code<YawMotion>(req.yaw), same_code<PitchMotion>(req.pitch));
}

Outcome angle(PodModel& pod, const p::GimbalAngleRequest& req) {
  return pod.gimbal().command_angles(
      req.pitch_move ? std::optional<double>(req.pitch_deg) : std::nullopt,
      req.yaw_move ? std::optional<double>(req.yaw_deg) : std::nullopt);
}

Lens lens_of(p::GimbalAimLens lens) {
  switch (lens) {
    case p::GimbalAimLens::kWide:
      return Lens::kWide;
    case p::GimbalAimLens::kThermal:
      return Lens::kThermal;
    case p::GimbalAimLens::kTele:
      break;
  }
  return Lens::kTele;
}

p::GimbalVersionAck version(RequestContext& ctx, const p::GimbalVersionRequest&) {
  const Versions& v = ctx.pod.versions();
  p::GimbalVersionAck ack;
  ack.hardware_major = v.gimbal_hardware.major;
  ack.hardware_minor = v.gimbal_hardware.minor;
  ack.hardware_patch = v.gimbal_hardware.patch;
  ack.software_major = v.gimbal_software.major;
  ack.software_minor = v.gimbal_software.minor;
  ack.software_patch = v.gimbal_software.patch;
  return ack;
}

template <class Req>
HandlerEntry calibration(CalibrationKind kind) {
  return plain<Req>(
      [kind](PodModel& pod, const Req&) { return pod.gimbal().start_calibration(kind); });
}

}  // namespace

void add_gimbal_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(plain<p::GimbalControlRequest>(control));
  out.push_back(plain<p::GimbalAngleRequest>(angle));
  out.push_back(calibration<p::GimbalDriftCalibrationRequest>(CalibrationKind::kDrift));
  out.push_back(
      plain<p::GimbalDialSpeedRequest>([](PodModel& pod, const p::GimbalDialSpeedRequest& req) {
        return pod.gimbal().set_dial_speed(req.pitch_speed_deg_s, req.yaw_speed_deg_s);
      }));
  out.push_back(with_data<p::GimbalVersionRequest>(version));
  out.push_back(
      plain<p::GimbalPointAtRequest>([](PodModel& pod, const p::GimbalPointAtRequest& req) {
        return pod.gimbal().point_at(lens_of(req.lens), req.zoom_x, req.x_px, req.y_px);
      }));
  out.push_back(plain<p::GimbalServoOffRequest>(
      [](PodModel& pod, const p::GimbalServoOffRequest&) { return pod.gimbal().servo_off(); }));
  out.push_back(calibration<p::GimbalLinearCalibrationRequest>(CalibrationKind::kLinear));
  out.push_back(plain<p::GimbalRestartRequest>(
      [](PodModel& pod, const p::GimbalRestartRequest&) { return pod.gimbal().soft_restart(); }));
  out.push_back(store<p::GimbalUseFlightControllerAttitudeRequest>(
      [](PodModel& pod, const p::GimbalUseFlightControllerAttitudeRequest&) {
        pod.gimbal().set_use_flight_controller_attitude(true);
      }));
  out.push_back(
      calibration<p::GimbalAccelerationCalibrationRequest>(CalibrationKind::kAccelerometer));
  out.push_back(plain<p::GimbalStabilisationRequest>(
      [](PodModel& pod, const p::GimbalStabilisationRequest& req) {
        return pod.gimbal().set_stabilisation(req.enable);
      }));
}

}  // namespace k40t::sim
