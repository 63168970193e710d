#include "k40t_driver/sim/pod_reports.h"

#include <cmath>

#include "code_mapping.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/sim/attitude_order.h"

namespace k40t::sim {

namespace {

using handlers::same_code;
namespace p = protocol;

bool always(const PodModel&) {
  return true;
}
bool camera_up(const PodModel& pod) {
  return pod.camera_available();
}
bool measuring(const PodModel& pod) {
  return pod.camera_available() && pod.thermal().settings().reported.measurement_on;
}
bool ranging(const PodModel& pod) {
  return pod.camera_available() && pod.laser().periodic();
}

template <class Msg>
Result<p::Payload> encode(const Msg& message, const p::CodecOptions& codec) {
  return p::encode_payload(message, codec);
}

Result<p::Payload> gimbal_status(const PodModel& pod, const p::CodecOptions& codec) {
  const auto link = [](bool ok) {
    return ok ? p::GimbalLinkState::kNormal : p::GimbalLinkState::kAbnormal;
  };
  p::GimbalStatus report;
  report.gimbal_link = link(pod.gimbal_link_ok());
  report.camera_link = link(pod.camera_link_ok());
  report.upgrade = same_code<p::GimbalUpgradeState>(pod.upgrade_status());
  report.ir_ok = pod.self_test() & kSelfTestInfrared;
  report.tele_ok = pod.self_test() & kSelfTestTele;
  report.wide_ok = pod.self_test() & kSelfTestWide;
  report.laser_ok = pod.self_test() & kSelfTestLaser;
  report.stabilisation = same_code<p::GimbalStabilisationState>(pod.gimbal().stabilisation_state());
  return encode(report, codec);
}

Result<p::Payload> gimbal_attitude(const PodModel& pod, const p::CodecOptions& codec) {
  const GimbalPose pose = pod.gimbal().pose();
  p::GimbalAttitude report;
  report.joint_yaw_deg = pose.joint_deg.yaw;
  report.joint_roll_deg = pose.joint_deg.roll;
  report.joint_pitch_deg = pose.joint_deg.pitch;
  // The attitude in the Euler order the pod uses (attitude_order): the chain's own angles, or the
  // aerospace angles of the same rotation.
  const YawPitchRoll attitude =
      attitude_in_order({pod.attitude_yaw_deg(), pose.joint_deg.pitch, pose.joint_deg.roll},
                        codec.conventions.attitude_order);
  report.yaw_deg = wrap_deg(attitude.yaw);
  report.roll_deg = attitude.roll;
  report.pitch_deg = attitude.pitch;
  report.yaw_rate_deg_s = pose.rate_deg_s.yaw;
  report.pitch_rate_deg_s = pose.rate_deg_s.pitch;
  report.roll_rate_deg_s = pose.rate_deg_s.roll;
  // The pod's signs and yaw range (docs/protocol/decisions.md#conventions); the model's pose
  // stays in true terms (right, up, right-down positive).
  p::attitude_to_wire(report, codec.conventions);
  return encode(report, codec);
}

Result<p::Payload> camera_system_status(const PodModel& pod, const p::CodecOptions& codec) {
  const CameraSettings& s = pod.camera().settings();
  const SdCard& sd = pod.camera().sd();
  p::CameraSystemStatus report;
  report.capture_mode = same_code<p::CaptureMode>(s.capture_mode);
  report.stream_resolution = same_code<p::ReportedStreamResolution>(s.stream_resolution);
  report.encoding = same_code<p::VideoEncoding>(s.stream_encoding);
  report.image_mode = same_code<p::ImageMode>(s.image_mode);
  report.bitrate = same_code<p::StreamBitrate>(s.stream_bitrate);
  report.photo_mode = same_code<p::PhotoMode>(s.photo_mode);
  report.time_lapse_interval_s = s.time_lapse_interval_s;
  report.burst_count = s.burst_count;
  report.sd_state = same_code<p::SdCardState>(sd.state());
  // Counts of the pod's unit (sd_capacity_unit), rounded down so used + free never exceeds total.
  report.sd_total_mb = p::sd_capacity_to_wire(sd.capacity_mb(), codec.conventions);
  report.sd_free_mb = p::sd_capacity_to_wire(sd.free_mb(), codec.conventions);
  report.sd_used_mb = p::sd_capacity_to_wire(sd.used_mb(), codec.conventions);
  return encode(report, codec);
}

Result<p::Payload> thermal_status(const PodModel& pod, const p::CodecOptions& codec) {
  const ThermalStats stats = pod.thermal_stats();
  p::ThermalStatus report;
  report.max_degC = stats.max_degC;
  report.min_degC = stats.min_degC;
  report.center_degC = stats.centre_degC;
  report.point_degC = stats.spot_degC;
  report.average_degC = stats.average_degC;
  report.max_x_px = static_cast<uint16_t>(stats.max_at.x);
  report.max_y_px = static_cast<uint16_t>(stats.max_at.y);
  report.min_x_px = static_cast<uint16_t>(stats.min_at.x);
  report.min_y_px = static_cast<uint16_t>(stats.min_at.y);
  report.center_x_px = static_cast<uint16_t>(stats.centre_at.x);
  report.center_y_px = static_cast<uint16_t>(stats.centre_at.y);
  report.point_x_px = static_cast<uint16_t>(stats.spot_at.x);
  report.point_y_px = static_cast<uint16_t>(stats.spot_at.y);
  report.high_alarm = stats.high_alarm;
  report.low_alarm = stats.low_alarm;
  report.difference_alarm = stats.difference_alarm;
  report.threshold_alarm = stats.threshold_alarm;
  return encode(report, codec);
}

Result<p::Payload> visible_status(const PodModel& pod, const p::CodecOptions& codec) {
  const Exposure exposure = pod.exposure();
  p::VisibleStatus report;
  report.zooming = pod.zoom().zooming();
  report.focal_length_mm = pod.zoom().focal_length_mm();
  report.zoom_x = pod.zoom().zoom();
  report.ev = same_code<p::ExposureValue>(exposure.ev_code);
  report.iso_db = exposure.iso_db;
  // 1/4, 1/8 and 1/15 s do not fit 16 bits of microseconds: what goes out is shutter_field's
  // (saturated by default, never wrapped unless the reading says so).
  report.shutter_us = p::shutter_to_wire(exposure.shutter_us, codec.conventions.shutter_field);
  report.ae_lock_on = pod.camera().visible().ae_lock_on;
  report.focusing = pod.zoom().focusing();
  // The document gives this field no unit; read as 0.01 mm like the focal length.
  report.precise_shot_focal_length_mm = pod.camera().settings().precise_focal_length_raw / 100.0;
  return encode(report, codec);
}

Result<p::Payload> periodic_range(const PodModel& pod, const p::CodecOptions& codec) {
  p::LaserPeriodicRangeStatus report;
  report.distance_m = pod.laser_range().value_or(0.0);  // 0: no return
  return encode(report, codec);
}

// One visitor per event kind: the status frame it becomes.
struct EventEncoder {
  const p::CodecOptions& codec;

