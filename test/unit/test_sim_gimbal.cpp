// The simulated gimbal (document section 3.1): dial speed, limits, direction moves, modes,
// point-to-aim, servo, stabilisation and calibration.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/sim/geometry.h"
#include "k40t_driver/sim/gimbal_model.h"
#include "sim_test_util.h"

namespace k40t::sim {
namespace {

using testing::advance;
using testing::events_of;

// A gimbal with the default configuration and the queue its events go to.
class SimGimbal : public ::testing::Test {
 protected:
  GimbalModel gimbal;
  EventQueue events;
};

TEST_F(SimGimbal, ReachesTheCommandedAngleInTheTimeTheDialSpeedImplies) {
  ASSERT_EQ(gimbal.set_dial_speed(10, 10), Outcome::kOk);
  ASSERT_EQ(gimbal.command_angles(std::nullopt, 45.0), Outcome::kOk);
  // 45 deg at 10 deg/s: 4.5 s. A tenth of a second before, it is one degree short.
  advance(gimbal, 4.4, events);
  EXPECT_NEAR(gimbal.pose().joint_deg.yaw, 44.0, 1e-6);
  EXPECT_NEAR(gimbal.pose().rate_deg_s.yaw, 10.0, 1e-6);
  advance(gimbal, 0.1, events);
  EXPECT_NEAR(gimbal.pose().joint_deg.yaw, 45.0, 1e-6);
  advance(gimbal, 0.1, events);
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.yaw, 45.0);
  EXPECT_DOUBLE_EQ(gimbal.pose().rate_deg_s.yaw, 0.0);
}

TEST_F(SimGimbal, EachAxisUsesItsOwnDialSpeed) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 5), Outcome::kOk);
  ASSERT_EQ(gimbal.command_angles(-60.0, -20.0), Outcome::kOk);
  advance(gimbal, 2.0, events);  // pitch done (2 s), yaw 10 of 20 deg
  EXPECT_NEAR(gimbal.pose().joint_deg.pitch, -60.0, 1e-6);
  EXPECT_NEAR(gimbal.pose().joint_deg.yaw, -10.0, 1e-6);
  EXPECT_NEAR(gimbal.pose().rate_deg_s.yaw, -5.0, 1e-6);
}

// docs/protocol/gimbal_laser_sbus.md, 0x000017: the project's one default dial speed.
TEST_F(SimGimbal, BeforeAnyDialSpeedItTurnsAtTheProjectsDefault) {
  EXPECT_DOUBLE_EQ(gimbal.pitch_dial_speed_deg_s(), protocol::GimbalDialSpeedRequest::kDefaultDegS);
  EXPECT_DOUBLE_EQ(gimbal.yaw_dial_speed_deg_s(), 20.0);
}

TEST_F(SimGimbal, DialSpeedOutsideOneToThirtyIsRefused) {
  EXPECT_EQ(gimbal.set_dial_speed(0.5, 10), Outcome::kFailure);
  EXPECT_EQ(gimbal.set_dial_speed(10, 31), Outcome::kFailure);
  EXPECT_EQ(gimbal.set_dial_speed(1, 30), Outcome::kOk);
  EXPECT_DOUBLE_EQ(gimbal.pitch_dial_speed_deg_s(), 1);
  EXPECT_DOUBLE_EQ(gimbal.yaw_dial_speed_deg_s(), 30);
}

TEST_F(SimGimbal, AnglesBeyondTheMechanicalLimitsAreRefused) {
  EXPECT_EQ(gimbal.command_angles(31.0, std::nullopt), Outcome::kFailure);
  EXPECT_EQ(gimbal.command_angles(-91.0, std::nullopt), Outcome::kFailure);
  EXPECT_EQ(gimbal.command_angles(std::nullopt, 180.5), Outcome::kFailure);
  EXPECT_EQ(gimbal.command_angles(30.0, -180.0), Outcome::kOk);
}

