// Conformance of the simulated pod's gimbal (section 3.1), seen from a client built only on the
// core library (see test_sim_conformance.cpp): movement, pointing, servo, calibrations, refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "sim_conformance_support.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // SimConformance, SimLink, quick_pod, near, aim, ResponseCode, 1s

// ---- gimbal (3.1) ---------------------------------------------------------------------------

TEST_F(SimConformance, GimbalMovesAsCommandedAtTheDialSpeed) {
  EXPECT_EQ(link.send(dial_speed(10, 20)), ResponseCode::kOk);
  EXPECT_EQ(link.send(angles(-10, 40)), ResponseCode::kOk);
  // Moving: the reported rates are the dial speeds.
  const auto moving = link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_yaw_deg > 5 && a.joint_yaw_deg < 15; });
  ASSERT_TRUE(moving);
  EXPECT_NEAR(moving->yaw_rate_deg_s, 20, 0.01);
  EXPECT_NEAR(moving->pitch_rate_deg_s, -10, 0.01);
  const auto there = link.wait_report<p::GimbalAttitude>([](const p::GimbalAttitude& a) {
    return near(a.joint_yaw_deg, 40, 0.001) && near(a.joint_pitch_deg, -10, 0.001);
  });
  ASSERT_TRUE(there);
  EXPECT_NEAR(there->yaw_deg, 40, 0.001);  // attitude: level vehicle heading north
  EXPECT_NEAR(there->pitch_deg, -10, 0.001);

  EXPECT_EQ(link.send(request_with(&p::GimbalControlRequest::yaw, p::GimbalYawDirection::kRight)),
            ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_yaw_deg > 45; }));
  EXPECT_EQ(link.send(p::GimbalControlRequest{}), ResponseCode::kOk);  // stop, stop
  ASSERT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.yaw_rate_deg_s == 0; }));

  EXPECT_EQ(link.send(dial_speed(30, 30)), ResponseCode::kOk);
  EXPECT_EQ(link.send(request_with(&p::GimbalControlRequest::mode, p::GimbalMode::kLookDown)),
            ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_pitch_deg == -90 && a.joint_yaw_deg == 0; },
      15s));
  EXPECT_EQ(link.send(request_with(&p::GimbalControlRequest::mode, p::GimbalMode::kCentre)),
            ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>(
      [](const p::GimbalAttitude& a) { return a.joint_pitch_deg == 0 && a.joint_yaw_deg == 0; },
      15s));
}

TEST_F(SimConformance, GimbalPointAtUsesTheLensFieldOfView) {
  ASSERT_EQ(link.send(dial_speed(30, 30)), ResponseCode::kOk);
  p::GimbalPointAtRequest point;
  point.lens = p::GimbalAimLens::kThermal;
  point.zoom_x = 1;
  point.x_px = 1920;  // right edge: half the thermal field of view
  point.y_px = 540;
  EXPECT_EQ(link.send(point), ResponseCode::kOk);
  const double half_fov = field_of_view(Lens::kThermal, 1).horizontal_deg / 2;
  EXPECT_TRUE(link.wait_report<p::GimbalAttitude>([&](const p::GimbalAttitude& a) {
    return near(a.joint_yaw_deg, half_fov, 0.02) && a.yaw_rate_deg_s == 0;
  }));
}

TEST_F(SimConformance, GimbalServoStabilisationVersionAndRestart) {
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kStabilising && s.ir_ok && s.laser_ok &&
           s.gimbal_link == p::GimbalLinkState::kNormal &&
           s.camera_link == p::GimbalLinkState::kNormal;
  }));
  EXPECT_EQ(link.send(p::GimbalServoOffRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kOff;
  }));
  EXPECT_EQ(link.send(request_with(&p::GimbalControlRequest::mode, p::GimbalMode::kCentre)),
            ResponseCode::kOk);  // the servo comes back on
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kStabilising;
  }));
  EXPECT_EQ(link.send(request_with<p::GimbalStabilisationRequest>(
                &p::GimbalStabilisationRequest::enable, false)),
            ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>([](const p::GimbalStatus& s) {
    return s.stabilisation == p::GimbalStabilisationState::kOff;
  }));

  const auto version = link.ask(p::GimbalVersionRequest{});
  EXPECT_EQ(version.code, ResponseCode::kOk);
  EXPECT_EQ(version.hardware_major, 1);
  EXPECT_EQ(version.hardware_minor, 2);
  EXPECT_EQ(version.software_major, 3);
  EXPECT_EQ(version.software_patch, 1);
  EXPECT_EQ(link.send(p::GimbalUseFlightControllerAttitudeRequest{}), ResponseCode::kOk);

  const SimLink::Mark before_restart = link.mark();  // the restart may end before send() returns
  EXPECT_EQ(link.send(p::GimbalRestartRequest{}), ResponseCode::kOk);
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(before_restart, [](const p::GimbalStatus& s) {
    return s.gimbal_link == p::GimbalLinkState::kAbnormal;
  }));
  EXPECT_TRUE(link.wait_report<p::GimbalStatus>(
      [](const p::GimbalStatus& s) { return s.gimbal_link == p::GimbalLinkState::kNormal; }));
}

TEST_F(SimConformance, GimbalCalibrationsReportProgress) {
  const SimLink::Mark before_calibration = link.mark();  // its end is reported once
  EXPECT_EQ(link.send(p::GimbalDriftCalibrationRequest{}), ResponseCode::kOk);
  EXPECT_EQ(link.send(p::GimbalLinearCalibrationRequest{}), ResponseCode::kBusy);
  EXPECT_EQ(link.send(angles(0, 10)), ResponseCode::kBusy);
  ASSERT_TRUE(link.wait_report<p::CameraUpgradeStatus>(
      before_calibration, [](const p::CameraUpgradeStatus& s) {
        return s.state == p::CameraUpgradeState::kSucceeded;
      }));
  const auto progress = link.all<p::CameraUpgradeStatus>();
  ASSERT_GE(progress.size(), 2u);
  EXPECT_EQ(progress.front().state, p::CameraUpgradeState::kRepairing);
  EXPECT_EQ(progress.back().progress_percent, 100);
  EXPECT_EQ(link.send(p::GimbalLinearCalibrationRequest{}), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_for([&] {
    const auto now = link.all<p::CameraUpgradeStatus>();
    return now.size() > progress.size() && now.back().state == p::CameraUpgradeState::kSucceeded;
  }));
  EXPECT_EQ(link.send(p::GimbalAccelerationCalibrationRequest{}), ResponseCode::kOk);
}

TEST_F(SimConformance, GimbalRefusesWhatTheDocumentDoesNotAllow) {
  EXPECT_EQ(link.send_raw(0x000017, {200, 10, 0}), ResponseCode::kFailure);  // dial speed 40 deg/s
  EXPECT_EQ(link.send_raw(0x000012, {0x00, 0x10, 0x27}),
            ResponseCode::kLengthMismatch);  // 3 of 6 bytes
  EXPECT_EQ(link.send_raw(0x000012, {0x00, 0xB9, 0x0B, 0x02, 0, 0, 0}),
            ResponseCode::kFailure);  // up 30.01 deg
  EXPECT_EQ(link.send_raw(0x000010, {0x30, 0x02, 0x02, 0x00}), ResponseCode::kFailure);  // mode 3
}

}  // namespace
}  // namespace k40t::sim
