// The pod's angles in REP 103 signs and units (driver/pod_frames.h), ROS-free.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/pod_frames.h"

namespace k40t::driver {
namespace {

constexpr double kEps = 1e-9;

TEST(Rep103, PodUpAndRightBecomeNegativePitchAndYaw) {
  const Rep103Angles a = rep103_from_pod(90.0, 10.0, 30.0);  // right 90, roll 10, up 30
  EXPECT_NEAR(a.yaw, -M_PI / 2, kEps);                       // REP 103: left positive
  EXPECT_NEAR(a.roll, 10.0 * M_PI / 180, kEps);
  EXPECT_NEAR(a.pitch, -M_PI / 6, kEps);  // REP 103: down positive
}

TEST(Rep103, CommandsGoBackToThePodsSigns) {
  const PodAngles pod = pod_from_rep103({-M_PI / 2, 0.0, M_PI / 6});  // right, 30 deg down
  EXPECT_NEAR(pod.yaw_deg, 90.0, kEps);                               // the pod: right positive
  EXPECT_NEAR(pod.pitch_deg, -30.0, kEps);                            // the pod: up positive
  const PodAngles back = pod_from_rep103(rep103_from_pod(12.0, -3.0, 45.0));
  EXPECT_NEAR(back.yaw_deg, 12.0, kEps);
  EXPECT_NEAR(back.roll_deg, -3.0, kEps);
  EXPECT_NEAR(back.pitch_deg, 45.0, kEps);
}

// attitude_order (docs/protocol/decisions.md#conventions) at roll 90, pitch 90 (REP 103 angles).
// By hand: Ry(90) Rx(90) takes x to -z, the 120 deg turn about (1, 1, -1): (1/2, 1/2, -1/2, 1/2);
// Rx(90) Ry(90) takes x to y, the 120 deg turn about (1, 1, 1): (1/2, 1/2, 1/2, 1/2).
TEST(AttitudeOrder, ZyxAndZxyComposeDifferently) {
  const Rep103Angles a{0.0, M_PI / 2, M_PI / 2};
  const Quaternion zyx = attitude_rotation(a, protocol::AttitudeOrder::kZyx);
  EXPECT_NEAR(zyx.x, 0.5, kEps);
  EXPECT_NEAR(zyx.y, 0.5, kEps);
  EXPECT_NEAR(zyx.z, -0.5, kEps);
  EXPECT_NEAR(zyx.w, 0.5, kEps);
  const Quaternion zxy = attitude_rotation(a, protocol::AttitudeOrder::kZxy);
  EXPECT_NEAR(zxy.x, 0.5, kEps);
  EXPECT_NEAR(zxy.y, 0.5, kEps);
  EXPECT_NEAR(zxy.z, 0.5, kEps);
  EXPECT_NEAR(zxy.w, 0.5, kEps);
  // Yaw alone: the same in both orders, a turn about z.
  const Quaternion yaw = attitude_rotation({M_PI / 2, 0.0, 0.0}, protocol::AttitudeOrder::kZxy);
  EXPECT_NEAR(yaw.z, std::sqrt(0.5), kEps);
  EXPECT_NEAR(yaw.w, std::sqrt(0.5), kEps);
}

}  // namespace
}  // namespace k40t::driver