TEST_F(SimGimbal, DirectionMovesUntilStoppedAndHolds) {
  ASSERT_EQ(gimbal.set_dial_speed(20, 20), Outcome::kOk);
  ASSERT_EQ(gimbal.move(YawMotion::kRight, PitchMotion::kDown), Outcome::kOk);
  advance(gimbal, 2.0, events);
  EXPECT_NEAR(gimbal.pose().joint_deg.yaw, 40.0, 1e-6);
  EXPECT_NEAR(gimbal.pose().joint_deg.pitch, -40.0, 1e-6);
  ASSERT_EQ(gimbal.move(YawMotion::kStop, PitchMotion::kStop), Outcome::kOk);
  advance(gimbal, 1.0, events);
  EXPECT_NEAR(gimbal.pose().joint_deg.yaw, 40.0, 1e-6);
  EXPECT_NEAR(gimbal.pose().joint_deg.pitch, -40.0, 1e-6);
  EXPECT_DOUBLE_EQ(gimbal.pose().rate_deg_s.yaw, 0.0);
}

TEST_F(SimGimbal, DirectionMoveStopsAtTheEndStops) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(gimbal.move(YawMotion::kLeft, PitchMotion::kUp), Outcome::kOk);
  advance(gimbal, 10.0, events);  // 300 deg of travel asked for
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.pitch, 30.0);
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.yaw, -180.0);
  EXPECT_DOUBLE_EQ(gimbal.pose().rate_deg_s.pitch, 0.0);
}

TEST_F(SimGimbal, CentreAndLookDown) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(gimbal.command_angles(20.0, 100.0), Outcome::kOk);
  advance(gimbal, 4.0, events);
  ASSERT_EQ(gimbal.look_down(), Outcome::kOk);
  advance(gimbal, 4.0, events);  // 110 deg of pitch, 100 of yaw at 30 deg/s
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.pitch, -90.0);
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.yaw, 0.0);
  ASSERT_EQ(gimbal.centre(), Outcome::kOk);
  advance(gimbal, 3.1, events);
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.pitch, 0.0);
}

TEST_F(SimGimbal, PointAtTurnsTowardThePixelByTheLensFieldOfView) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 30), Outcome::kOk);
  // The right edge of the telephoto image at 1x is half its horizontal field of view away.
  const FieldOfView tele_1x = field_of_view(Lens::kTele, 1.0);
  ASSERT_EQ(gimbal.point_at(Lens::kTele, 1.0, 1920, 540), Outcome::kOk);
  EXPECT_NEAR(gimbal.yaw_target_deg(), tele_1x.horizontal_deg / 2, 1e-6);
  EXPECT_NEAR(gimbal.pitch_target_deg(), 0.0, 1e-6);
  advance(gimbal, 2.0, events);

  // At 10x the same pixel offset is a tenth of the tangent: a smaller turn.
  const double yaw_before = gimbal.pose().joint_deg.yaw;
  ASSERT_EQ(gimbal.point_at(Lens::kTele, 10.0, 960, 1080), Outcome::kOk);
  const double expected_down =
      rad_to_deg(std::atan(std::tan(deg_to_rad(field_of_view(Lens::kTele, 10).vertical_deg / 2))));
  EXPECT_NEAR(gimbal.pitch_target_deg(), -expected_down, 1e-6);
  EXPECT_NEAR(gimbal.yaw_target_deg(), yaw_before, 1e-6);

  // The thermal lens has its own, narrower field of view.
  GimbalModel other;
  ASSERT_EQ(other.point_at(Lens::kThermal, 1.0, 1, 540), Outcome::kOk);
  EXPECT_NEAR(other.yaw_target_deg(), -field_of_view(Lens::kThermal, 1).horizontal_deg / 2, 0.05);
  EXPECT_EQ(other.point_at(Lens::kThermal, 1.0, 0, 540), Outcome::kFailure);
}

TEST_F(SimGimbal, ServoOffStopsMotionUntilTheNextCommand) {
  ASSERT_EQ(gimbal.command_angles(std::nullopt, 90.0), Outcome::kOk);
  advance(gimbal, 1.0, events);
  ASSERT_EQ(gimbal.servo_off(), Outcome::kOk);
  const double where = gimbal.pose().joint_deg.yaw;
  advance(gimbal, 1.0, events);
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.yaw, where);
  EXPECT_FALSE(gimbal.servo_on());
  EXPECT_EQ(gimbal.stabilisation_state(), StabilisationState::kOff);
  ASSERT_EQ(gimbal.centre(), Outcome::kOk);
  EXPECT_TRUE(gimbal.servo_on());
  EXPECT_EQ(gimbal.stabilisation_state(), StabilisationState::kActive);
}

