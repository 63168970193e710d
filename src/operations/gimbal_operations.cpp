#include "k40t_driver/operations/gimbal_operations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::operations {

namespace p = protocol;

namespace {
constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kDegToRad = M_PI / 180.0;

const char* calibration_name(CalibrationKind kind) {
  static constexpr EnumName<CalibrationKind> kNames[] = {
      {CalibrationKind::kDrift, "gimbal drift calibration"},
      {CalibrationKind::kLinear, "gimbal linear calibration"},
      {CalibrationKind::kAccelerometer, "gimbal accelerometer calibration"}};
  return name_in(kNames, kind, "gimbal calibration");
}
}  // namespace

Result<p::GimbalAngleRequest> angle_request_from_rep103(double pitch_rad, double yaw_rad) {
  // REP 103 pitch is the pod's pitch negated, so the pod's "up 30 .. down 90" becomes -30..+90 deg.
  const Status valid = p::first_failure(
      p::check_range("pitch", pitch_rad, -p::GimbalAngleRequest::kPitchMaxDeg * kDegToRad,
                     -p::GimbalAngleRequest::kPitchMinDeg * kDegToRad, "rad (positive = down)"),
      p::check_range("yaw", yaw_rad, -p::GimbalAngleRequest::kYawLimitDeg * kDegToRad,
                     p::GimbalAngleRequest::kYawLimitDeg * kDegToRad, "rad (positive = left)"));
  if (!valid) return valid;
  p::GimbalAngleRequest request;
  request.pitch_deg = -pitch_rad * kRadToDeg;
  request.yaw_deg = -yaw_rad * kRadToDeg;
  return request;
}

JointAngles rep103_joints(const p::GimbalAttitude& attitude) {
  // The signs of ros/conversions.h: REP 103 yaw and pitch are the pod's negated, roll is kept.
  JointAngles joints;
  joints.yaw_rad = -attitude.joint_yaw_deg * kDegToRad;
  joints.roll_rad = attitude.joint_roll_deg * kDegToRad;
  joints.pitch_rad = -attitude.joint_pitch_deg * kDegToRad;
  return joints;
}

Result<GimbalMove> GimbalMove::create(const GimbalMoveGoal& goal, double now_s) {
  Result<p::GimbalAngleRequest> request = angle_request_from_rep103(goal.pitch_rad, goal.yaw_rad);
  if (!request) return request.status();
  if (!std::isfinite(goal.tolerance_rad) || goal.tolerance_rad < 0 || goal.tolerance_rad > M_PI) {
    return Status::fail("field 'tolerance' must be 0 (the default, 0.5 deg) or 0..pi rad, got " +
                        std::to_string(goal.tolerance_rad));
  }
  const double tolerance = goal.tolerance_rad == 0 ? kDefaultToleranceRad : goal.tolerance_rad;
  return with_timeout(goal.timeout_s, kDefaultTimeoutS, [&](double seconds) {
    return GimbalMove(goal, request.value(), tolerance, seconds, now_s);
  });
}

GimbalMove::GimbalMove(const GimbalMoveGoal& goal, const p::GimbalAngleRequest& request,
                       double tolerance_rad, double timeout_s, double now_s)
    : TrackedOperation("gimbal move", "both joints within tolerance in 0x000002", timeout_s, now_s),
      goal_(goal),
      request_(request),
      tolerance_rad_(tolerance_rad) {}

void GimbalMove::on_attitude(const p::GimbalAttitude& attitude) {
  joints_ = rep103_joints(attitude);
  // The yaw joint has end stops, so its error is not wrapped: -179 deg is far from +179 deg.
  error_rad_ = std::max(std::abs(joints_->pitch_rad - goal_.pitch_rad),
                        std::abs(joints_->yaw_rad - goal_.yaw_rad));
  char text[96];
  std::snprintf(text, sizeof text, "%.2f deg from the target", error_rad_ * kRadToDeg);
  Step step;
  step.text = text;
  if (error_rad_ <= tolerance_rad_) step.phase = Phase::kSucceeded;
  tracker().report(step);
}

Result<CalibrationKind> calibration_kind(int kind) {
  if (kind < 0 || kind > 2) {
    return Status::fail("field 'kind' must be 0 (drift), 1 (linear) or 2 (accelerometer), got " +
                        std::to_string(kind));
  }
  return static_cast<CalibrationKind>(kind);
}

std::optional<Step> calibration_step(const p::CameraUpgradeStatus& status) {
  Step step;
  switch (status.state) {
    case p::CameraUpgradeState::kRepairing:
      step.text = "calibrating, " + std::to_string(status.progress_percent) + " %";
      return step;
    case p::CameraUpgradeState::kSucceeded:
      step.phase = Phase::kSucceeded;
      step.text = "done";
      return step;
    case p::CameraUpgradeState::kFailed:
      step.phase = Phase::kFailed;
      step.text = "the pod reported the calibration failed";
      return step;
    case p::CameraUpgradeState::kUpgrading:
      break;
  }
  return std::nullopt;
}

Result<GimbalCalibration> GimbalCalibration::create(int kind, double timeout_s, double now_s,
                                                    p::CalibrationEnd end) {
  Result<CalibrationKind> which = calibration_kind(kind);
  if (!which) return which.status();
  return with_timeout(timeout_s, kDefaultTimeoutS, [&](double seconds) {
    return GimbalCalibration(which.value(), seconds, now_s, end);
  });
}

namespace {
const char* awaited_end(p::CalibrationEnd end) {
  switch (end) {
    case p::CalibrationEnd::kStatus:
      return "0x000008 'succeeded' (calibration_end: status)";
    case p::CalibrationEnd::kAck:
      return "the OK ACK (calibration_end: ack)";
    case p::CalibrationEnd::kAuto:
      break;
  }
  return "0x000008 'succeeded' after its 'repairing' (calibration_end: auto)";
}
}  // namespace

GimbalCalibration::GimbalCalibration(CalibrationKind kind, double timeout_s, double now_s,
                                     p::CalibrationEnd end)
    : TrackedOperation(calibration_name(kind), awaited_end(end), timeout_s, now_s),
      kind_(kind),
      end_(end) {
  if (end == p::CalibrationEnd::kAck)
    tracker().end_with_ack("done (the OK ACK, calibration_end: ack)");
  if (end == p::CalibrationEnd::kAuto) {
    tracker().end_if_quiet_after_ack(
        kQuietS,
        "done (the OK ACK and no 0x000008 'repairing' within 1.5 s, calibration_end: auto)");
  }
}

void GimbalCalibration::on_status(const p::CameraUpgradeStatus& status) {
  if (end_ == p::CalibrationEnd::kAck) return;  // 0x000008 is the camera's, not this
  const std::optional<Step> step = calibration_step(status);
  if (!step) return;
  if (status.state == p::CameraUpgradeState::kRepairing) repairing_seen_ = true;
  if (!repairing_seen_) return;  // an upgrade's end, or an idle pod's "succeeded"
  if (status.state == p::CameraUpgradeState::kRepairing ||
      status.state == p::CameraUpgradeState::kSucceeded) {
    progress_percent_ = status.progress_percent;
  }
  tracker().report(*step);
}

}  // namespace k40t::operations
