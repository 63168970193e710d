// The gimbal's long operations without ROS: moving to angles until the joints are there, and a
// calibration until the pod reports its end. Angles are REP 103 (radians, pitch positive down,
// yaw positive left), the convention of joint_states and gimbal/set_angle (ros/conversions.h);
// the pod's own (degrees, pitch up, yaw right) stays inside.
#pragma once

#include <cmath>
#include <optional>

#include "k40t_driver/operations/operation_tracker.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::operations {

// REP 103 target -> 0x000012, checked in the caller's units (the error names the field, its range
// in radians and its sign convention). Shared with the gimbal/set_angle service.
Result<protocol::GimbalAngleRequest> angle_request_from_rep103(double pitch_rad, double yaw_rad);

struct JointAngles {  // REP 103, radians
  double yaw_rad = 0;
  double roll_rad = 0;
  double pitch_rad = 0;
};
JointAngles rep103_joints(const protocol::GimbalAttitude& attitude);

struct GimbalMoveGoal {
  double pitch_rad = 0;
  double yaw_rad = 0;
  double tolerance_rad = 0;  // 0: kDefaultToleranceRad
  double timeout_s = 0;      // 0: kDefaultTimeoutS
};

// Succeeds when a 0x000002 report puts both joints within the tolerance of the target.
class GimbalMove : public TrackedOperation {
 public:
  static constexpr double kDefaultToleranceRad = 0.5 * M_PI / 180;  // 0.5 deg
  // The longest move, 360 deg of yaw, takes 18 s at the default dial speed of 20 deg/s; 30 s
  // leaves room for dial speeds down to 12 deg/s (slower ones need a goal timeout).
  static constexpr double kDefaultTimeoutS = 30;

  static Result<GimbalMove> create(const GimbalMoveGoal& goal, double now_s);

  const protocol::GimbalAngleRequest& request() const { return request_; }
  void on_attitude(const protocol::GimbalAttitude& attitude);
  const std::optional<JointAngles>& joints() const { return joints_; }
  double error_rad() const { return error_rad_; }  // largest axis error of the last report
  double tolerance_rad() const { return tolerance_rad_; }

 private:
  GimbalMove(const GimbalMoveGoal& goal, const protocol::GimbalAngleRequest& request,
             double tolerance_rad, double timeout_s, double now_s);

  GimbalMoveGoal goal_;
  protocol::GimbalAngleRequest request_;
  double tolerance_rad_;
  std::optional<JointAngles> joints_;
  double error_rad_ = -1;
};

enum class CalibrationKind : uint8_t { kDrift = 0, kLinear = 1, kAccelerometer = 2 };
// 0 drift (0x000013), 1 linear (0x00002E), 2 accelerometer (0x000031); shared with the
// gimbal/calibrate service.
Result<CalibrationKind> calibration_kind(int kind);

// A pod that reports calibrations in 0x000008 (section 3.2.1.4, the camera's upgrade/repair
// report) sends "repairing" with a percentage, then "succeeded" or "failed"; 0x000001 has no
// calibration field. "Upgrading" frames belong to a TF-card upgrade and are ignored.
std::optional<Step> calibration_step(const protocol::CameraUpgradeStatus& status);

// How it ends is the reading calibration_end (docs/protocol/decisions.md#conventions): the
// document gives the calibrations only an ACK.
//   - status: 0x000008 "succeeded"/"failed" after a "repairing" of its own (so an upgrade's end,
//     or an idle pod's "succeeded", never ends it);
//   - ack: the OK ACK is the end;
//   - auto: like status if a "repairing" comes within kQuietS of the OK ACK, else done then.
class GimbalCalibration : public TrackedOperation {
 public:
  static constexpr double kDefaultTimeoutS = 60;  // the calibrations take seconds (drift ~5 s)
  static constexpr double kQuietS = 1.5;          // auto: "no 0x000008 for it" (report is 1 Hz)

  static Result<GimbalCalibration> create(
      int kind, double timeout_s, double now_s,
      protocol::CalibrationEnd end = protocol::CalibrationEnd::kAuto);

  CalibrationKind kind() const { return kind_; }
  void on_status(const protocol::CameraUpgradeStatus& status);
  int progress_percent() const { return progress_percent_; }  // -1: none reported yet

 private:
  GimbalCalibration(CalibrationKind kind, double timeout_s, double now_s,
                    protocol::CalibrationEnd end);

  CalibrationKind kind_;
  protocol::CalibrationEnd end_;
  bool repairing_seen_ = false;
  int progress_percent_ = -1;
};

}  // namespace k40t::operations