TEST_F(SimGimbal, StabilisationCanBeSwitchedOff) {
  EXPECT_EQ(gimbal.stabilisation_state(), StabilisationState::kActive);
  ASSERT_EQ(gimbal.set_stabilisation(false), Outcome::kOk);
  EXPECT_EQ(gimbal.stabilisation_state(), StabilisationState::kOff);
}

TEST(SimGimbalConfigured, CalibrationReportsProgressOnceASecondAndBlocksMotion) {
  GimbalConfig config;
  config.drift_calibration_s = 5;
  GimbalModel gimbal(config);
  EventQueue events;
  ASSERT_EQ(gimbal.start_calibration(CalibrationKind::kDrift), Outcome::kOk);
  EXPECT_EQ(gimbal.start_calibration(CalibrationKind::kLinear), Outcome::kBusy);
  EXPECT_EQ(gimbal.centre(), Outcome::kBusy);
  advance(gimbal, 2.5, events);
  EXPECT_NEAR(*gimbal.calibration_progress(), 0.5, 0.01);
  advance(gimbal, 3.0, events);
  EXPECT_FALSE(gimbal.calibrating());
  const auto reports = events_of<MaintenanceEvent>(events);
  ASSERT_EQ(reports.size(), 6u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(reports[i].state, MaintenanceState::kRepairing);
    EXPECT_EQ(reports[i].progress, i * 20);
  }
  EXPECT_EQ(reports[5].state, MaintenanceState::kSucceeded);
  EXPECT_EQ(reports[5].progress, 100);
  EXPECT_EQ(gimbal.centre(), Outcome::kOk);
}

TEST_F(SimGimbal, SoftRestartGoesLimpThenReturnsToCentre) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(gimbal.command_angles(std::nullopt, 30.0), Outcome::kOk);
  advance(gimbal, 1.0, events);
  ASSERT_EQ(gimbal.soft_restart(), Outcome::kOk);
  EXPECT_TRUE(gimbal.restarting());
  EXPECT_EQ(gimbal.move(YawMotion::kLeft, PitchMotion::kStop), Outcome::kBusy);
  advance(gimbal, gimbal.config().restart_s + 1.5, events);
  EXPECT_FALSE(gimbal.restarting());
  EXPECT_DOUBLE_EQ(gimbal.pose().joint_deg.yaw, 0.0);
}

TEST_F(SimGimbal, TrackingHoldsTheBoxAndRefusesManualMotion) {
  ASSERT_EQ(gimbal.set_dial_speed(30, 30), Outcome::kOk);
  ASSERT_EQ(gimbal.start_tracking(Lens::kTele, 1.0, 1920, 540), Outcome::kOk);
  EXPECT_TRUE(gimbal.tracking());
  EXPECT_NEAR(gimbal.yaw_target_deg(), field_of_view(Lens::kTele, 1).horizontal_deg / 2, 1e-6);
  EXPECT_EQ(gimbal.centre(), Outcome::kBusy);
  EXPECT_EQ(gimbal.move(YawMotion::kLeft, PitchMotion::kStop), Outcome::kBusy);
  advance(gimbal, 2.0, events);
  gimbal.stop_tracking();
  EXPECT_EQ(gimbal.centre(), Outcome::kOk);
}

TEST(SimGeometry, WrapAndDirectionsAreConsistent) {
  EXPECT_DOUBLE_EQ(wrap_deg(190), -170);
  EXPECT_DOUBLE_EQ(wrap_deg(-180), 180);
  const Vec3 d = direction(30, -20);
  EXPECT_NEAR(yaw_of(d), 30, 1e-9);
  EXPECT_NEAR(pitch_of(d), -20, 1e-9);
  const CameraBasis basis = camera_basis(90, 0);  // looking east
  EXPECT_NEAR(basis.right.x, -1, 1e-12);          // right of east is south
  EXPECT_NEAR(basis.up.z, 1, 1e-12);
}

}  // namespace
}  // namespace k40t::sim