  template <class Frame>
  std::optional<OutgoingMessage> send(const Frame& frame) const {
    const Result<p::Payload> payload = encode(frame, codec);
    if (!payload) return std::nullopt;
    return OutgoingMessage{Frame::kId, *payload};
  }
  // Photo, precise reshoot and record status frames begin with the lens and the state.
  template <class Frame, class Event>
  static Frame lens_and_state(const Event& e) {
    Frame frame;
    frame.lens = same_code<decltype(frame.lens)>(e.lens_mode);
    frame.state = same_code<decltype(frame.state)>(e.state);
    return frame;
  }

  std::optional<OutgoingMessage> operator()(const ZoomStatusEvent& e) const {
    p::ZoomStatus frame;
    frame.progress = e.zooming ? p::ZoomProgress::kZooming : p::ZoomProgress::kDone;
    return send(frame);
  }
  std::optional<OutgoingMessage> operator()(const PhotoStatusEvent& e) const {
    if (e.precise) return send(lens_and_state<p::PreciseReshootStatus>(e));
    p::PhotoStatus frame = lens_and_state<p::PhotoStatus>(e);
    frame.burst_count = e.count;
    return send(frame);
  }
  std::optional<OutgoingMessage> operator()(const RecordStatusEvent& e) const {
    p::RecordStatus frame = lens_and_state<p::RecordStatus>(e);
    frame.recording_time_s = e.seconds;
    return send(frame);
  }
  std::optional<OutgoingMessage> operator()(const FormatStatusEvent& e) const {
    p::SdFormatStatus frame;
    frame.state = same_code<p::SdFormatState>(e.state);
    return send(frame);
  }
  std::optional<OutgoingMessage> operator()(const TfUpgradeStatusEvent& e) const {
    p::TfCardUpgradeStatus frame;
    frame.state = same_code<p::TfUpgradeState>(e.state);
    return send(frame);
  }
  std::optional<OutgoingMessage> operator()(const MaintenanceEvent& e) const {
    // A pod whose calibrations end with their ACK never reports them here.
    if (e.calibration && codec.conventions.calibration_end == p::CalibrationEnd::kAck)
      return std::nullopt;
    p::CameraUpgradeStatus report;
    report.state = same_code<p::CameraUpgradeState>(e.state);
    report.progress_percent = e.progress;
    return send(report);
  }
  std::optional<OutgoingMessage> operator()(const GpsRequestEvent&) const { return std::nullopt; }
};

}  // namespace

const std::vector<PeriodicReport>& periodic_reports() {
  static const std::vector<PeriodicReport> kReports = {
      {p::GimbalStatus::kId, 0.5, always, gimbal_status},
      {p::GimbalAttitude::kId, 0.1, always, gimbal_attitude},
      {p::CameraSystemStatus::kId, 1.0, camera_up, camera_system_status},
      {p::ThermalStatus::kId, 0.2, measuring, thermal_status},
      {p::VisibleStatus::kId, 0.2, camera_up, visible_status},
      {p::LaserPeriodicRangeStatus::kId, 1.0, ranging, periodic_range},
  };
  return kReports;
}

ReportScheduler::ReportScheduler() : next_due_s_(periodic_reports().size(), 0.0) {}

std::vector<const PeriodicReport*> ReportScheduler::due(const PodModel& pod, double now_s) {
  std::vector<const PeriodicReport*> out;
  const auto& reports = periodic_reports();
  for (size_t i = 0; i < reports.size(); ++i) {
    if (!reports[i].active(pod)) {
      next_due_s_[i] = now_s;  // first report as soon as it becomes active
      continue;
    }
    if (now_s + 1e-9 < next_due_s_[i]) continue;
    out.push_back(&reports[i]);
    // Keep the cadence; after a stall, skip the missed slots rather than bursting.
    next_due_s_[i] += reports[i].period_s;
    if (next_due_s_[i] <= now_s) next_due_s_[i] = now_s + reports[i].period_s;
  }
  return out;
}

std::optional<OutgoingMessage> encode_event(const PodEvent& event, const p::CodecOptions& codec) {
  return std::visit(EventEncoder{codec}, event);
}

}  // namespace k40t::sim
