// GimbalMove and GimbalCalibration: goal validation in REP 103 units, arrival within the
// tolerance from 0x000002 reports, calibration progress and end from 0x000008.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/operations/gimbal_operations.h"

namespace k40t::operations {
namespace {

namespace p = protocol;
constexpr double kDeg = M_PI / 180;

p::GimbalAttitude joints_deg(double pod_pitch, double pod_yaw) {  // the pod's own signs
  p::GimbalAttitude a;
  a.joint_pitch_deg = pod_pitch;
  a.joint_yaw_deg = pod_yaw;
  return a;
}

TEST(AngleRequest, Rep103SignsBecomeThePodsSigns) {
  // REP 103: pitch +20 deg = looking down, yaw +30 deg = turned left. The pod: down and left are
  // negative (protocol/messages/gimbal.h).
  Result<p::GimbalAngleRequest> r = angle_request_from_rep103(20 * kDeg, 30 * kDeg);
  ASSERT_TRUE(r) << r.error();
  EXPECT_NEAR(r->pitch_deg, -20, 1e-9);
  EXPECT_NEAR(r->yaw_deg, -30, 1e-9);
  EXPECT_TRUE(r->pitch_move);
  EXPECT_TRUE(r->yaw_move);
}

TEST(AngleRequest, LimitsAreTheDocumentsInRadians) {
  // Section 3.1.2.2: up 30 deg .. down 90 deg, 180 deg each way.
  EXPECT_TRUE(angle_request_from_rep103(90 * kDeg, 0));
  EXPECT_TRUE(angle_request_from_rep103(-30 * kDeg, 180 * kDeg));
  const Result<p::GimbalAngleRequest> too_high = angle_request_from_rep103(-31 * kDeg, 0);
  ASSERT_FALSE(too_high);
  EXPECT_NE(too_high.error().find("field 'pitch'"), std::string::npos);
  EXPECT_NE(too_high.error().find("positive = down"), std::string::npos);
  const Result<p::GimbalAngleRequest> yaw = angle_request_from_rep103(0, 181 * kDeg);
  ASSERT_FALSE(yaw);
  EXPECT_NE(yaw.error().find("field 'yaw'"), std::string::npos);
}

TEST(Rep103Joints, NegatesPitchAndYawKeepsRoll) {
  p::GimbalAttitude a;
  a.joint_pitch_deg = 10;  // up
  a.joint_yaw_deg = -40;   // left
  a.joint_roll_deg = 5;
  const JointAngles j = rep103_joints(a);
  EXPECT_NEAR(j.pitch_rad, -10 * kDeg, 1e-12);
  EXPECT_NEAR(j.yaw_rad, 40 * kDeg, 1e-12);
  EXPECT_NEAR(j.roll_rad, 5 * kDeg, 1e-12);
}

TEST(GimbalMove, RefusesBadGoals) {
  GimbalMoveGoal goal;
  goal.pitch_rad = 2.0;  // beyond 90 deg down
  EXPECT_FALSE(GimbalMove::create(goal, 0));
  goal.pitch_rad = 0;
  goal.tolerance_rad = -0.1;
  const Result<GimbalMove> tolerance = GimbalMove::create(goal, 0);
  ASSERT_FALSE(tolerance);
  EXPECT_NE(tolerance.error().find("field 'tolerance'"), std::string::npos);
  goal.tolerance_rad = 0;
  goal.timeout_s = -1;
  EXPECT_FALSE(GimbalMove::create(goal, 0));
}

TEST(GimbalMove, ArrivesWithinTheToleranceOnBothAxes) {
  GimbalMoveGoal goal;
  goal.pitch_rad = 45 * kDeg;  // down 45
  goal.yaw_rad = -90 * kDeg;   // right 90
  goal.tolerance_rad = 1 * kDeg;
  Result<GimbalMove> move = GimbalMove::create(goal, 0);
  ASSERT_TRUE(move) << move.error();
  move->tracker().acknowledged(true, "ok");
  move->on_attitude(joints_deg(-44.5, 80));  // pitch there, yaw 10 deg short
  EXPECT_EQ(move->tracker().phase(), Phase::kRunning);
  EXPECT_NEAR(move->error_rad(), 10 * kDeg, 1e-9);
  ASSERT_TRUE(move->joints());
  EXPECT_NEAR(move->joints()->yaw_rad, -80 * kDeg, 1e-9);
  move->on_attitude(joints_deg(-44.5, 89.2));
  EXPECT_EQ(move->tracker().phase(), Phase::kSucceeded);
  EXPECT_NE(move->tracker().reason().find("deg from the target"), std::string::npos);
}

TEST(GimbalMove, YawErrorIsNotWrappedAcrossTheEndStops) {
  GimbalMoveGoal goal;
  goal.yaw_rad = 179 * kDeg;
  Result<GimbalMove> move = GimbalMove::create(goal, 0);
  ASSERT_TRUE(move);
  move->tracker().acknowledged(true, "ok");
  move->on_attitude(joints_deg(0, 179));  // REP 103 yaw -179: the other end stop
  EXPECT_EQ(move->tracker().phase(), Phase::kRunning);
  EXPECT_NEAR(move->error_rad(), 358 * kDeg, 1e-9);
}

TEST(GimbalMove, DefaultToleranceAndTimeout) {
  Result<GimbalMove> move = GimbalMove::create(GimbalMoveGoal{}, 10);
  ASSERT_TRUE(move);
  EXPECT_DOUBLE_EQ(move->tolerance_rad(), GimbalMove::kDefaultToleranceRad);
  EXPECT_EQ(move->tracker().timeout_s(), GimbalMove::kDefaultTimeoutS);
  move->tracker().acknowledged(true, "ok");
  move->on_attitude(joints_deg(0.6, 0));  // 0.6 deg off: outside 0.5 deg
  EXPECT_EQ(move->tracker().check(10 + GimbalMove::kDefaultTimeoutS), Phase::kTimedOut);
  EXPECT_NE(move->tracker().reason().find("0.60 deg from the target"), std::string::npos);
}

TEST(CalibrationKind, ZeroToTwo) {
  EXPECT_EQ(calibration_kind(0).value(), CalibrationKind::kDrift);
  EXPECT_EQ(calibration_kind(2).value(), CalibrationKind::kAccelerometer);
  const Result<CalibrationKind> bad = calibration_kind(3);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "field 'kind' must be 0 (drift), 1 (linear) or 2 (accelerometer), got 3");
}

TEST(GimbalCalibration, ProgressFromRepairingThenSucceeded) {
  Result<GimbalCalibration> c = GimbalCalibration::create(1, 0, 0);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind(), CalibrationKind::kLinear);
  EXPECT_EQ(c->tracker().timeout_s(), GimbalCalibration::kDefaultTimeoutS);
  EXPECT_EQ(c->progress_percent(), -1);
  c->tracker().acknowledged(true, "ok");
  p::CameraUpgradeStatus status;
  status.state = p::CameraUpgradeState::kRepairing;
  status.progress_percent = 40;
  c->on_status(status);
  EXPECT_EQ(c->progress_percent(), 40);
  EXPECT_EQ(c->tracker().status_text(), "calibrating, 40 %");
  // A TF-card upgrade's frame is not this calibration's.
  status.state = p::CameraUpgradeState::kUpgrading;
  status.progress_percent = 90;
  c->on_status(status);
  EXPECT_EQ(c->progress_percent(), 40);
  status.state = p::CameraUpgradeState::kSucceeded;
  status.progress_percent = 100;
  c->on_status(status);
  EXPECT_EQ(c->tracker().phase(), Phase::kSucceeded);
  EXPECT_EQ(c->progress_percent(), 100);
  EXPECT_EQ(c->tracker().reason(), "gimbal linear calibration: done");
}

