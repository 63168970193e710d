// sim/vehicle_motion.h and the control commands `fly`, `orbit`; the gimbal's continuous yaw
// (--gimbal-yaw-continuous): the scenarios of gimbal/look_at's rostest (docs/geo.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/gimbal_model.h"
#include "k40t_driver/sim/vehicle_motion.h"
#include "sim_control_target.h"

namespace k40t::sim {
namespace {

TEST(SimVehicleMotion, FliesThenChangesCourseWithoutAJump) {
  VehicleMotion motion(0, 15);
  EXPECT_NEAR(motion.position(2).y, 30, 1e-12);
  motion.fly(2, 10, 0);  // from (0, 30) north at 10 m/s
  EXPECT_NEAR(motion.position(2).y, 30, 1e-12);
  EXPECT_NEAR(motion.position(3).x, 10, 1e-12);
  EXPECT_NEAR(motion.position(3).y, 30, 1e-12);
  EXPECT_NEAR(motion.velocity(3).x, 10, 1e-12);
  motion.fly(3, 0, 0);  // hover
  EXPECT_NEAR(motion.position(100).x, 10, 1e-12);
}

TEST(SimVehicleMotion, OrbitsThroughWhereItIs) {
  VehicleMotion motion(0, 0);
  // Centre 150 m north: the vehicle is due south of it, radius 150 m. Clockwise seen from above
  // (north towards east) at 10 m/s: from the south it heads west.
  ASSERT_TRUE(motion.orbit(0, 150, 0, 10));
  EXPECT_NEAR(motion.velocity(0).x, 0, 1e-12);
  EXPECT_NEAR(motion.velocity(0).y, -10, 1e-12);
  // A quarter turn (2 pi 150 / 4 / 10 = 23.56 s) later it is due west of the centre.
  const double quarter = M_PI * 150 / 2 / 10;
  EXPECT_NEAR(motion.position(quarter).x, 150, 1e-9);
  EXPECT_NEAR(motion.position(quarter).y, -150, 1e-9);
  // Always 150 m from the centre, always 10 m/s.
  for (double t : {1.0, 7.5, 40.0}) {
    const Vec3 p = motion.position(t), v = motion.velocity(t);
    EXPECT_NEAR(std::hypot(p.x - 150, p.y), 150, 1e-9);
    EXPECT_NEAR(std::hypot(v.x, v.y), 10, 1e-9);
  }
  EXPECT_FALSE(motion.orbit(quarter, 150, -150, 10));  // at the centre: refused
}

TEST(SimVehicleMotion, ControlCommands) {
  testing::FakeTarget target;
  EXPECT_EQ(execute_control_command("fly 0 15", target), "ok flying 0 m/s north, 15 m/s east");
  for (int i = 0; i < 100; ++i) target.pod.step(0.01);
  EXPECT_NEAR(target.pod.pod_position().y, 15, 1e-9);
  EXPECT_EQ(execute_control_command("orbit 0 165 10", target),
            "ok orbiting 0 m north, 165 m east at 10 m/s");
  for (int i = 0; i < 100; ++i) target.pod.step(0.01);
  EXPECT_NEAR(std::hypot(target.pod.pod_position().x, target.pod.pod_position().y - 165), 150,
              1e-6);
  EXPECT_EQ(execute_control_command("fly 0 101", target).rfind("error", 0), 0u);
  const std::string truth = execute_control_command("truth", target);
  EXPECT_NE(truth.find(" zoom 1 hfov 61.5"), std::string::npos) << truth;
}

TEST(SimGimbalYaw, EndStopsByDefaultContinuousOnRequest) {
  EventQueue events;
  GimbalModel stops;
  stops.command_angles(0.0, 170.0);
  for (int i = 0; i < 1000; ++i) stops.step(0.01, events);
  stops.command_angles(0.0, -170.0);
  stops.step(0.5, events);  // 20 deg/s: 10 deg back towards 0, not through the back
  EXPECT_NEAR(stops.pose().joint_deg.yaw, 160, 1e-9);

  GimbalConfig config;
  config.yaw_continuous = true;
  GimbalModel continuous(config);
  continuous.command_angles(0.0, 170.0);
  for (int i = 0; i < 1000; ++i) continuous.step(0.01, events);
  continuous.command_angles(0.0, -170.0);
  continuous.step(0.5, events);  // 10 deg through the back: 180
  EXPECT_NEAR(std::abs(continuous.pose().joint_deg.yaw), 180, 1e-9);
  continuous.step(0.5, events);
  EXPECT_NEAR(continuous.pose().joint_deg.yaw, -170, 1e-9);
  // Turning right past 180 comes round to the left side.
  continuous.move(YawMotion::kLeft, PitchMotion::kStop);  // left: decreasing, -170 -> -180 -> 170
  continuous.step(1.0, events);
  EXPECT_NEAR(continuous.pose().joint_deg.yaw, 170, 1e-9);
}

}  // namespace
}  // namespace k40t::sim