TEST(GimbalCalibration, FailedStateAndBadGoals) {
  Result<GimbalCalibration> c = GimbalCalibration::create(0, 5, 0);
  ASSERT_TRUE(c);
  c->tracker().acknowledged(true, "ok");
  p::CameraUpgradeStatus status;
  status.state = p::CameraUpgradeState::kRepairing;
  c->on_status(status);
  status.state = p::CameraUpgradeState::kFailed;
  c->on_status(status);
  EXPECT_EQ(c->tracker().phase(), Phase::kFailed);
  EXPECT_FALSE(GimbalCalibration::create(7, 0, 0));
  EXPECT_FALSE(GimbalCalibration::create(0, -2, 0));
}

p::CameraUpgradeStatus upgrade_frame(p::CameraUpgradeState state) {
  p::CameraUpgradeStatus status;
  status.state = state;
  status.progress_percent = state == p::CameraUpgradeState::kSucceeded ? 100 : 50;
  return status;
}

// calibration_end (docs/protocol/decisions.md#conventions): a pod that ends a calibration with
// its ACK alone.
TEST(GimbalCalibrationEnd, AckEndsItAtTheAck) {
  Result<GimbalCalibration> c = GimbalCalibration::create(0, 0, 0, p::CalibrationEnd::kAck);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tracker().check(0.1), Phase::kRunning);
  c->tracker().acknowledged(true, "ok");
  EXPECT_EQ(c->tracker().phase(), Phase::kSucceeded);
  EXPECT_EQ(c->tracker().reason(),
            "gimbal drift calibration: done (the OK ACK, calibration_end: ack)");
}

TEST(GimbalCalibrationEnd, AutoWithout0x000008EndsWithinTwoSecondsOfTheAck) {
  Result<GimbalCalibration> c = GimbalCalibration::create(0, 0, 10, p::CalibrationEnd::kAuto);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tracker().check(12), Phase::kRunning);  // no ACK yet: nothing ends it
  c->tracker().acknowledged(true, "ok");
  EXPECT_EQ(c->tracker().check(12.05), Phase::kRunning);
  // An idle pod's "succeeded", or a TF upgrade's, is not this calibration's.
  c->on_status(upgrade_frame(p::CameraUpgradeState::kSucceeded));
  EXPECT_EQ(c->tracker().check(13.5), Phase::kRunning);
  EXPECT_EQ(c->tracker().check(13.6), Phase::kSucceeded);
  EXPECT_NE(c->tracker().reason().find("calibration_end: auto"), std::string::npos);
}

TEST(GimbalCalibrationEnd, AutoWithRepairingWaitsForItsEnd) {
  Result<GimbalCalibration> c = GimbalCalibration::create(2, 0, 0, p::CalibrationEnd::kAuto);
  ASSERT_TRUE(c);
  c->tracker().acknowledged(true, "ok");
  EXPECT_EQ(c->tracker().check(0.1), Phase::kRunning);
  c->on_status(upgrade_frame(p::CameraUpgradeState::kRepairing));
  EXPECT_EQ(c->tracker().check(5), Phase::kRunning);
  c->on_status(upgrade_frame(p::CameraUpgradeState::kSucceeded));
  EXPECT_EQ(c->tracker().phase(), Phase::kSucceeded);
}

TEST(GimbalCalibrationEnd, StatusIgnoresAnUpgradesEndAndNeverEndsQuietly) {
  Result<GimbalCalibration> c = GimbalCalibration::create(1, 0, 0, p::CalibrationEnd::kStatus);
  ASSERT_TRUE(c);
  c->tracker().acknowledged(true, "ok");
  c->on_status(upgrade_frame(p::CameraUpgradeState::kUpgrading));
  c->on_status(upgrade_frame(p::CameraUpgradeState::kSucceeded));
  c->on_status(upgrade_frame(p::CameraUpgradeState::kFailed));
  EXPECT_EQ(c->tracker().check(30), Phase::kRunning);
  c->on_status(upgrade_frame(p::CameraUpgradeState::kRepairing));
  c->on_status(upgrade_frame(p::CameraUpgradeState::kSucceeded));
  EXPECT_EQ(c->tracker().phase(), Phase::kSucceeded);
}

}  // namespace
}  // namespace k40t::operations
